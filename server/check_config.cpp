#include "server/check_config.hpp"

#include "frontends/face.hpp"

#include "station/asio.hpp"
#include "station/station.hpp"
#include "station/transports.hpp"

namespace slmp::server {
namespace {

// The station's scenarios need transports to act on; a check has none.
class NoTransports final : public station::Transports {
public:
    void refuse_connections(bool) override {}
    void restart_sessions() override {}
};

}  // namespace

static void check_station(const config::StationConfig& station_config) {
    const auto& frontends = station_config.frontends;
    auto checked = station_config.server;
    // What would touch disk is left out: the state directory would be created,
    // recordings truncated. Their paths are checked when the simulator starts.
    checked.persistence.state_dir.clear();
    checked.record_file.clear();
    checked.record_pcap_file.clear();
    boost::asio::io_context io;
    NoTransports transports;   // outlives the station that points at it
    station::Station station(boost::asio::make_strand(io), checked);
    station.connect(transports);
    station.take_initial_snapshot();   // reads --snapshot's file
    for (const auto& face : frontends.faces)
        if (auto problem = face.face->check(station.cpu(), face); !problem.empty()) throw config::ConfigError(problem);
}

void check_configuration(const config::StationConfig& station_config) {
    try {
        check_station(station_config);
    } catch (const config::ConfigError& e) {
        if (station_config.server.name.empty()) throw;
        throw config::ConfigError("station '" + station_config.server.name + "': " + e.what());
    }
}

}  // namespace slmp::server
