// A protocol face on a pseudo-terminal (the host link's --serial PATH):
// RS-232C-style tools open PATH (a symlink to the pty's slave, /dev/pts/N) and
// talk to the station's unit of the face as over a serial line. The terminal is raw (no CR/NL
// translation, no echo); baud rate and parity settings a client makes are
// accepted and mean nothing on a pty.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "station/asio.hpp"

#include "frontends/face.hpp"

namespace slmp::server {

class SerialPort {
public:
    // Opens the pty and makes `link_path` point at its slave; throws
    // config::ConfigError naming the problem and the fix.
    SerialPort(const station::Home& home, frontends::Unit& unit, std::filesystem::path link_path);
    ~SerialPort();
    SerialPort(const SerialPort&) = delete;
    SerialPort& operator=(const SerialPort&) = delete;

    const std::string& device() const { return device_; }   // /dev/pts/N
    void stop();

private:
    boost::asio::awaitable<void> serve();

    frontends::Unit& unit_;
    std::unique_ptr<frontends::SessionState> state_;   // one line, one session (the host link: one QQ list)
    boost::asio::posix::stream_descriptor master_;
    int slave_fd_ = -1;           // held open so the master never reads EOF between clients
    std::string device_;
    std::filesystem::path link_path_;
};

}  // namespace slmp::server
