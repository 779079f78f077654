#include "devicemodel/file_store.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <ctime>
#include <fstream>
#include <iterator>

namespace slmp::devicemodel {

namespace fs = std::filesystem;

namespace {

// Temporary files of an atomic write: never listed, so a crash mid-write
// leaves nothing a client can see.
constexpr std::string_view kTempPrefix = ".slmp-tmp-";

struct Fd {
    int fd = -1;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

bool write_all(int fd, std::span<const std::uint8_t> bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        auto n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            return false;
        }
        done += static_cast<std::size_t>(n);
    }
    return true;
}

}  // namespace

// --- FolderStore ---------------------------------------------------------------

FolderStore::FolderStore(fs::path root) : root_(std::move(root)) {}

fs::path FolderStore::host(const HostPath& path) const {
    auto out = root_;
    for (const auto& name : path) out /= name;
    return out;
}

std::optional<std::vector<HostEntry>> FolderStore::list(const HostPath& dir) const {
    std::error_code ec;
    // Every step must be a real directory, not a link to one (a link could lead out).
    auto at = root_;
    for (const auto& name : dir) {
        at /= name;
        if (!fs::is_directory(fs::symlink_status(at, ec))) return std::nullopt;
    }
    if (!fs::is_directory(fs::symlink_status(at, ec))) return std::nullopt;
    std::vector<HostEntry> out;
    for (fs::directory_iterator it(at, ec), end; !ec && it != end; it.increment(ec)) {
        auto status = it->symlink_status(ec);
        if (ec) break;
        auto name = it->path().filename().string();
        if (name.starts_with(kTempPrefix)) continue;
        if (!fs::is_regular_file(status) && !fs::is_directory(status)) continue;   // links, devices, sockets
        struct ::stat st{};
        if (::lstat(it->path().c_str(), &st) != 0) continue;
        HostEntry entry{name, fs::is_directory(status), fs::is_directory(status) ? 0 : static_cast<std::uint64_t>(st.st_size),
                        static_cast<std::int64_t>(st.st_mtime), (st.st_mode & S_IWUSR) != 0};
        out.push_back(std::move(entry));
    }
    std::sort(out.begin(), out.end(), [](const HostEntry& a, const HostEntry& b) { return a.name < b.name; });
    return out;
}

std::optional<std::vector<std::uint8_t>> FolderStore::read(const HostPath& file) const {
    std::error_code ec;
    auto path = host(file);
    if (!fs::is_regular_file(fs::symlink_status(path, ec))) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Temp file, fsync, rename over, fsync the folder: the way station/state_store.cpp
// saves device memory, so kill -9 leaves the file before or after a write.
bool FolderStore::write(const HostPath& file, std::span<const std::uint8_t> bytes, std::int64_t mtime) {
    auto path = host(file);
    auto dir = path.parent_path();
    auto temp = dir / (std::string(kTempPrefix) + path.filename().string());
    {
        Fd out{::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644)};
        if (out.fd < 0) return false;
        // The date goes on before the rename, so the file appears with it.
        struct ::timespec times[2] = {{0, UTIME_OMIT}, {static_cast<time_t>(mtime), 0}};
        if (!write_all(out.fd, bytes) || ::futimens(out.fd, times) != 0 || ::fsync(out.fd) != 0) {
            ::unlink(temp.c_str());
            return false;
        }
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        ::unlink(temp.c_str());
        return false;
    }
    Fd folder{::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)};
    if (folder.fd >= 0) ::fsync(folder.fd);
    return true;
}

bool FolderStore::remove(const HostPath& file) {
    std::error_code ec;
    return fs::remove(host(file), ec) && !ec;
}

bool FolderStore::set_mtime(const HostPath& file, std::int64_t mtime) {
    struct ::timespec times[2];
    times[0].tv_sec = 0;
    times[0].tv_nsec = UTIME_OMIT;
    times[1].tv_sec = static_cast<time_t>(mtime);
    times[1].tv_nsec = 0;
    return ::utimensat(AT_FDCWD, host(file).c_str(), times, AT_SYMLINK_NOFOLLOW) == 0;
}

bool FolderStore::make_directory(const HostPath& dir, std::int64_t mtime) {
    std::error_code ec;
    return fs::create_directory(host(dir), ec) && !ec && set_mtime(dir, mtime);
}

// --- MemoryStore ---------------------------------------------------------------

std::string MemoryStore::key(const HostPath& path) {
    std::string out;
    for (const auto& name : path) {
        if (!out.empty()) out += '\\';
        out += name;
    }
    return out;
}

std::optional<std::vector<HostEntry>> MemoryStore::list(const HostPath& dir) const {
    auto prefix = key(dir);
    if (!prefix.empty()) {
        auto it = nodes_.find(prefix);
        if (it == nodes_.end() || !it->second.directory) return std::nullopt;
        prefix += '\\';
    }
    std::vector<HostEntry> out;
    for (const auto& [path, node] : nodes_) {
        if (!path.starts_with(prefix)) continue;
        auto rest = path.substr(prefix.size());
        if (rest.empty() || rest.find('\\') != std::string::npos) continue;
        out.push_back({rest, node.directory, node.bytes.size(), node.mtime, true});
    }
    return out;   // std::map order: sorted by name
}

std::optional<std::vector<std::uint8_t>> MemoryStore::read(const HostPath& file) const {
    auto it = nodes_.find(key(file));
    if (it == nodes_.end() || it->second.directory) return std::nullopt;
    return it->second.bytes;
}

bool MemoryStore::write(const HostPath& file, std::span<const std::uint8_t> bytes, std::int64_t mtime) {
    auto& node = nodes_[key(file)];
    node.directory = false;
    node.bytes.assign(bytes.begin(), bytes.end());
    node.mtime = mtime;
    return true;
}

bool MemoryStore::remove(const HostPath& file) { return nodes_.erase(key(file)) > 0; }

bool MemoryStore::set_mtime(const HostPath& file, std::int64_t mtime) {
    auto it = nodes_.find(key(file));
    if (it == nodes_.end()) return false;
    it->second.mtime = mtime;
    return true;
}

bool MemoryStore::make_directory(const HostPath& dir, std::int64_t mtime) {
    auto [it, added] = nodes_.try_emplace(key(dir));
    if (added) {
        it->second.directory = true;
        it->second.mtime = mtime;
    }
    return added;
}

}  // namespace slmp::devicemodel
