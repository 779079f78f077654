// The plant's networks and the relay of a request to another station
// (network_map.hpp; docs/plants.md, "Networks and routes").
#include "station/network_map.hpp"

#include <algorithm>
#include <deque>
#include <set>

#include "devicemodel/hex.hpp"
#include "protocol/error_response.hpp"
#include "station/response_timing.hpp"
#include "station/station.hpp"

namespace slmp::station {

namespace asio = boost::asio;
using protocol::EndCode;

void NetworkMap::add(Station& station, const std::string& name, const std::vector<config::NetworkConfig>& networks) {
    // The plant's configuration refused a station No. or a master given twice (plant_config.cpp).
    for (const auto& n : networks) {
        if (n.station == 0) continue;   // link devices only: no module station No. to route to
        networks_[n.number].push_back({&station, name, n.station, n.master});
        modules_[&station].push_back(n.number);
    }
}

const NetworkMap::Member* NetworkMap::member(std::uint16_t network, std::uint8_t station) const {
    auto it = networks_.find(network);
    if (it == networks_.end()) return nullptr;
    const auto& members = it->second;
    // 7D the designated control/master station, 7E the current one (§3.1.3):
    // the same station, as no network here loses its master; without a
    // "master" entry the lowest station No. (inferred: the usual parameter).
    if (station == 0x7D || station == 0x7E) {
        auto master = std::find_if(members.begin(), members.end(), [](const Member& m) { return m.master; });
        if (master != members.end()) return &*master;
        auto lowest = std::min_element(members.begin(), members.end(),
                                       [](const Member& a, const Member& b) { return a.number < b.number; });
        return lowest == members.end() ? nullptr : &*lowest;
    }
    for (const auto& m : members)
        if (m.number == station) return &m;
    return nullptr;
}

NetworkMap::Found NetworkMap::find(Station& from, std::uint8_t network, std::uint8_t station) const {
    Found found;
    found.relay.hops.push_back(&from);
    if (network == 0x00) {   // network 00 names only the own station (FF); another station: 4A02
        if (station == 0xFF) found.relay.target = &from;
        else found.error = EndCode::RouteStationNotFound;
        return found;
    }
    auto own = modules_.find(&from);
    if (own == modules_.end() || !networks_.contains(network)) {
        found.error = EndCode::RouteNetworkNotFound;
        return found;
    }
    const auto* target = member(network, station);
    if (!target) {
        found.error = EndCode::RouteStationNotFound;
        return found;
    }
    found.relay.target = target->station;
    if (target->station == &from) return found;
    // The shortest way through the networks (the routing parameters a real
    // plant sets by hand; derived here): breadth first from the networks the
    // receiving station is on, a relay station being one on two networks.
    std::map<std::uint16_t, std::vector<Station*>> via;   // network -> relay stations to reach it
    std::deque<std::uint16_t> queue;
    for (auto n : own->second) {
        via[n] = {};
        queue.push_back(n);
    }
    while (!queue.empty() && !via.contains(network)) {
        const auto n = queue.front();
        queue.pop_front();
        for (const auto& m : networks_.at(n)) {
            if (m.station == &from) continue;
            for (auto next : modules_.at(m.station)) {
                if (via.contains(next)) continue;
                auto path = via[n];
                path.push_back(m.station);
                via[next] = std::move(path);
                queue.push_back(next);
            }
        }
    }
    auto way = via.find(network);
    if (way == via.end()) {   // no relay station links the networks
        found.error = EndCode::RouteNetworkNotFound;
        return found;
    }
    if (way->second.size() > kMaxRelayStations) {
        found.error = EndCode::RouteTooManyRelays;
        return found;
    }
    found.relay.hops.insert(found.relay.hops.end(), way->second.begin(), way->second.end());
    return found;
}

namespace {

// What the receiving port answers when the target station did not: after the
// request's monitoring timer, CF71 (SLMP Reference Manual §4.4); with timer 0
// ("wait forever") nothing.
StrandTask<Handled> no_answer(Station& port, std::vector<std::uint8_t> frame, protocol::FrameScan scan) {
    Handled handled;
    handled.outcome.action = protocol::Outcome::Action::Silent;
    handled.outcome.consumed = frame.size();
    const auto timer = ResponseTiming::monitoring_timer(scan.header, frame);
    if (timer.count() == 0) co_return handled;
    co_await asio::co_spawn(port.home(), port.wait_on_clock(timer), use_strand);
    const auto body = std::span<const std::uint8_t>(frame).subspan(scan.header.header_size);
    protocol::FieldReader in(scan.header.codec, body, {});
    in.u16("monitoring timer");
    auto& o = handled.outcome;
    o.command = in.u16("command");
    o.subcommand = in.u16("subcommand");
    o.action = protocol::Outcome::Action::Respond;
    o.end_code = EndCode::RelayTimeout;
    o.response = protocol::encode_error_response(scan.header, o.command, o.subcommand, o.end_code);
    o.note = "the routed station did not answer within the monitoring timer";
    co_return handled;
}

}  // namespace

StrandTask<Handled> Relays::pass_on(Relay relay, std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy,
                                    protocol::Peer peer) {
    // The receiving station framed it; its header again, for the data code and the timer.
    const auto scan = protocol::scan_frame(frame, protocol::Direction::Request, policy, frame.size(), protocol::FrameSet{false, true});
    // Each station on the way: its passing-on time and its scenario faults.
    for (std::size_t k = 0; k < relay.hops.size(); ++k) {
        auto* hop = relay.hops[k];
        auto refused = co_await asio::co_spawn(hop->home(), hop->pass_through(frame, policy, peer, k == 0), use_strand);
        if (!refused) continue;
        refused->outcome.consumed = frame.size();
        // A relay station that drops it leaves the receiving module waiting: CF71 at its timer.
        if (refused->outcome.action != protocol::Outcome::Action::Respond && k > 0)
            co_return co_await no_answer(*relay.hops.front(), std::move(frame), scan);
        co_return std::move(*refused);
    }
    auto& session = sessions_[relay.target];
    auto handled = co_await asio::co_spawn(relay.target->home(), relay.target->serve_routed(frame, policy, session, peer),
                                           use_strand);
    if (handled.outcome.action == protocol::Outcome::Action::Respond) co_return handled;
    co_return co_await no_answer(*relay.hops.front(), std::move(frame), scan);
}

}  // namespace slmp::station
