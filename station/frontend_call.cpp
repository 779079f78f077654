#include "station/frontend_call.hpp"

#include <spdlog/spdlog.h>

#include "station/station.hpp"

namespace slmp::station {

FrontEndCall::FrontEndCall(Station& station, scenarios::Protocol protocol, std::uint64_t connection,
                           const protocol::Peer& peer)
    : station_(station), protocol_(protocol), connection_(connection), peer_(peer),
      started_(std::chrono::steady_clock::now()) {
    station_.catch_up();   // a sleeping scan loop first runs the scans due by now
    station_.activity().request_starting();   // the scan's writes so far are not this request's
}

frontends::Gate FrontEndCall::gate() {
    return [this](std::string_view command) {
        incoming_.request_protocol = protocol_;
        incoming_.command_text = std::string(command);
        incoming_.peer = peer_;
        plan_ = station_.scenario().frontend_before(incoming_, connection_);
        frontends::Intercept intercept;
        if (plan_.silent) intercept.kind = frontends::Intercept::Kind::Silent;
        else if (plan_.frontend_code) intercept = {frontends::Intercept::Kind::Answer, *plan_.frontend_code};
        return intercept;
    };
}

FrontEndCall::Delivery FrontEndCall::finish(std::span<const std::uint8_t> request, std::string_view command, bool known,
                                            std::string_view name, std::string_view code,
                                            std::span<const std::uint8_t> response) {
    Delivery delivery;
    delivery.close = plan_.close;
    delivery.reset = plan_.reset;
    delivery.delay = std::chrono::microseconds(static_cast<std::int64_t>(plan_.decision.delay_ms * 1000));
    const auto protocol = scenarios::to_string(protocol_);
    if (!plan_.decision.fired.empty())
        station_.log().debug("{} {}: {} {}: scenario fault(s) fired", protocol, peer_.text(), command, plan_.decision.fired.size());
    FrontEndRecord record{protocol,  connection_, peer_,    command,  known,
                          name,      code,        delivery.close || delivery.reset,
                          request,   response,    std::chrono::steady_clock::now() - started_,
                          plan_.decision.fired};
    station_.scenario().frontend_recorded(record);
    station_.activity().frontend_request(record);
    station_.touched();   // the request may have started a timer or changed the state
    return delivery;
}

}  // namespace slmp::station
