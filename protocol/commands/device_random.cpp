// Read Random 0403 / Write Random 1402, and Entry Monitor Device 0801 /
// Execute Monitor 0802, which register the same device list as 0403 and read
// it later. Subcommands 0000/0002 (and bits 0001/0003 for 1402) and their
// extended forms 0080–0083. Spec: SLMP Reference Manual §5.2.
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
using OperandUnit = DeviceOperand::Unit;

// Resolves every device of a list, each `words` words wide.
EndCode resolve_all(CommandContext& ctx, const std::vector<DeviceField>& fields, unsigned words, Use use,
                    std::vector<Target>& targets) {
    for (const auto& field : fields) {
        Target target;
        if (auto code = resolve(ctx, field, use, target); code != EndCode::Ok) return code;
        if (!fits(target, devices_in_words(*target.spec, words))) return end_code(ctx.port.out_of_range_code);
        targets.push_back(target);
    }
    return EndCode::Ok;
}

std::uint32_t read_value(const Target& t, unsigned words) {
    std::uint16_t w[2] = {0, 0};
    t.memory->read_words(*t.spec, t.number, std::span(w, words));
    return w[0] | std::uint32_t{w[1]} << 16;
}

void write_value(const Target& t, std::span<const std::uint16_t> words) { t.memory->write_words(*t.spec, t.number, words); }

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

// The fields of the operands of one unit, in request order.
std::vector<DeviceField> fields_of(const Operands& ops, OperandUnit unit) {
    std::vector<DeviceField> fields;
    for (const auto& d : ops.devices)
        if (d.unit == unit) fields.push_back(d.field);
    return fields;
}

// The request of 0403 and 0801: counts, then the word and double-word devices.
void decode_device_list(DecodeContext& d, const FormLimit& limit) {
    auto word_points = d.in.u8("word access points");
    auto dword_points = d.in.u8("double-word access points");
    if (!d.in.ok()) return fail_field(d);
    if (over(d, limit, std::uint64_t{word_points} + dword_points)) fail(d, over_limit_code(d, limit));
    for (unsigned i = 0; i < word_points + dword_points && d.in.ok(); ++i) {
        const bool word = i < word_points;
        auto field = read_device(d, word ? "word access device" : "double-word access device");
        if (d.in.ok()) d.out.devices.push_back({field, word ? OperandUnit::Word : OperandUnit::DoubleWord, 1});
    }
    if (!d.in.finish()) fail_field(d);
}

}  // namespace

void decode_random_read(DecodeContext& d) { decode_device_list(d, d.port.random_read_points); }
void decode_monitor(DecodeContext& d) { decode_device_list(d, d.port.monitor_points); }

void decode_random_write_words(DecodeContext& d) {
    auto word_points = d.in.u8("word access points");
    auto dword_points = d.in.u8("double-word access points");
    if (!d.in.ok()) return fail_field(d);
    // 12 per word point + 14 per double-word point (§6.4).
    auto weight_sum = std::uint64_t{word_points} * 12 + std::uint64_t{dword_points} * 14;
    if (over(d, d.port.random_write_weight, weight_sum)) fail(d, over_limit_code(d, d.port.random_write_weight));
    for (unsigned i = 0; i < word_points + dword_points && d.in.ok(); ++i) {
        const bool word = i < word_points;
        DeviceOperand device{read_device(d, word ? "word access device" : "double-word access device"),
                             word ? OperandUnit::Word : OperandUnit::DoubleWord, 1};
        auto value = word ? d.in.u16("word data") : d.in.u32("double-word data");
        device.words = {static_cast<std::uint16_t>(value)};
        if (!word) device.words.push_back(static_cast<std::uint16_t>(value >> 16));
        if (d.in.ok()) d.out.devices.push_back(std::move(device));
    }
    if (!d.in.finish()) fail_field(d);
}

void decode_random_write_bits(DecodeContext& d) {
    auto points = d.in.u8("bit access points");
    if (!d.in.ok()) return fail_field(d);
    if (over(d, d.port.random_write_bits, points)) fail(d, over_limit_code(d, d.port.random_write_bits));
    for (unsigned i = 0; i < points && d.in.ok(); ++i) {
        DeviceOperand device{read_device(d, "bit access device"), OperandUnit::Bit, 1};
        // Set/reset: 1 byte / 2 characters in the Q form, 2 bytes / 4 in the
        // iQ-R form (§6.4); any nonzero value sets the bit.
        auto state = d.spec.form == DeviceForm::Q ? d.in.u8("set/reset") : d.in.u16("set/reset");
        device.bits = {static_cast<std::uint8_t>(state != 0)};
        if (d.in.ok()) d.out.devices.push_back(std::move(device));
    }
    if (!d.in.finish()) fail_field(d);
}

EndCode random_read(CommandContext& ctx) {
    if (ctx.operands.error != EndCode::Ok) return ctx.operands.error;
    return answer(ctx, fields_of(ctx.operands, OperandUnit::Word), fields_of(ctx.operands, OperandUnit::DoubleWord),
                  Use::RandomRead);
}

EndCode random_write_words(CommandContext& ctx) {
    const auto& ops = ctx.operands;
    if (ops.error != EndCode::Ok) return ops.error;
    std::vector<Target> word_targets, dword_targets;
    if (auto code = resolve_all(ctx, fields_of(ops, OperandUnit::Word), 1, Use::RandomWrite, word_targets);
        code != EndCode::Ok)
        return code;
    if (auto code = resolve_all(ctx, fields_of(ops, OperandUnit::DoubleWord), 2, Use::RandomWrite, dword_targets);
        code != EndCode::Ok)
        return code;
    std::size_t w = 0, dw = 0;
    for (const auto& device : ops.devices)
        write_value(device.unit == OperandUnit::Word ? word_targets[w++] : dword_targets[dw++], device.words);
    return EndCode::Ok;
}

EndCode random_write_bits(CommandContext& ctx) {
    const auto& profile = ctx.port;
    const auto& ops = ctx.operands;
    if (ops.error != EndCode::Ok) return ops.error;
    std::vector<Target> targets;
    for (const auto& device : ops.devices) {
        Target target;
        if (auto code = resolve(ctx, device.field, Use::RandomWrite, target); code != EndCode::Ok) return code;
        if (target.spec->unit != Unit::Bit) return end_code(profile.bad_unit_code);
        if (!fits(target, 1)) return end_code(profile.out_of_range_code);
        targets.push_back(target);
    }
    for (std::size_t i = 0; i < targets.size(); ++i)
        targets[i].memory->set_bit(*targets[i].spec, targets[i].number, ops.devices[i].bits.front() != 0);
    return EndCode::Ok;
}

EndCode monitor_register(CommandContext& ctx) {
    if (ctx.operands.error != EndCode::Ok) return ctx.operands.error;
    auto words = fields_of(ctx.operands, OperandUnit::Word);
    auto dwords = fields_of(ctx.operands, OperandUnit::DoubleWord);
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
