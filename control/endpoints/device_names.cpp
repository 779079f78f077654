#include "control/endpoints/device_names.hpp"

#include "control/http/reply.hpp"
#include "frontends/hostlink/addresses.hpp"
#include "frontends/hostlink/host_link.hpp"
#include "frontends/jw51cm/addresses.hpp"
#include "frontends/jw51cm/computer_link.hpp"

namespace slmp::control {

NamedDevice parse_station_device(const station::Station& station, const std::string& text) {
    const auto& frontends = station.frontends();
    std::string error;
    if (frontends.hostlink) {
        if (auto cell = hostlink::resolve_name(frontends.hostlink->options().map, text, &error)) {
            NamedDevice named{cell->device, std::nullopt};
            if (cell->long_word) named.view = View::Dwords;
            else if (cell->device.spec->unit == devicemodel::Unit::Bit) named.view = View::Words;   // 16 bits a channel
            return named;
        }
        if (!error.empty()) throw ApiError{Status::bad_request, error};
    }
    if (frontends.jw51cm) {
        if (auto cell = jw51cm::resolve_name(frontends.jw51cm->map(), text, &error)) return {*cell, std::nullopt};
        if (!error.empty()) throw ApiError{Status::bad_request, error};
    }
    return {parse_device(text, station.cpu().profile().numbering), std::nullopt};
}

}  // namespace slmp::control
