// Label access: Array Label Read/Write 041A/141A, Label Read/Write Random
// 041C/141B (subcommand 0000). Names are resolved by the CPU's LabelTable
// (devicemodel/labels.hpp); this file only moves fields.
// Spec: SLMP Reference Manual §5.3; the end codes are chosen (the manuals
// name the conditions, never the codes) and listed in docs/labels.md:
//   40C0  the name does not resolve: no such label or member, "Access from
//         External Device" off (real-CPU measurements), a forbidden form
//         (AAA.3, K4AAA, BBB[XXX]), %n not registered or abbreviating an
//         array, an element index past the array, a name that stops at a
//         structure or timer;
//   C05C  the name resolves but the request asks what the label cannot give:
//         unit spec not 0/1 or not matching the type, fixed value not 00,
//         041A/141A on a timer-family member or a 2-D/3-D bit array, a length
//         that is 0, not whole elements, past the array's end, or (141B) not
//         the type's length; zero points;
//   CEE1/CEE2  request/response data over 1920 bytes (§2.1, JA 4.4);
//   C050/C061  the codec's: ASCII not hex, data short or left over.
// Check order: every field of an entry, then its name, then its unit and
// length, entry by entry; memory is touched only when the whole request passed.
#include <string>
#include <vector>

#include "devicemodel/labels.hpp"
#include "protocol/commands/handlers.hpp"
#include "protocol/label_values.hpp"
#include "devicemodel/utf16.hpp"

namespace slmp::protocol::commands {
namespace {

using devicemodel::BasicType;
using devicemodel::LabelRef;

// §2.1: at most 1920 bytes of data in a message (taken per message, request
// and response each, counted as sent: ASCII characters in ASCII frames).
constexpr std::size_t kMaxDataBytes = 1920;
constexpr std::uint8_t kUnitBit = 0, kUnitByte = 1;

std::string read_name(FieldReader& in) {
    auto length = in.u16("label name length");
    std::vector<std::uint16_t> units;
    for (std::uint16_t i = 0; i < length && in.ok(); ++i) units.push_back(in.u16("label name"));
    return devicemodel::utf16_to_utf8(units);
}

// The names a request carries, as the call monitor and recordings show them
// (CommandContext::named): the first eight, then how many more.
void note_name(CommandContext& ctx, const std::string& name, std::uint16_t index, std::uint16_t points) {
    constexpr std::uint16_t kShown = 8;
    if (index < kShown) ctx.named += (index ? ", " : "") + name;
    if (index == kShown) ctx.named += " +" + std::to_string(points - kShown) + " more";
}

std::string read_entry_name(CommandContext& ctx, std::uint16_t index, std::uint16_t points) {
    auto name = read_name(ctx.in);
    if (ctx.in.ok()) note_name(ctx, name, index, points);
    return name;
}

// Abbreviation points and the registered prefixes (%1 ... %n).
std::vector<std::string> read_abbreviations(FieldReader& in) {
    auto count = in.u16("abbreviation points");
    std::vector<std::string> out;
    for (std::uint16_t i = 0; i < count && in.ok(); ++i) out.push_back(read_name(in));
    return out;
}

EndCode resolve(CommandContext& ctx, const std::string& name, const std::vector<std::string>& abbreviations,
                LabelRef& ref) {
    devicemodel::LabelFault fault{};
    auto found = ctx.cpu.labels().resolve(name, abbreviations, fault);
    if (!found) return EndCode::LabelNotFound;
    ref = *found;
    return EndCode::Ok;
}

std::uint32_t element_bytes(const LabelRef& ref) { return devicemodel::data_bytes(ref.basic, ref.chars); }

// 041A/141A: which elements an entry covers. Unit 0 counts bits, unit 1 bytes.
EndCode array_span(const LabelRef& ref, std::uint8_t unit, std::uint8_t fixed, std::uint16_t length,
                   std::uint32_t& count) {
    if (fixed != 0 || (unit != kUnitBit && unit != kUnitByte)) return EndCode::BadRequestContent;
    // ZH §2.1: not the timer family, not 2-D/3-D bit arrays.
    if (ref.timer_member || (ref.basic == BasicType::Bit && ref.array_dims >= 2)) return EndCode::BadRequestContent;
    if ((unit == kUnitBit) != (ref.basic == BasicType::Bit)) return EndCode::BadRequestContent;
    if (unit == kUnitBit) {
        count = length;
    } else {
        if (length % element_bytes(ref) != 0) return EndCode::BadRequestContent;
        count = length / element_bytes(ref);
    }
    if (count == 0 || count > ref.elements) return EndCode::BadRequestContent;
    return EndCode::Ok;
}

struct Write {
    LabelRef ref;
    std::vector<std::vector<std::uint16_t>> elements;
};

void apply_writes(CommandContext& ctx, const std::vector<Write>& writes) {
    for (const auto& w : writes)
        for (std::uint32_t i = 0; i < w.elements.size(); ++i)
            devicemodel::write_element(ctx.cpu.memory(), w.ref, i, w.elements[i]);
}

// What every label command starts with: the 1920-byte limit on the request
// data, the point count (0 is refused) and the abbreviation definitions.
struct Preamble {
    std::uint16_t points = 0;
    std::vector<std::string> abbreviations;
};

EndCode read_preamble(CommandContext& ctx, const char* points_field, Preamble& out) {
    if (ctx.in.remaining() > kMaxDataBytes) return EndCode::RequestTooLarge;
    out.points = ctx.in.u16(points_field);
    out.abbreviations = read_abbreviations(ctx.in);
    if (!ctx.in.ok()) return ctx.in.error();
    if (out.points == 0) return EndCode::BadRequestContent;
    return EndCode::Ok;
}

EndCode finish_response(CommandContext& ctx) {
    return ctx.out.bytes().size() > kMaxDataBytes ? EndCode::ResponseTooLarge : EndCode::Ok;
}

}  // namespace

EndCode array_label_read(CommandContext& ctx) {
    Preamble preamble;
    if (auto code = read_preamble(ctx, "array points", preamble); code != EndCode::Ok) return code;
    const auto points = preamble.points;
    const auto& abbreviations = preamble.abbreviations;
    struct Entry {
        LabelRef ref;
        std::uint8_t unit;
        std::uint16_t length;
        std::uint32_t count;
    };
    std::vector<Entry> entries;
    for (std::uint16_t p = 0; p < points; ++p) {
        auto name = read_entry_name(ctx, p, points);
        Entry e{};
        e.unit = ctx.in.u8("read unit specification");
        auto fixed = ctx.in.u8("fixed value");
        e.length = ctx.in.u16("read array data length");
        if (!ctx.in.ok()) return ctx.in.error();
        if (auto code = resolve(ctx, name, abbreviations, e.ref); code != EndCode::Ok) return code;
        if (auto code = array_span(e.ref, e.unit, fixed, e.length, e.count); code != EndCode::Ok) return code;
        entries.push_back(e);
    }
    if (!ctx.in.finish()) return ctx.in.error();

    const auto& memory = ctx.cpu.memory();
    ctx.out.u16(points);
    for (const auto& e : entries) {
        ctx.out.u8(static_cast<std::uint8_t>(e.ref.basic));
        ctx.out.u8(e.unit);   // echoes the request (inferred, §2.7)
        ctx.out.u16(e.length);
        if (e.unit == kUnitBit) {
            // Bits packed from bit 0 of the first word upward, unused bits 0 (§2.6).
            std::vector<std::uint16_t> packed((e.count + 15) / 16, 0);
            for (std::uint32_t i = 0; i < e.count; ++i)
                if (devicemodel::read_element(memory, e.ref, i)[0] & 1)
                    packed[i / 16] = static_cast<std::uint16_t>(packed[i / 16] | 1u << (i % 16));
            ctx.out.words(packed);
        } else {
            for (std::uint32_t i = 0; i < e.count; ++i)
                write_label_value(ctx.out, e.ref.basic, devicemodel::read_element(memory, e.ref, i));
        }
    }
    return finish_response(ctx);
}

EndCode array_label_write(CommandContext& ctx) {
    Preamble preamble;
    if (auto code = read_preamble(ctx, "array points", preamble); code != EndCode::Ok) return code;
    const auto points = preamble.points;
    const auto& abbreviations = preamble.abbreviations;
    std::vector<Write> writes;
    for (std::uint16_t p = 0; p < points; ++p) {
        auto name = read_entry_name(ctx, p, points);
        auto unit = ctx.in.u8("write unit specification");
        auto fixed = ctx.in.u8("fixed value");
        auto length = ctx.in.u16("write array data length");
        if (!ctx.in.ok()) return ctx.in.error();
        Write w;
        std::uint32_t count = 0;
        if (auto code = resolve(ctx, name, abbreviations, w.ref); code != EndCode::Ok) return code;
        if (auto code = array_span(w.ref, unit, fixed, length, count); code != EndCode::Ok) return code;
        if (unit == kUnitBit) {
            // §2.8: bit data rounded up to whole words.
            auto packed = ctx.in.words((count + 15) / 16, "write data");
            for (std::uint32_t i = 0; i < count && ctx.in.ok(); ++i)
                w.elements.push_back({static_cast<std::uint16_t>(packed[i / 16] >> (i % 16) & 1)});
        } else {
            auto words = devicemodel::basic_words(w.ref.basic, w.ref.chars);
            for (std::uint32_t i = 0; i < count && ctx.in.ok(); ++i)
                w.elements.push_back(read_label_value(ctx.in, w.ref.basic, words));
        }
        if (!ctx.in.ok()) return ctx.in.error();
        writes.push_back(std::move(w));
    }
    if (!ctx.in.finish()) return ctx.in.error();
    apply_writes(ctx, writes);
    return EndCode::Ok;
}

EndCode label_read_random(CommandContext& ctx) {
    Preamble preamble;
    if (auto code = read_preamble(ctx, "read data points", preamble); code != EndCode::Ok) return code;
    const auto points = preamble.points;
    const auto& abbreviations = preamble.abbreviations;
    std::vector<LabelRef> refs(points);
    for (std::uint16_t p = 0; p < points; ++p) {
        auto name = read_entry_name(ctx, p, points);
        if (!ctx.in.ok()) return ctx.in.error();
        if (auto code = resolve(ctx, name, abbreviations, refs[p]); code != EndCode::Ok) return code;
    }
    if (!ctx.in.finish()) return ctx.in.error();

    ctx.out.u16(points);
    for (const auto& ref : refs) {
        ctx.out.u8(static_cast<std::uint8_t>(ref.basic));
        ctx.out.u8(0);   // spare: undefined on a real CPU, 00 here (§2.9)
        ctx.out.u16(static_cast<std::uint16_t>(element_bytes(ref)));
        write_label_value(ctx.out, ref.basic, devicemodel::read_element(ctx.cpu.memory(), ref, 0));
    }
    return finish_response(ctx);
}

EndCode label_write_random(CommandContext& ctx) {
    Preamble preamble;
    if (auto code = read_preamble(ctx, "write data points", preamble); code != EndCode::Ok) return code;
    const auto points = preamble.points;
    const auto& abbreviations = preamble.abbreviations;
    std::vector<Write> writes;
    for (std::uint16_t p = 0; p < points; ++p) {
        auto name = read_entry_name(ctx, p, points);
        auto length = ctx.in.u16("write data length");
        if (!ctx.in.ok()) return ctx.in.error();
        Write w;
        if (auto code = resolve(ctx, name, abbreviations, w.ref); code != EndCode::Ok) return code;
        // §2.10: the length must be the type's.
        if (length != element_bytes(w.ref)) return EndCode::BadRequestContent;
        w.elements.push_back(read_label_value(ctx.in, w.ref.basic, devicemodel::basic_words(w.ref.basic, w.ref.chars)));
        if (!ctx.in.ok()) return ctx.in.error();
        writes.push_back(std::move(w));
    }
    if (!ctx.in.finish()) return ctx.in.error();
    apply_writes(ctx, writes);
    return EndCode::Ok;
}

}  // namespace slmp::protocol::commands
