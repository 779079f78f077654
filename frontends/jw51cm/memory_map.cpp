#include "frontends/jw51cm/memory_map.hpp"

namespace slmp::jw51cm {

namespace dm = slmp::devicemodel;

namespace {

dm::DeviceAddress at(const char* text) { return *dm::parse_address(text); }

dm::DeviceAddress at(const char* symbol, std::uint32_t number) {
    return dm::DeviceAddress{dm::find_by_symbol(symbol), number};
}

}  // namespace

MemoryMap::MemoryMap(std::uint32_t file_bytes, std::uint32_t timers)
    : timers_(timers), timer_values_(at("TN0")), timer_contacts_(at("TS0")) {
    regions_.push_back({0, 0, 01600, at("M0"), "file 0 relays 00000-15777"});
    regions_.push_back({0, 01600, 04000 - 01600, at("D2560"), "file 0 bytes 01600-03777"});
    regions_.push_back({0, 04000, 016000 - 04000, at("D0"), "file 0 registers 09000-99777"});
    regions_.push_back({0, 016000, 020000 - 016000, at("D3136"), "file 0 bytes 16000-17777"});
    for (std::uint8_t f = 1; f <= 7; ++f)
        regions_.push_back({f, 0, file_bytes, at("ZR", file_bytes / 2 * (f - 1u)), "file " + std::to_string(f)});
}

std::uint32_t MemoryMap::file_size(std::uint8_t file) const {
    std::uint32_t size = 0;
    for (const auto& r : regions_)
        if (r.file == file) size = std::max(size, r.first_byte + r.bytes);
    return size;
}

std::string MemoryMap::check(const dm::DeviceMemory& memory) const {
    for (const auto& r : regions_) {
        const auto& spec = *r.base.spec;
        std::uint64_t devices = spec.unit == dm::Unit::Bit ? 8ull * r.bytes : (r.bytes + 1) / 2;
        if (!memory.contains(spec.area, r.base.number, devices))
            return "jw51cm: " + r.name + " needs " + std::to_string(devices) + " " + std::string(spec.symbol) +
                   " device(s) from " + dm::format_address(r.base) + ", past the " + std::string(dm::area_name(spec.area)) +
                   " size of " + std::to_string(memory.size(spec.area)) + "; lower \"file_bytes\" or raise device_sizes";
    }
    if (!memory.contains(timer_values_.spec->area, 0, timers_))
        return "jw51cm: " + std::to_string(timers_) + " timers/counters need as many T devices, past the T size of " +
               std::to_string(memory.size(timer_values_.spec->area)) + "; lower \"timers\" or raise device_sizes T";
    return {};
}

const Region* MemoryMap::find(std::uint8_t file, std::uint32_t address) const {
    for (const auto& r : regions_)
        if (r.file == file && address >= r.first_byte && address < r.first_byte + r.bytes) return &r;
    return nullptr;
}

bool MemoryMap::contains(std::uint8_t file, std::uint32_t address, std::uint32_t count) const {
    // Regions of a file are contiguous from byte 0, so the end decides.
    return count > 0 && static_cast<std::uint64_t>(address) + count <= file_size(file);
}

std::uint8_t ByteAccess::byte(std::uint8_t file, std::uint32_t address) const {
    const auto* r = map_.find(file, address);
    if (!r) return 0;
    auto offset = address - r->first_byte;
    const auto& spec = *r->base.spec;
    if (spec.unit == dm::Unit::Bit) {
        std::uint8_t value = 0;
        for (unsigned bit = 0; bit < 8; ++bit)
            if (memory_.bit(spec, r->base.number + 8 * offset + bit)) value |= static_cast<std::uint8_t>(1u << bit);
        return value;
    }
    std::uint16_t word = 0;
    memory_.read_words(spec, r->base.number + offset / 2, std::span<std::uint16_t>(&word, 1));
    return static_cast<std::uint8_t>(offset % 2 ? word >> 8 : word);
}

void ByteAccess::set_byte(std::uint8_t file, std::uint32_t address, std::uint8_t value) {
    const auto* r = map_.find(file, address);
    if (!r) return;
    auto offset = address - r->first_byte;
    const auto& spec = *r->base.spec;
    if (spec.unit == dm::Unit::Bit) {
        for (unsigned bit = 0; bit < 8; ++bit) memory_.set_bit(spec, r->base.number + 8 * offset + bit, (value >> bit) & 1);
        return;
    }
    std::uint16_t word = 0;
    auto number = r->base.number + offset / 2;
    memory_.read_words(spec, number, std::span<std::uint16_t>(&word, 1));
    word = offset % 2 ? static_cast<std::uint16_t>((word & 0x00FF) | value << 8)
                      : static_cast<std::uint16_t>((word & 0xFF00) | value);
    memory_.write_words(spec, number, std::span<const std::uint16_t>(&word, 1));
}

}  // namespace slmp::jw51cm
