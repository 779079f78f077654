#include "station/activity.hpp"

namespace slmp::station {


void Activity::request(const RequestRecord& record) {
    if (auto it = connections_.find(record.connection); it != connections_.end()) ++it->second.requests;
    for (auto* observer : observers_) observer->on_request(record);
}

void Activity::frontend_request(const FrontEndRecord& record) {
    if (auto it = connections_.find(record.connection); it != connections_.end()) ++it->second.requests;
    for (auto* observer : observers_) observer->on_frontend_request(record);
}

void Activity::opened(Connection connection) {
    auto id = connection.id;
    auto& stored = connections_[id] = std::move(connection);
    for (auto* observer : observers_) observer->on_opened(stored);
}

void Activity::closed(std::uint64_t id, std::string_view why) {
    auto it = connections_.find(id);
    if (it == connections_.end()) return;
    auto connection = std::move(it->second);
    connections_.erase(it);
    for (auto* observer : observers_) observer->on_closed(connection, why);
}

bool Activity::close(std::uint64_t id, const std::string& why) {
    auto it = connections_.find(id);
    if (it == connections_.end()) return false;
    // The session reports closed() itself once its coroutine has finished.
    auto close = it->second.close;
    if (close) close(why);
    return true;
}

}  // namespace slmp::station
