// Read Block 0406 / Write Block 1406 — subcommands 0000/0002 and the extended
// 0080/0082. Spec: SLMP Reference Manual §5.2; the mixed word+bit
// write refusal: real-CPU measurements.
//
// A word block is n words of a word device; a bit block is n words (16 bits
// each) of a bit device — timer and counter contacts and coils go in bit blocks.
// Check order: block counts (×2 for 0080), mixed-write refusal (1406), fields
// and left-over data (C050/C061), total points (1406: plus 4 or 9 per block),
// then each block resolves (C05B, 4043, 4030), has the right kind of device
// (C05C) and fits (4031/C056) — all before the first write.
#include <vector>

#include "protocol/commands/handlers.hpp"
#include "protocol/commands/limits.hpp"
#include "protocol/device_access.hpp"

namespace slmp::protocol::commands {
namespace {

using devicemodel::Unit;

// Reads the block counts and the blocks; `with_data` for 1406.
void decode_blocks(DecodeContext& d, bool with_data) {
    const auto& profile = d.port;
    auto word_blocks = d.in.u8("word device blocks");
    auto bit_blocks = d.in.u8("bit device blocks");
    if (!d.in.ok()) return fail_field(d);
    if (over(d, profile.block_count, std::uint64_t{word_blocks} + bit_blocks)) fail(d, over_limit_code(d, profile.block_count));
    if (with_data && word_blocks > 0 && bit_blocks > 0 &&
        profile.mixed_block_write.kind == Refusal::Kind::EndCode)
        fail(d, end_code(profile.mixed_block_write.end_code));
    for (unsigned i = 0; i < word_blocks + bit_blocks && d.in.ok(); ++i) {
        DeviceOperand block;
        block.bit_block = i >= word_blocks;
        block.field = read_device(d, block.bit_block ? "bit device block" : "word device block");
        block.points = d.in.u16("block points");
        if (with_data) block.words = d.in.words(block.points, "block write data");
        if (d.in.ok()) d.out.devices.push_back(std::move(block));
    }
    if (!d.in.finish()) fail_field(d);
}

// Totals, then every block's device.
EndCode check_blocks(CommandContext& ctx, bool write, std::vector<Target>& targets) {
    const auto& profile = ctx.port;
    const auto& blocks = ctx.operands.devices;
    std::uint64_t total = 0;
    for (const auto& block : blocks) total += block.points;
    // 1406 counts a per-block overhead: 4 (Q form) or 9 (iQ-R form) (§6.8).
    if (write) total += blocks.size() * (ctx.spec.form == DeviceForm::Q ? 4 : 9);
    if (total > profile.block_points.max) return end_code(profile.block_points.end_code);
    for (const auto& block : blocks) {
        if (block.points == 0) return end_code(profile.block_points.end_code);
        Target target;
        if (auto code = resolve(ctx, block.field, write ? Use::BlockWrite : Use::BlockRead, target); code != EndCode::Ok)
            return code;
        bool bit_device = target.spec->unit == Unit::Bit;
        if (bit_device != block.bit_block) return end_code(profile.bad_unit_code);
        if (!fits(target, devices_in_words(*target.spec, block.points))) return end_code(profile.out_of_range_code);
        targets.push_back(target);
    }
    return EndCode::Ok;
}

}  // namespace

void decode_block_read(DecodeContext& d) { decode_blocks(d, false); }
void decode_block_write(DecodeContext& d) { decode_blocks(d, true); }

EndCode block_read(CommandContext& ctx) {
    if (ctx.operands.error != EndCode::Ok) return ctx.operands.error;
    std::vector<Target> targets;
    if (auto code = check_blocks(ctx, false, targets); code != EndCode::Ok) return code;
    for (std::size_t i = 0; i < targets.size(); ++i) {
        std::vector<std::uint16_t> words(ctx.operands.devices[i].points);
        targets[i].memory->read_words(*targets[i].spec, targets[i].number, words);
        ctx.out.words(words);
    }
    return EndCode::Ok;
}

EndCode block_write(CommandContext& ctx) {
    if (ctx.operands.error != EndCode::Ok) return ctx.operands.error;
    std::vector<Target> targets;
    if (auto code = check_blocks(ctx, true, targets); code != EndCode::Ok) return code;
    for (std::size_t i = 0; i < targets.size(); ++i)
        targets[i].memory->write_words(*targets[i].spec, targets[i].number, ctx.operands.devices[i].words);
    return EndCode::Ok;
}

}  // namespace slmp::protocol::commands
