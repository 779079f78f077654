// The host-link command table: every fact about each command in one row
// (Ladder Motion host-link manual, docs/hostlink.md). Nothing else names a command code:
// host_link.cpp looks the row up and calls its handler.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "frontends/hostlink/host_link.hpp"

namespace slmp::hostlink {

// What a handler sees: the command, its text (between the command and the
// FCS), the station's memory through the map, and the connection's state.
struct Context {
    HostLink& link;
    LinkState& state;
    AreaAccess memory;
    std::string_view command;
    std::string_view text;
};

// A handler's answer.
struct Answer {
    enum class Kind { Normal, Echo, Silent, Unknown };
    Kind kind = Kind::Normal;
    std::string code = "00";   // Normal: the response code; data only with 00
    std::string data;
    static Answer ok(std::string data = {}) { return {Kind::Normal, "00", std::move(data)}; }
    static Answer error(std::string code = "01") { return {Kind::Normal, std::move(code), {}}; }
};

using Handler = Answer (*)(const struct CommandRow& row, Context& context);

enum class Compat : std::uint8_t { Omron, New, Incompatible, Refused };   // §5's ○ / N / I / ×

struct CommandRow {
    std::string_view code;       // two characters, case-sensitive ("Rr" is not "RR")
    std::string_view function;   // the manual's name, for docs and logs
    Handler handler;
    Area area = Area::Count;     // the area a read/write command serves (Count: none)
    Compat compat = Compat::Omron;
    bool writes = false;
};

std::span<const CommandRow> command_table();
// The row for a command code (RI/WI are the list's spellings of Rl/Wl, §8).
const CommandRow* find_command(std::string_view code);

// Handlers (handlers_*.cpp).
Answer read_words(const CommandRow&, Context&);
Answer write_words(const CommandRow&, Context&);
Answer read_bits(const CommandRow&, Context&);
Answer write_bits(const CommandRow&, Context&);
Answer read_flags(const CommandRow&, Context&);
Answer write_flags(const CommandRow&, Context&);
Answer model_code(const CommandRow&, Context&);
Answer test_echo(const CommandRow&, Context&);
Answer system_info(const CommandRow&, Context&);
Answer composite(const CommandRow&, Context&);
Answer refused(const CommandRow&, Context&);
Answer silent(const CommandRow&, Context&);
Answer initialise(const CommandRow&, Context&);
Answer read_image(const CommandRow&, Context&);
Answer write_image(const CommandRow&, Context&);

// Fields: decimal and hex digits of a fixed width (nullopt when any is not one).
std::optional<std::uint32_t> decimal(std::string_view text);
std::optional<std::uint32_t> hex(std::string_view text);

}  // namespace slmp::hostlink
