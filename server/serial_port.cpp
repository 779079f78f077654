#include "server/serial_port.hpp"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include <spdlog/spdlog.h>

#include "config/config_error.hpp"
#include "station/log_exception.hpp"

namespace slmp::server {

namespace asio = boost::asio;

namespace {

[[noreturn]] void fail(const std::string& what) {
    throw config::ConfigError("--serial: " + what + ": " + std::strerror(errno) +
                              "; check that /dev/pts is mounted and the path's folder is writable");
}

}  // namespace

SerialPort::SerialPort(const station::Home& home, frontends::Unit& unit, std::filesystem::path link_path)
    : unit_(unit), state_(unit.new_session(protocol::Peer{})), master_(home), link_path_(std::move(link_path)) {
    int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    if (master < 0) fail("cannot open a pseudo-terminal");
    if (::grantpt(master) != 0 || ::unlockpt(master) != 0) {
        ::close(master);
        fail("cannot unlock the pseudo-terminal");
    }
    device_ = ::ptsname(master);
    slave_fd_ = ::open(device_.c_str(), O_RDWR | O_NOCTTY);
    if (slave_fd_ < 0) {
        ::close(master);
        fail("cannot open " + device_);
    }
    termios raw{};
    ::tcgetattr(slave_fd_, &raw);
    ::cfmakeraw(&raw);
    ::tcsetattr(slave_fd_, TCSANOW, &raw);
    master_.assign(master);
    std::error_code ec;
    std::filesystem::remove(link_path_, ec);
    std::filesystem::create_symlink(device_, link_path_, ec);
    if (ec)
        throw config::ConfigError("--serial " + link_path_.string() + ": cannot create the link to " + device_ + ": " +
                                  ec.message() + "; give a path in a writable folder");
    asio::co_spawn(home, serve(), station::log_exception(std::string(unit_.face().log_name()) + " on " + device_ + ": read loop failed"));
}

SerialPort::~SerialPort() {
    std::error_code ec;
    std::filesystem::remove(link_path_, ec);
    if (slave_fd_ >= 0) ::close(slave_fd_);
}

asio::awaitable<void> SerialPort::serve() {
    std::vector<std::uint8_t> pending;
    std::array<std::uint8_t, 1024> chunk;
    while (master_.is_open()) {
        boost::system::error_code ec;
        auto n = co_await master_.async_read_some(asio::buffer(chunk), asio::redirect_error(asio::use_awaitable, ec));
        if (ec) {
            if (ec == asio::error::operation_aborted || !master_.is_open()) co_return;
            spdlog::warn("{} on {}: read failed: {}", unit_.face().log_name(), device_, ec.message());
            co_return;
        }
        pending.insert(pending.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(n));
        std::string out;
        std::size_t offset = 0;
        while (offset < pending.size()) {
            auto result = unit_.stream(std::span<const std::uint8_t>(pending).subspan(offset), state_.get(), {});
            if (result.need_more) break;
            offset += result.consumed;
            out += result.response;
        }
        pending.erase(pending.begin(), pending.begin() + static_cast<std::ptrdiff_t>(offset));
        if (!out.empty()) co_await asio::async_write(master_, asio::buffer(out), asio::redirect_error(asio::use_awaitable, ec));
    }
}

void SerialPort::stop() {
    boost::system::error_code ec;
    master_.close(ec);
}

}  // namespace slmp::server
