// The one device table: every MELSEC device a client can name, with its codes
// for both subcommand families, its ASCII names, its unit and its numbering.
// Source: SLMP Reference Manual §5.2 (CN §5.2, JP cross-check).
//
// This file knows nothing about frames: the codes are plain numbers and the
// names plain text, so the SLMP codec, the config parser, the CLI and the
// scenario language all share it.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace slmp::devicemodel {

// Storage areas. Several device symbols can share one area: TS/TC/TN are the
// contact, coil and current value of the same timers; R is a window onto ZR;
// DX/DY reach X/Y directly.
enum class Area : std::uint8_t {
    X, Y, M, L, F, V, B, SB, S, SM,           // bit areas
    D, W, SW, SD, R, ZR, RD, Z,               // word areas
    LZ,                                       // double-word area
    T, ST, C, LT, LST, LC,                    // timers and counters
    G, HG,                                    // buffer memory (module, CPU buffer, its fixed-cycle area)
    Count
};

// Which part of a timer/counter a symbol names; Plain for everything else.
enum class Part : std::uint8_t { Plain, Contact, Coil, Value };

enum class Unit : std::uint8_t { Bit, Word, DoubleWord };
enum class Radix : std::uint8_t { Oct = 8, Dec = 10, Hex = 16 };

struct DeviceSpec {
    std::string_view symbol;     // "D", "TN", "LTN", "ZR"
    std::uint16_t iqr_code;      // binary code, iQ-R form (0002/0003)
    std::int16_t q_code;         // binary code, Q/L form (0000/0001); -1: iQ-R form only
    std::string_view ascii_q;    // 2-character ASCII name, Q/L form ("" when iQ-R only)
    Area area;
    Part part;
    Unit unit;
    Radix radix;                 // numbering in address text and in ASCII frames (X/Y: see Numbering)
    std::string_view name;       // English name, for messages and docs
    // G and HG exist only behind an extension (module access U1 G10, CPU buffer
    // U3E0 G10 / HG10; subcommands 008x): named as plain devices they answer C05B
    // (real-CPU measurements).
    bool extension_only = false;
};

// The table itself, in the manual's order.
std::span<const DeviceSpec> all_devices();

const DeviceSpec* find_by_symbol(std::string_view symbol);   // case-insensitive
const DeviceSpec* find_by_iqr_code(std::uint16_t code);
const DeviceSpec* find_by_q_code(std::uint8_t code);
// ASCII device names as sent on the wire: "D*", "TN", "D***", "LTN*", "SM**";
// '*' and ' ' padding are both accepted. `width` is 2 (Q form) or 4 (iQ-R form).
const DeviceSpec* find_by_ascii(std::string_view text, std::size_t width);
// The ASCII name padded with '*' to `width` characters (2 or 4).
std::string ascii_name(const DeviceSpec& spec, std::size_t width);

// The storage symbol of an area ("T" for TS/TC/TN), used in sizes and messages.
std::string_view area_name(Area area);
std::optional<Area> area_by_name(std::string_view name);  // "D", "T", "LT" ...
// How many 16-bit words one device of this unit occupies on the wire when read
// by word-unit commands (LTN/LSTN: 4 — value, value high, status, system).
unsigned words_per_device(const DeviceSpec& spec);

// How a CPU numbers X and Y (and DX/DY, which reach them): hexadecimal on
// iQ-R, Q and L, octal on iQ-F (FX5: X0-X7, X10 ...; the profile's
// "xy_radix"). Every other device's radix is fixed by the table. The number a
// DeviceAddress holds is the bit index either way: FX5 X10 is number 8, which
// is also what a binary frame carries.
struct Numbering {
    Radix xy = Radix::Hex;
    friend bool operator==(const Numbering&, const Numbering&) = default;
};
// Address text in a station's files (configuration, scenarios) follows that
// station's CPU. Their loaders hold a NumberingScope for one load, so the many
// small parsers under them need not pass the numbering along: parse_address
// and format_address without a Numbering use the innermost scope of this
// thread (hexadecimal when there is none).
class NumberingScope {
public:
    explicit NumberingScope(Numbering numbering);
    ~NumberingScope();
    NumberingScope(const NumberingScope&) = delete;
    NumberingScope& operator=(const NumberingScope&) = delete;
    static Numbering current();

private:
    Numbering previous_;
};

// The radix a device is written in under `numbering`.
Radix radix_of(const DeviceSpec& spec, Numbering numbering = {});
std::string_view radix_name(Radix radix);   // "octal", "decimal", "hexadecimal"

// A device address such as D100, X1F, ZR1000, TN5, LTN0, SM400.
struct DeviceAddress {
    const DeviceSpec* spec = nullptr;
    std::uint32_t number = 0;
};

// Parses address text through the table. Returns nullopt and fills `error`
// (when given) with a message that names the problem.
// Without a Numbering: NumberingScope::current().
std::optional<DeviceAddress> parse_address(std::string_view text, std::string* error = nullptr);
std::optional<DeviceAddress> parse_address(std::string_view text, Numbering numbering, std::string* error = nullptr);
std::string format_address(const DeviceAddress& address);
std::string format_address(const DeviceAddress& address, Numbering numbering);

}  // namespace slmp::devicemodel
