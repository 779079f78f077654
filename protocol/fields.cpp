#include "protocol/fields.hpp"

#include "protocol/hex.hpp"

namespace slmp::protocol {

using devicemodel::DeviceSpec;
using devicemodel::Radix;

namespace {

int ascii_radix(const DeviceSpec& spec, const CodecOptions& options) {
    if (spec.symbol == "ZR" && options.zr_ascii_hex) return 16;
    return static_cast<int>(spec.radix);
}

std::size_t code_bytes(DeviceForm form) { return form == DeviceForm::Q ? 1 : 2; }
std::size_t number_bytes(DeviceForm form) { return form == DeviceForm::Q ? 3 : 4; }
std::size_t ascii_code_chars(DeviceForm form) { return form == DeviceForm::Q ? 2 : 4; }

}  // namespace

FieldReader::FieldReader(Codec codec, std::span<const std::uint8_t> data, CodecOptions options)
    : codec_(codec), data_(data), options_(options) {}

void FieldReader::fail(EndCode code, std::string_view what) {
    if (ok()) {
        error_ = code;
        error_field_ = what;
    }
}

std::span<const std::uint8_t> FieldReader::take(std::size_t count, std::string_view what) {
    if (!ok()) return {};
    if (remaining() < count) {
        fail(EndCode::LengthMismatch, what);
        pos_ = data_.size();
        return {};
    }
    auto span = data_.subspan(pos_, count);
    pos_ += count;
    return span;
}

std::uint32_t FieldReader::number(std::size_t bytes, std::string_view what) {
    if (codec_ == Codec::Binary) {
        auto field = take(bytes, what);
        std::uint32_t value = 0;
        for (std::size_t i = 0; i < field.size(); ++i) value |= std::uint32_t{field[i]} << (8 * i);
        return value;
    }
    auto field = take(bytes * 2, what);
    if (field.empty()) return 0;
    auto value = parse_hex(field);
    if (!value) fail(EndCode::AsciiConversion, what);
    return value.value_or(0);
}

std::uint8_t FieldReader::u8(std::string_view what) { return static_cast<std::uint8_t>(number(1, what)); }
std::uint16_t FieldReader::u16(std::string_view what) { return static_cast<std::uint16_t>(number(2, what)); }
std::uint32_t FieldReader::u32(std::string_view what) { return number(4, what); }

DeviceField FieldReader::device(DeviceForm form, std::string_view what) {
    DeviceField field;
    if (codec_ == Codec::Binary) {
        // Binary: number first, then code (§3.3).
        field.number = number(number_bytes(form), what);
        field.code = static_cast<std::uint16_t>(number(code_bytes(form), what));
        field.spec = form == DeviceForm::Q ? devicemodel::find_by_q_code(static_cast<std::uint8_t>(field.code))
                                           : devicemodel::find_by_iqr_code(field.code);
        return field;
    }
    // ASCII: code first, then the number in the device's own radix; leading
    // zeros may be sent as spaces (§5.4).
    auto code = take(ascii_code_chars(form), what);
    auto digits = take(ascii_number_digits(form), what);
    if (!ok()) return field;
    field.spec = devicemodel::find_by_ascii(
        std::string_view(reinterpret_cast<const char*>(code.data()), code.size()), code.size());
    int radix = field.spec ? ascii_radix(*field.spec, options_) : 16;
    std::size_t i = 0;
    while (i < digits.size() && digits[i] == ' ') ++i;
    std::uint64_t value = 0;
    for (; i < digits.size(); ++i) {
        auto parsed = parse_hex(digits.subspan(i, 1));
        if (!parsed || static_cast<int>(*parsed) >= radix) {
            fail(EndCode::AsciiConversion, what);
            return field;
        }
        value = value * static_cast<unsigned>(radix) + *parsed;
    }
    field.number = static_cast<std::uint32_t>(value);
    return field;
}

std::vector<std::uint8_t> FieldReader::bits(std::size_t count, std::string_view what) {
    std::vector<std::uint8_t> points(count, 0);
    if (codec_ == Codec::Binary) {
        auto packed = take((count + 1) / 2, what);
        if (packed.empty()) return points;
        for (std::size_t i = 0; i < count; ++i) {
            auto nibble = i % 2 == 0 ? packed[i / 2] >> 4 : packed[i / 2] & 0x0F;
            if (nibble > 1) fail(EndCode::BadRequestContent, what);
            points[i] = nibble & 1;
        }
        return points;
    }
    auto chars = take(count, what);
    for (std::size_t i = 0; i < chars.size(); ++i) {
        if (chars[i] != '0' && chars[i] != '1') fail(EndCode::AsciiConversion, what);
        points[i] = chars[i] == '1';
    }
    return points;
}

std::vector<std::uint16_t> FieldReader::words(std::size_t count, std::string_view what) {
    std::vector<std::uint16_t> values(count, 0);
    for (auto& value : values) {
        value = u16(what);
        if (!ok()) break;
    }
    return values;
}

std::span<const std::uint8_t> FieldReader::raw(std::size_t count, std::string_view what) { return take(count, what); }

bool FieldReader::finish() {
    if (ok() && remaining() != 0) fail(EndCode::LengthMismatch, "data after the last field");
    return ok();
}

void FieldWriter::number(std::uint32_t value, std::size_t bytes) {
    if (codec_ == Codec::Binary) {
        for (std::size_t i = 0; i < bytes; ++i) out_.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
    } else {
        append_hex(out_, value, static_cast<unsigned>(bytes * 2));
    }
}

void FieldWriter::device(DeviceForm form, const devicemodel::DeviceAddress& address) {
    const auto& spec = *address.spec;
    if (codec_ == Codec::Binary) {
        number(address.number, number_bytes(form));
        number(form == DeviceForm::Q ? static_cast<std::uint16_t>(spec.q_code) : spec.iqr_code, code_bytes(form));
        return;
    }
    for (char c : devicemodel::ascii_name(spec, ascii_code_chars(form))) out_.push_back(static_cast<std::uint8_t>(c));
    auto radix = static_cast<std::uint32_t>(ascii_radix(spec, options_));
    auto digits = ascii_number_digits(form);
    std::vector<std::uint8_t> text(digits, '0');
    auto value = address.number;
    for (std::size_t i = digits; i-- > 0 && value != 0; value /= radix)
        text[i] = static_cast<std::uint8_t>("0123456789ABCDEF"[value % radix]);
    out_.insert(out_.end(), text.begin(), text.end());
}

void FieldWriter::bits(std::span<const std::uint8_t> points) {
    if (codec_ == Codec::Binary) {
        for (std::size_t i = 0; i < points.size(); i += 2) {
            std::uint8_t byte = static_cast<std::uint8_t>((points[i] ? 1 : 0) << 4);
            if (i + 1 < points.size() && points[i + 1]) byte |= 1;
            out_.push_back(byte);
        }
        return;
    }
    for (auto p : points) out_.push_back(p ? '1' : '0');
}

void FieldWriter::words(std::span<const std::uint16_t> values) {
    for (auto v : values) u16(v);
}

void FieldWriter::raw(std::span<const std::uint8_t> bytes) { out_.insert(out_.end(), bytes.begin(), bytes.end()); }

}  // namespace slmp::protocol
