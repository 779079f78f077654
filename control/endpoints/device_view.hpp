// How the HTTP API shows a run of devices: as bits (one 0/1 a bit device), as
// 16-bit words (bit devices packed 16 a word, bit 0 = lowest device, as SLMP
// word units show them), as 32-bit double words (two words, low word first;
// one value a device for LTN, LSTN, LCN, LZ) or as a string (word devices, two
// bytes a word, low byte first, ended by the first NUL). docs/api.md.
//
// Every check happens before anything is written, so a rejected write changes
// nothing; the API runs on the SLMP thread, so a write is atomic with respect
// to SLMP requests.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "devicemodel/cpu.hpp"
#include "devicemodel/device_table.hpp"

namespace slmp::control {

enum class View : std::uint8_t { Bits, Words, Dwords, String };

std::optional<View> parse_view(std::string_view text);   // "bits", "words", "dwords", "string"
std::string_view to_string(View view);
View default_view(const devicemodel::DeviceSpec& spec);

// The most values one request may read or write.
inline constexpr std::uint32_t kMaxValues = 65536;

// `count` values of `view` from `start`, checked against the device and its
// configured size. Throws ApiError (400) with a message that names the fix.
struct DeviceRun {
    devicemodel::DeviceAddress start;
    View view = View::Words;
    std::uint32_t count = 1;      // values (string: words)
    std::uint64_t devices = 1;    // devices spanned
    devicemodel::Numbering numbering;   // how its addresses are written (FX5: X/Y in octal)
};

devicemodel::DeviceAddress parse_device(const std::string& text, devicemodel::Numbering numbering = {});
DeviceRun make_run(const devicemodel::Cpu& cpu, devicemodel::DeviceAddress start, View view, std::uint64_t count);

// Where a run lives, for its out-of-range messages: the owner's name
// ("R08CPU", "module U3 (Q62DA)") and how to make an area larger.
struct RunPlace {
    std::string name;
    std::string enlarge;   // "raise device_sizes.D in the configuration"
    devicemodel::Numbering numbering = {};
};
DeviceRun make_run(const devicemodel::DeviceMemory& memory, const RunPlace& place, devicemodel::DeviceAddress start,
                   View view, std::uint64_t count);

// {"device", "as", "count", "values" | "string"} for the run as it is now.
nlohmann::json read_run(const devicemodel::DeviceMemory& memory, const DeviceRun& run);

// Checks every value of a {"values": [...]} body against the view and returns
// them as raw (two's complement) numbers; throws ApiError naming the bad one.
std::vector<std::uint32_t> parse_values(const nlohmann::json& values, View view);
void write_run(devicemodel::DeviceMemory& memory, const DeviceRun& run, const std::vector<std::uint32_t>& values);

// Strings: one byte a character (Latin-1, U+0000-U+00FF), packed two a word,
// low byte first, always NUL-terminated as the CPU's string instructions do
// ("AB" takes two words: 0x4241 0x0000). Throws ApiError for other characters.
std::vector<std::uint16_t> pack_string(const std::string& utf8);
std::string unpack_string(const std::vector<std::uint16_t>& words);   // up to the first NUL, as UTF-8

}  // namespace slmp::control
