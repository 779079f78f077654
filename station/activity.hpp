// What a station reports about its traffic: every handled frame (handle()) and
// every TCP connection that opens or closes (reported by the transport). The HTTP API's metrics, event
// stream and connection list are observers of this; with none attached a
// request costs one map lookup and an empty loop (no strings are built).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "protocol/engine.hpp"
#include "protocol/peer.hpp"

namespace slmp::station {

using protocol::Transport;

struct ComparedRequest;   // station/comparison.hpp


using protocol::to_string;   // "tcp", "udp"

// One handled frame, as the station saw it. Valid only during the call.
struct RequestRecord {
    std::uint64_t connection = 0;              // TCP connection id, or the UDP port's session id
    const protocol::Peer& peer;                // who sent it, over which transport
    std::span<const std::uint8_t> frame;       // the request bytes the outcome consumed
    const protocol::Request& request;          // as decoded (the same the scenarios and the engine saw)
    const protocol::Outcome& outcome;
    std::chrono::nanoseconds latency{};        // time spent in the engine
    // The "model" timing mode's response time for it (docs/timing.md); unset in the other modes.
    std::optional<std::chrono::microseconds> modelled{};
};

// One Ondemand push (2101) the station sent to a client (docs/timing.md). Valid only during the call.
struct PushRecord {
    std::uint64_t connection = 0;              // TCP connection id, or the UDP port's session id
    const protocol::Peer& peer;
    std::span<const std::uint8_t> frame;       // the bytes sent
    std::string_view why;                      // "POST /api/ondemand", "timeline /timeline/steps/0", ...
};

// One request a protocol face (frontends/face.hpp) handled, reported like an
// SLMP one. Valid only during the call.
struct FrontEndRecord {
    std::string_view protocol;                 // the face's name
    std::uint64_t connection = 0;              // TCP connection id, or the UDP port's session id
    const slmp::protocol::Peer& peer;          // (qualified: `protocol` is a member here)
    std::string_view command;                  // "RD", "24" (JW COM in hex); empty: none could be read
    bool known = false;                        // the command is in the front end's table (metrics name others "other")
    std::string_view name;                     // the command table's name for it; empty when unknown
    std::string_view code;                     // response code / RSLT answered ("00", "IC", "10"); empty: no answer
    bool closed = false;                       // a fault closed the connection instead
    std::span<const std::uint8_t> request;     // the bytes the request took (garbage dropped included)
    std::span<const std::uint8_t> response;    // the bytes sent back (empty: none)
    std::chrono::nanoseconds latency{};        // time spent in the front end
    const std::vector<std::string>& faults;    // the scenario faults that fired on it
};

struct Connection {
    std::uint64_t id = 0;
    protocol::Peer peer;                       // the client, its transport and the simulator's port it reached
    std::chrono::system_clock::time_point opened;
    std::uint64_t requests = 0;
    std::function<void(const std::string& why)> close;   // closes it (from the HTTP API)
};

class ActivityObserver {
public:
    virtual void on_request_starting() {}   // a frame is about to be handled
    virtual void on_request(const RequestRecord&) {}
    virtual void on_opened(const Connection&) {}
    virtual void on_closed(const Connection&, std::string_view /*why*/) {}
    virtual void on_pushed(const PushRecord&) {}
    virtual void on_frontend_request(const FrontEndRecord&) {}
    // Differential mode (docs/twin.md, "Compare"): a request the upstream and
    // the twin answered differently, once it is in the report.
    virtual void on_difference(const ComparedRequest&) {}

protected:
    ~ActivityObserver() = default;
};

class Activity {
public:
    void add_observer(ActivityObserver* observer) { observers_.push_back(observer); }
    void remove_observer(ActivityObserver* observer) { std::erase(observers_, observer); }

    // Around each frame the engine handles: before it (so changes made since
    // are not blamed on it) and after it, with its outcome.
    void request_starting() {
        for (auto* observer : observers_) observer->on_request_starting();
    }
    void request(const RequestRecord& record);
    void frontend_request(const FrontEndRecord& record);
    void opened(Connection connection);
    void closed(std::uint64_t id, std::string_view why);
    void pushed(const PushRecord& record) {
        for (auto* observer : observers_) observer->on_pushed(record);
    }
    void difference(const ComparedRequest& compared) {
        for (auto* observer : observers_) observer->on_difference(compared);
    }

    // Open TCP connections by id (ids grow, so this is also the order they opened in).
    const std::map<std::uint64_t, Connection>& connections() const { return connections_; }
    // Closes a connection; false when there is none with this id.
    bool close(std::uint64_t id, const std::string& why);

private:
    std::vector<ActivityObserver*> observers_;
    std::map<std::uint64_t, Connection> connections_;
};

}  // namespace slmp::station
