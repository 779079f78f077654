// The symbol of one part of a timer or counter area, for code that holds an
// area and needs the device a client names: (T, Contact) -> TS, (C, Value) -> CN.
// Kept out of device_table.hpp, which nearly every file includes.
#pragma once

#include "devicemodel/device_table.hpp"

namespace slmp::devicemodel {

// Null when the area has no such part.
const DeviceSpec* find_by_part(Area area, Part part);

}  // namespace slmp::devicemodel
