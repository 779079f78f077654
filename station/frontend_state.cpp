#include "station/frontend_state.hpp"

#include <cstring>

#include "config/config_error.hpp"
#include "devicemodel/byte_reader.hpp"
#include "frontends/hostlink/host_link.hpp"
#include "frontends/jw51cm/computer_link.hpp"

namespace slmp::station {

namespace {

constexpr char kMagic[8] = {'S', 'L', 'M', 'P', 'U', 'N', 'T', '1'};

// The JW clock: the offset in seconds, then 1 and the stop instant (s since
// the epoch) when B3 CTRL 01 stopped it, else 0 and 0. 17 bytes.
std::vector<std::uint8_t> jw_clock(const jw51cm::ComputerLink& link) {
    devicemodel::ByteWriter w;
    w.u64(static_cast<std::uint64_t>(link.clock_offset.count()));
    w.u8(link.clock_stopped ? 1 : 0);
    auto stopped = link.clock_stopped ? std::chrono::duration_cast<std::chrono::seconds>(link.clock_stopped->time_since_epoch()).count() : 0;
    w.u64(static_cast<std::uint64_t>(stopped));
    return std::move(w.out);
}

[[noreturn]] void refuse(const std::string& part, std::size_t got, std::size_t want) {
    throw config::ConfigError("the snapshot's '" + part + "' holds " + std::to_string(got) + " bytes and this station's " +
                              std::to_string(want) + "; restore it with the configuration it was taken with");
}

}  // namespace

UnitParts take_units(const Station::FrontEnds& f) {
    UnitParts parts;
    if (f.hostlink) {
        parts["hostlink environment"] = f.hostlink->environment();
        parts["hostlink object"] = f.hostlink->object();
    }
    if (f.jw51cm) {
        parts["jw51cm write mode"] = {f.jw51cm->write_mode_};
        parts["jw51cm system memory"] = f.jw51cm->system_memory;
        parts["jw51cm program"] = f.jw51cm->program;
        parts["jw51cm clock"] = jw_clock(*f.jw51cm);
    }
    return parts;
}

void give_units(const UnitParts& parts, Station::FrontEnds& f) {
    // Every size first: a refused part changes nothing.
    auto check = [&](const std::string& name, std::size_t want) -> const std::vector<std::uint8_t>* {
        auto it = parts.find(name);
        if (it == parts.end()) return nullptr;   // taken without that front end: it keeps its state
        if (it->second.size() != want) refuse(name, it->second.size(), want);
        return &it->second;
    };
    const std::vector<std::uint8_t>*environment = nullptr, *object = nullptr, *mode = nullptr, *system = nullptr,
    *program = nullptr, *clock = nullptr;
    if (f.hostlink) {
        environment = check("hostlink environment", f.hostlink->environment().size());
        object = check("hostlink object", f.hostlink->object().size());
    }
    if (f.jw51cm) {
        mode = check("jw51cm write mode", 1);
        system = check("jw51cm system memory", f.jw51cm->system_memory.size());
        program = check("jw51cm program", f.jw51cm->program.size());
        clock = check("jw51cm clock", 17);
        if (mode && (*mode)[0] > 2) throw config::ConfigError("the snapshot's 'jw51cm write mode' is not 0, 1 or 2");
    }
    if (environment) f.hostlink->environment() = *environment;
    if (object) f.hostlink->object() = *object;
    if (mode) f.jw51cm->write_mode_ = (*mode)[0];
    if (system) f.jw51cm->system_memory = *system;
    if (program) f.jw51cm->program = *program;
    if (clock) {   // 17 bytes, checked above
        devicemodel::ByteReader r(*clock);
        f.jw51cm->clock_offset = std::chrono::seconds(static_cast<std::int64_t>(*r.u64()));
        auto stopped = *r.u8();
        auto at = static_cast<std::int64_t>(*r.u64());
        if (stopped)
            f.jw51cm->clock_stopped = std::chrono::system_clock::time_point(std::chrono::seconds(at));
        else
            f.jw51cm->clock_stopped.reset();
    }
}

std::vector<std::uint8_t> encode_units(const UnitParts& parts) {
    devicemodel::ByteWriter w;
    w.out.assign(std::begin(kMagic), std::end(kMagic));
    w.u32(static_cast<std::uint32_t>(parts.size()));
    for (const auto& [name, bytes] : parts) {
        w.name(name);
        w.u32(static_cast<std::uint32_t>(bytes.size()));
        w.bytes(bytes);
    }
    return std::move(w.out);
}

UnitParts decode_units(std::span<const std::uint8_t> bytes, const std::string& source) {
    auto fail = [&](const std::string& why) {
        return config::ConfigError(source + ": " + why + "; move the file away to start the front ends afresh");
    };
    devicemodel::ByteReader r(bytes);
    auto need = [&](auto value) {
        if (!value) throw fail("truncated front-end state");
        return *value;
    };
    auto magic = need(r.bytes(sizeof kMagic));
    if (std::memcmp(magic.data(), kMagic, sizeof kMagic) != 0) throw fail("not a slmp-sim front-end state file (bad magic)");
    UnitParts parts;
    for (auto count = need(r.u32()); count > 0; --count) {
        auto name = need(r.name());
        auto part = need(r.bytes(need(r.u32())));
        parts[name].assign(part.begin(), part.end());
    }
    if (!r.done()) throw fail("unexpected bytes after the last part");
    return parts;
}

}  // namespace slmp::station
