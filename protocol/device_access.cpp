#include "protocol/device_access.hpp"

#include <algorithm>
#include <initializer_list>

namespace slmp::protocol {
namespace {

using devicemodel::Area;
using devicemodel::DeviceSpec;
using devicemodel::Part;
using devicemodel::Unit;
using Kind = DeviceExtension::Kind;

// End code when an extension names a module, network or CPU that is not there
// (chosen: real CPUs answer 4043 for Extend Unit module 0000 — hardware §2).
constexpr EndCode kNoSuchModule = EndCode::ModuleNotPresent;
// End code for a write to another CPU's buffer memory.
constexpr EndCode kOtherCpusBuffer = EndCode::ExtendedTargetRefused;

bool is_in(const DeviceSpec& spec, std::initializer_list<std::string_view> symbols) {
    return std::find(symbols.begin(), symbols.end(), spec.symbol) != symbols.end();
}

// Devices each command may not name (4030 on iQ-R).
bool forbidden(const DeviceSpec& spec, Use use) {
    switch (use) {
        case Use::BatchRead: return is_in(spec, {"LTS", "LTC", "LSTS", "LSTC"});
        case Use::BatchWrite: return is_in(spec, {"LTS", "LTC", "LTN", "LSTS", "LSTC", "LSTN"});
        case Use::RandomRead: return is_in(spec, {"LTS", "LTC", "LSTS", "LSTC", "LCS", "LCC"});
        case Use::RandomWrite: return false;
        case Use::Monitor:
            return is_in(spec, {"TS", "TC", "LTS", "LTC", "LTN", "STS", "STC", "LSTS", "LSTC", "LSTN", "CS", "CC",
                                "LCS", "LCC", "LCN"});
        case Use::BlockRead:
        case Use::BlockWrite:
            return is_in(spec, {"LTS", "LTC", "LTN", "LSTS", "LSTC", "LSTN", "LCS", "LCC", "LCN", "LZ"});
    }
    return false;
}

bool writes(Use use) { return use == Use::BatchWrite || use == Use::RandomWrite || use == Use::BlockWrite; }

// The current value of Z n (16-bit, signed) or LZ n (32-bit, signed) of a CPU.
bool index_value(const devicemodel::Cpu& cpu, const Modifier& m, std::int64_t& value) {
    value = 0;
    if (m.reg == Modifier::Register::None) return true;
    const bool z = m.reg == Modifier::Register::Z;
    const auto* spec = devicemodel::find_by_symbol(z ? "Z" : "LZ");
    if (m.number >= cpu.memory().size(spec->area)) return false;
    auto raw = cpu.memory().value(*spec, m.number);
    value = z ? static_cast<std::int16_t>(raw) : static_cast<std::int32_t>(raw);
    return true;
}

}  // namespace

EndCode resolve(CommandContext& ctx, const DeviceField& field, Use use, Target& target) {
    const auto& profile = ctx.port;
    if (!field.spec) return end_code(profile.unknown_device_code);
    const auto& spec = *field.spec;
    const auto& ext = field.extension;
    target.spec = &spec;

    std::int64_t offset = 0;
    if (!index_value(ctx.cpu, ext.target_modifier, offset)) return EndCode::BadRequestContent;
    const auto place = static_cast<std::int64_t>(ext.target) + offset;
    // U3E0-U3E3 is the CPU buffer memory however it was written: the ASCII form
    // has no F8/FA byte to tell it from a module, and Z may move a U onto it.
    // Any other number behind FA names a CPU that is not there: 4043, as a
    // missing module or network (the same answer in binary and ASCII).
    const bool cpu_place = place >= 0x3E0 && place <= 0x3E3;
    auto kind = ext.kind == Kind::ModuleAccess && cpu_place ? Kind::CpuBuffer : ext.kind;
    switch (kind) {
        case Kind::None:
            if (spec.extension_only) return end_code(profile.unknown_device_code);
            target.memory = &ctx.cpu.memory();
            target.owner = &ctx.cpu;
            break;
        case Kind::LinkDirect:
            if (!is_in(spec, {"X", "Y", "B", "SB", "W", "SW"})) return end_code(profile.unknown_device_code);
            target.memory = place >= 0 && place <= 0xFFFF ? ctx.cpu.network(static_cast<std::uint16_t>(place)) : nullptr;
            if (!target.memory) return kNoSuchModule;
            break;
        case Kind::ModuleAccess: {
            if (spec.area != Area::G) return end_code(profile.unknown_device_code);
            auto* module = place >= 0 && place <= 0xFFFF ? ctx.cpu.module(static_cast<std::uint16_t>(place)) : nullptr;
            if (!module) return kNoSuchModule;
            target.memory = &module->memory;
            break;
        }
        case Kind::CpuBuffer: {
            if (spec.area != Area::G && spec.area != Area::HG) return end_code(profile.unknown_device_code);
            if (!cpu_place) return kNoSuchModule;
            auto* cpu = ctx.cpus[static_cast<std::size_t>(place - 0x3E0)];
            if (!cpu) return kNoSuchModule;
            // Each CPU of a multi-CPU rack writes only its own CPU buffer memory;
            // another CPU's is read-only to it (issue 14; 414A as seen on
            // protected extended targets, real-CPU measurements).
            if (writes(use) && cpu != &ctx.cpu) return kOtherCpusBuffer;
            target.memory = &cpu->memory();
            target.owner = cpu;
            break;
        }
    }

    if (!index_value(ctx.cpu, ext.device_modifier, offset)) return EndCode::BadRequestContent;
    auto number = static_cast<std::int64_t>(field.number) + offset;
    if (ext.indirect) {
        // "@Dn": Dn and Dn+1 hold, as a 32-bit value, the number of the device
        // of the same kind that is meant (chosen; ADRSET's encoding is CPU-internal).
        if (spec.unit != Unit::Word) return EndCode::BadRequestContent;
        if (number < 0 || !target.memory->contains(spec.area, static_cast<std::uint64_t>(number), 2))
            return end_code(profile.out_of_range_code);
        auto n = static_cast<std::uint32_t>(number);
        number = target.memory->value(spec, n) | std::int64_t{target.memory->value(spec, n + 1)} << 16;
    }
    if (number < 0 || number > 0xFFFFFFFF) return end_code(profile.out_of_range_code);
    target.number = static_cast<std::uint32_t>(number);

    if (forbidden(spec, use)) return end_code(profile.not_accessible_code);
    if (writes(use))
        for (auto area : profile.read_only)
            if (area == spec.area && ext.kind == Kind::None) return end_code(profile.not_accessible_code);
    return EndCode::Ok;
}

bool fits(const Target& target, std::uint64_t devices) {
    if (target.owner) return target.owner->in_range(target.spec->area, target.number, devices);
    return target.memory->contains(target.spec->area, target.number, devices);
}

std::uint64_t devices_in_words(const DeviceSpec& spec, std::uint64_t words) {
    if (spec.unit == Unit::Bit) return words * 16;
    if (spec.unit == Unit::Word) return words;
    auto per = devicemodel::words_per_device(spec);
    return (words + per - 1) / per;
}

}  // namespace slmp::protocol
