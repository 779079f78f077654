// SLMP, the MELSEC CPU's own protocol, as a protocol face (frontends/face.hpp):
// registered first, configured by the station's own "ports" (--tcp-port,
// --udp-port), and timed — the station serves its requests on its own path
// (station/inbox.hpp), when the timing mode says, with relays, the upstream
// and Ondemand pushes. The protocol itself is protocol/ (docs/frames.md).
#pragma once

#include "frontends/face.hpp"

namespace slmp::slmp_face {

const frontends::Face& face();

}  // namespace slmp::slmp_face
