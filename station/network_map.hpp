// The plant's networks (docs/plants.md, "Networks and routes"): which station
// is which station No. on which network, and through which relay stations a
// module's port reaches another station. Built once before the io_context
// runs and read-only afterwards, so every station's strand reads it without a
// lock. The relay itself (Relays) carries a request to the target station's
// strand, has it served there and brings the answer back.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "station/asio.hpp"
#include "station/redundant_pair.hpp"

#include "config/config.hpp"
#include "protocol/end_code.hpp"
#include "protocol/engine.hpp"
#include "protocol/peer.hpp"

namespace slmp::station {

class Station;
struct Handled;

// Where a request a module's port received goes: the station that serves it
// and the stations that pass it on, the receiving one first.
struct Relay {
    Station* target = nullptr;
    std::vector<Station*> hops;   // the receiving station, then each relay station
};

class NetworkMap {
public:
    // `station` with its network modules (the "networks" entries with a
    // station No.) and its routing parameters, as the plant's configuration
    // checked them.
    void add(Station& station, const std::string& name, const std::vector<config::NetworkConfig>& networks,
             const std::vector<config::RouteConfig>& routes = {});

    struct Found {
        protocol::EndCode error = protocol::EndCode::Ok;   // 4A01, 4A02, 4A03 (docs/end-codes.md)
        Relay relay;   // target == &from: the receiving station itself
    };
    // The station a request that reached `from` names with `network`/`station`
    // (§3.1.3: 7D the configured master, 7E the current one), or with the
    // station-number-extended frame's extended station No. when `extended`
    // (§3.1.6: 0000 the configured master, else the station No. itself), and
    // the relay stations on the way there, hop by hop: each station's routing
    // parameter for the network, else the first relay station of its shortest
    // way. At most 7 relay stations (a loop of routing parameters ends there).
    Found find(Station& from, std::uint8_t network, std::uint16_t station, bool extended = false) const;

    // A redundant pair's CPU and a multidrop station (docs/plants.md), by the
    // names the configuration gives; link() makes them stations once every
    // station is added (a partner that is no station of the plant: no pair).
    void add_redundant(Station& station, const std::string& name, const config::RedundantConfig& redundant);
    void add_multidrop(Station& station, const std::string& name, const config::MultidropConfig& multidrop);
    void link();

    // Past the station a route reached (`found.relay.target`): the CPU of its
    // redundant pair that module I/O 03D0-03D3 names, or the multidrop station
    // behind its serial module (module I/O 0000-01FF, multidrop No.). Moves the
    // target there, the station passed becoming a hop; or sets `found.error`:
    // 4248 while the pair switches (by role, and every file command), 4245
    // when the CPU by role is down. `file`: the request is a file command.
    void beyond(Found& found, std::uint16_t module_io, std::uint8_t multidrop, bool file) const;

    // The station's own part in them, for its engine (protocol::RouteIdentity).
    protocol::RouteIdentity identity(const Station& station) const;
    // The pair a station is in; null when none.
    RedundantPair* pair_of(const Station& station) const;

    // For GET /api/stations: each network's stations (No., name, master).
    struct Member {
        Station* station = nullptr;
        std::string name;
        std::uint16_t number = 0;
        bool master = false;
    };
    const std::map<std::uint16_t, std::vector<Member>>& networks() const { return networks_; }

    static constexpr std::size_t kMaxRelayStations = 7;   // 8 networks in a route (SLMP Reference Manual §2.3)

private:
    const Member* member(std::uint16_t network, std::uint16_t station, bool extended = false) const;
    // The next station a request on its way to `network` goes to from `at`
    // (a station with a module on a network other than `network`); null: none.
    Station* next_hop(const Station& at, std::uint16_t network) const;

    struct Via {   // a routing parameter: network -> its relay destination
        std::uint16_t network;
        std::uint16_t station;
    };
    std::map<const Station*, std::map<std::uint16_t, Via>> routes_;

    std::map<std::uint16_t, std::vector<Member>> networks_;
    std::map<const Station*, std::vector<std::uint16_t>> modules_;   // the networks each station is on

    struct Named {
        Station* station;
        std::string name;
    };
    std::vector<std::pair<Named, config::RedundantConfig>> redundant_;   // as configured, until link()
    std::vector<std::pair<Named, config::MultidropConfig>> multidrop_;
    std::vector<std::unique_ptr<RedundantPair>> pairs_;
    std::map<const Station*, RedundantPair*> pair_of_;
    struct Drop {   // a multidrop station: behind `via`'s serial module `module_io`, No. `number`
        const Station* via;
        std::uint16_t module_io;
        std::uint8_t number;
        auto operator<=>(const Drop&) const = default;
    };
    std::map<Drop, Station*> drops_;
    std::map<std::string, Station*> by_name_;   // every station add() saw
    std::map<const Station*, config::MultidropConfig> drop_of_;
};

// One connection's (or UDP port's) requests that a route takes to other
// stations: the protocol session it has at each of them (remote password,
// monitor registration, file locks are per connection there too), and the
// trip itself. Lives with the connection; each session is touched only on
// its station's strand, while the connection waits for the answer.
class Relays {
public:
    // Carries `frame` through relay.hops (each adds its passing-on time in the
    // model timing mode) to relay.target, which serves it in its own timing
    // mode; resumes the caller on its own strand with the answer. The
    // request's monitoring timer runs on the receiving station's clock from
    // now over the whole way: a target that does not answer, or answers later
    // than the timer, gets CF71 from the port when it runs out (the late
    // answer is dropped; the target has executed the request all the same).
    // `spent`: the time the receiving module held it already (model timing: its Ke).
    StrandTask<Handled> pass_on(Relay relay, std::vector<std::uint8_t> frame, protocol::DataCodePolicy policy,
                                protocol::Peer peer, std::chrono::microseconds spent = {});

private:
    // The connection's session at one station; shared with a trip still under
    // way after the port gave up on it (the connection may be gone by then).
    using SharedSession = std::shared_ptr<std::optional<protocol::Session>>;
    std::map<const Station*, SharedSession> sessions_;
};

}  // namespace slmp::station
