// Buffer memory by address: Memory Read/Write 0613/1613 (the own station's
// buffer memory, in words) and Extend Unit Read/Write 0601/1601 (an
// intelligent function module's buffer memory, in bytes). The same stores are
// reached by the extended device commands as U3E0\G / U(io)\G.
// Spec: SLMP Reference Manual §5.4–§5.5; module numbers 0000/03FF:
// real-CPU measurements.
#include <vector>

#include "protocol/commands/handlers.hpp"

namespace slmp::protocol::commands {
namespace {

using devicemodel::Area;

constexpr std::uint32_t kMaxMemoryWords = 480;       // 0613/1613: 1–480 words
constexpr std::uint32_t kMaxExtendUnitBytes = 1920;  // 0601/1601: 2–1920 bytes

const devicemodel::DeviceSpec& g() { return *devicemodel::find_by_symbol("G"); }

struct ByteWindow {
    devicemodel::DeviceMemory* memory = nullptr;
    std::uint32_t first_byte = 0;   // byte offset in the module's buffer memory
};

// 0601/1601 addressing: start address = buffer word × 2 + the module's head
// address; the module number is its start I/O ÷ 16. Module numbers 03E0–03E3
// are the CPU buffer memory of CPU No.1–4 (real-CPU measurements), whose
// head address is 0 (chosen: the manual's table has no entry for a CPU). A
// write to another CPU's buffer memory answers 414A: each CPU of a rack writes
// only its own (issue 14).
EndCode locate(CommandContext& ctx, std::uint32_t address, std::uint16_t bytes, std::uint16_t module_number,
               bool writing, ByteWindow& window) {
    if (module_number == 0x0000) return EndCode::ModuleNotPresent;
    if (module_number == 0x03FF) return EndCode::ModuleNotAccessible;
    std::uint32_t head = 0;
    if (module_number >= 0x03E0 && module_number <= 0x03E3) {
        auto* cpu = ctx.cpus[module_number - 0x03E0u];
        window.memory = cpu ? &cpu->memory() : nullptr;
        if (cpu && writing && cpu != &ctx.cpu) return EndCode::ExtendedTargetRefused;
    } else if (auto* module = ctx.cpu.module(module_number)) {
        window.memory = &module->memory;
        head = module->head_address;
    }
    if (!window.memory) return EndCode::ModuleNotPresent;
    if (bytes < 2 || bytes > kMaxExtendUnitBytes) return EndCode::WordPointsOverLimit;
    if (address < head) return end_code(ctx.port.out_of_range_code);
    window.first_byte = address - head;
    if (std::uint64_t{window.first_byte} + bytes > std::uint64_t{window.memory->size(Area::G)} * 2)
        return end_code(ctx.port.out_of_range_code);
    return EndCode::Ok;
}

std::uint8_t byte_at(const ByteWindow& w, std::uint32_t i) {
    auto byte = w.first_byte + i;
    auto word = w.memory->value(g(), byte / 2);
    return static_cast<std::uint8_t>(byte % 2 ? word >> 8 : word);
}

void set_byte(const ByteWindow& w, std::uint32_t i, std::uint8_t value) {
    auto byte = w.first_byte + i;
    auto word = w.memory->value(g(), byte / 2);
    word = byte % 2 ? (word & 0x00FF) | (std::uint32_t{value} << 8) : (word & 0xFF00) | value;
    w.memory->set_value(g(), byte / 2, word);
}

EndCode check_words(CommandContext& ctx, std::uint32_t address, std::uint16_t words) {
    if (words == 0 || words > kMaxMemoryWords) return EndCode::WordPointsOverLimit;
    if (!ctx.cpu.station_buffer().contains(Area::G, address, words)) return end_code(ctx.port.out_of_range_code);
    return EndCode::Ok;
}

}  // namespace

EndCode memory_read(CommandContext& ctx) {
    auto address = ctx.in.u32("start address");
    auto words = ctx.in.u16("word length");
    if (!ctx.in.finish()) return ctx.in.error();
    if (auto code = check_words(ctx, address, words); code != EndCode::Ok) return code;
    std::vector<std::uint16_t> values(words);
    ctx.cpu.station_buffer().read_words(g(), address, values);
    ctx.out.words(values);
    return EndCode::Ok;
}

EndCode memory_write(CommandContext& ctx) {
    auto address = ctx.in.u32("start address");
    auto words = ctx.in.u16("word length");
    if (!ctx.in.ok()) return ctx.in.error();
    if (auto code = check_words(ctx, address, words); code != EndCode::Ok) return code;
    auto values = ctx.in.words(words, "write data");
    if (!ctx.in.finish()) return ctx.in.error();
    ctx.cpu.station_buffer().write_words(g(), address, values);
    return EndCode::Ok;
}

EndCode extend_unit_read(CommandContext& ctx) {
    auto address = ctx.in.u32("start address");
    auto bytes = ctx.in.u16("byte count");
    auto module_number = ctx.in.u16("module number");
    if (!ctx.in.finish()) return ctx.in.error();
    ByteWindow window;
    if (auto code = locate(ctx, address, bytes, module_number, false, window); code != EndCode::Ok) return code;
    // Bytes in memory order, low byte first, in both codecs (ASCII: 2 characters a byte).
    for (std::uint32_t i = 0; i < bytes; ++i) ctx.out.u8(byte_at(window, i));
    return EndCode::Ok;
}

EndCode extend_unit_write(CommandContext& ctx) {
    auto address = ctx.in.u32("start address");
    auto bytes = ctx.in.u16("byte count");
    auto module_number = ctx.in.u16("module number");
    if (!ctx.in.ok()) return ctx.in.error();
    ByteWindow window;
    if (auto code = locate(ctx, address, bytes, module_number, true, window); code != EndCode::Ok) return code;
    std::vector<std::uint8_t> data(bytes);
    for (auto& byte : data) byte = ctx.in.u8("write data");
    if (!ctx.in.finish()) return ctx.in.error();
    for (std::uint32_t i = 0; i < bytes; ++i) set_byte(window, i, data[i]);
    return EndCode::Ok;
}

}  // namespace slmp::protocol::commands
