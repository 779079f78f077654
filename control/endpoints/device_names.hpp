// The address text of the HTTP API's device endpoints: a MELSEC device (D100,
// M0, ZR0) or, on a station that serves a front end, that protocol's name for
// a cell — host link CIO0010, HR5, DM0100, VR3; JW relay 04033, register
// 09000, file address F1:0200 — resolved through the station's memory map
// to the device that holds it. docs/api.md, "Devices".
#pragma once

#include <optional>
#include <string>

#include "control/endpoints/device_view.hpp"
#include "station/station.hpp"

namespace slmp::control {

struct NamedDevice {
    devicemodel::DeviceAddress start;
    std::optional<View> view;   // the form's own default view (VR: dwords); unset: the device's
};

// Throws ApiError (400) naming the form when the text is a front end's name
// that is wrong, or no address at all.
NamedDevice parse_station_device(const station::Station& station, const std::string& text);

}  // namespace slmp::control
