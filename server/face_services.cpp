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
    // The request waiting for its answer (one at a time).
    bool waiting = false;
    Whole whole;
    Answer answer;

    void close() {
        closed = true;
        is_connected = false;
        boost::system::error_code ec;
        tcp.close(ec);
        udp.close(ec);
    }

    // Opens, then reads for as long as the connection lasts: one reader, so
    // a TCP connection the partner closes while idle shows as not connected,
    // and a UDP answer that comes after its request was given up cannot be
    // taken for the next request's.
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
        if (!ec && !closed) co_await read();
    }

    station::StrandTask<> read() {
        std::vector<std::uint8_t> chunk(65536);
        boost::system::error_code ec;
        while (!closed) {
            std::size_t n = 0;
            if (transport == protocol::Transport::Tcp)
                n = co_await tcp.async_read_some(asio::buffer(chunk), asio::redirect_error(use_strand, ec));
            else
                n = co_await udp.async_receive(asio::buffer(chunk), asio::redirect_error(use_strand, ec));
            if (closed) co_return;
            // UDP: an ICMP "port unreachable" for an earlier datagram; the caller's timer decides.
            if (ec == asio::error::connection_refused && transport == protocol::Transport::Udp) continue;
            if (ec) break;
            if (transport == protocol::Transport::Tcp) {
                received.insert(received.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
                deliver();
            } else if (waiting) {
                take(std::vector<std::uint8_t>(chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n)));
            }   // else a datagram nobody asked for: dropped
        }
        if (closed) co_return;
        is_connected = false;   // the partner closed or reset the connection
        if (waiting) take(std::nullopt);
    }

    // A whole TCP answer in `received` goes to the request waiting for it; bytes nobody asked for are dropped.
    void deliver() {
        if (!waiting) {
            received.clear();
            return;
        }
        auto length = whole(received);
        if (!length || *length > received.size()) return;
        std::vector<std::uint8_t> result(received.begin(), received.begin() + static_cast<std::ptrdiff_t>(*length));
        received.erase(received.begin(), received.begin() + static_cast<std::ptrdiff_t>(*length));
        take(std::move(result));
    }

    void take(std::optional<std::vector<std::uint8_t>> result) {
        waiting = false;
        auto callback = std::move(answer);   // it may ask the next request at once
        answer = nullptr;
        callback(std::move(result));
    }

    station::StrandTask<> exchange(std::vector<std::uint8_t> request, Whole ask_whole, Answer ask_answer) {
        auto self = shared_from_this();
        whole = std::move(ask_whole);
        answer = std::move(ask_answer);
        waiting = true;
        received.clear();
        boost::system::error_code ec;
        if (transport == protocol::Transport::Tcp)
            co_await asio::async_write(tcp, asio::buffer(request), asio::redirect_error(use_strand, ec));
        else
            co_await udp.async_send(asio::buffer(request), asio::redirect_error(use_strand, ec));
        if (closed || !waiting) co_return;
        if (ec && transport == protocol::Transport::Tcp) {   // UDP: the answer does not come; the caller's timer decides
            is_connected = false;
            take(std::nullopt);
        }
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
        std::function<bool()> still_wanted = [&] { return !*stopped && wanted(); };   // named: see Relays::pass_on
        co_await station.wait_on_clock(timer, std::move(still_wanted));
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
