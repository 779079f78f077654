#include "scenarios/faults.hpp"

#include <algorithm>

#include "devicemodel/hex.hpp"

namespace slmp::scenarios {

std::string_view to_string(FaultKind kind) {
    switch (kind) {
        case FaultKind::EndCode: return "end_code";
        case FaultKind::Delay: return "delay";
        case FaultKind::NoResponse: return "no_response";
        case FaultKind::Close: return "close";
        case FaultKind::Reset: return "reset";
        case FaultKind::Split: return "split";
        case FaultKind::Coalesce: return "coalesce";
        case FaultKind::Corrupt: return "corrupt";
        case FaultKind::RefuseConnections: return "refuse_connections";
        case FaultKind::PowerCycle: return "power_cycle";
    }
    return "?";
}

void FaultSet::add(const Fault& fault, const std::string& source, std::uint64_t seed, const std::string& scenario) {
    auto name = fault.id.empty() ? source + "#" + fault.pointer : fault.id;
    entries_.push_back(Entry{&fault, std::move(name), scenario, Rng(seed), fault.enabled});
}

bool FaultSet::enable(const std::string& id, bool on) {
    bool found = false;
    for (auto& e : entries_)
        if (e.name == id) e.enabled = on, found = true;   // the name is the id when there is one
    return found;
}

std::vector<FaultStats> FaultSet::stats() const {
    std::vector<FaultStats> list;
    for (const auto& e : entries_)
        list.push_back({e.name, std::string(to_string(e.fault->action.kind)), e.scenario, e.enabled, e.matched, e.fired});
    return list;
}

bool FaultSet::matches(const Fault& fault, const Incoming& incoming) {
    const auto& r = incoming.request;
    const auto& m = fault.match;
    if (m.request_protocol != incoming.request_protocol) return false;
    if (incoming.frontend()) {
        // The loader allows only these keys on a front end's fault.
        const auto& names = m.frontend_commands;
        if (!names.empty() && std::find(names.begin(), names.end(), incoming.command_text) == names.end()) return false;
        if (m.transport && incoming.peer.transport != *m.transport) return false;
        if (m.connection && incoming.connection != *m.connection) return false;
        if (m.client && incoming.peer.address != *m.client) return false;
        return true;
    }
    auto listed = [](const std::vector<std::uint16_t>& list, std::uint16_t v) {
        return list.empty() || std::find(list.begin(), list.end(), v) != list.end();
    };
    if ((!m.commands.empty() || !m.subcommands.empty()) && !r.has_command) return false;
    if (!listed(m.commands, r.command) || !listed(m.subcommands, r.subcommand)) return false;
    if (m.access != Access::Any && incoming.access() != m.access) return false;
    if (!m.devices.empty() && !touches(r, m.devices)) return false;
    if (m.frame && r.header.kind != *m.frame) return false;
    if (m.code && r.header.codec != *m.code) return false;
    if (m.transport && incoming.peer.transport != *m.transport) return false;
    if (m.connection && incoming.connection != *m.connection) return false;
    if (m.client && incoming.peer.address != *m.client) return false;
    if (m.route_network && r.header.route.network != *m.route_network) return false;
    if (m.route_station && r.header.route.station != *m.route_station) return false;
    return true;
}

FaultDecision FaultSet::decide(const Incoming& incoming, double now_ms, const EventSink& log) {
    const auto& request = incoming.request;
    FaultDecision d;
    for (auto& e : entries_) {
        const auto& f = *e.fault;
        if (!e.enabled || now_ms < f.from_ms || now_ms >= f.until_ms || !matches(f, incoming)) continue;
        if (++e.matched <= f.skip) continue;
        if (f.count && e.fired >= f.count) continue;
        // The draw happens for every eligible request, fired or not, so the
        // sequence depends only on the traffic, never on other faults.
        if (f.probability < 1 && !(e.rng.unit() < f.probability)) continue;
        ++e.fired;
        d.fired.push_back(e.name);
        const auto& a = f.action;
        auto drop = [&](FaultDecision::Drop how) {
            if (d.drop == FaultDecision::Drop::None) d.drop = how;
        };
        switch (a.kind) {
            case FaultKind::EndCode:
                if (incoming.frontend()) {
                    if (!d.frontend_code) d.frontend_code = a.frontend_code;
                } else if (!d.end_code) {
                    d.end_code = a.end_code;
                }
                break;
            case FaultKind::Delay:
                if (d.delay_ms == 0) d.delay_ms = a.delay_min_ms == a.delay_max_ms ? a.delay_min_ms : e.rng.between(a.delay_min_ms, a.delay_max_ms);
                break;
            case FaultKind::NoResponse: drop(FaultDecision::Drop::NoResponse); break;
            case FaultKind::Close: drop(FaultDecision::Drop::Close); break;
            case FaultKind::Reset: drop(FaultDecision::Drop::Reset); break;
            case FaultKind::Split:
                if (!d.split) d.split = a;
                break;
            case FaultKind::Coalesce:
                if (!d.coalesce) d.coalesce = a;
                break;
            case FaultKind::Corrupt: d.corruptions.push_back(a); break;
            case FaultKind::RefuseConnections:
                if (!d.refuse_ms) d.refuse_ms = a.period_ms;
                break;
            case FaultKind::PowerCycle:
                if (!d.power_cycle_ms) d.power_cycle_ms = a.period_ms;
                break;
        }
        if (log)
            log(EventLevel::Info, "fault '" + e.name + "' (" + std::string(to_string(a.kind)) + ") fired on " +
                                      (incoming.frontend() ? std::string(to_string(incoming.request_protocol)) + " " + incoming.command_text
                                       : request.has_command ? devicemodel::hex4(request.command) + "/" + devicemodel::hex4(request.subcommand)
                                                             : std::string("a request")) +
                                      incoming.from() + " (" + std::to_string(e.fired) +
                                      (e.fired == 1 ? " time)" : " times)"));
    }
    return d;
}

void corrupt(std::vector<std::uint8_t>& response, const protocol::FrameHeader& request, const FaultAction& action, Rng& rng) {
    if (response.empty()) return;
    const bool binary = request.codec == protocol::Codec::Binary;
    switch (action.corruption) {
        case Corruption::Length: {
            // The response data length is the header's last field (§3.1).
            auto end = protocol::header_size(request.kind, request.codec);
            if (response.size() < end) return;
            if (binary) {
                std::uint16_t v = static_cast<std::uint16_t>(response[end - 2] | response[end - 1] << 8);
                v = static_cast<std::uint16_t>(v + action.bytes);
                response[end - 2] = static_cast<std::uint8_t>(v & 0xFF);
                response[end - 1] = static_cast<std::uint8_t>(v >> 8);
            } else {
                std::string text(response.begin() + static_cast<long>(end - 4), response.begin() + static_cast<long>(end));
                auto v = static_cast<std::uint16_t>(std::stoul(text, nullptr, 16) + action.bytes);
                auto digits = devicemodel::hex4(v);
                std::copy(digits.begin(), digits.end(), response.begin() + static_cast<long>(end - 4));
            }
            return;
        }
        case Corruption::Subheader:
            // D000 -> D100 (ASCII), D0 00 -> D1 00 (binary): no longer a response subheader.
            if (binary) response[0] ^= 0x01;
            else if (response.size() > 1) response[1] = response[1] == '1' ? '2' : '1';
            return;
        case Corruption::Random:
            for (std::size_t i = 0; i < action.bytes; ++i) {
                auto& b = response[rng.below(response.size())];
                b = static_cast<std::uint8_t>(b ^ (1 + rng.below(255)));   // always a different value
            }
            return;
    }
}

std::vector<std::size_t> split_sizes(std::size_t size, const FaultAction& split) {
    std::vector<std::size_t> pieces;
    if (split.chunk_bytes > 0) {
        for (std::size_t at = 0; at < size; at += split.chunk_bytes) pieces.push_back(std::min(split.chunk_bytes, size - at));
        return pieces;
    }
    auto n = std::min(split.chunks, size);
    for (std::size_t i = 0; i < n; ++i) pieces.push_back(size * (i + 1) / n - size * i / n);
    return pieces;
}

}  // namespace slmp::scenarios
