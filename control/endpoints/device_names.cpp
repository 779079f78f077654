#include "control/endpoints/device_names.hpp"

#include "control/http/reply.hpp"
#include "frontends/face.hpp"

namespace slmp::control {

NamedDevice parse_station_device(const station::Station& station, const std::string& text) {
    std::string error;
    for (const auto* unit : station.frontends()) {
        if (auto name = unit->resolve_name(text, &error)) {
            NamedDevice named{name->start, std::nullopt};
            if (name->view == frontends::DeviceName::View::Dwords) named.view = View::Dwords;
            else if (name->view == frontends::DeviceName::View::Words) named.view = View::Words;
            return named;
        }
        if (!error.empty()) throw ApiError{Status::bad_request, error};
    }
    return {parse_device(text, station.cpu().profile().numbering), std::nullopt};
}

}  // namespace slmp::control
