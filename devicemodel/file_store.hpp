// Where a drive's files live: a host folder (FolderStore) or memory
// (MemoryStore). A store knows host names only; the drive above it
// (devicemodel/drives.hpp) has already checked every name, so a path here is a
// list of names that exist or are to be created, never "..", never a separator.
// Symbolic links and special files in a folder are not listed and cannot be
// reached, so nothing outside the folder is served (docs/files.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace slmp::devicemodel {

using HostPath = std::vector<std::string>;   // names from the drive's root, as the host spells them

struct HostEntry {
    std::string name;
    bool directory = false;
    std::uint64_t size = 0;
    std::int64_t mtime = 0;   // seconds since the epoch
    bool writable = true;     // the host lets us write it (a read-only file gets attribute 01H)
};

class FileStore {
public:
    virtual ~FileStore() = default;
    // The entries of a directory, sorted by name; nullopt when it is not one.
    virtual std::optional<std::vector<HostEntry>> list(const HostPath& dir) const = 0;
    virtual std::optional<std::vector<std::uint8_t>> read(const HostPath& file) const = 0;
    // Replaces (or creates) a file whole, dated `mtime` (the CPU's clock, not
    // the host's): a crash leaves the old or the new content.
    virtual bool write(const HostPath& file, std::span<const std::uint8_t> bytes, std::int64_t mtime) = 0;
    virtual bool remove(const HostPath& file) = 0;
    virtual bool set_mtime(const HostPath& file, std::int64_t mtime) = 0;
    virtual bool make_directory(const HostPath& dir, std::int64_t mtime) = 0;
    // Where files are, for messages and the API ("memory" for a MemoryStore).
    virtual std::string location() const = 0;
};

class FolderStore final : public FileStore {
public:
    explicit FolderStore(std::filesystem::path root);
    std::optional<std::vector<HostEntry>> list(const HostPath& dir) const override;
    std::optional<std::vector<std::uint8_t>> read(const HostPath& file) const override;
    bool write(const HostPath& file, std::span<const std::uint8_t> bytes, std::int64_t mtime) override;
    bool remove(const HostPath& file) override;
    bool set_mtime(const HostPath& file, std::int64_t mtime) override;
    bool make_directory(const HostPath& dir, std::int64_t mtime) override;
    std::string location() const override { return root_.string(); }

private:
    std::filesystem::path host(const HostPath& path) const;
    std::filesystem::path root_;
};

class MemoryStore final : public FileStore {
public:
    std::optional<std::vector<HostEntry>> list(const HostPath& dir) const override;
    std::optional<std::vector<std::uint8_t>> read(const HostPath& file) const override;
    bool write(const HostPath& file, std::span<const std::uint8_t> bytes, std::int64_t mtime) override;
    bool remove(const HostPath& file) override;
    bool set_mtime(const HostPath& file, std::int64_t mtime) override;
    bool make_directory(const HostPath& dir, std::int64_t mtime) override;
    std::string location() const override { return "memory"; }

private:
    struct Node {
        bool directory = false;
        std::vector<std::uint8_t> bytes;
        std::int64_t mtime = 0;
    };
    static std::string key(const HostPath& path);
    std::map<std::string, Node> nodes_;   // "A\B" -> node; the root is implicit
};

}  // namespace slmp::devicemodel
