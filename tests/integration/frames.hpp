// Hand-built frames for black-box tests.
//
// Requests are built with the project's client library (protocol/client.hpp),
// but the EXPECTED responses are spelled out here from the manual's rules
// (SLMP Reference Manual ch. 4, §5.2), independently of
// the codec under test, so a codec bug cannot hide itself by being symmetric.
#pragma once

#include <cstdint>
#include <iomanip>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "devicemodel/device_table.hpp"
#include "protocol/client.hpp"

namespace slmp::test {

using Bytes = std::vector<std::uint8_t>;

// "50 00 0A ff" -> bytes. Whitespace is ignored.
inline Bytes hex(const std::string& text) {
    Bytes out;
    int high = -1;
    for (char c : text) {
        int v;
        if (c >= '0' && c <= '9') v = c - '0';
        else if (c >= 'a' && c <= 'f') v = c - 'a' + 10;
        else if (c >= 'A' && c <= 'F') v = c - 'A' + 10;
        else continue;
        if (high < 0) high = v;
        else {
            out.push_back(static_cast<std::uint8_t>(high << 4 | v));
            high = -1;
        }
    }
    return out;
}

inline Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }

// Bytes for failure messages: printable ASCII frames as text, binary as hex.
inline std::string show(std::span<const std::uint8_t> bytes) {
    bool printable = !bytes.empty();
    for (auto b : bytes) printable = printable && b >= 0x20 && b < 0x7F;
    std::ostringstream out;
    if (printable) {
        out << '"' << std::string(bytes.begin(), bytes.end()) << '"';
    } else {
        out << std::hex << std::uppercase << std::setfill('0');
        for (std::size_t i = 0; i < bytes.size(); ++i) out << (i ? " " : "") << std::setw(2) << int(bytes[i]);
    }
    return out.str();
}

inline Bytes concat(std::initializer_list<Bytes> parts) {
    Bytes out;
    for (auto& p : parts) out.insert(out.end(), p.begin(), p.end());
    return out;
}

inline std::string hex_digits(std::uint32_t value, int digits) {
    std::ostringstream out;
    out << std::hex << std::uppercase << std::setfill('0') << std::setw(digits) << value;
    return out.str();
}

using protocol::Codec;
using protocol::FrameKind;

// The shape of a conversation: frame kind, data code, 4E serial.
struct Wire {
    FrameKind kind = FrameKind::E3;
    Codec codec = Codec::Binary;
    std::uint16_t serial = 0;

    protocol::client::FrameOptions options() const {
        protocol::client::FrameOptions o;
        o.kind = kind;
        o.codec = codec;
        o.serial = serial;
        return o;
    }
    std::string name() const {
        return std::string(kind == FrameKind::E3 ? "3E" : "4E") + (codec == Codec::Binary ? " binary" : " ASCII");
    }
};

// Expected response for the own-station route (network 00, station FF, I/O 03FF,
// multidrop 00), end code `end_code`, response data `data` (already in the codec).
inline Bytes expected_response(const Wire& w, std::span<const std::uint8_t> data, std::uint16_t end_code = 0) {
    Bytes out;
    if (w.codec == Codec::Binary) {
        if (w.kind == FrameKind::E3) {
            out = {0xD0, 0x00};
        } else {
            out = {0xD4, 0x00, std::uint8_t(w.serial & 0xFF), std::uint8_t(w.serial >> 8), 0x00, 0x00};
        }
        auto length = static_cast<std::uint16_t>(2 + data.size());
        Bytes route = {0x00, 0xFF, 0xFF, 0x03, 0x00, std::uint8_t(length & 0xFF), std::uint8_t(length >> 8),
                       std::uint8_t(end_code & 0xFF), std::uint8_t(end_code >> 8)};
        out.insert(out.end(), route.begin(), route.end());
    } else {
        std::string head = w.kind == FrameKind::E3 ? "D000" : "D400" + hex_digits(w.serial, 4) + "0000";
        head += "00FF03FF00" + hex_digits(static_cast<std::uint32_t>(4 + data.size()), 4) + hex_digits(end_code, 4);
        out = text(head);
    }
    out.insert(out.end(), data.begin(), data.end());
    return out;
}

// Response data for word values: 2 bytes LE each, or 4 hex digits each.
inline Bytes word_data(const Wire& w, std::initializer_list<std::uint16_t> words) {
    Bytes out;
    for (auto v : words) {
        if (w.codec == Codec::Binary) {
            out.push_back(std::uint8_t(v & 0xFF));
            out.push_back(std::uint8_t(v >> 8));
        } else {
            auto t = hex_digits(v, 4);
            out.insert(out.end(), t.begin(), t.end());
        }
    }
    return out;
}
inline Bytes word_data(const Wire& w, const std::vector<std::uint16_t>& words) {
    Bytes out;
    for (auto v : words) {
        auto one = word_data(w, {v});
        out.insert(out.end(), one.begin(), one.end());
    }
    return out;
}

// Response data for bit values: nibbles (first point high, odd count padded
// with 0), or one '0'/'1' character per point.
inline Bytes bit_data(const Wire& w, const std::vector<std::uint8_t>& bits) {
    Bytes out;
    if (w.codec == Codec::Binary) {
        for (std::size_t i = 0; i < bits.size(); i += 2) {
            std::uint8_t b = static_cast<std::uint8_t>((bits[i] ? 0x10 : 0) | (i + 1 < bits.size() && bits[i + 1] ? 0x01 : 0));
            out.push_back(b);
        }
    } else {
        for (auto b : bits) out.push_back(b ? '1' : '0');
    }
    return out;
}

// The error information that follows a non-zero end code (own station).
inline Bytes error_info(const Wire& w, std::uint16_t command, std::uint16_t subcommand) {
    if (w.codec == Codec::Binary)
        return {0x00, 0xFF, 0xFF, 0x03, 0x00, std::uint8_t(command & 0xFF), std::uint8_t(command >> 8),
                std::uint8_t(subcommand & 0xFF), std::uint8_t(subcommand >> 8)};
    return text("00FF03FF00" + hex_digits(command, 4) + hex_digits(subcommand, 4));
}

inline devicemodel::DeviceAddress addr(const std::string& s) {
    std::string error;
    auto a = devicemodel::parse_address(s, &error);
    if (!a) throw std::runtime_error("bad test address " + s + ": " + error);
    return *a;
}

}  // namespace slmp::test
