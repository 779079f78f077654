// The field codec (protocol/fields.hpp): a FieldReader decodes a sequence of
// fields picked by the input from the rest of the input. Input layout:
//   [0] bit 0 codec (binary/ASCII), bit 1 zr_ascii_hex
//   [1] number of fields n (mod 32), then n op bytes (low 4 bits: the field,
//       high 4 bits: a count for bits/words/raw), then the data the reader gets
// Checked: nothing read past the span (ASan sees it: the data is its own heap
// block), remaining() only shrinks, the error is sticky, raw() stays inside the
// data, bits()/words() return the count asked for, and a plain device that
// decodes cleanly encodes back (FieldWriter) to bytes that decode to the same device.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "protocol/fields.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

using namespace slmp::protocol;

void round_trip(Codec codec, CodecOptions options, DeviceForm form, const DeviceField& field) {
    if (!field.spec) return;
    FieldWriter w(codec, options);
    w.device(form, slmp::devicemodel::DeviceAddress{field.spec, field.number});
    FieldReader again(codec, w.bytes(), options);
    auto back = again.device(form, "device");
    FUZZ_CHECK(again.finish(), "re-encoded %.*s%u does not decode (end code %04X)",
               static_cast<int>(field.spec->symbol.size()), field.spec->symbol.data(), field.number,
               raw(again.error()));
    FUZZ_CHECK(back.spec == field.spec && back.number == field.number, "%.*s%u decodes back as %.*s%u",
               static_cast<int>(field.spec->symbol.size()), field.spec->symbol.data(), field.number,
               back.spec ? static_cast<int>(back.spec->symbol.size()) : 1, back.spec ? back.spec->symbol.data() : "?",
               back.number);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const Codec codec = data[0] & 1 ? Codec::Ascii : Codec::Binary;
    const CodecOptions options{(data[0] & 2) != 0};
    std::size_t ops = data[1] % 32;
    if (size < 2 + ops) return 0;
    std::span<const std::uint8_t> script(data + 2, ops);
    // A block of exactly the data's size, so any read past it is an ASan report.
    const std::vector<std::uint8_t> bytes(data + 2 + ops, data + size);
    const std::span<const std::uint8_t> all(bytes);

    FieldReader r(codec, all, options);
    std::size_t remaining = r.remaining();
    FUZZ_CHECK(remaining == all.size(), "a new reader has %zu of %zu bytes left", remaining, all.size());
    bool failed = false;
    for (auto op : script) {
        const std::size_t count = op >> 4;
        switch (op & 0x0F) {
            case 0: r.u8("u8"); break;
            case 1: r.u16("u16"); break;
            case 2: r.u32("u32"); break;
            case 3:
            case 4: {
                const auto form = (op & 0x0F) == 3 ? DeviceForm::Q : DeviceForm::IQR;
                const bool was_ok = r.ok();
                const auto before = r.remaining();
                auto field = r.device(form, "device");
                if (was_ok && r.ok()) {
                    // Re-read just this field on its own to compare with the writer.
                    FieldReader alone(codec, all.subspan(all.size() - before, before - r.remaining()), options);
                    auto same = alone.device(form, "device");
                    FUZZ_CHECK(alone.finish() && same.spec == field.spec && same.number == field.number,
                               "the same device bytes decode differently alone");
                    round_trip(codec, options, form, field);
                }
                break;
            }
            case 5: r.extended_device(DeviceForm::Q, "extended"); break;
            case 6: r.extended_device(DeviceForm::IQR, "extended"); break;
            case 7: {
                auto points = r.bits(count * 3, "bits");
                FUZZ_CHECK(points.size() == count * 3, "bits(%zu) returned %zu", count * 3, points.size());
                for (auto p : points) FUZZ_CHECK(p <= 1, "a bit point of %u", p);
                break;
            }
            case 8: {
                auto words = r.words(count, "words");
                FUZZ_CHECK(words.size() == count, "words(%zu) returned %zu", count, words.size());
                break;
            }
            case 9: {
                auto span = r.raw(count * 5, "raw");
                FUZZ_CHECK(span.empty() || span.size() == count * 5, "raw(%zu) returned %zu", count * 5, span.size());
                if (!span.empty())
                    FUZZ_CHECK(span.data() >= all.data() && span.data() + span.size() <= all.data() + all.size(),
                               "raw() points outside the data");
                break;
            }
            default: r.finish(); break;
        }
        FUZZ_CHECK(r.remaining() <= remaining, "remaining() grew from %zu to %zu", remaining, r.remaining());
        remaining = r.remaining();
        FUZZ_CHECK(!(failed && r.ok()), "the reader's error was cleared");
        failed = !r.ok();
    }
    r.finish();
    FUZZ_CHECK(r.ok() == (r.error() == EndCode::Ok), "ok() and error() disagree");
    return 0;
}
