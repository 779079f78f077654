// What --record and --record-pcap have in common: something told about every
// connection and every exchange as they happen. The JSON-lines recording
// (recording.hpp) and the pcap capture (pcap_writer.hpp) each implement it;
// the station's scenario hook (station/scenario_hook.cpp) keeps a list of them,
// so both formats can be on at once. The format's reader, for replay and
// slmp-replay, is scenarios/recording.hpp.
#pragma once

#include <chrono>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scenarios/scenario.hpp"

namespace slmp::station {

using scenarios::Transport;

// Which connection an event belongs to, as a recording names it.
struct RecordedLink {
    std::uint64_t connection = 0;    // TCP connection id, or the UDP port's session id
    Transport transport = Transport::Tcp;
    std::string peer;                // the client: "127.0.0.1:50312"
    std::uint16_t local_port = 0;    // the simulator's port the client talked to (0: unknown)
};

class Recorder {
public:
    using TimePoint = std::chrono::steady_clock::time_point;
    virtual ~Recorder() = default;

    virtual void opened(TimePoint at, const RecordedLink& link) = 0;
    // `response` is null when nothing was sent; `faults` names the faults that
    // fired; `named` what the request named besides devices (label names).
    virtual void exchange(TimePoint at, const RecordedLink& link, std::span<const std::uint8_t> request,
                          const std::vector<std::uint8_t>* response, const std::vector<std::string>& faults,
                          const std::string& named) = 0;
    virtual void closed(TimePoint at, const RecordedLink& link, const std::string& why) = 0;
    // A protocol face's exchange (`protocol` the face's name; `command` "RD",
    // "24"; `code` the response code or RSLT, empty with no answer). The
    // JSON-lines recording keeps it; the pcap capture does not.
    virtual void frontend_exchange(TimePoint /*at*/, const RecordedLink& /*link*/, std::string_view /*protocol*/,
                                   std::string_view /*command*/, std::string_view /*code*/,
                                   std::span<const std::uint8_t> /*request*/, std::span<const std::uint8_t> /*response*/,
                                   bool /*answered*/, const std::vector<std::string>& /*faults*/) {}
    // An Ondemand push the station sent unasked (docs/timing.md): by default a
    // response without a request, marked "ondemand".
    virtual void pushed(TimePoint at, const RecordedLink& link, const std::vector<std::uint8_t>& frame) {
        exchange(at, link, {}, &frame, {"ondemand"}, "");
    }
};

}  // namespace slmp::station
