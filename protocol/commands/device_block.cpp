// Read Block 0406 / Write Block 1406 — subcommands 0000/0002 and the extended
// 0080/0082. Spec: slmp-frames-and-devices.md §6.7–§6.8; the mixed word+bit
// write refusal: hardware-behaviour.md §2.
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

struct Block {
    DeviceField field;
    std::uint16_t points = 0;
    bool bits = false;
    std::vector<std::uint16_t> data;   // 1406 only
    Target target;
};

// Reads the block counts and the blocks; `with_data` for 1406.
EndCode read_blocks(CommandContext& ctx, bool with_data, std::vector<Block>& blocks) {
    const auto& profile = ctx.cpu.profile();
    auto word_blocks = ctx.in.u8("word device blocks");
    auto bit_blocks = ctx.in.u8("bit device blocks");
    if (!ctx.in.ok()) return ctx.in.error();
    if (over(ctx, profile.block_count, std::uint64_t{word_blocks} + bit_blocks))
        return over_limit_code(ctx, profile.block_count);
    if (with_data && word_blocks > 0 && bit_blocks > 0 &&
        profile.mixed_block_write.kind == devicemodel::Refusal::Kind::EndCode)
        return end_code(profile.mixed_block_write.end_code);
    for (unsigned i = 0; i < word_blocks + bit_blocks && ctx.in.ok(); ++i) {
        Block block;
        block.bits = i >= word_blocks;
        block.field = read_device(ctx, block.bits ? "bit device block" : "word device block");
        block.points = ctx.in.u16("block points");
        if (with_data) block.data = ctx.in.words(block.points, "block write data");
        blocks.push_back(std::move(block));
    }
    if (!ctx.in.finish()) return ctx.in.error();
    return EndCode::Ok;
}

// Totals, then every block's device.
EndCode check_blocks(CommandContext& ctx, bool write, std::vector<Block>& blocks) {
    const auto& profile = ctx.cpu.profile();
    std::uint64_t total = 0;
    for (const auto& block : blocks) total += block.points;
    // 1406 counts a per-block overhead: 4 (Q form) or 9 (iQ-R form) (§6.8).
    if (write) total += blocks.size() * (ctx.spec.form == DeviceForm::Q ? 4 : 9);
    if (total > profile.block_points.max) return end_code(profile.block_points.end_code);
    for (auto& block : blocks) {
        if (block.points == 0) return end_code(profile.block_points.end_code);
        auto use = write ? Use::BlockWrite : Use::BlockRead;
        if (auto code = resolve(ctx, block.field, use, block.target); code != EndCode::Ok) return code;
        bool bit_device = block.target.spec->unit == Unit::Bit;
        if (bit_device != block.bits) return end_code(profile.bad_unit_code);
        if (!fits(block.target, devices_in_words(*block.target.spec, block.points)))
            return end_code(profile.out_of_range_code);
    }
    return EndCode::Ok;
}

}  // namespace

EndCode block_read(CommandContext& ctx) {
    std::vector<Block> blocks;
    if (auto code = read_blocks(ctx, false, blocks); code != EndCode::Ok) return code;
    if (auto code = check_blocks(ctx, false, blocks); code != EndCode::Ok) return code;
    for (const auto& block : blocks) {
        std::vector<std::uint16_t> words(block.points);
        block.target.memory->read_words(*block.target.spec, block.target.number, words);
        ctx.out.words(words);
    }
    return EndCode::Ok;
}

EndCode block_write(CommandContext& ctx) {
    std::vector<Block> blocks;
    if (auto code = read_blocks(ctx, true, blocks); code != EndCode::Ok) return code;
    if (auto code = check_blocks(ctx, true, blocks); code != EndCode::Ok) return code;
    for (const auto& block : blocks)
        block.target.memory->write_words(*block.target.spec, block.target.number, block.data);
    return EndCode::Ok;
}

}  // namespace slmp::protocol::commands
