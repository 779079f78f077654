// The Sharp JW-51CM computer link as a protocol face (frontends/face.hpp): its
// "jw51cm" section, the "sharp-jw" station kind, its unit (one ComputerLink).
#pragma once

#include "frontends/face.hpp"

namespace slmp::jw51cm {

const frontends::Face& face();

}  // namespace slmp::jw51cm
