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
    by_name_[name] = &station;
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

void NetworkMap::add_redundant(Station& station, const std::string& name, const config::RedundantConfig& redundant) {
    by_name_[name] = &station;
    redundant_.push_back({{&station, name}, redundant});
}

void NetworkMap::add_multidrop(Station& station, const std::string& name, const config::MultidropConfig& multidrop) {
    by_name_[name] = &station;
    multidrop_.push_back({{&station, name}, multidrop});
}

void NetworkMap::link() {
    // The plant's configuration checked the names and that each pair is one A and one B (plant_config.cpp).
    for (const auto& [self, config] : redundant_) {
        auto partner = by_name_.find(config.pair);
        if (partner == by_name_.end() || pair_of_.contains(self.station)) continue;
        const bool a = config.system == 'A';
        auto* first = a ? self.station : partner->second;
        auto* second = a ? partner->second : self.station;
        // Either CPU may give the switch time (the plant's check made them agree); chosen default 100 ms.
        const auto other = std::find_if(redundant_.begin(), redundant_.end(),
                                       [&](const auto& r) { return r.first.station == partner->second; });
        auto ms = config.switchover_ms;
        if (!ms && other != redundant_.end()) ms = other->second.switchover_ms;
        const auto switchover = std::chrono::milliseconds(static_cast<long long>(ms.value_or(100)));
        // Either CPU may give the tracked ranges too (the plant's check made them agree).
        auto tracking = config.tracking;
        if (!tracking && other != redundant_.end()) tracking = other->second.tracking;
        pairs_.push_back(std::make_unique<RedundantPair>(*first, a ? self.name : config.pair, *second,
                                                         a ? config.pair : self.name, switchover, tracking));
        pair_of_[first] = pair_of_[second] = pairs_.back().get();
    }
    for (const auto& [self, config] : multidrop_) {
        auto via = by_name_.find(config.via);
        if (via == by_name_.end()) continue;
        drops_[{via->second, config.module_io, config.number}] = self.station;
        drop_of_[self.station] = config;
    }
}

RedundantPair* NetworkMap::pair_of(const Station& station) const {
    auto it = pair_of_.find(&station);
    return it == pair_of_.end() ? nullptr : it->second;
}

protocol::RouteIdentity NetworkMap::identity(const Station& station) const {
    protocol::RouteIdentity identity;
    identity.redundant = pair_of_.contains(&station);
    if (auto it = drop_of_.find(&station); it != drop_of_.end()) {
        identity.multidrop = true;
        identity.multidrop_io = it->second.module_io;
        identity.multidrop_number = it->second.number;
    }
    return identity;
}

void NetworkMap::beyond(Found& found, std::uint16_t module_io, std::uint8_t multidrop, bool file) const {
    auto* at = found.relay.target;
    auto pass = [&](Station* next) {   // `at` passes it on: over its serial line, or the tracking cable
        if (found.relay.hops.back() != at) found.relay.hops.push_back(at);
        found.relay.target = next;
    };
    if (module_io <= 0x01FF) {   // a multidrop station behind `at`'s serial module (§3.1.4, §3.1.5)
        auto drop = drops_.find({at, module_io, multidrop});
        if (drop == drops_.end()) return;   // none: the station answers (4A02, 4B02) as before
        if (file) {   // not among the file commands' destinations (§3.1.4)
            found.error = EndCode::RouteNotCpu;
            return;
        }
        pass(drop->second);
        return;
    }
    const auto* pair = pair_of(*at);
    if (!pair) return;   // 03D0-03D3 at a CPU of no pair: 4B02 from it
    const bool by_role = module_io == 0x03D0 || module_io == 0x03D1;
    protocol::Route route;
    route.module_io = module_io;
    if (file && !protocol::file_route_allowed(route)) return;   // the restricted table: 4B02 from the station
    // During a switch the roles are in between, and a file command would lose
    // its file to the other system (§3.1.4 *1): the pair answers 4248.
    if (pair->switching() && (by_role || file)) {
        found.error = EndCode::SystemSwitching;
        return;
    }
    if (module_io < 0x03D0 || module_io > 0x03D3) return;
    auto& cpu = pair->pick(module_io);
    if (&cpu == at) return;
    // A CPU the route reached through the network that is down itself answers nothing (CF71 at the timer).
    if (at != found.relay.hops.front() && !pair->available(*at)) return;
    if (!pair->available(cpu)) {   // the other system over the tracking cable
        found.error = EndCode::OtherSystemError;
        return;
    }
    pass(&cpu);
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
