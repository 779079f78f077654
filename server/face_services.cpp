#include "server/face_services.hpp"

#include <array>
#include <optional>
#include <vector>

#include "station/log_exception.hpp"

namespace slmp::server {

namespace asio = boost::asio;
using station::use_strand;

using Whole = std::function<std::optional<std::size_t>(std::span<const std::uint8_t>)>;
using Answer = std::function<void(std::optional<std::vector<std::uint8_t>>)>;

// The sockets and what waits on them, shared with the handlers in flight: the
// Outgoing's destruction closes the sockets and marks it so that a handler
// that still runs calls nobody.
struct OutgoingSockets : std::enable_shared_from_this<OutgoingSockets> {
    OutgoingSockets(const station::Home& home, protocol::Transport transport, asio::ip::address address, std::uint16_t port)
        : transport(transport), partner(address, port), tcp(home), udp(home) {}

    protocol::Transport transport;
    bool closed = false;
    bool unusable = false;   // an address that is none: open() reports false
    bool is_connected = false;
    asio::ip::tcp::endpoint partner;
    station::StrandSocket tcp;
    station::StrandDatagramSocket udp;
    std::vector<std::uint8_t> received;

    void close() {
        closed = true;
        is_connected = false;
        boost::system::error_code ec;
        tcp.close(ec);
        udp.close(ec);
    }

    station::StrandTask<> open(std::function<void(bool)> done) {
        auto self = shared_from_this();
        boost::system::error_code ec;
        if (unusable) {
            ec = asio::error::host_not_found;
        } else if (transport == protocol::Transport::Tcp) {
            co_await tcp.async_connect(partner, asio::redirect_error(use_strand, ec));
            if (!ec) tcp.set_option(asio::ip::tcp::no_delay(true), ec);
        } else {
            udp.open(partner.address().is_v4() ? asio::ip::udp::v4() : asio::ip::udp::v6(), ec);
            if (!ec) udp.connect({partner.address(), partner.port()}, ec);   // only the partner's datagrams reach it
        }
        if (closed) co_return;
        is_connected = !ec;
        if (ec) {
            boost::system::error_code ignored;
            tcp.close(ignored);
            udp.close(ignored);
        }
        done(!ec);
    }

    station::StrandTask<> exchange(std::vector<std::uint8_t> request, Whole whole, Answer answer) {
        auto self = shared_from_this();
        boost::system::error_code ec;
        std::optional<std::vector<std::uint8_t>> result;
        if (transport == protocol::Transport::Tcp) {
            co_await asio::async_write(tcp, asio::buffer(request), asio::redirect_error(use_strand, ec));
            std::array<std::uint8_t, 2048> chunk{};
            while (!ec && !closed) {
                if (auto length = whole(received); length && *length <= received.size()) {
                    result.emplace(received.begin(), received.begin() + static_cast<std::ptrdiff_t>(*length));
                    received.erase(received.begin(), received.begin() + static_cast<std::ptrdiff_t>(*length));
                    break;
                }
                auto n = co_await tcp.async_read_some(asio::buffer(chunk), asio::redirect_error(use_strand, ec));
                received.insert(received.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
            }
            if (ec) is_connected = false;
        } else {
            co_await udp.async_send(asio::buffer(request), asio::redirect_error(use_strand, ec));
            std::vector<std::uint8_t> datagram(65536);
            // An ICMP "port unreachable" from an earlier datagram shows as a refused receive: read on,
            // the answer (or the caller's timer) decides.
            for (int tries = 0; tries < 4 && !closed; ++tries) {
                auto n = co_await udp.async_receive(asio::buffer(datagram), asio::redirect_error(use_strand, ec));
                if (!ec) {
                    datagram.resize(n);
                    result = std::move(datagram);
                    break;
                }
                if (ec != asio::error::connection_refused) break;
            }
        }
        if (closed) co_return;
        answer(std::move(result));
    }
};

namespace {

class OutgoingLink final : public frontends::Outgoing {
public:
    explicit OutgoingLink(std::shared_ptr<OutgoingSockets> link) : link_(std::move(link)) {}
    ~OutgoingLink() override { link_->close(); }

    void open(std::function<void(bool)> done) override {
        asio::co_spawn(link_->tcp.get_executor(), link_->open(std::move(done)),
                       station::log_exception("outgoing connection failed"));
    }
    bool connected() const override { return link_->is_connected; }
    void exchange(std::vector<std::uint8_t> request, Whole whole, Answer answer) override {
        asio::co_spawn(link_->tcp.get_executor(), link_->exchange(std::move(request), std::move(whole), std::move(answer)),
                       station::log_exception("outgoing exchange failed"));
    }

private:
    std::shared_ptr<OutgoingSockets> link_;
};

}  // namespace

void FaceServices::after(std::chrono::milliseconds timer, std::function<bool()> wanted, std::function<void()> then) {
    auto wait = [](station::Station& station, std::chrono::milliseconds timer, std::function<bool()> wanted,
                   std::function<void()> then, std::shared_ptr<bool> stopped) -> station::StrandTask<> {
        co_await station.wait_on_clock(timer, [&] { return !*stopped && wanted(); });
        if (!*stopped && wanted()) then();
    };
    if (*stopped_) return;
    asio::co_spawn(home_, wait(station_, timer, std::move(wanted), std::move(then), stopped_),
                   station::log_exception("a unit's timer failed"));
}

std::unique_ptr<frontends::Outgoing> FaceServices::connect(protocol::Transport transport, const std::string& address,
                                                           std::uint16_t port) {
    boost::system::error_code ec;
    auto ip = asio::ip::make_address(address, ec);
    auto link = std::make_shared<OutgoingSockets>(home_, transport, ec ? asio::ip::address(asio::ip::address_v4::loopback()) : ip, port);
    link->unusable = static_cast<bool>(ec) || *stopped_;
    std::erase_if(links_, [](const std::weak_ptr<OutgoingSockets>& l) { return l.expired(); });
    links_.push_back(link);
    return std::make_unique<OutgoingLink>(std::move(link));
}

void FaceServices::stop() {
    *stopped_ = true;
    for (auto& weak : links_)
        if (auto link = weak.lock()) link->close();
    links_.clear();
}

}  // namespace slmp::server
