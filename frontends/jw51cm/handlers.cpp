// The JW-51CM commands (JW-51CM manual, docs/jw51cm.md). Every field and range is
// checked before the first write: a refused request changes nothing.
#include <chrono>

#include "frontends/jw51cm/command_table.hpp"

namespace slmp::jw51cm {

namespace {

namespace chr = std::chrono;

std::uint32_t u16(std::span<const std::uint8_t> text, std::size_t at) {
    return text[at] | static_cast<std::uint32_t>(text[at + 1]) << 8;
}

void echo(Context& c, std::size_t bytes) { c.out.insert(c.out.end(), c.text.begin(), c.text.begin() + static_cast<std::ptrdiff_t>(bytes)); }

// DSEG, DADR and L of the byte commands (24/34/35): file 0–7, 1–1024 bytes inside the file.
struct ByteRange {
    std::uint8_t file;
    std::uint32_t address, length;
};
std::optional<ByteRange> byte_range(const Context& c) {
    ByteRange r{c.text[0], u16(c.text, 1), u16(c.text, 3)};
    if (r.file > 7 || r.length == 0 || r.length > kMaxData || !c.link.map().contains(r.file, r.address, r.length))
        return std::nullopt;
    return r;
}

// A relay: DSEG, DADR, BLOC (bit 0–7).
struct Relay {
    std::uint8_t file;
    std::uint32_t address;
    unsigned bit;
};
std::optional<Relay> relay(const Context& c) {
    Relay r{c.text[0], u16(c.text, 1), c.text[3]};
    if (r.file > 7 || r.bit > 7 || !c.link.map().contains(r.file, r.address, 1)) return std::nullopt;
    return r;
}

ByteAccess bytes(Context& c) { return ByteAccess(c.link.cpu().memory(), c.link.map()); }

// System memory (SEG 08) and program (PSEG 08/09) ranges.
std::optional<std::size_t> system_range(const Context& c) {
    auto address = u16(c.text, 1), length = u16(c.text, 3);
    if (c.text[0] != 0x08 || length == 0 || length > kMaxData || address + length > c.link.system_memory.size())
        return std::nullopt;
    return address;
}
std::optional<std::size_t> program_range(const Context& c) {
    auto steps = c.link.options().program_steps;
    auto address = u16(c.text, 1), length = u16(c.text, 3);
    // §7.2: at most 512 words per command.
    if ((c.text[0] != 0x08 && c.text[0] != 0x09) || length == 0 || length > 512 || address + length > steps)
        return std::nullopt;
    return 2 * ((c.text[0] - 0x08u) * steps + address);
}

// The PLC calendar: the host's UTC clock plus the offset B2/B3 set (inferred:
// the unit's own clock; SLMP's SD registers do not follow it).
chr::sys_seconds plc_now(const ComputerLink& link) {
    auto base = link.clock_stopped.value_or(link.now());
    return chr::floor<chr::seconds>(base) + link.clock_offset;
}

std::uint8_t bcd(unsigned value) { return static_cast<std::uint8_t>((value / 10) << 4 | (value % 10)); }
std::optional<unsigned> from_bcd(std::uint8_t b) {
    if ((b >> 4) > 9 || (b & 0xF) > 9) return std::nullopt;
    return (b >> 4) * 10u + (b & 0xFu);
}

void set_plc_time(ComputerLink& link, chr::sys_seconds wanted) {
    auto base = chr::floor<chr::seconds>(link.clock_stopped.value_or(link.now()));
    link.clock_offset = wanted - base;
}

}  // namespace

Rslt mode_read(Context& c) {
    c.out.push_back(c.link.write_mode_);
    return Rslt::Ok;
}

Rslt mode_set(Context& c) {
    if (c.text[0] > 2) return Rslt::Format;
    c.link.write_mode_ = c.text[0];
    c.out.push_back(c.text[0]);
    return Rslt::Ok;
}

Rslt relay_monitor(Context& c) {
    auto r = relay(c);
    if (!r) return Rslt::Format;
    echo(c, 4);
    c.out.push_back((bytes(c).byte(r->file, r->address) >> r->bit) & 1);
    return Rslt::Ok;
}

Rslt relay_set(Context& c) {
    auto r = relay(c);
    if (!r || c.text[4] > 1) return Rslt::Format;
    auto access = bytes(c);
    auto value = access.byte(r->file, r->address);
    auto mask = static_cast<std::uint8_t>(1u << r->bit);
    access.set_byte(r->file, r->address, static_cast<std::uint8_t>(c.text[4] ? value | mask : value & ~mask));
    echo(c, 4);
    return Rslt::Ok;
}

Rslt timer_monitor(Context& c) {
    auto first = u16(c.text, 0), count = u16(c.text, 2);
    const auto& map = c.link.map();
    if (count == 0 || count > 256 || first + count > map.timers()) return Rslt::Format;
    echo(c, 4);
    const auto& memory = c.link.cpu().memory();
    for (std::uint32_t i = 0; i < count; ++i) {
        auto value = memory.value(*map.timer_values().spec, first + i);   // raw, as stored (§7.2)
        c.out.push_back(static_cast<std::uint8_t>(value));
        c.out.push_back(static_cast<std::uint8_t>(value >> 8));
    }
    const auto& attributes = c.link.options().timer_attributes;
    for (std::uint32_t i = 0; i < count; ++i) {
        auto found = attributes.find(first + i);
        c.out.push_back(found == attributes.end() ? 0x00 : found->second);
    }
    return Rslt::Ok;
}

// §6.2 lists 32 as "stopped or running", error 13 says set/reset while stopped
// fails: 13 wins (inferred, the spec's reading).
Rslt timer_set(Context& c) {
    auto number = u16(c.text, 0);
    if (number >= c.link.map().timers() || c.text[2] > 1) return Rslt::Format;
    if (c.link.cpu().runtime().state() != devicemodel::RunState::Run) return Rslt::TimerWhileStopped;
    c.link.cpu().memory().set_bit(*c.link.map().timer_contacts().spec, number, c.text[2] == 1);
    echo(c, 2);
    return Rslt::Ok;
}

Rslt register_read(Context& c) {
    auto r = byte_range(c);
    if (!r) return Rslt::Format;
    echo(c, 5);
    auto access = bytes(c);
    for (std::uint32_t i = 0; i < r->length; ++i) c.out.push_back(access.byte(r->file, r->address + i));
    return Rslt::Ok;
}

Rslt register_write(Context& c) {
    auto r = byte_range(c);
    if (!r) return Rslt::Format;
    auto access = bytes(c);
    for (std::uint32_t i = 0; i < r->length; ++i) access.set_byte(r->file, r->address + i, c.text[5 + i]);
    echo(c, 5);
    return Rslt::Ok;
}

Rslt register_fill(Context& c) {
    auto r = byte_range(c);
    if (!r) return Rslt::Format;
    auto access = bytes(c);
    for (std::uint32_t i = 0; i < r->length; ++i) access.set_byte(r->file, r->address + i, c.text[5]);
    echo(c, 5);
    return Rslt::Ok;
}

Rslt system_read(Context& c) {
    auto at = system_range(c);
    if (!at) return Rslt::Format;
    echo(c, 5);
    auto length = u16(c.text, 3);
    c.out.insert(c.out.end(), c.link.system_memory.begin() + static_cast<std::ptrdiff_t>(*at),
                 c.link.system_memory.begin() + static_cast<std::ptrdiff_t>(*at + length));
    return Rslt::Ok;
}

Rslt system_write(Context& c) {
    auto at = system_range(c);
    if (!at) return Rslt::Format;
    auto length = u16(c.text, 3);
    std::copy(c.text.begin() + 5, c.text.begin() + 5 + length, c.link.system_memory.begin() + static_cast<std::ptrdiff_t>(*at));
    echo(c, 5);
    return Rslt::Ok;
}

Rslt program_read(Context& c) {
    auto at = program_range(c);
    if (!at) return Rslt::Format;
    echo(c, 5);
    auto length = 2u * u16(c.text, 3);
    c.out.insert(c.out.end(), c.link.program.begin() + static_cast<std::ptrdiff_t>(*at),
                 c.link.program.begin() + static_cast<std::ptrdiff_t>(*at + length));
    return Rslt::Ok;
}

Rslt program_write(Context& c) {
    auto at = program_range(c);
    if (!at) return Rslt::Format;
    auto length = 2u * u16(c.text, 3);
    std::copy(c.text.begin() + 5, c.text.begin() + 5 + length, c.link.program.begin() + static_cast<std::ptrdiff_t>(*at));
    echo(c, 5);
    return Rslt::Ok;
}

Rslt date_read(Context& c) {
    auto now = plc_now(c.link);
    chr::year_month_day date{chr::floor<chr::days>(now)};
    chr::weekday weekday{chr::floor<chr::days>(now)};
    c.out.push_back(bcd(static_cast<unsigned>(static_cast<int>(date.year()) % 100)));
    c.out.push_back(bcd(static_cast<unsigned>(date.month())));
    c.out.push_back(bcd(static_cast<unsigned>(date.day())));
    c.out.push_back(static_cast<std::uint8_t>(weekday.c_encoding()));   // 00 Sunday … 06 Saturday
    return Rslt::Ok;
}

Rslt time_read(Context& c) {
    auto now = plc_now(c.link);
    chr::hh_mm_ss time{now - chr::floor<chr::days>(now)};
    c.out.push_back(bcd(static_cast<unsigned>(time.hours().count())));
    c.out.push_back(bcd(static_cast<unsigned>(time.minutes().count())));
    c.out.push_back(bcd(static_cast<unsigned>(time.seconds().count())));
    return Rslt::Ok;
}

// B2: the weekday follows the date (inferred: DW is checked, 0–6, then computed).
Rslt date_set(Context& c) {
    auto y = from_bcd(c.text[0]), m = from_bcd(c.text[1]), d = from_bcd(c.text[2]);
    if (!y || !m || !d || c.text[3] > 6) return Rslt::Format;
    // Two-digit years: 70–99 are 1970–1999, 00–69 are 2000–2069 (inferred).
    chr::year_month_day date{chr::year(static_cast<int>(*y >= 70 ? 1900 + *y : 2000 + *y)), chr::month(*m), chr::day(*d)};
    if (!date.ok()) return Rslt::Format;
    auto now = plc_now(c.link);
    auto time_of_day = now - chr::floor<chr::days>(now);
    set_plc_time(c.link, chr::sys_days(date) + time_of_day);
    return Rslt::Ok;
}

// B3: CTRL 00 the clock runs, 01 it stands, 08 30-second adjust.
Rslt time_set(Context& c) {
    auto h = from_bcd(c.text[0]), m = from_bcd(c.text[1]), s = from_bcd(c.text[2]);
    auto control = c.text[3];
    if (!h || !m || !s || *h > 23 || *m > 59 || *s > 59 || (control != 0x00 && control != 0x01 && control != 0x08))
        return Rslt::Format;
    auto now = plc_now(c.link);
    auto today = chr::floor<chr::days>(now);
    chr::sys_seconds wanted = today + chr::hours(*h) + chr::minutes(*m) + chr::seconds(*s);
    if (control == 0x08) {   // to the nearest minute of the running clock, as a 30-second adjust does
        auto seconds = (now - chr::floor<chr::minutes>(now)).count();
        wanted = chr::floor<chr::minutes>(now) + chr::minutes(seconds >= 30 ? 1 : 0);
    }
    if (control == 0x01 && !c.link.clock_stopped) c.link.clock_stopped = c.link.now();
    if (control == 0x00) c.link.clock_stopped.reset();
    set_plc_time(c.link, wanted);
    return Rslt::Ok;
}

// E8: 00 running, 01 stopped by another unit (the key switch, SLMP, a scenario), 02 stopped by this unit.
Rslt run_monitor(Context& c) {
    const auto& runtime = c.link.cpu().runtime();
    std::uint8_t mode = 0x00;
    if (runtime.state() != devicemodel::RunState::Run) {
        const auto& hold = runtime.operating_state().hold();
        bool ours = hold.kind != devicemodel::OperatingState::Hold::Kind::None && hold.owner == kUnitClient &&
                    runtime.operating_state().cause() == devicemodel::StopCause::Remote;
        mode = ours ? 0x02 : 0x01;
    }
    c.out.push_back(mode);
    return Rslt::Ok;
}

// F8 01 holds a remote STOP in the station's operating state with this unit as
// its owner; F8 00 releases only this unit's hold (inferred, §7.2).
Rslt run_stop(Context& c) {
    auto mode = c.text[0];
    if (mode > 1) return Rslt::Format;
    auto& cpu = c.link.cpu();
    if (mode == 1) {
        cpu.runtime().remote_stop(cpu.memory(), kUnitClient);
    } else {
        const auto& hold = cpu.runtime().operating_state().hold();
        if (hold.kind != devicemodel::OperatingState::Hold::Kind::None && hold.owner == kUnitClient)
            cpu.runtime().remote_run(cpu.memory(), kUnitClient, false, devicemodel::ClearMode::None);
    }
    c.out.push_back(mode);
    return Rslt::Ok;
}

}  // namespace slmp::jw51cm
