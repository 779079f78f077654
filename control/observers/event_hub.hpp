// The /api/events publisher: request summaries, device writes and connection
// changes, each formatted once as a server-sent event and queued for every
// subscriber that asked for its type.
//
// Nothing is formatted, and device memory has no write observer attached,
// while nobody subscribes. Device changes are collected as runs while a
// request is handled and published right after it, named by their source:
// the SLMP peer or the API. Changes made by the simulator itself (the scan's
// special relays and registers, timers, scenarios) are "internal": collected
// for at most kInternalBatch, and always published before the next request.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "station/asio.hpp"

#include <nlohmann/json.hpp>

#include "station/station.hpp"

namespace slmp::control {

enum EventType : unsigned {
    kRequestEvents = 1,
    kDeviceEvents = 2,
    kConnectionEvents = 4,
    kCompareEvents = 8,   // differential mode's differences (docs/twin.md, "Compare")
    kAllEvents = 15
};

// "request,devices,connection,compare" -> bits; false names an unknown type in *error.
bool parse_event_types(std::string_view text, unsigned* types, std::string* error);

class EventHub final : public station::ActivityObserver, public devicemodel::WriteObserver {
public:
    // A subscriber's queue; the stream writer drains it and sleeps on `wake`.
    struct Subscriber {
        explicit Subscriber(const station::Home& home, unsigned types) : types(types), wake(home) {}
        unsigned types;
        std::deque<std::shared_ptr<const std::string>> queue;
        std::uint64_t dropped = 0;     // events lost to a full queue since the last overflow notice
        bool closed = false;
        boost::asio::steady_timer wake;
    };
    static constexpr std::size_t kMaxQueued = 4096;        // per subscriber, then events are dropped
    static constexpr std::size_t kMaxValuesPerEvent = 4096;
    // The scan rewrites clock and scan-time registers every few milliseconds;
    // batching keeps that to a few events a second.
    static constexpr std::chrono::milliseconds kInternalBatch{100};

    EventHub(const station::Home& home, station::Station& station);
    ~EventHub();
    EventHub(const EventHub&) = delete;
    EventHub& operator=(const EventHub&) = delete;

    std::shared_ptr<Subscriber> subscribe(unsigned types);
    void unsubscribe(const std::shared_ptr<Subscriber>& subscriber);
    void close_all();   // shutdown: every stream ends

    // Publishes the device writes collected so far, naming their source (and,
    // for an SLMP request, its peer and connection).
    void flush_writes(std::string_view source, const protocol::Peer* peer = nullptr, std::uint64_t connection = 0);

    // Device waits (control/observers/device_waits.hpp) hear of every change as well:
    // while one is pending the write observer stays attached. `listener` is
    // told once per change; nullptr detaches it.
    void set_change_listener(std::function<void()> listener);

    void on_request_starting() override { flush_writes("internal"); }
    void on_request(const station::RequestRecord& record) override;
    void on_frontend_request(const station::FrontEndRecord& record) override;   // a "request" event too
    void on_opened(const station::Connection& connection) override;
    void on_pushed(const station::PushRecord& push) override;   // an "ondemand" event (request events)
    void on_closed(const station::Connection& connection, std::string_view why) override;
    void on_difference(const station::ComparedRequest& compared) override;   // a "compare" event
    void written(const devicemodel::DeviceSpec& spec, std::uint32_t first, std::uint32_t count) override;
    // Label-area words wake the waits; the event stream shows device runs only.
    void label_area_written(std::uint32_t) override {
        if (change_listener_) change_listener_();
    }

private:
    struct Run {
        const devicemodel::DeviceSpec* spec;
        std::uint32_t first;
        std::uint32_t count;
    };
    bool wanted(unsigned type) const { return (listening_ & type) != 0; }
    void publish(unsigned type, std::string_view name, const nlohmann::json& data);
    void update_listening();

    station::Home home_;
    station::Station& station_;
    std::vector<std::shared_ptr<Subscriber>> subscribers_;
    unsigned listening_ = 0;   // union of the subscribers' types
    std::vector<Run> pending_;
    boost::asio::steady_timer internal_flush_;
    bool flush_armed_ = false;
    std::function<void()> change_listener_;
};

}  // namespace slmp::control
