// Test-side encoders for the label commands 041A/141A/041C/141B, written from
// the layouts of the SLMP Reference Manual §5.3 independently of
// protocol/ (a codec bug cannot hide by being symmetric), and a CPU with
// labels declared through the configuration parser.
#pragma once

#include <string>
#include <vector>

#include "support/device_commands.hpp"

namespace slmp::test {

// A label name: its length in UTF-16 units, then each unit (ASCII names only here).
inline Payload label_name(const std::string& text) {
    Payload p = word(static_cast<std::uint16_t>(text.size()));
    for (unsigned char c : text) p = p + word(c);
    return p;
}

inline Payload abbreviations(const std::vector<std::string>& prefixes) {
    Payload p = word(static_cast<std::uint16_t>(prefixes.size()));
    for (const auto& a : prefixes) p = p + label_name(a);
    return p;
}

// A 64-bit value: 8 bytes little-endian / 16 hex digits, high first.
inline Payload qword(std::uint64_t v) {
    return {le(static_cast<std::uint32_t>(v), 4) + " " + le(static_cast<std::uint32_t>(v >> 32), 4),
            hexn(static_cast<std::uint32_t>(v >> 32), 8) + hexn(static_cast<std::uint32_t>(v), 8)};
}

struct ArrayEntry {
    std::string name;
    std::uint8_t unit;      // 0 bit, 1 byte
    std::uint16_t length;   // bits (unit 0) or bytes (unit 1)
    Payload data = {};      // 141A only
};

inline Payload array_read_req(const std::vector<ArrayEntry>& entries, const std::vector<std::string>& abbr = {}) {
    Payload p = word(0x041A) + word(0x0000) + word(static_cast<std::uint16_t>(entries.size())) + abbreviations(abbr);
    for (const auto& e : entries) p = p + label_name(e.name) + byte(e.unit) + byte(0) + word(e.length);
    return p;
}
inline Payload array_write_req(const std::vector<ArrayEntry>& entries, const std::vector<std::string>& abbr = {}) {
    Payload p = word(0x141A) + word(0x0000) + word(static_cast<std::uint16_t>(entries.size())) + abbreviations(abbr);
    for (const auto& e : entries) p = p + label_name(e.name) + byte(e.unit) + byte(0) + word(e.length) + e.data;
    return p;
}
inline Payload random_label_read_req(const std::vector<std::string>& names, const std::vector<std::string>& abbr = {}) {
    Payload p = word(0x041C) + word(0x0000) + word(static_cast<std::uint16_t>(names.size())) + abbreviations(abbr);
    for (const auto& n : names) p = p + label_name(n);
    return p;
}
struct RandomEntry {
    std::string name;
    std::uint16_t length;
    Payload data;
};
inline Payload random_label_write_req(const std::vector<RandomEntry>& entries, const std::vector<std::string>& abbr = {}) {
    Payload p = word(0x141B) + word(0x0000) + word(static_cast<std::uint16_t>(entries.size())) + abbreviations(abbr);
    for (const auto& e : entries) p = p + label_name(e.name) + word(e.length) + e.data;
    return p;
}

// A CPU of `profile` with the labels (and structures) of a configuration text.
inline devicemodel::Cpu cpu_with_labels(const std::string& config_json, const std::string& profile = "R08CPU") {
    auto config = config::parse_server_config(config_json, "test.json");
    auto cpu = make_cpu(profile);
    config::declare_labels(cpu, config.labels);
    return cpu;
}

}  // namespace slmp::test
