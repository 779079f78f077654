// Test-side encoders for the device commands beyond 0401/1401 — Read/Write
// Random 0403/1402, Entry Monitor 0801/0802, Read/Write Block 0406/1406,
// Memory 0613/1613, Extend Unit 0601/1601 — and for the extended device
// specification of Appendix 1 (subcommands 008x). Like fixtures.hpp they are
// written from the manual's layouts (SLMP Reference Manual §5.2, Appendix 1;
// SLMP Reference Manual §5.4–§5.5), independently of protocol/, so a codec bug
// cannot hide by being symmetric.
//
// Also a Connection: one Session kept across requests (Entry Monitor 0801
// registers per connection), and an engine that may hold CPU No.2–4.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "support/fixtures.hpp"

namespace slmp::test {

// One byte: "01" / "01"; four bytes: "4E 4F 54 4C" / "4C544F4E".
inline Payload byte(std::uint8_t v) {
    return {le(v, 1), hexn(v, 2)};
}
inline Payload dword(std::uint32_t v) {
    return {le(v, 4), hexn(v, 8)};
}

inline Payload join(const std::vector<Payload>& parts) {
    Payload p;
    for (const auto& part : parts) p = p + part;
    return p;
}

// Subcommand of a device command: 0000/0002 (+1 bit units, +0x80 extended).
inline std::uint16_t device_sub(Form form, bool extended, bool bit_units = false) {
    return static_cast<std::uint16_t>(subcommand(form, bit_units) | (extended ? 0x80 : 0));
}

// ---------------------------------------------------------------------------
// The extended device specification (Appendix 1, §7.1)

// An index register as the extended forms write it: none, "Z4", "LZ1".
struct IndexReg {
    enum Kind { None, Z, LZ } kind = None;
    std::uint8_t number = 0;
};
inline IndexReg z(std::uint8_t n) {
    return {IndexReg::Z, n};
}
inline IndexReg lz(std::uint8_t n) {
    return {IndexReg::LZ, n};
}

struct Extension {
    enum Kind { None, J, U, U3E } kind = None;
    std::uint16_t target = 0;  // network No., start I/O ÷ 16, or 03E0–03E3
    IndexReg target_index;     // J1Z0\..., §7.5
    IndexReg device_index;     // D100Z4, §7.6
    bool indirect = false;     // @D0, §7.7
    std::string at = "@0";     // ASCII position of '@' in the 2-character field (unresolved: "@0" or "0@")
};
inline Extension extension(Extension::Kind kind, std::uint16_t target) {
    Extension e;
    e.kind = kind;
    e.target = target;
    return e;
}
inline Extension link_direct(std::uint16_t network) {
    return extension(Extension::J, network);
}
inline Extension module_access(std::uint16_t io_div_16) {
    return extension(Extension::U, io_div_16);
}
inline Extension cpu_buffer(std::uint16_t cpu_io = 0x3E0) {
    return extension(Extension::U3E, cpu_io);
}

namespace detail {
inline std::string ascii_index(const IndexReg& r, Form form) {
    const bool q = form == Form::Q;
    std::string digits{static_cast<char>('0' + r.number / 10), static_cast<char>('0' + r.number % 10)};
    switch (r.kind) {
        case IndexReg::None:
            return q ? "000" : "0000";
        case IndexReg::Z:
            return (q ? "Z" : "Z ") + digits;
        case IndexReg::LZ:
            return "LZ" + digits;
    }
    return "";
}
inline std::string binary_index(const IndexReg& r, bool indirect = false) {
    std::uint32_t flags = r.kind == IndexReg::Z ? 0x40 : r.kind == IndexReg::LZ ? 0x80 : 0x00;
    if (indirect) flags |= 0x08;
    return hexn(r.number, 2) + " " + hexn(flags, 2);
}
}  // namespace detail

// One device in the 008x layout: binary 11 (Q form) / 13 (iQ-R form) bytes,
// ASCII 20 / 28 characters (10-digit device number in the iQ-R form).
inline Payload ext_device(Form form, std::string_view address, const Extension& ext = {}) {
    std::string error;
    auto parsed = devicemodel::parse_address(address, &error);
    if (!parsed) throw std::invalid_argument(error);
    const auto& spec = *parsed->spec;
    const bool q = form == Form::Q;
    if (q && spec.q_code < 0) throw std::invalid_argument("no Q-form code for " + std::string(address));
    Payload p;
    std::uint8_t direct = ext.kind == Extension::J     ? 0xF9
                          : ext.kind == Extension::U   ? 0xF8
                          : ext.kind == Extension::U3E ? 0xFA
                                                       : 0x00;
    p.binary = detail::binary_index(ext.device_index, ext.indirect) + " " + le(parsed->number, q ? 3 : 4) + " " +
               le(q ? static_cast<std::uint32_t>(spec.q_code) : spec.iqr_code, q ? 1 : 2) + " " +
               detail::binary_index(ext.target_index) + " " + le(ext.target, 2) + " " + hexn(direct, 2);
    std::string code(q ? spec.ascii_q : spec.symbol);
    code.resize(q ? 2 : 4, '*');
    std::string digits(q ? 6 : 10, '0');
    auto n = parsed->number;
    auto radix = static_cast<unsigned>(devicemodel::radix_of(spec, devicemodel::NumberingScope::current()));
    for (std::size_t i = digits.size(); i-- > 0 && n != 0; n /= radix) digits[i] = "0123456789ABCDEF"[n % radix];
    std::string extension =
        ext.kind == Extension::None ? "0000" : (ext.kind == Extension::J ? "J" : "U") + hexn(ext.target, 3);
    p.ascii = (ext.indirect ? ext.at : "00") + extension + detail::ascii_index(ext.target_index, form) + code + digits +
              detail::ascii_index(ext.device_index, form);
    return p;
}

// A device field in the plain or the extended layout.
inline Payload field(Form form, bool extended, std::string_view address, const Extension& ext = {}) {
    return extended ? ext_device(form, address, ext) : device(form, address);
}

// ---------------------------------------------------------------------------
// Requests (from the command on)

// 0403 / 0801: counts, word-access devices, then double-word-access devices.
inline Payload random_read_req(std::uint16_t sub, const std::vector<Payload>& words, const std::vector<Payload>& dwords,
                               std::uint16_t command = 0x0403) {
    return word(command) + word(sub) + byte(static_cast<std::uint8_t>(words.size())) +
           byte(static_cast<std::uint8_t>(dwords.size())) + join(words) + join(dwords);
}
inline Payload monitor_entry_req(std::uint16_t sub, const std::vector<Payload>& words,
                                 const std::vector<Payload>& dwords) {
    return random_read_req(sub, words, dwords, 0x0801);
}
inline Payload monitor_execute_req() {
    return word(0x0802) + word(0x0000);
}

// 1402 word units: {device, 2-byte value} × words, {device, 4-byte value} × dwords.
inline Payload random_write_words_req(std::uint16_t sub, const std::vector<std::pair<Payload, std::uint16_t>>& words,
                                      const std::vector<std::pair<Payload, std::uint32_t>>& dwords) {
    Payload p = word(0x1402) + word(sub) + byte(static_cast<std::uint8_t>(words.size())) +
                byte(static_cast<std::uint8_t>(dwords.size()));
    for (const auto& [dev, v] : words) p = p + dev + word(v);
    for (const auto& [dev, v] : dwords) p = p + dev + dword(v);
    return p;
}
// 1402 bit units: set/reset is 1 byte ("01") in the Q form, 2 ("0001") in the iQ-R form (§6.4).
inline Payload random_write_bits_req(std::uint16_t sub, const std::vector<std::pair<Payload, bool>>& points) {
    const bool iqr = (sub & 0x0002) != 0;
    Payload p = word(0x1402) + word(sub) + byte(static_cast<std::uint8_t>(points.size()));
    for (const auto& [dev, on] : points) p = p + dev + (iqr ? word(on ? 1 : 0) : byte(on ? 1 : 0));
    return p;
}

// 0406: counts, then {device, points} for word blocks, then for bit blocks.
inline Payload block_read_req(std::uint16_t sub, const std::vector<std::pair<Payload, std::uint16_t>>& word_blocks,
                              const std::vector<std::pair<Payload, std::uint16_t>>& bit_blocks) {
    Payload p = word(0x0406) + word(sub) + byte(static_cast<std::uint8_t>(word_blocks.size())) +
                byte(static_cast<std::uint8_t>(bit_blocks.size()));
    for (const auto& [dev, n] : word_blocks) p = p + dev + word(n);
    for (const auto& [dev, n] : bit_blocks) p = p + dev + word(n);
    return p;
}
// 1406: as 0406 with each block's data after its point count.
using Block = std::pair<Payload, std::vector<std::uint16_t>>;
inline Payload block_write_req(std::uint16_t sub, const std::vector<Block>& word_blocks,
                               const std::vector<Block>& bit_blocks) {
    Payload p = word(0x1406) + word(sub) + byte(static_cast<std::uint8_t>(word_blocks.size())) +
                byte(static_cast<std::uint8_t>(bit_blocks.size()));
    for (const auto& [dev, data] : word_blocks)
        p = p + dev + word(static_cast<std::uint16_t>(data.size())) + words(data);
    for (const auto& [dev, data] : bit_blocks)
        p = p + dev + word(static_cast<std::uint16_t>(data.size())) + words(data);
    return p;
}

// 0613 / 1613: 4-byte start address, word length, data words.
inline Payload memory_read_req(std::uint32_t address, std::uint16_t count) {
    return word(0x0613) + word(0x0000) + dword(address) + word(count);
}
inline Payload memory_write_req(std::uint32_t address, const std::vector<std::uint16_t>& values) {
    return word(0x1613) + word(0x0000) + dword(address) + word(static_cast<std::uint16_t>(values.size())) +
           words(values);
}

// 0601 / 1601: start address, byte count, module No.; data bytes in memory
// order (ASCII: 2 characters a byte, low byte first).
inline Payload memory_bytes(const std::vector<std::uint8_t>& data) {
    Payload p;
    for (auto b : data) p = p + byte(b);
    return p;
}
inline Payload extend_unit_read_req(std::uint32_t address, std::uint16_t count, std::uint16_t module) {
    return word(0x0601) + word(0x0000) + dword(address) + word(count) + word(module);
}
inline Payload extend_unit_write_req(std::uint32_t address, std::uint16_t module,
                                     const std::vector<std::uint8_t>& data) {
    return word(0x1601) + word(0x0000) + dword(address) + word(static_cast<std::uint16_t>(data.size())) + word(module) +
           memory_bytes(data);
}

// ---------------------------------------------------------------------------
// A connection: one engine (CPU No.1, optionally No.2–4) and one Session.

struct Connection {
    protocol::Engine& engine;
    protocol::Session session{};

    Outcome send(const Wire& wire, const Payload& p, Route route = {}) {
        auto frame = wire.request(p, route);
        return engine.process(frame, DataCodePolicy::Auto, session);
    }
    std::string exchange(const Wire& wire, const Payload& p, Route route = {}) {
        return wire.show(send(wire, p, route));
    }
};

// Route to CPU No.n of a multi-CPU system (module I/O 03E0 + n - 1).
inline Route cpu_route(int number) {
    Route r;
    r.module_io = static_cast<std::uint16_t>(0x03E0 + number - 1);
    return r;
}

inline const devicemodel::DeviceSpec& spec_of(std::string_view symbol) {
    return *devicemodel::find_by_symbol(symbol);
}

// An R08CPU with networks 1 and 2 (`link_points` of each link device) and a
// Q62DA at start I/O 0030 (U3, 4096 words, Extend Unit head address 1008H).
inline devicemodel::Cpu make_station(std::uint32_t link_points = 8192) {
    auto cpu = make_cpu("R08CPU");
    devicemodel::DeviceSizes link{};
    for (auto area : {devicemodel::Area::X, devicemodel::Area::Y, devicemodel::Area::B, devicemodel::Area::SB,
                      devicemodel::Area::W, devicemodel::Area::SW})
        link[static_cast<std::size_t>(area)] = link_points;
    cpu.add_network(1, link);
    cpu.add_network(2, link);
    cpu.add_module(3, "Q62DA", 4096, 0x1008);
    return cpu;
}

// §6.3 Example RR's stored values (Example EM registers the same devices):
// D0 = 1995H, TN0 = 1202H, M115..M100 = 2030H, X2F..X20 = 4849H,
// D1501:D1500 = 4C544F4EH, Y17F..Y160 = C3DEB9AFH, M1142..M1111 = BADDBCB7H.
inline void load_example_rr(devicemodel::Cpu& cpu) {
    auto set = [&](const char* symbol, std::uint32_t number, std::vector<std::uint16_t> values) {
        cpu.memory().write_words(*devicemodel::find_by_symbol(symbol), number, values);
    };
    set("D", 0, {0x1995});
    set("TN", 0, {0x1202});
    set("M", 100, {0x2030});
    set("X", 0x20, {0x4849});
    set("D", 1500, {0x4F4E, 0x4C54});
    set("Y", 0x160, {0xB9AF, 0xC3DE});
    set("M", 1111, {0xBCB7, 0xBADD});
}
// Example RR's answer (JP's ASCII response; binary inferred from it), which is
// also Execute Monitor's after Example EM (inferred).
inline const Payload kExampleRRAnswer{"95 19 02 12 30 20 49 48 4E 4F 54 4C AF B9 DE C3 B7 BC DD BA",
                                      "19951202203048494C544F4EC3DEB9AFBADDBCB7"};

// Sends a request that must be refused with `code`, and checks that it changed nothing.
inline void check_refused(devicemodel::Cpu& cpu, const Wire& wire, const Payload& request, std::uint16_t code,
                          std::uint16_t command, std::uint16_t sub) {
    auto before = snapshot(cpu);
    CHECK(wire.exchange(cpu, request) == wire.expect(error(code, command, sub)));
    CHECK((snapshot(cpu) == before));
}

}  // namespace slmp::test
