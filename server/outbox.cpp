#include "server/outbox.hpp"

#include <algorithm>

namespace slmp::server {

namespace asio = boost::asio;

Outbox::Outbox(station::StrandSocket& socket)
    : socket_(socket), timer_(socket.get_executor()), hold_timer_(socket.get_executor()) {
    boost::system::error_code ignored;
    socket_.non_blocking(true, ignored);   // send_now(): a full send buffer is would_block, not a wait
}

void Outbox::add(std::vector<std::uint8_t> response, const scenarios::Delivery& delivery) {
    if (group_size_ == 0 && delivery.coalesce > 1) {
        // This response opens a coalescing group of `coalesce` responses;
        // responses already queued (same read) ride along, so the order holds.
        group_size_ = items_.size() + delivery.coalesce;
        hold_until_ = std::chrono::steady_clock::now() + delivery.hold;
        released_ = false;
    }
    items_.push_back({std::move(response), delivery});
    if (group_size_ > 0 && items_.size() >= group_size_) released_ = true;
}

bool Outbox::send_now(boost::system::error_code& ec) {
    if (items_.empty()) return true;
    if (group_size_ > 0) return false;
    for (const auto& item : items_)
        if (!item.delivery.plain()) return false;
    auto* bytes = &items_.front().bytes;
    if (items_.size() > 1) {   // several answers of one read: one write, as send() does
        batch_.clear();
        for (const auto& item : items_) batch_.insert(batch_.end(), item.bytes.begin(), item.bytes.end());
        bytes = &batch_;
    }
    const auto written = socket_.write_some(asio::buffer(*bytes), ec);
    if (ec == asio::error::would_block || ec == asio::error::try_again) ec = {};
    if (ec || written == bytes->size()) {
        items_.clear();
        return true;
    }
    // The send buffer is full: the rest leaves with send(), asynchronously.
    std::vector<std::uint8_t> rest(bytes->begin() + static_cast<std::ptrdiff_t>(written), bytes->end());
    items_.clear();
    items_.push_back({std::move(rest), {}});
    return false;
}

void Outbox::watch_hold() {
    if (group_size_ == 0 || released_) return;
    watching_ = true;
    expired_ = false;
    hold_timer_.expires_at(hold_until_);
    hold_timer_.async_wait([this](const boost::system::error_code& ec) {
        if (ec || !watching_) return;
        expired_ = true;
        boost::system::error_code ignored;
        socket_.cancel(ignored);   // the session's read returns operation_aborted
    });
}

bool Outbox::hold_expired() {
    watching_ = false;
    hold_timer_.cancel();
    if (!expired_) return false;
    expired_ = false;
    released_ = true;
    return true;
}

station::StrandTask<> Outbox::wait(std::chrono::microseconds duration) {
    if (duration.count() <= 0) co_return;
    timer_.expires_after(duration);
    boost::system::error_code ignored;
    co_await timer_.async_wait(asio::redirect_error(station::use_strand, ignored));
}

station::StrandTask<> Outbox::write(const std::vector<std::uint8_t>& bytes, boost::system::error_code& ec) {
    if (bytes.empty() || ec) co_return;
    co_await asio::async_write(socket_, asio::buffer(bytes), asio::redirect_error(station::use_strand, ec));
}

station::StrandTask<> Outbox::send(boost::system::error_code& ec) {
    std::vector<std::uint8_t> batch;   // plain responses go out together
    if (group_size_ > 0 && released_) {
        // The group leaves in one write, after the longest delay any of its responses asked for.
        std::chrono::microseconds delay{0};
        for (const auto& item : items_) {
            delay = std::max(delay, item.delivery.delay);
            batch.insert(batch.end(), item.bytes.begin(), item.bytes.end());
        }
        items_.clear();
        group_size_ = 0;
        released_ = false;
        co_await wait(delay);
        co_await write(batch, ec);
        co_return;
    }
    if (group_size_ > 0) co_return;   // still holding: everything waits behind the group
    while (!items_.empty() && !ec) {
        auto item = std::move(items_.front());
        items_.pop_front();
        const auto& d = item.delivery;
        if (d.plain()) {
            // Usually the only response of the read: it goes out as it is, not copied.
            if (batch.empty()) batch = std::move(item.bytes);
            else batch.insert(batch.end(), item.bytes.begin(), item.bytes.end());
            continue;
        }
        co_await write(batch, ec);
        batch.clear();
        co_await wait(d.delay);
        if (d.pieces.empty()) {
            batch = std::move(item.bytes);
            continue;
        }
        std::size_t at = 0;
        for (std::size_t i = 0; i < d.pieces.size() && !ec; ++i) {
            if (i > 0) co_await wait(d.pause);
            std::vector<std::uint8_t> piece(item.bytes.begin() + static_cast<long>(at),
                                            item.bytes.begin() + static_cast<long>(at + d.pieces[i]));
            at += d.pieces[i];
            co_await write(piece, ec);
        }
    }
    co_await write(batch, ec);
}

}  // namespace slmp::server
