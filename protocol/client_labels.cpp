#include "protocol/client_labels.hpp"

#include "protocol/label_values.hpp"
#include "devicemodel/utf16.hpp"

namespace slmp::protocol::client {
namespace {

using devicemodel::BasicType;

void name(FieldWriter& w, const std::string& text) {
    auto units = devicemodel::utf8_to_utf16(text);
    w.u16(static_cast<std::uint16_t>(units.size()));
    w.words(units);
}

void head(FieldWriter& w, std::size_t points, std::span<const std::string> abbreviations) {
    w.u16(static_cast<std::uint16_t>(points));
    w.u16(static_cast<std::uint16_t>(abbreviations.size()));
    for (const auto& a : abbreviations) name(w, a);
}

}  // namespace

std::vector<std::uint8_t> label_read_random(const FrameOptions& options, std::span<const std::string> names,
                                            std::span<const std::string> abbreviations) {
    return build_request(options, 0x041C, 0x0000, [&](FieldWriter& w) {
        head(w, names.size(), abbreviations);
        for (const auto& n : names) name(w, n);
    });
}

std::vector<std::uint8_t> label_write_random(const FrameOptions& options, std::span<const LabelWrite> writes,
                                             std::span<const std::string> abbreviations) {
    return build_request(options, 0x141B, 0x0000, [&](FieldWriter& w) {
        head(w, writes.size(), abbreviations);
        for (const auto& e : writes) {
            name(w, e.name);
            w.u16(static_cast<std::uint16_t>(e.value.words.size() * 2));
            write_label_value(w, e.value.type, e.value.words);
        }
    });
}

std::vector<std::uint8_t> array_label_read(const FrameOptions& options, std::span<const ArrayRead> reads,
                                           std::span<const std::string> abbreviations) {
    return build_request(options, 0x041A, 0x0000, [&](FieldWriter& w) {
        head(w, reads.size(), abbreviations);
        for (const auto& r : reads) {
            name(w, r.name);
            w.u8(r.bits ? 0 : 1);
            w.u8(0);
            w.u16(r.length);
        }
    });
}

std::vector<std::uint8_t> array_label_write(const FrameOptions& options, std::span<const ArrayWrite> writes,
                                            std::span<const std::string> abbreviations) {
    return build_request(options, 0x141A, 0x0000, [&](FieldWriter& w) {
        head(w, writes.size(), abbreviations);
        for (const auto& e : writes) {
            name(w, e.name);
            const bool bits = e.type == BasicType::Bit;
            w.u8(bits ? 0 : 1);
            w.u8(0);
            if (bits) {
                w.u16(static_cast<std::uint16_t>(e.elements.size()));
                std::vector<std::uint16_t> packed((e.elements.size() + 15) / 16, 0);
                for (std::size_t i = 0; i < e.elements.size(); ++i)
                    if (!e.elements[i].empty() && (e.elements[i][0] & 1))
                        packed[i / 16] = static_cast<std::uint16_t>(packed[i / 16] | 1u << (i % 16));
                w.words(packed);
            } else {
                std::size_t bytes = 0;
                for (const auto& el : e.elements) bytes += el.size() * 2;
                w.u16(static_cast<std::uint16_t>(bytes));
                for (const auto& el : e.elements) write_label_value(w, e.type, el);
            }
        }
    });
}

std::optional<std::vector<LabelData>> decode_label_read(const Response& response, bool array) {
    auto in = response.reader();
    auto points = in.u16("points");
    std::vector<LabelData> out;
    for (std::uint16_t p = 0; p < points && in.ok(); ++p) {
        LabelData d;
        d.type_id = in.u8("data type ID");
        d.unit = in.u8("unit");
        d.length = in.u16("length");
        const auto type = static_cast<BasicType>(d.type_id);
        if (array && d.unit == 0) {
            auto packed = in.words((d.length + 15u) / 16, "bit data");
            for (std::uint32_t i = 0; i < d.length && in.ok(); ++i)
                d.elements.push_back({static_cast<std::uint16_t>(packed[i / 16] >> (i % 16) & 1)});
        } else {
            // Strings are one element of length/2 words; other types fixed-size elements.
            const auto bits = label_value_bits(type);
            const std::uint32_t element = type == BasicType::String || type == BasicType::WString ? d.length
                                          : bits == 64                                         ? 8
                                          : bits == 32                                         ? 4
                                                                                               : 2;
            if (element == 0 || d.length % element) return std::nullopt;
            for (std::uint32_t i = 0; i < d.length / element && in.ok(); ++i)
                d.elements.push_back(read_label_value(in, type, element / 2));
        }
        out.push_back(std::move(d));
    }
    if (!in.finish()) return std::nullopt;
    return out;
}

}  // namespace slmp::protocol::client
