// A file of the state directory, written so that a crash at any moment leaves
// either the old or the new snapshot, never a torn one: write a temporary file,
// fsync it, rename it over the old one, fsync the directory.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace slmp::station {

class StateStore {
public:
    // Creates the directory when missing; throws config::ConfigError when it cannot.
    // `name`: the file in it (the device memory's snapshot.bin, the front ends'
    // units.bin, the drives' memo).
    explicit StateStore(std::filesystem::path dir, const std::string& name = "snapshot.bin");

    const std::filesystem::path& file() const { return file_; }
    // The saved snapshot, or nullopt when there is none yet.
    std::optional<std::vector<std::uint8_t>> load() const;
    // Throws std::system_error naming the file when a step fails.
    void save(std::span<const std::uint8_t> bytes) const;

private:
    std::filesystem::path dir_;
    std::filesystem::path file_;
    std::filesystem::path temp_;
};

}  // namespace slmp::station
