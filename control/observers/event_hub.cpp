#include "control/observers/event_hub.hpp"

#include <algorithm>

#include "control/http/timestamp.hpp"
#include "control/observers/activity_json.hpp"
#include "scenarios/recording.hpp"

namespace slmp::control {

using nlohmann::json;

bool parse_event_types(std::string_view text, unsigned* types, std::string* error) {
    *types = 0;
    std::size_t start = 0;
    while (start <= text.size()) {
        auto end = std::min(text.find(',', start), text.size());
        auto name = text.substr(start, end - start);
        if (name == "request") *types |= kRequestEvents;
        else if (name == "devices") *types |= kDeviceEvents;
        else if (name == "connection") *types |= kConnectionEvents;
        else if (name == "compare") *types |= kCompareEvents;
        else {
            *error = "unknown event type '" + std::string(name) +
                     "'; use request, devices, connection and/or compare, comma-separated";
            return false;
        }
        start = end + 1;
    }
    return true;
}

EventHub::EventHub(const station::Home& home, station::Station& station) : home_(home), station_(station), internal_flush_(home) {
    station_.activity().add_observer(this);
}

EventHub::~EventHub() {
    station_.activity().remove_observer(this);
    station_.cpu().memory().set_write_observer(nullptr);
}

std::shared_ptr<EventHub::Subscriber> EventHub::subscribe(unsigned types) {
    auto subscriber = std::make_shared<Subscriber>(home_, types);
    subscribers_.push_back(subscriber);
    update_listening();
    return subscriber;
}

void EventHub::unsubscribe(const std::shared_ptr<Subscriber>& subscriber) {
    subscriber->closed = true;
    std::erase(subscribers_, subscriber);
    update_listening();
}

void EventHub::close_all() {
    for (auto& s : subscribers_) {
        s->closed = true;
        s->wake.cancel();
    }
    subscribers_.clear();
    internal_flush_.cancel();
    update_listening();
}

// The write observer is attached only while someone wants device events, so
// SLMP writes cost nothing extra otherwise.
void EventHub::update_listening() {
    listening_ = 0;
    for (const auto& s : subscribers_) listening_ |= s->types;
    station_.cpu().memory().set_write_observer(wanted(kDeviceEvents) || change_listener_ ? this : nullptr);
    if (!wanted(kDeviceEvents)) pending_.clear();
}

void EventHub::publish(unsigned type, std::string_view name, const json& data) {
    auto text = std::make_shared<std::string>("event: ");
    text->append(name);
    text->append("\ndata: ");
    text->append(data.dump(-1, ' ', false, json::error_handler_t::replace));
    text->append("\n\n");
    std::shared_ptr<const std::string> message = std::move(text);
    for (auto& s : subscribers_) {
        if (!(s->types & type)) continue;
        if (s->queue.size() >= kMaxQueued) {
            ++s->dropped;   // a stalled reader must not grow memory without bound
            continue;
        }
        s->queue.push_back(message);
        s->wake.cancel();
    }
}

void EventHub::set_change_listener(std::function<void()> listener) {
    change_listener_ = std::move(listener);
    update_listening();
}

void EventHub::written(const devicemodel::DeviceSpec& spec, std::uint32_t first, std::uint32_t count) {
    if (change_listener_) change_listener_();
    if (!wanted(kDeviceEvents)) return;
    if (!pending_.empty()) {
        auto& last = pending_.back();
        // Consecutive or repeated devices of the same kind extend the last run.
        if (last.spec == &spec && first >= last.first && first <= last.first + last.count) {
            last.count = std::max(last.count, first + count - last.first);
            return;
        }
    } else if (!flush_armed_) {
        // Changes made outside a request are published by this timer unless a
        // request or an API write flushes them first.
        flush_armed_ = true;
        internal_flush_.expires_after(kInternalBatch);
        internal_flush_.async_wait([this](const boost::system::error_code& ec) {
            flush_armed_ = false;
            if (!ec) flush_writes("internal");
        });
    }
    pending_.push_back(Run{&spec, first, count});
}

void EventHub::flush_writes(std::string_view source, const protocol::Peer* peer, std::uint64_t connection) {
    if (pending_.empty()) return;
    auto runs = std::move(pending_);
    pending_.clear();
    const auto& memory = station_.cpu().memory();
    auto time = iso_time(std::chrono::system_clock::now());
    for (const auto& run : runs) {
        auto shown = std::min<std::size_t>(run.count, kMaxValuesPerEvent);
        auto values = json::array();
        for (std::uint32_t i = 0; i < shown; ++i) values.push_back(memory.value(*run.spec, run.first + i));
        json data{{"time", time},
                  {"device", devicemodel::format_address({run.spec, run.first}, station_.cpu().profile().numbering)},
                  {"count", run.count},
                  {"values", std::move(values)},
                  {"source", source}};
        if (shown < run.count) data["truncated"] = true;
        if (peer) {
            data["peer"] = peer->text();
            data["connection"] = connection;
        }
        publish(kDeviceEvents, "devices", data);
    }
}

void EventHub::on_request(const station::RequestRecord& record) {
    if (wanted(kRequestEvents)) publish(kRequestEvents, "request", request_json(record, station_.cpu().profile().numbering));
    flush_writes("slmp", &record.peer, record.connection);
}

void EventHub::on_frontend_request(const station::FrontEndRecord& record) {
    if (wanted(kRequestEvents)) publish(kRequestEvents, "request", frontend_request_json(record));
    flush_writes(record.protocol, &record.peer, record.connection);
}

void EventHub::on_pushed(const station::PushRecord& p) {
    if (!wanted(kRequestEvents)) return;
    publish(kRequestEvents, "ondemand",
            {{"connection", p.connection},
             {"transport", station::to_string(p.peer.transport)},
             {"peer", p.peer.endpoint()},
             {"command", "2101"},
             {"frame", scenarios::to_hex(p.frame)},
             {"why", p.why}});
}

void EventHub::on_difference(const station::ComparedRequest& compared) {
    if (wanted(kCompareEvents)) publish(kCompareEvents, "compare", compared_json(compared));
}

void EventHub::on_opened(const station::Connection& connection) {
    if (!wanted(kConnectionEvents)) return;
    auto data = connection_json(connection);
    data["event"] = "opened";
    publish(kConnectionEvents, "connection", data);
}

void EventHub::on_closed(const station::Connection& connection, std::string_view why) {
    if (!wanted(kConnectionEvents)) return;
    auto data = connection_json(connection);
    data["event"] = "closed";
    data["why"] = why;
    publish(kConnectionEvents, "connection", data);
}

}  // namespace slmp::control
