// Everything but the area reads and writes: MM, TS, R&, QQMR/QQIR, the
// refused OMRON commands, XZ and `**`, and the RE/WE, RP/WP images.
#include <chrono>

#include "devicemodel/hex.hpp"
#include "frontends/hostlink/command_table.hpp"

namespace slmp::hostlink {

namespace {

constexpr std::size_t kMaxImageWords = 16;   // §6.15/§6.16: at most 16 words per record

}  // namespace

Answer model_code(const CommandRow&, Context& c) {
    if (!c.text.empty()) return Answer::error();
    return Answer::ok("11");   // §6.8: always C2000H/CQM1-compatible
}

Answer test_echo(const CommandRow&, Context&) { return {Answer::Kind::Echo, {}, {}}; }

Answer refused(const CommandRow&, Context& c) { return Answer::error(c.link.options().refused_code); }

Answer silent(const CommandRow&, Context&) { return {Answer::Kind::Silent, {}, {}}; }

// `**` resets the link state and nothing else; PLC memory stays (§6.12, inferred).
Answer initialise(const CommandRow&, Context& c) {
    c.state.composite.reset();
    return {Answer::Kind::Silent, {}, {}};
}

// R& (§6.7): item number 4 hex, byte count 4 decimal; the count must be the item's size.
Answer system_info(const CommandRow&, Context& c) {
    if (c.text.size() != 8) return Answer::error();
    auto item = hex(c.text.substr(0, 4));
    auto bytes = decimal(c.text.substr(4, 4));
    if (!item || !bytes) return Answer::error();
    const auto& runtime = c.link.cpu().runtime();
    bool running = runtime.state() == devicemodel::RunState::Run;
    // Cycle time in 200 ns units, from the scan statistics (0 before the second scan in RUN).
    std::uint32_t cycle = 0;
    std::uint32_t per_second = 0;
    if (auto times = runtime.scan_times()) {
        auto us = static_cast<std::uint64_t>(times->current.count());
        cycle = static_cast<std::uint32_t>(std::min<std::uint64_t>(us * 5, 0xFFFF));
        per_second = us == 0 ? 0xFFFF : static_cast<std::uint32_t>(std::min<std::uint64_t>(1000000 / us, 0xFFFF));
    }
    std::uint32_t value = 0;
    unsigned size = 0;
    switch (*item) {
        case 1: value = 1, size = 1; break;                      // the system is up
        case 3: value = running ? 1 : 0, size = 1; break;        // 1 ladder running; 0 "undefined" in STOP (inferred)
        case 4: value = 3, size = 1; break;                      // system type 3: Ladder Motion
        case 5: {                                                // changes while the scan runs, frozen when it stops
            auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(runtime.now().time_since_epoch());
            value = static_cast<std::uint32_t>(ms.count()) & 0xFFFF, size = 2;
            break;
        }
        case 6: value = cycle, size = 2; break;
        case 7: value = cycle, size = 2; break;                  // ladder time: the scan time too (inferred)
        case 8: value = per_second, size = 2; break;
        case 9: value = c.link.options().version, size = 2; break;
        default: return Answer::error();                         // 2, 10 reserved; others unknown (inferred 01)
    }
    if (*bytes != size) return Answer::error();
    return Answer::ok(devicemodel::hex_text(value, static_cast<int>(2 * size)));
}

namespace {

// QQ area codes (§6.9): 4 characters, space padded; TIMH/CNTR are TIM/CNT.
std::optional<Area> composite_area(std::string_view code) {
    if (code == "CIO ") return Area::Cio;
    if (code == "LR  ") return Area::Lr;
    if (code == "HR  ") return Area::Hr;
    if (code == "AR  ") return Area::Ar;
    if (code == "DM  ") return Area::Dm;
    if (code == "TIM " || code == "TIMH" || code == "CNT " || code == "CNTR") return Area::TcPresent;
    return std::nullopt;
}

std::optional<QqEntry> composite_entry(std::string_view text, const MemoryMap& map) {
    if (text.size() != 10) return std::nullopt;
    auto area = composite_area(text.substr(0, 4));
    auto channel = decimal(text.substr(4, 4));   // decimal, OMRON style (inferred)
    if (!area || !channel || *channel >= map.size(*area)) return std::nullopt;
    auto format = text.substr(8, 2);
    QqEntry entry{*area, *channel, -1};
    if (format != "CH") {
        auto bit = decimal(format);
        if (!bit || *bit > 15) return std::nullopt;
        entry.bit = static_cast<int>(*bit);
        // TIM/CNT with a bit format read the completion flag (inferred, OMRON-like).
        if (*area == Area::TcPresent) {
            entry.area = Area::TcUp;
            if (*channel >= map.size(Area::TcUp)) return std::nullopt;
        }
    }
    return entry;
}

std::string composite_item(const QqEntry& e, const AreaAccess& memory) {
    if (e.area == Area::TcUp) return memory.bit(Area::TcUp, e.channel) ? "1" : "0";
    auto word = memory.word(e.area, e.channel);
    if (e.bit >= 0) return (word >> e.bit) & 1 ? "1" : "0";
    return devicemodel::hex_text(word, 4);
}

}  // namespace

// QQMR registers a list (kept until the next QQMR or `**`); QQIR reads it (§6.9, §6.10).
Answer composite(const CommandRow&, Context& c) {
    auto sub = c.text.substr(0, std::min<std::size_t>(2, c.text.size()));
    auto rest = c.text.substr(sub.size());
    if (sub == "IR") {
        if (!rest.empty() || !c.state.composite) return Answer::error();   // no list yet: 01 (inferred)
        std::string data;
        for (const auto& e : *c.state.composite) data += (data.empty() ? "" : ",") + composite_item(e, c.memory);
        return Answer::ok(std::move(data));
    }
    if (sub != "MR") return {Answer::Kind::Unknown, {}, {}};
    std::vector<QqEntry> entries;
    std::size_t data_chars = 0;
    for (std::size_t at = 0; at <= rest.size();) {
        auto comma = rest.find(',', at);
        auto piece = rest.substr(at, comma == std::string_view::npos ? std::string_view::npos : comma - at);
        auto entry = composite_entry(piece, c.link.options().map);
        if (!entry) return Answer::error();
        data_chars += (entries.empty() ? 0 : 1) + (entry->bit >= 0 ? 1 : 4);
        entries.push_back(*entry);
        if (comma == std::string_view::npos) break;
        at = comma + 1;
    }
    // QQIR's answer must fit one record too: `@00QQIR00` + data + FCS `*` CR.
    if (data_chars + 13 > kMaxRecordBytes) return Answer::error();
    c.state.composite = std::move(entries);
    return Answer::ok();
}

namespace {

std::vector<std::uint8_t>& image_of(const CommandRow& row, Context& c) {
    return row.code[1] == 'E' ? c.link.environment() : c.link.object();
}

}  // namespace

// RE/RP (§6.16, §6.17): byte address 4 hex + word count (RE: hex per §5-15,
// RP: decimal per the list; "0001"–"0009" read the same either way). A word
// is two bytes of the image, the first one high (inferred: an opaque image).
Answer read_image(const CommandRow& row, Context& c) {
    if (c.text.size() != 8) return Answer::error();
    auto address = hex(c.text.substr(0, 4));
    auto count = row.code == "RE" ? hex(c.text.substr(4, 4)) : decimal(c.text.substr(4, 4));
    const auto& image = image_of(row, c);
    if (!address || !count || *count == 0 || *count > kMaxImageWords || *count * 4 > kMaxResponseData ||
        *address + 2ull * *count > image.size())
        return Answer::error();
    std::string data;
    for (std::uint32_t i = 0; i < *count; ++i)
        data += devicemodel::hex_text(static_cast<std::uint32_t>(image[*address + 2 * i] << 8 | image[*address + 2 * i + 1]), 4);
    return Answer::ok(std::move(data));
}

// WE/WP: address 0000 starts a download, FFFF with no data ends it (§6.15).
Answer write_image(const CommandRow& row, Context& c) {
    if (c.text.size() < 4) return Answer::error();
    auto address = hex(c.text.substr(0, 4));
    auto data = c.text.substr(4);
    if (!address) return Answer::error();
    if (*address == 0xFFFF) return data.empty() ? Answer::ok() : Answer::error();
    auto& image = image_of(row, c);
    auto words = data.size() / 4;
    if (data.empty() || data.size() % 4 != 0 || words > kMaxImageWords || *address + 2 * words > image.size())
        return Answer::error();
    std::vector<std::uint16_t> values;
    for (std::size_t i = 0; i < words; ++i) {
        auto v = hex(data.substr(4 * i, 4));
        if (!v) return Answer::error();
        values.push_back(static_cast<std::uint16_t>(*v));
    }
    for (std::size_t i = 0; i < words; ++i) {
        image[*address + 2 * i] = static_cast<std::uint8_t>(values[i] >> 8);
        image[*address + 2 * i + 1] = static_cast<std::uint8_t>(values[i]);
    }
    return Answer::ok();
}

}  // namespace slmp::hostlink
