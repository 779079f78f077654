#include "server/node_search.hpp"

#include <array>

#include <spdlog/spdlog.h>

#include "station/log_exception.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using asio::ip::udp;

asio::ip::address NodeSearchListener::search_address(const asio::ip::address& bind) {
    if (bind.is_v4() && bind.to_v4().to_bytes()[0] == 127) return asio::ip::make_address_v4("127.255.255.255");
    return asio::ip::address_v4::any();
}

namespace {

station::StrandDatagramSocket search_socket(const station::Home& home, const asio::ip::address& bind, std::uint16_t port) {
    station::StrandDatagramSocket socket(home);
    const udp::endpoint at(NodeSearchListener::search_address(bind), port);
    socket.open(at.protocol());
    socket.set_option(asio::socket_base::reuse_address(true));   // every node station of the host on one port
    socket.set_option(asio::socket_base::broadcast(true));
    socket.bind(at);
    return socket;
}

}  // namespace

NodeSearchListener::NodeSearchListener(const station::Home& home, station::Station& station,
                                       const config::NodeSearchConfig& config, const asio::ip::address& bind,
                                       std::uint16_t answer_port)
    : station_(station),
      config_(config),
      answer_port_(answer_port),
      session_(station.new_session(config::PortConfig{config::Transport::Udp, config.port})),
      socket_(search_socket(home, bind, config.port)),
      random_(std::random_device{}()) {
    asio::co_spawn(home, serve(),
                   station::log_exception("node search port " + std::to_string(config.port) + ": receive loop failed"));
}

void NodeSearchListener::stop() {
    boost::system::error_code ignored;
    socket_.close(ignored);
}

station::StrandTask<> NodeSearchListener::serve() {
    std::array<std::uint8_t, 4096> buffer;
    udp::endpoint sender;
    for (;;) {
        boost::system::error_code ec;
        const auto n = co_await socket_.async_receive_from(asio::buffer(buffer), sender, asio::redirect_error(station::use_strand, ec));
        if (ec == asio::error::operation_aborted || !socket_.is_open()) co_return;
        if (ec) continue;
        asio::co_spawn(socket_.get_executor(), answer(std::vector<std::uint8_t>(buffer.begin(), buffer.begin() + n), sender),
                       station::log_exception("node search port " + std::to_string(config_.port) + ": an answer failed"));
    }
}

station::StrandTask<> NodeSearchListener::answer(std::vector<std::uint8_t> datagram, udp::endpoint sender) {
    const auto request = station_.engine().decode(datagram, protocol::DataCodePolicy::Auto, {}, false);
    if (!request.complete() || !request.has_command || request.command != 0x0E30) {
        station_.log().debug("node search port {}: {} bytes from {} are no node search; ignored", config_.port,
                             datagram.size(), sender.address().to_string());
        co_return;
    }
    // The manual's random wait, drawn for this answer, on the station's clock.
    const auto delay = std::uniform_int_distribution<std::uint32_t>(0, config_.max_delay_ms)(random_);
    co_await station_.wait_on_clock(std::chrono::milliseconds(delay));
    if (!socket_.is_open()) co_return;
    protocol::Peer peer;
    peer.transport = protocol::Transport::Udp;
    peer.address = sender.address().to_string();
    peer.port = sender.port();
    peer.local_port = answer_port_;   // reported as the server port: the node's SLMP port
    if (sender.address().is_v4()) peer.ipv4 = sender.address().to_v4().to_bytes();
    auto handled = station_.handle(datagram, protocol::DataCodePolicy::Auto, session_, peer);
    if (handled.outcome.action != protocol::Outcome::Action::Respond) co_return;
    boost::system::error_code ec;
    co_await socket_.async_send_to(asio::buffer(handled.outcome.response), sender, asio::redirect_error(station::use_strand, ec));
    if (ec) station_.log().debug("node search port {}: answer to {} not sent: {}", config_.port, sender.address().to_string(), ec.message());
}

}  // namespace slmp::server
