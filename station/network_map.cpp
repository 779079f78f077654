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

void NetworkMap::add(Station& station, const std::string& name, const std::vector<config::NetworkConfig>& networks,
                     const std::vector<config::RouteConfig>& routes) {
    by_name_[name] = &station;
    for (const auto& r : routes) routes_[&station][r.network] = Via{r.via_network, r.via_station};
    // The plant's configuration refused a station No. or a master given twice (plant_config.cpp).
    for (const auto& n : networks) {
        if (n.station == 0) continue;   // link devices only: no module station No. to route to
        networks_[n.number].push_back({&station, name, n.station, n.master});
        modules_[&station].push_back(n.number);
    }
}

const NetworkMap::Member* NetworkMap::member(std::uint16_t network, std::uint16_t station, bool extended) const {
    auto it = networks_.find(network);
    if (it == networks_.end()) return nullptr;
    const auto& members = it->second;
    // 7D the designated control/master station, 7E the current one (§3.1.3):
    // the same station, as no network here loses its master; without a
    // "master" entry the lowest station No. (inferred: the usual parameter).
    // The extended station No. 0000 is the designated one (§3.1.6).
    if (extended ? station == 0x0000 : station == 0x7D || station == 0x7E) {
        auto master = std::find_if(members.begin(), members.end(), [](const Member& m) { return m.master; });
        if (master != members.end()) return &*master;
        auto lowest = std::min_element(members.begin(), members.end(),
                                       [](const Member& a, const Member& b) { return a.number < b.number; });
        return lowest == members.end() ? nullptr : &*lowest;
    }
    // The station No. field names 01-78 (§3.1.3); station 7C's extended
    // station No. names 121-65534 (§3.1.6: 0079-FFFE, inferred from the
    // decimal range; 0001-0078 and FFFF at another network name no station).
    if (extended ? station < 0x79 || station == 0xFFFF : station > 0x78) return nullptr;
    for (const auto& m : members)
        if (m.number == station) return &m;
    return nullptr;
}

NetworkMap::Found NetworkMap::find(Station& from, std::uint8_t network, std::uint16_t station, bool extended) const {
    Found found;
    found.relay.hops.push_back(&from);
    if (network == 0x00) {   // network 00 names only the own station (FF); another station: 4A02
        if (!extended && station == 0xFF) found.relay.target = &from;
        else found.error = EndCode::RouteStationNotFound;
        return found;
    }
    if (!modules_.contains(&from) || !networks_.contains(network)) {
        found.error = EndCode::RouteNetworkNotFound;
        return found;
    }
    const auto* target = member(network, station, extended);
    if (!target) {
        found.error = EndCode::RouteStationNotFound;
        return found;
    }
    found.relay.target = target->station;
    if (target->station == &from) return found;
    // Hop by hop, as each station's network module decides with its own
    // routing parameters (docs/plants.md, "Routing parameters"): until a
    // station on the target's network holds it.
    const Station* at = &from;
    while (std::find(modules_.at(at).begin(), modules_.at(at).end(), network) == modules_.at(at).end()) {
        auto* next = next_hop(*at, network);
        if (!next) {   // no routing parameter, no relay station links the networks
            found.error = EndCode::RouteNetworkNotFound;
            return found;
        }
        found.relay.hops.push_back(next);
        if (found.relay.hops.size() - 1 > kMaxRelayStations) {   // also a loop of routing parameters
            found.error = EndCode::RouteTooManyRelays;
            return found;
        }
        at = next;
    }
    return found;
}

Station* NetworkMap::next_hop(const Station& at, std::uint16_t network) const {
    // A routing parameter given by hand: the station it names on one of `at`'s
    // networks (the plant's configuration checked both).
    if (auto own = routes_.find(&at); own != routes_.end())
        if (auto via = own->second.find(network); via != own->second.end()) {
            const auto* relay = member(via->second.network, via->second.station);
            return relay && relay->station != &at ? relay->station : nullptr;
        }
    // Derived: the first relay station on the shortest way through the
    // networks, breadth first from the networks `at` is on, a relay station
    // being one on two networks.
    std::map<std::uint16_t, Station*> first;   // network -> the first relay station on the way to it
    std::deque<std::uint16_t> queue;
    for (auto n : modules_.at(&at)) {
        first[n] = nullptr;
        queue.push_back(n);
    }
    while (!queue.empty() && !first.contains(network)) {
        const auto n = queue.front();
        queue.pop_front();
        for (const auto& m : networks_.at(n)) {
            if (m.station == &at) continue;
            for (auto next : modules_.at(m.station)) {
                if (first.contains(next)) continue;
                first[next] = first[n] ? first[n] : m.station;
                queue.push_back(next);
            }
        }
    }
    auto way = first.find(network);
    return way == first.end() ? nullptr : way->second;
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

// What the receiving port answers when the target station did not answer in
// time: CF71 (SLMP Reference Manual §4.4, "processing aborted by a timeout"),
// with the request's route in the error information.
Handled relay_timeout(std::span<const std::uint8_t> frame, const protocol::FrameScan& scan, std::chrono::milliseconds timer) {
    Handled handled;
    const auto body = frame.subspan(scan.header.header_size);
    protocol::FieldReader in(scan.header.codec, body, {});
    in.u16("monitoring timer");
    auto& o = handled.outcome;
    o.consumed = frame.size();
    o.command = in.u16("command");
    o.subcommand = in.u16("subcommand");
    o.action = protocol::Outcome::Action::Respond;
    o.end_code = EndCode::RelayTimeout;
    o.response = protocol::encode_error_response(scan.header, o.command, o.subcommand, o.end_code);
    o.note = "the routed station did not answer within the monitoring timer (" + std::to_string(timer.count()) + " ms)";
    return handled;
}

Handled silent(std::size_t size) {
    Handled handled;
    handled.outcome.action = protocol::Outcome::Action::Silent;
    handled.outcome.consumed = size;
    return handled;
}

// A request's way to its target and its answer's way back.
struct Trip {
    Handled handled;
    bool dropped = false;   // no answer came back (a relay or the target dropped it): the timer answers
};

StrandTask<Trip> trip(Relay relay, std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy, protocol::Peer peer,
                      std::shared_ptr<std::optional<protocol::Session>> session) {
    // Each station on the way: its passing-on time and its scenario faults.
    for (std::size_t k = 0; k < relay.hops.size(); ++k) {
        auto* hop = relay.hops[k];
        auto refused = co_await asio::co_spawn(hop->home(), hop->pass_through(frame, policy, peer, k == 0), use_strand);
        if (!refused) continue;
        refused->outcome.consumed = frame.size();
        // A relay station that drops it leaves the receiving module waiting: CF71 at its timer.
        const bool dropped = refused->outcome.action != protocol::Outcome::Action::Respond && k > 0;
        co_return Trip{std::move(*refused), dropped};
    }
    auto handled = co_await asio::co_spawn(relay.target->home(), relay.target->serve_routed(frame, policy, *session, peer),
                                           use_strand);
    const bool dropped = handled.outcome.action != protocol::Outcome::Action::Respond;
    co_return Trip{std::move(handled), dropped};
}

}  // namespace

StrandTask<Handled> Relays::pass_on(Relay relay, std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy,
                                    protocol::Peer peer, std::chrono::microseconds spent) {
    // The receiving station framed it; its header again, for the data code and the timer.
    const auto scan = protocol::scan_frame(frame, protocol::Direction::Request, policy, frame.size(), protocol::FrameSet{false, true});
    const auto timer = ResponseTiming::monitoring_timer(scan.header, frame);
    auto& session = sessions_[relay.target];
    if (!session) session = std::make_shared<std::optional<protocol::Session>>();
    auto& port = *relay.hops.front();
    if (timer.count() == 0) {   // "wait forever": the answer whenever it comes, none when none comes
        auto done = co_await trip(std::move(relay), frame, policy, std::move(peer), session);
        co_return done.dropped ? silent(frame.size()) : std::move(done.handled);
    }
    // The trip and the timer race; the first to finish answers (both finish on
    // this strand, so `race` needs no lock). The timer stops waiting once the
    // answer is in; a trip that loses goes on to its end, its answer dropped.
    struct Race {
        std::optional<Handled> answer;
        std::shared_ptr<std::atomic<bool>> answered = std::make_shared<std::atomic<bool>>(false);
        StrandTimer wake;
        explicit Race(const Strand& strand) : wake(strand, std::chrono::steady_clock::time_point::max()) {}
    };
    auto race = std::make_shared<Race>(co_await asio::this_coro::executor);
    auto finish = [race](Handled handled) {
        if (race->answer) return;
        race->answer = std::move(handled);
        race->wake.cancel();
    };
    asio::co_spawn(race->wake.get_executor(), trip(std::move(relay), frame, policy, peer, session),
                   [finish, race, &port](std::exception_ptr error, Trip done) {
                       if (error || done.dropped) return;   // the timer answers
                       finish(std::move(done.handled));
                       *race->answered = true;
                       asio::post(port.home(), [&port] { port.stop_waiting(); });
                   });
    auto out_of_time = [](Station& port, std::chrono::microseconds left,
                          std::shared_ptr<const std::atomic<bool>> answered) -> StrandTask<bool> {
        // Named, not a temporary in the co_await expression: GCC 12 destroys
        // such a temporary twice, and the shared_ptr it holds with it.
        std::function<bool()> wanted = [answered] { return !*answered; };
        auto wait = port.wait_on_clock(left, std::move(wanted));
        co_await asio::co_spawn(port.home(), std::move(wait), use_strand);
        co_return !*answered;
    };
    const auto left = std::max(std::chrono::microseconds{0}, std::chrono::microseconds(timer) - spent);
    asio::co_spawn(race->wake.get_executor(), out_of_time(port, left, race->answered),
                   [finish, frame, scan, timer](std::exception_ptr error, bool ran_out) {
                       if (!error && ran_out) finish(relay_timeout(frame, scan, timer));
                   });
    boost::system::error_code ignored;
    if (!race->answer) co_await race->wake.async_wait(asio::redirect_error(use_strand, ignored));
    if (!race->answer) co_return silent(frame.size());   // the station stopped meanwhile
    co_return std::move(*race->answer);
}

}  // namespace slmp::station
