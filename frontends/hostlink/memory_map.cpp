#include "frontends/hostlink/memory_map.hpp"

namespace slmp::hostlink {

namespace dm = slmp::devicemodel;

const std::array<AreaInfo, static_cast<std::size_t>(Area::Count)>& area_infos() {
    // Defaults (inferred design, §11.2): CIO on M, HR on L (both retentive
    // relays), LR on B, AR on M past CIO (kept apart from CIO), DM on D, VR on
    // R pairs (low word first), T/C on the timers; set values have no MELSEC
    // counterpart and sit on W.
    static const std::array<AreaInfo, static_cast<std::size_t>(Area::Count)> infos{{
        {Area::Cio, "CIO", Element::Channel, "M0", 256, "relay channels (CIO)"},
        {Area::Hr, "HR", Element::Channel, "L0", 100, "holding relays (HR)"},
        {Area::Lr, "LR", Element::Channel, "B0", 64, "link relays (LR)"},
        {Area::Ar, "AR", Element::Channel, "M4096", 28, "auxiliary relays (AR)"},
        {Area::Dm, "DM", Element::Channel, "D0", 6656, "data memory (DM)"},
        {Area::Vr, "VR", Element::LongWord, "R0", 1024, "VR long words"},
        {Area::TcPresent, "TC", Element::Channel, "TN0", 512, "timer/counter present values"},
        {Area::TcSet, "TC_SET", Element::Channel, "W0", 512, "timer/counter set values"},
        {Area::TcUp, "TC_UP", Element::Flag, "TS0", 512, "time-up/count-up flags"},
    }};
    return infos;
}

const AreaInfo& info(Area area) { return area_infos()[static_cast<std::size_t>(area)]; }

std::optional<Area> area_by_key(std::string_view key) {
    for (const auto& i : area_infos())
        if (i.key == key) return i.area;
    return std::nullopt;
}

MemoryMap::MemoryMap() {
    for (const auto& i : area_infos()) {
        auto base = dm::parse_address(i.default_device);
        bindings_[static_cast<std::size_t>(i.area)] = Binding{*base, i.default_size};
    }
}

std::string MemoryMap::check(const dm::DeviceMemory& memory) const {
    for (const auto& i : area_infos()) {
        const auto& b = binding(i.area);
        const auto& spec = *b.base.spec;
        std::string where = "hostlink: areas/" + std::string(i.key) + " (" + dm::format_address(b.base) + ")";
        std::uint64_t devices = 0;
        switch (i.element) {
            case Element::Flag:
                if (spec.unit != dm::Unit::Bit)
                    return where + ": the flags need a bit device; use e.g. TS0, M0";
                devices = b.size;
                break;
            case Element::Channel:
            case Element::LongWord: {
                if (spec.unit == dm::Unit::DoubleWord)
                    return where + ": a double-word device cannot hold 16-bit channels; use a word device such as D or R";
                std::uint64_t words = i.element == Element::LongWord ? 2ull * b.size : b.size;
                devices = spec.unit == dm::Unit::Bit ? words * 16 : words;
                break;
            }
        }
        if (!memory.contains(spec.area, b.base.number, devices))
            return where + ": " + std::to_string(b.size) + " element(s) need " + std::to_string(devices) + " " +
                   std::string(spec.symbol) + " device(s) from " + std::to_string(b.base.number) + ", past the " +
                   std::string(dm::area_name(spec.area)) + " size of " + std::to_string(memory.size(spec.area)) +
                   "; lower \"size\", move \"device\" or raise device_sizes";
    }
    return {};
}

namespace {

// Word `index` of a binding: bit devices give 16 devices per word.
std::uint32_t word_number(const Binding& b, std::uint32_t index) {
    return b.base.spec->unit == dm::Unit::Bit ? b.base.number + 16 * index : b.base.number + index;
}

}  // namespace

std::uint16_t AreaAccess::word(Area area, std::uint32_t index) const {
    const auto& b = map_.binding(area);
    std::uint16_t value = 0;
    memory_.read_words(*b.base.spec, word_number(b, index), std::span<std::uint16_t>(&value, 1));
    return value;
}

void AreaAccess::set_word(Area area, std::uint32_t index, std::uint16_t value) {
    const auto& b = map_.binding(area);
    memory_.write_words(*b.base.spec, word_number(b, index), std::span<const std::uint16_t>(&value, 1));
}

std::uint32_t AreaAccess::long_word(std::uint32_t index) const {
    return word(Area::Vr, 2 * index) | static_cast<std::uint32_t>(word(Area::Vr, 2 * index + 1)) << 16;
}

void AreaAccess::set_long_word(std::uint32_t index, std::uint32_t value) {
    set_word(Area::Vr, 2 * index, static_cast<std::uint16_t>(value));
    set_word(Area::Vr, 2 * index + 1, static_cast<std::uint16_t>(value >> 16));
}

bool AreaAccess::bit(Area area, std::uint32_t index) const {
    const auto& b = map_.binding(area);
    if (b.base.spec->unit == dm::Unit::Bit) return memory_.bit(*b.base.spec, b.base.number + index);
    return (word(area, index / 16) >> (index % 16)) & 1;
}

void AreaAccess::set_bit(Area area, std::uint32_t index, bool on) {
    const auto& b = map_.binding(area);
    if (b.base.spec->unit == dm::Unit::Bit) {
        memory_.set_bit(*b.base.spec, b.base.number + index, on);
        return;
    }
    auto mask = static_cast<std::uint16_t>(1u << (index % 16));
    auto w = word(area, index / 16);
    set_word(area, index / 16, static_cast<std::uint16_t>(on ? (w | mask) : (w & ~mask)));
}

}  // namespace slmp::hostlink
