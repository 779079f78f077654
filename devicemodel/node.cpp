#include "devicemodel/node.hpp"

namespace slmp::devicemodel {

Node::Node() {
    for (auto id = kFirstNodeParameter; id <= kLastNodeParameter; ++id)
        parameters_[id].value.assign(kNodeParameterBytes, 0);
}

const NodeParameter* Node::parameter(std::uint16_t id) const {
    auto it = parameters_.find(id);
    return it == parameters_.end() ? nullptr : &it->second;
}

// JA §4.2.1.8, Timeout event: 10 s after Start or the owner's last Set without
// another Set or an End, the held values are dropped and the exclusion ends.
Node::WriteState Node::write_state(TimePoint now) {
    if (state_ != WriteState::Normal && now >= deadline_) {
        pending_.clear();
        state_ = WriteState::Normal;
        owner_ = 0;
    }
    return state_;
}

Node::Verdict Node::start(Client client, TimePoint now) {
    if (write_state(now) != WriteState::Normal) return Verdict::Busy;   // Start while started or holding: CEE0
    state_ = WriteState::Started;
    owner_ = client;
    deadline_ = now + kWriteTimeout;
    pending_.clear();
    return Verdict::Ok;
}

// Set, End and Cancel: CF31 in the normal state, CEE0 from another client.
Node::Verdict Node::owner_event(Client client, TimePoint now) {
    if (write_state(now) == WriteState::Normal) return Verdict::NotStarted;
    if (client != owner_) return Verdict::Busy;
    return Verdict::Ok;
}

Node::Verdict Node::set(Client client, const std::vector<std::pair<std::uint16_t, std::vector<std::uint8_t>>>& values,
                        TimePoint now) {
    if (auto verdict = owner_event(client, now); verdict != Verdict::Ok) return verdict;
    for (const auto& [id, value] : values) {
        const auto* known = parameter(id);
        if (!known || known->value.size() != value.size()) return Verdict::BadParameter;
    }
    for (const auto& [id, value] : values) pending_[id] = value;
    state_ = WriteState::Holding;
    deadline_ = now + kWriteTimeout;
    return Verdict::Ok;
}

Node::Verdict Node::end(Client client, TimePoint now) {
    if (auto verdict = owner_event(client, now); verdict != Verdict::Ok) return verdict;
    for (auto& [id, value] : pending_) parameters_[id].value = std::move(value);   // 反映処理 (Holding only holds any)
    pending_.clear();
    state_ = WriteState::Normal;
    owner_ = 0;
    return Verdict::Ok;
}

Node::Verdict Node::cancel(Client client, TimePoint now) {
    if (auto verdict = owner_event(client, now); verdict != Verdict::Ok) return verdict;
    pending_.clear();
    state_ = WriteState::Normal;
    owner_ = 0;
    return Verdict::Ok;
}

}  // namespace slmp::devicemodel
