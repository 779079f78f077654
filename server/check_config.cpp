#include "server/check_config.hpp"

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

void check_configuration(const config::ServerConfig& config) {
    auto checked = config;
    // What would touch disk is left out: the state directory would be created,
    // recordings truncated. Their paths are checked when the simulator starts.
    checked.persistence.state_dir.clear();
    checked.record_file.clear();
    checked.record_pcap_file.clear();
    boost::asio::io_context io;
    NoTransports transports;   // outlives the station that points at it
    station::Station station(io, checked);
    station.connect(transports);
}

}  // namespace slmp::server
