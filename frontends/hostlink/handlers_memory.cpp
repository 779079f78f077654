// The area reads and writes (§6.1–§6.6). Every field, count and range is
// checked before the first write, so a refused request changes nothing.
#include "devicemodel/hex.hpp"
#include "frontends/hostlink/command_table.hpp"

namespace slmp::hostlink {

namespace {


bool fits(std::uint64_t start, std::uint64_t count, std::uint64_t size) { return count > 0 && start + count <= size; }

// Hex characters per element: 8 for a VR, 4 for a channel or word.
std::size_t width_of(Area area) { return info(area).element == Element::LongWord ? 8 : 4; }

// "CCCRR" (§4): bit index 16·CCC + RR; RR above 15 names no bit.
std::optional<std::uint32_t> bit_address(std::string_view text) {
    auto channel = decimal(text.substr(0, 3));
    auto bit = decimal(text.substr(3, 2));
    if (!channel || !bit || *bit > 15) return std::nullopt;
    return *channel * 16 + *bit;
}

}  // namespace

Answer read_words(const CommandRow& row, Context& c) {
    if (c.text.size() != 8) return Answer::error();
    auto start = decimal(c.text.substr(0, 4));
    auto count = decimal(c.text.substr(4, 4));
    if (!start || !count || !fits(*start, *count, c.link.options().map.size(row.area))) return Answer::error();
    auto width = width_of(row.area);
    if (*count * width > kMaxResponseData) return Answer::error();   // §3.3: one record, never split
    std::string data;
    for (std::uint32_t i = 0; i < *count; ++i) {
        if (row.area == Area::Vr) data += devicemodel::hex_text(c.memory.long_word(*start + i), 8);
        else data += devicemodel::hex_text(c.memory.word(row.area, *start + i), 4);
    }
    return Answer::ok(std::move(data));
}

Answer write_words(const CommandRow& row, Context& c) {
    if (c.text.size() < 4) return Answer::error();
    auto start = decimal(c.text.substr(0, 4));
    auto data = c.text.substr(4);
    auto width = width_of(row.area);
    // No count field: the data length gives it; a partial word is an error (§6.4, inferred).
    if (!start || data.empty() || data.size() % width != 0) return Answer::error();
    auto count = static_cast<std::uint32_t>(data.size() / width);
    if (!fits(*start, count, c.link.options().map.size(row.area))) return Answer::error();
    std::vector<std::uint32_t> values;
    for (std::uint32_t i = 0; i < count; ++i) {
        auto value = hex(data.substr(i * width, width));
        if (!value) return Answer::error();
        values.push_back(*value);
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        if (row.area == Area::Vr) c.memory.set_long_word(*start + i, values[i]);
        else c.memory.set_word(row.area, *start + i, static_cast<std::uint16_t>(values[i]));
    }
    return Answer::ok();
}

Answer read_bits(const CommandRow& row, Context& c) {
    if (c.text.size() != 9) return Answer::error();
    auto first = bit_address(c.text.substr(0, 5));
    auto count = decimal(c.text.substr(5, 4));
    // Bits run on across channels: 00115 is followed by 00200 (inferred).
    if (!first || !count || !fits(*first, *count, 16ull * c.link.options().map.size(row.area)) ||
        *count > kMaxResponseData)
        return Answer::error();
    std::string data;
    for (std::uint32_t i = 0; i < *count; ++i) data += c.memory.bit(row.area, *first + i) ? '1' : '0';
    return Answer::ok(std::move(data));
}

namespace {

// "0"/"1" per point after an address of `address_width` digits, applied to
// `first`… only when every character is a 0 or 1 and the run fits `points`.
template <typename Set>
Answer write_points(Context& c, std::optional<std::uint32_t> first, std::size_t address_width, std::uint64_t points,
                    Set&& set) {
    auto data = c.text.substr(address_width);
    if (!first || data.empty() || !fits(*first, data.size(), points)) return Answer::error();
    for (char ch : data)
        if (ch != '0' && ch != '1') return Answer::error();
    for (std::size_t i = 0; i < data.size(); ++i) set(*first + static_cast<std::uint32_t>(i), data[i] == '1');
    return Answer::ok();
}

}  // namespace

Answer write_bits(const CommandRow& row, Context& c) {
    if (c.text.size() < 5) return Answer::error();
    auto area = row.area;
    return write_points(c, bit_address(c.text.substr(0, 5)), 5, 16ull * c.link.options().map.size(area),
                        [&c, area](std::uint32_t index, bool on) { c.memory.set_bit(area, index, on); });
}

Answer read_flags(const CommandRow& row, Context& c) {
    if (c.text.size() != 8) return Answer::error();
    auto start = decimal(c.text.substr(0, 4));
    auto count = decimal(c.text.substr(4, 4));
    if (!start || !count || !fits(*start, *count, c.link.options().map.size(row.area)) || *count > kMaxResponseData)
        return Answer::error();
    std::string data;
    for (std::uint32_t i = 0; i < *count; ++i) data += c.memory.bit(row.area, *start + i) ? '1' : '0';
    return Answer::ok(std::move(data));
}

Answer write_flags(const CommandRow& row, Context& c) {
    if (c.text.size() < 4) return Answer::error();
    auto area = row.area;
    return write_points(c, decimal(c.text.substr(0, 4)), 4, c.link.options().map.size(area),
                        [&c, area](std::uint32_t index, bool on) { c.memory.set_bit(area, index, on); });
}

}  // namespace slmp::hostlink
