// The Ladder Motion host link as a protocol face (frontends/face.hpp): its
// "hostlink" section, --hostlink-port and --serial, the "ladder-motion"
// station kind, its unit (HostLink and a LinkState a connection).
#pragma once

#include "frontends/face.hpp"

namespace slmp::hostlink {

const frontends::Face& face();

}  // namespace slmp::hostlink
