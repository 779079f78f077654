// What a scenario matches a request against: the request as protocol::decode
// left it (frame, command, the devices a device command names), who sent it,
// and which TCP connection it came on. The station decodes once; faults,
// triggers and replay read the same Request the engine then executes.
#pragma once

#include <cstdint>
#include <vector>

#include "protocol/peer.hpp"
#include "protocol/request.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios {

struct Incoming {
    protocol::Request request;
    protocol::Peer peer;              // address empty in tests that do not care
    std::uint64_t connection = 0;     // n-th TCP connection since start (0 for UDP)
    // A front end's request has no decoded `request`: its protocol and command text instead.
    Protocol request_protocol = kSlmp;
    std::string command_text;         // "RD", "24" (JW COM in uppercase hex)

    bool frontend() const { return request_protocol != kSlmp; }
    Access access() const {
        return request.writes_devices() ? Access::Write : request.reads_devices() ? Access::Read : Access::Any;
    }
    // " from tcp:127.0.0.1:50312" for log lines; empty without a peer.
    std::string from() const { return peer.address.empty() ? std::string() : " from " + peer.text(); }
};

// Whether any plain device the request names lies in any of `ranges`
// (008x link, module and buffer-memory devices are not the CPU's own devices).
bool touches(const protocol::Request& request, const std::vector<DeviceRange>& ranges);

}  // namespace slmp::scenarios
