// When the end_of_scan and model timing modes serve a request
// (docs/timing.md). The transports hold the bytes; these say when to hand
// them to Station::handle() and whether the monitoring timer ran out first.
#include "station/station.hpp"

#include <algorithm>

#include "protocol/error_response.hpp"
#include "station/response_timing.hpp"
#include "station/scan_loop.hpp"

namespace slmp::station {

using std::chrono::microseconds;
using protocol::Outcome;

std::optional<Queued> Station::next_request(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy,
                                            const protocol::Session& session) const {
    std::size_t offset = 0;
    while (offset < input.size()) {
        const auto request = engine_.decode(input.subspan(offset), policy, session.own);
        switch (request.frame) {
            case protocol::Request::Frame::NeedMore: return std::nullopt;
            case protocol::Request::Frame::Garbage: offset += std::max<std::size_t>(request.size, 1); continue;
            case protocol::Request::Frame::TooLarge: return Queued{offset, offset + 1, {}};   // refused at once, no wait
            case protocol::Request::Frame::Complete: break;
        }
        return Queued{offset, offset + request.size, ResponseTiming::monitoring_timer(request, input.subspan(offset))};
    }
    return std::nullopt;
}

std::optional<Service> Station::model_service(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy,
                                              const protocol::Session& session,
                                              std::chrono::steady_clock::time_point arrival) {
    if (!timing_ || !scan_) return std::nullopt;
    const auto request = engine_.decode(input, policy, session.own);
    if (!request.complete() || !request.has_command) return std::nullopt;
    const auto& clock = scan_->clock();
    // The next END after the arrival in CPU time: a running clock's scan covers period × speed of it.
    const auto cpu_period = clock.frozen() ? std::chrono::duration_cast<microseconds>(scan_->period())
                                           : std::chrono::duration_cast<microseconds>(scan_->period() * clock.speed());
    const auto next_end = scan_->last_end() + cpu_period;
    const auto scan_wait = next_end > arrival ? std::chrono::duration_cast<microseconds>(next_end - arrival) : microseconds{0};
    const auto modelled = timing_->modelled(request, scan_wait);
    const auto timer = ResponseTiming::monitoring_timer(request, input);
    // The port gives up when the timer runs out first (docs/timing.md).
    if (timer.count() > 0 && modelled > timer) return Service{arrival + timer, true, timer};
    return Service{arrival + modelled, false, modelled};
}

std::optional<Service> Station::end_of_scan_service(std::chrono::steady_clock::time_point arrival,
                                                    std::chrono::milliseconds timer,
                                                    std::chrono::steady_clock::time_point now, bool at_end) {
    // The END that serves it has come: in time unless it came after the timer.
    // Before it: only a timer that has run out answers now.
    const bool expired = timer.count() > 0 && now - arrival > timer;
    if (!at_end && !(timer.count() > 0 && now - arrival >= timer)) return std::nullopt;
    return Service{now, at_end ? expired : true, std::nullopt};
}

Outcome Station::timed_out(const protocol::Request& request, std::chrono::milliseconds timer) {
    // CF71, "processing aborted because of a timeout"; the CPU never ran the
    // request, so nothing is read or written.
    Outcome o;
    o.action = Outcome::Action::Respond;
    o.consumed = request.size;
    o.command = request.command;
    o.subcommand = request.subcommand;
    o.end_code = protocol::EndCode::RelayTimeout;
    o.response = protocol::encode_error_response(request.header, request.command, request.subcommand, o.end_code);
    o.note = "the monitoring timer (" + std::to_string(timer.count()) +
             " ms) ran out before the CPU served the request; answered CF71 when it did";
    return o;
}

}  // namespace slmp::station
