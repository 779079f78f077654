// Read Random 0403 / Write Random 1402, and Entry Monitor Device 0801 /
// Execute Monitor 0802, which register the same device list as 0403 and read
// it later. Subcommands 0000/0002 (and bits 0001/0003 for 1402) and their
// extended forms 0080–0083. Spec: slmp-frames-and-devices.md §6.3–§6.6.
//
// Check order: the point counts (C054/C053, ×2 for 0080/0081), then every
// device field decodes and nothing is left over (C050/C061), then every device
// resolves (C05B, 4043, 4030) and fits (4031/C056), bit units need bit devices
// (C05C) — all before the first write, so a rejected request changes nothing.
//
// A word access point is one word: a word device, or 16 bits of a bit device
// from the named one; a double-word point is two words (32 bits). Long devices
// (LTN, LCN, LZ) give their 32-bit value as a double word, its low half as a word.
#include <vector>

#include "protocol/commands/handlers.hpp"
#include "protocol/commands/limits.hpp"
#include "protocol/device_access.hpp"

namespace slmp::protocol::commands {
namespace {

using devicemodel::Unit;

struct Entry {
    Target target;
    std::uint32_t value = 0;
};

std::vector<DeviceField> read_devices(CommandContext& ctx, std::size_t count, std::string_view what) {
    std::vector<DeviceField> fields;
    for (std::size_t i = 0; i < count && ctx.in.ok(); ++i) fields.push_back(read_device(ctx, what));
    return fields;
}

// Resolves every device of a list, each `words` words wide.
EndCode resolve_all(CommandContext& ctx, const std::vector<DeviceField>& fields, unsigned words, Use use,
                    std::vector<Target>& targets) {
    for (const auto& field : fields) {
        Target target;
        if (auto code = resolve(ctx, field, use, target); code != EndCode::Ok) return code;
        if (!fits(target, devices_in_words(*target.spec, words))) return end_code(ctx.cpu.profile().out_of_range_code);
        targets.push_back(target);
    }
    return EndCode::Ok;
}

std::uint32_t read_value(const Target& t, unsigned words) {
    std::uint16_t w[2] = {0, 0};
    t.memory->read_words(*t.spec, t.number, std::span(w, words));
    return w[0] | std::uint32_t{w[1]} << 16;
}

void write_value(const Target& t, unsigned words, std::uint32_t value) {
    std::uint16_t w[2] = {static_cast<std::uint16_t>(value), static_cast<std::uint16_t>(value >> 16)};
    t.memory->write_words(*t.spec, t.number, std::span<const std::uint16_t>(w, words));
}

// The response of 0403 and 0802: word values, then double-word values.
EndCode answer(CommandContext& ctx, const std::vector<DeviceField>& words, const std::vector<DeviceField>& dwords,
               Use use) {
    std::vector<Target> word_targets, dword_targets;
    if (auto code = resolve_all(ctx, words, 1, use, word_targets); code != EndCode::Ok) return code;
    if (auto code = resolve_all(ctx, dwords, 2, use, dword_targets); code != EndCode::Ok) return code;
    for (const auto& t : word_targets) ctx.out.u16(static_cast<std::uint16_t>(read_value(t, 1)));
    for (const auto& t : dword_targets) ctx.out.u32(read_value(t, 2));
    return EndCode::Ok;
}

// The request of 0403 and 0801: counts, then the word and double-word devices.
EndCode read_device_list(CommandContext& ctx, const devicemodel::FormLimit& limit, std::vector<DeviceField>& words,
                         std::vector<DeviceField>& dwords) {
    auto word_points = ctx.in.u8("word access points");
    auto dword_points = ctx.in.u8("double-word access points");
    if (!ctx.in.ok()) return ctx.in.error();
    if (over(ctx, limit, std::uint64_t{word_points} + dword_points)) return over_limit_code(ctx, limit);
    words = read_devices(ctx, word_points, "word access device");
    dwords = read_devices(ctx, dword_points, "double-word access device");
    if (!ctx.in.finish()) return ctx.in.error();
    return EndCode::Ok;
}

}  // namespace

EndCode random_read(CommandContext& ctx) {
    std::vector<DeviceField> words, dwords;
    if (auto code = read_device_list(ctx, ctx.cpu.profile().random_read_points, words, dwords); code != EndCode::Ok)
        return code;
    return answer(ctx, words, dwords, Use::RandomRead);
}

EndCode random_write_words(CommandContext& ctx) {
    const auto& profile = ctx.cpu.profile();
    auto word_points = ctx.in.u8("word access points");
    auto dword_points = ctx.in.u8("double-word access points");
    if (!ctx.in.ok()) return ctx.in.error();
    // 12 per word point + 14 per double-word point (§6.4).
    auto weight_sum = std::uint64_t{word_points} * 12 + std::uint64_t{dword_points} * 14;
    if (over(ctx, profile.random_write_weight, weight_sum)) return over_limit_code(ctx, profile.random_write_weight);

    std::vector<DeviceField> fields;
    std::vector<std::uint32_t> values;
    for (unsigned i = 0; i < word_points + dword_points && ctx.in.ok(); ++i) {
        fields.push_back(read_device(ctx, i < word_points ? "word access device" : "double-word access device"));
        values.push_back(i < word_points ? ctx.in.u16("word data") : ctx.in.u32("double-word data"));
    }
    if (!ctx.in.finish()) return ctx.in.error();
    std::vector<DeviceField> words(fields.begin(), fields.begin() + word_points);
    std::vector<DeviceField> dwords(fields.begin() + word_points, fields.end());
    std::vector<Target> word_targets, dword_targets;
    if (auto code = resolve_all(ctx, words, 1, Use::RandomWrite, word_targets); code != EndCode::Ok) return code;
    if (auto code = resolve_all(ctx, dwords, 2, Use::RandomWrite, dword_targets); code != EndCode::Ok) return code;
    for (std::size_t i = 0; i < word_targets.size(); ++i) write_value(word_targets[i], 1, values[i]);
    for (std::size_t i = 0; i < dword_targets.size(); ++i) write_value(dword_targets[i], 2, values[word_points + i]);
    return EndCode::Ok;
}

EndCode random_write_bits(CommandContext& ctx) {
    const auto& profile = ctx.cpu.profile();
    auto points = ctx.in.u8("bit access points");
    if (!ctx.in.ok()) return ctx.in.error();
    if (over(ctx, profile.random_write_bits, points)) return over_limit_code(ctx, profile.random_write_bits);
    std::vector<DeviceField> fields;
    std::vector<bool> states;
    for (unsigned i = 0; i < points && ctx.in.ok(); ++i) {
        fields.push_back(read_device(ctx, "bit access device"));
        // Set/reset: 1 byte / 2 characters in the Q form, 2 bytes / 4 in the
        // iQ-R form (§6.4); any nonzero value sets the bit.
        states.push_back((ctx.spec.form == DeviceForm::Q ? ctx.in.u8("set/reset") : ctx.in.u16("set/reset")) != 0);
    }
    if (!ctx.in.finish()) return ctx.in.error();
    std::vector<Target> targets;
    for (const auto& field : fields) {
        Target target;
        if (auto code = resolve(ctx, field, Use::RandomWrite, target); code != EndCode::Ok) return code;
        if (target.spec->unit != Unit::Bit) return end_code(profile.bad_unit_code);
        if (!fits(target, 1)) return end_code(profile.out_of_range_code);
        targets.push_back(target);
    }
    for (std::size_t i = 0; i < targets.size(); ++i)
        targets[i].memory->set_bit(*targets[i].spec, targets[i].number, states[i]);
    return EndCode::Ok;
}

EndCode monitor_register(CommandContext& ctx) {
    std::vector<DeviceField> words, dwords;
    if (auto code = read_device_list(ctx, ctx.cpu.profile().monitor_points, words, dwords); code != EndCode::Ok)
        return code;
    // Validate now, so a bad registration is refused and the old one kept.
    std::vector<Target> unused;
    if (auto code = resolve_all(ctx, words, 1, Use::Monitor, unused); code != EndCode::Ok) return code;
    if (auto code = resolve_all(ctx, dwords, 2, Use::Monitor, unused); code != EndCode::Ok) return code;
    ctx.session.monitor = MonitorRegistration{true, ctx.spec.form, std::move(words), std::move(dwords)};
    return EndCode::Ok;
}

EndCode monitor_execute(CommandContext& ctx) {
    if (!ctx.in.finish()) return ctx.in.error();
    // Without a registration the command is out of sequence: C059 (JP §4.4).
    if (!ctx.session.monitor.registered) return EndCode::UnsupportedCommand;
    return answer(ctx, ctx.session.monitor.words, ctx.session.monitor.dwords, Use::Monitor);
}

}  // namespace slmp::protocol::commands
