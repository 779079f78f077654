// When the end_of_scan and model timing modes serve a request
// (docs/timing.md). The inbox (station/inbox.hpp) holds the bytes; these say
// when to hand them to Station::handle() and whether the monitoring timer ran
// out first.
#include "station/station.hpp"

#include <algorithm>

#include "protocol/error_response.hpp"
#include "station/response_timing.hpp"
#include "station/scan_loop.hpp"

namespace slmp::station {

using std::chrono::microseconds;
using protocol::Outcome;

std::optional<Queued> Station::next_request(std::span<const std::uint8_t> input, protocol::DataCodePolicy policy) const {
    std::size_t offset = 0;
    while (offset < input.size()) {
        const auto rest = input.subspan(offset);
        const auto scan = engine_.frame(rest, policy);
        switch (scan.status) {
            case protocol::FrameScan::Status::NeedMore: return std::nullopt;
            case protocol::FrameScan::Status::Garbage: offset += std::max<std::size_t>(scan.size, 1); continue;
            case protocol::FrameScan::Status::TooLarge: return Queued{offset, offset + 1, {}, true};
            case protocol::FrameScan::Status::Complete: break;
        }
        return Queued{offset, offset + scan.size, ResponseTiming::monitoring_timer(scan.header, rest), false};
    }
    return std::nullopt;
}

Ticket Station::schedule(std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy, const protocol::Session& session,
                         std::chrono::steady_clock::time_point arrival) {
    Ticket ticket;
    ticket.bytes = std::move(frame);
    ticket.request = engine_.decode(ticket.bytes, policy, session.own);
    const auto& request = ticket.request;
    if (!timing_ || !scan_ || !request.complete() || !request.has_command) return ticket;
    const auto& clock = scan_->clock();
    // The next END after the arrival in CPU time: a running clock's scan covers period × speed of it.
    const auto cpu_period = clock.frozen() ? std::chrono::duration_cast<microseconds>(scan_->period())
                                           : std::chrono::duration_cast<microseconds>(scan_->period() * clock.speed());
    const auto next_end = scan_->last_end() + cpu_period;
    const auto scan_wait = next_end > arrival ? std::chrono::duration_cast<microseconds>(next_end - arrival) : microseconds{0};
    const auto modelled = timing_->modelled(request, scan_wait);
    const auto timer = ResponseTiming::monitoring_timer(request, ticket.bytes);
    // The port gives up when the timer runs out first (docs/timing.md).
    if (timer.count() > 0 && modelled > timer) ticket.service = Service{arrival + timer, true, timer};
    else ticket.service = Service{arrival + modelled, false, modelled};
    return ticket;
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
