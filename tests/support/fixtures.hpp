// Helpers for the unit tests: bytes from hex or ASCII text, a CPU from a
// profile name, one call into the engine, and a test-side encoder for the four
// frame shapes (3E/4E × binary/ASCII).
//
// The encoder here is written independently of protocol/ (it only borrows the
// device table for codes, and test_device_table.cpp checks that table against
// the manual), so a test that compares engine output with it can fail.
#pragma once

#include <catch2/catch.hpp>

#include <cstdint>
#include <ostream>
#include <span>
#include <stdexcept>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/cpu.hpp"
#include "devicemodel/device_table.hpp"
#include "protocol/engine.hpp"
#include "protocol/frame.hpp"

namespace slmp::test {

using Bytes = std::vector<std::uint8_t>;
using protocol::Codec;
using protocol::DataCodePolicy;
using protocol::FrameKind;
using protocol::Outcome;
using protocol::Route;

// ---------------------------------------------------------------------------
// Bytes and text

// "50 00 00 FF" (spaces and '|' are ignored) -> {0x50, 0x00, 0x00, 0xFF}.
inline Bytes bytes(std::string_view hex) {
    Bytes out;
    int high = -1;
    for (char c : hex) {
        if (c == ' ' || c == '|' || c == '\n') continue;
        int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'A' && c <= 'F' ? c - 'A' + 10 : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
        if (digit < 0) throw std::invalid_argument("bytes(): not hex: " + std::string(hex));
        if (high < 0) {
            high = digit;
        } else {
            out.push_back(static_cast<std::uint8_t>(high << 4 | digit));
            high = -1;
        }
    }
    if (high >= 0) throw std::invalid_argument("bytes(): odd digit count: " + std::string(hex));
    return out;
}

// ASCII text -> its bytes ("5000" -> 35 30 30 30).
inline Bytes text(std::string_view s) { return Bytes(s.begin(), s.end()); }

// Bytes -> "D0 00 00 FF" (upper case, one space between bytes).
inline std::string hex(std::span<const std::uint8_t> data) {
    static constexpr char kDigits[] = "0123456789ABCDEF";
    std::string out;
    for (auto b : data) {
        if (!out.empty()) out += ' ';
        out += kDigits[b >> 4];
        out += kDigits[b & 0xF];
    }
    return out;
}

// Bytes -> the characters they are.
inline std::string str(std::span<const std::uint8_t> data) { return std::string(data.begin(), data.end()); }

// Upper-case hex of `value`, `digits` wide.
inline std::string hexn(std::uint32_t value, unsigned digits) {
    static constexpr char kDigits[] = "0123456789ABCDEF";
    std::string out(digits, '0');
    for (unsigned i = digits; i-- > 0; value >>= 4) out[i] = kDigits[value & 0xF];
    return out;
}

// Little-endian hex bytes of `value` ("0401", 2 bytes -> "01 04").
inline std::string le(std::uint32_t value, unsigned n) {
    std::string out;
    for (unsigned i = 0; i < n; ++i, value >>= 8) out += (i ? " " : "") + hexn(value & 0xFF, 2);
    return out;
}

// ---------------------------------------------------------------------------
// CPUs and the engine

inline devicemodel::Cpu make_cpu(const std::string& profile = "R08CPU") {
    return devicemodel::Cpu(config::load_profile(profile).cpu);
}

// The SLMP port of a CPU built from a built-in profile (loaded once per
// profile: a profile file holds both halves, the Cpu keeps only its own).
inline const protocol::PortProfile& port_of(const devicemodel::Cpu& cpu) {
    static std::map<std::string, protocol::PortProfile> ports;
    auto it = ports.find(cpu.profile().name);
    if (it == ports.end()) it = ports.emplace(cpu.profile().name, config::load_profile(cpu.profile().name).port).first;
    return it->second;
}

// An engine in front of `cpu`, with its profile's port.
inline protocol::Engine engine_for(devicemodel::Cpu& cpu, protocol::EngineOptions options = {}) {
    return protocol::Engine(cpu, port_of(cpu), options);
}

inline Outcome run(devicemodel::Cpu& cpu, std::span<const std::uint8_t> request,
                   DataCodePolicy policy = DataCodePolicy::Auto, protocol::EngineOptions options = {}) {
    protocol::Session session;
    return engine_for(cpu, options).process(request, policy, session);
}

inline std::string to_string(Outcome::Action action) {
    switch (action) {
        case Outcome::Action::NeedMore: return "NeedMore";
        case Outcome::Action::Respond: return "Respond";
        case Outcome::Action::Silent: return "Silent";
        case Outcome::Action::Close: return "Close";
        case Outcome::Action::Restart: return "Restart";
    }
    return "?";
}

// Every stored value of every device (including the R/ZR slack), to prove that
// a rejected request changed nothing.
inline std::vector<std::uint32_t> snapshot(const devicemodel::Cpu& cpu) {
    std::vector<std::uint32_t> all;
    const auto& memory = cpu.memory();
    for (const auto& spec : devicemodel::all_devices()) {
        auto n = memory.size(spec.area);
        if (spec.area == devicemodel::Area::R || spec.area == devicemodel::Area::ZR)
            n = std::max(memory.size(devicemodel::Area::R), memory.size(devicemodel::Area::ZR)) + 1024;
        for (std::uint32_t i = 0; i < n; ++i) all.push_back(memory.value(spec, i));
    }
    return all;
}

// ---------------------------------------------------------------------------
// Payloads: the same request or response data in both codecs.
//   binary: hex bytes ("01 04 00 00 ..."), ascii: the characters ("04010000...").
// A request payload starts at the command; a response payload at the end code.

struct Payload {
    std::string binary;
    std::string ascii;
};

inline Payload operator+(const Payload& a, const Payload& b) {
    return {a.binary + (a.binary.empty() || b.binary.empty() ? "" : " ") + b.binary, a.ascii + b.ascii};
}

// A 16-bit field: "01 04" / "0401".
inline Payload word(std::uint16_t v) { return {le(v, 2), hexn(v, 4)}; }

// End code 0000 followed by `data`.
inline Payload ok(const Payload& data = {}) { return word(0x0000) + data; }

// Word values: 2 bytes LE / 4 hex digits each.
inline Payload words(std::initializer_list<std::uint16_t> values) {
    Payload p;
    for (auto v : values) p = p + word(v);
    return p;
}
inline Payload words(const std::vector<std::uint16_t>& values) {
    Payload p;
    for (auto v : values) p = p + word(v);
    return p;
}

// Bit values: one nibble each, first point high (binary) / '0','1' (ASCII).
inline Payload bits(const std::vector<int>& points) {
    Payload p;
    for (std::size_t i = 0; i < points.size(); i += 2) {
        int byte = (points[i] ? 0x10 : 0) | (i + 1 < points.size() && points[i + 1] ? 0x01 : 0);
        p.binary += (i ? " " : "") + hexn(static_cast<std::uint32_t>(byte), 2);
    }
    for (auto v : points) p.ascii += v ? '1' : '0';
    return p;
}

// Error information after an end code: route of the answering station, then
// the request's command and subcommand (SLMP Reference Manual ch. 4, real-CPU measurements).
inline Payload error(std::uint16_t end_code, std::uint16_t command, std::uint16_t subcommand, Route route = {}) {
    return word(end_code) + Payload{le(route.network, 1), hexn(route.network, 2)} +
           Payload{le(route.station, 1), hexn(route.station, 2)} + word(route.module_io) +
           Payload{le(route.multidrop, 1), hexn(route.multidrop, 2)} + word(command) + word(subcommand);
}

// A device in the Q form (subcommands 0000/0001) or the iQ-R form (0002/0003).
enum class Form { Q, IQR };

// The device field of a request: binary number then code; ASCII code then
// number in the device's radix (X/Y: that of the NumberingScope in effect).
// `zr_hex` numbers ZR in hex in ASCII.
inline Payload device(Form form, std::string_view address, bool zr_hex = false) {
    std::string error;
    auto parsed = devicemodel::parse_address(address, &error);
    if (!parsed) throw std::invalid_argument(error);
    const auto& spec = *parsed->spec;
    const bool q = form == Form::Q;
    if (q && spec.q_code < 0) throw std::invalid_argument("no Q-form code for " + std::string(address));
    Payload p;
    p.binary = le(parsed->number, q ? 3 : 4) + " " +
               le(q ? static_cast<std::uint32_t>(spec.q_code) : spec.iqr_code, q ? 1 : 2);
    std::string code(q ? spec.ascii_q : spec.symbol);
    code.resize(q ? 2 : 4, '*');
    unsigned radix = spec.symbol == "ZR" && zr_hex
                         ? 16
                         : static_cast<unsigned>(devicemodel::radix_of(spec, devicemodel::NumberingScope::current()));
    std::string digits(q ? 6 : 8, '0');
    auto n = parsed->number;
    for (std::size_t i = digits.size(); i-- > 0 && n != 0; n /= radix) digits[i] = "0123456789ABCDEF"[n % radix];
    p.ascii = code + digits;
    return p;
}

inline std::uint16_t subcommand(Form form, bool bit_units) {
    return static_cast<std::uint16_t>((form == Form::IQR ? 2 : 0) + (bit_units ? 1 : 0));
}

// 0401 requests (from the command on).
inline Payload read_words_req(Form form, std::string_view address, std::uint16_t points, bool zr_hex = false) {
    return word(0x0401) + word(subcommand(form, false)) + device(form, address, zr_hex) + word(points);
}
inline Payload read_bits_req(Form form, std::string_view address, std::uint16_t points) {
    return word(0x0401) + word(subcommand(form, true)) + device(form, address) + word(points);
}
// 1401 requests.
inline Payload write_words_req(Form form, std::string_view address, const std::vector<std::uint16_t>& values) {
    return word(0x1401) + word(subcommand(form, false)) + device(form, address) +
           word(static_cast<std::uint16_t>(values.size())) + words(values);
}
inline Payload write_bits_req(Form form, std::string_view address, const std::vector<int>& values) {
    return word(0x1401) + word(subcommand(form, true)) + device(form, address) +
           word(static_cast<std::uint16_t>(values.size())) + bits(values);
}

// ---------------------------------------------------------------------------
// Wires: the four frame shapes a payload can travel in.

struct Wire {
    FrameKind kind = FrameKind::E3;
    Codec codec = Codec::Binary;
    std::uint16_t serial = 0x1234;   // 4E only
    std::uint16_t timer = 0x0010;

    bool ascii() const { return codec == Codec::Ascii; }
    std::string name() const {
        return std::string(kind == FrameKind::E3 ? "3E " : "4E ") + (ascii() ? "ASCII" : "binary");
    }

    // Header up to and including the length field, for a body of `body` bytes.
    Bytes header(bool response, std::size_t body, Route route = {}) const {
        std::string h;
        if (ascii()) {
            h = response ? "D" : "5";
            h += kind == FrameKind::E3 ? "000" : "400" + hexn(serial, 4) + "0000";
            h += hexn(route.network, 2) + hexn(route.station, 2) + hexn(route.module_io, 4) +
                 hexn(route.multidrop, 2) + hexn(static_cast<std::uint32_t>(body), 4);
            return text(h);
        }
        h = std::string(response ? "D" : "5") + (kind == FrameKind::E3 ? "0 00" : "4 00 " + le(serial, 2) + " 00 00");
        h += " " + le(route.network, 1) + " " + le(route.station, 1) + " " + le(route.module_io, 2) + " " +
             le(route.multidrop, 1) + " " + le(static_cast<std::uint32_t>(body), 2);
        return bytes(h);
    }

    Bytes data(const Payload& p) const { return ascii() ? text(p.ascii) : bytes(p.binary); }

    // A whole request frame: header, monitoring timer, then the payload.
    Bytes request(const Payload& p, Route route = {}) const {
        auto body = data(word(timer) + p);
        auto frame = header(false, body.size(), route);
        frame.insert(frame.end(), body.begin(), body.end());
        return frame;
    }
    // A whole response frame around a response payload (end code onward).
    Bytes response(const Payload& p, Route route = {}) const {
        auto body = data(p);
        auto frame = header(true, body.size(), route);
        frame.insert(frame.end(), body.begin(), body.end());
        return frame;
    }

    // Frames as readable text: hex bytes for binary, the characters for ASCII.
    std::string show(std::span<const std::uint8_t> frame) const { return ascii() ? str(frame) : hex(frame); }
    std::string show(const Outcome& out) const {
        if (out.action != Outcome::Action::Respond) return "<" + to_string(out.action) + ": " + out.note + ">";
        return show(out.response);
    }

    // Sends a request payload through the engine and shows the answer.
    std::string exchange(devicemodel::Cpu& cpu, const Payload& p, Route route = {}) const {
        return show(run(cpu, request(p, route)));
    }
    // The expected answer, shown the same way.
    std::string expect(const Payload& p, Route route = {}) const { return show(response(p, route)); }
};

inline std::ostream& operator<<(std::ostream& os, const Wire& wire) { return os << wire.name(); }

inline const Wire kBinary3E{FrameKind::E3, Codec::Binary};
inline const Wire kBinary4E{FrameKind::E4, Codec::Binary};
inline const Wire kAscii3E{FrameKind::E3, Codec::Ascii};
inline const Wire kAscii4E{FrameKind::E4, Codec::Ascii};

}  // namespace slmp::test

namespace Catch {
template <>
struct StringMaker<slmp::test::Wire> {
    static std::string convert(const slmp::test::Wire& wire) { return wire.name(); }
};
}  // namespace Catch
