#include "station/state_store.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <fstream>
#include <iterator>
#include <system_error>

#include "config/config_error.hpp"

namespace slmp::station {
namespace {

[[noreturn]] void fail(const std::string& what, const std::filesystem::path& path) {
    throw std::system_error(errno, std::generic_category(), what + " " + path.string());
}

// Closes the descriptor on every path out.
struct Fd {
    int fd;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

StateStore::StateStore(std::filesystem::path dir, const std::string& name)
    : dir_(std::move(dir)), file_(dir_ / name), temp_(dir_ / (name + ".tmp")) {
    std::error_code ec;
    std::filesystem::create_directories(dir_, ec);
    if (ec || !std::filesystem::is_directory(dir_))
        throw config::ConfigError("state directory " + dir_.string() + ": " +
                                  (ec ? ec.message() : std::string("not a directory")) +
                                  "; give --state-dir a writable directory");
}

std::optional<std::vector<std::uint8_t>> StateStore::load() const {
    std::ifstream in(file_, std::ios::binary);
    if (!in) return std::nullopt;
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void StateStore::save(std::span<const std::uint8_t> bytes) const {
    {
        Fd out{::open(temp_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)};
        if (out.fd < 0) fail("cannot create", temp_);
        std::size_t done = 0;
        while (done < bytes.size()) {
            auto n = ::write(out.fd, bytes.data() + done, bytes.size() - done);
            if (n < 0) {
                if (errno == EINTR) continue;
                fail("cannot write", temp_);
            }
            done += static_cast<std::size_t>(n);
        }
        if (::fsync(out.fd) != 0) fail("cannot fsync", temp_);
    }
    if (::rename(temp_.c_str(), file_.c_str()) != 0) fail("cannot rename over", file_);
    // The rename itself must reach the disk before the old file is gone for good.
    Fd dir{::open(dir_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
    if (dir.fd >= 0) ::fsync(dir.fd);
}

}  // namespace slmp::station
