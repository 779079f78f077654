#include "protocol/fields.hpp"

#include <bit>
#include <cstring>

#include "devicemodel/hex.hpp"

namespace slmp::protocol {

using devicemodel::DeviceSpec;
using devicemodel::Radix;

namespace {

int ascii_radix(const DeviceSpec& spec, const CodecOptions& options) {
    if (spec.symbol == "ZR" && options.zr_ascii_hex) return 16;
    return static_cast<int>(devicemodel::radix_of(spec, options.numbering));
}

std::size_t code_bytes(DeviceForm form) { return form == DeviceForm::Q ? 1 : 2; }
std::size_t number_bytes(DeviceForm form) { return form == DeviceForm::Q ? 3 : 4; }
std::size_t ascii_code_chars(DeviceForm form) { return form == DeviceForm::Q ? 2 : 4; }

const DeviceSpec* ascii_code(std::span<const std::uint8_t> code) {
    if (code.empty()) return nullptr;
    return devicemodel::find_by_ascii(std::string_view(reinterpret_cast<const char*>(code.data()), code.size()),
                                      code.size());
}

// Binary modifier word: byte 0 = register number, byte 1 high nibble 4 = Z,
// 8 = LZ (§7.5, §7.6).
Modifier binary_modifier(std::uint16_t word) {
    auto kind = (word >> 12) & 0xF;
    Modifier m;
    m.number = static_cast<std::uint8_t>(word & 0xFF);
    m.reg = kind == 0x4 ? Modifier::Register::Z : kind == 0x8 ? Modifier::Register::LZ : Modifier::Register::None;
    return m;
}

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
    auto value = devicemodel::parse_hex(field);
    if (!value) fail(EndCode::AsciiConversion, what);
    return value.value_or(0);
}

std::uint8_t FieldReader::u8(std::string_view what) { return static_cast<std::uint8_t>(number(1, what)); }
std::uint16_t FieldReader::u16(std::string_view what) { return static_cast<std::uint16_t>(number(2, what)); }
std::uint32_t FieldReader::u32(std::string_view what) { return number(4, what); }

std::vector<std::uint8_t> FieldReader::octets(std::size_t count, std::string_view what) {
    std::vector<std::uint8_t> value(count);
    for (std::size_t i = 0; i < count && ok(); ++i) {
        const auto octet = static_cast<std::uint8_t>(number(1, what));
        value[codec_ == Codec::Binary ? count - 1 - i : i] = octet;
    }
    return ok() ? value : std::vector<std::uint8_t>(count);
}

std::uint64_t FieldReader::u64(std::string_view what) {
    auto first = std::uint64_t{number(4, what)};
    auto second = std::uint64_t{number(4, what)};
    return codec_ == Codec::Binary ? first | second << 32 : first << 32 | second;
}

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
    // ASCII: code first, then the number in the device's own radix.
    field.spec = ascii_code(take(ascii_code_chars(form), what));
    field.number = device_number(field.spec, ascii_number_digits(form), what);
    return field;
}

DeviceField FieldReader::device_1e(std::string_view what) {
    DeviceField field;
    if (codec_ == Codec::Binary) {
        field.number = number(4, what);
        field.code = static_cast<std::uint16_t>(number(2, what));
    } else {
        field.code = static_cast<std::uint16_t>(number(2, what));
        field.number = number(4, what);
    }
    // The code is the device name's two characters, high byte first.
    static constexpr std::string_view kNames[] = {"X ", "Y ", "M ", "S ", "B ", "F ", "D ", "W ", "R ",
                                                  "TN", "TS", "TC", "CN", "CS", "CC"};
    const char name[2] = {static_cast<char>(field.code >> 8), static_cast<char>(field.code & 0xFF)};
    const std::string_view text(name, 2);
    for (auto known : kNames)
        if (known == text) field.spec = devicemodel::find_by_ascii(text, 2);
    return field;
}

// Leading zeros may be sent as spaces (§5.4); an unknown device's number is
// read as hex so that the reader stays in step.
std::uint32_t FieldReader::device_number(const DeviceSpec* spec, std::size_t digits_count, std::string_view what) {
    auto digits = take(digits_count, what);
    int radix = spec ? ascii_radix(*spec, options_) : 16;
    std::size_t i = 0;
    while (i < digits.size() && digits[i] == ' ') ++i;
    std::uint64_t value = 0;
    for (; i < digits.size(); ++i) {
        auto parsed = devicemodel::parse_hex(digits.subspan(i, 1));
        if (!parsed || static_cast<int>(*parsed) >= radix) {
            fail(EndCode::AsciiConversion, what);
            return 0;
        }
        value = value * static_cast<unsigned>(radix) + *parsed;
    }
    if (value > 0xFFFFFFFFu) fail(EndCode::BadRequestContent, what);
    return static_cast<std::uint32_t>(value);
}


// ASCII modifier: "000" / "Znn" (Q form), "0000" / "Z nn" / "LZnn" (iQ-R form).
Modifier FieldReader::ascii_modifier(std::size_t width, std::string_view what) {
    auto chars = take(width, what);
    Modifier m;
    if (chars.empty()) return m;
    std::string_view text(reinterpret_cast<const char*>(chars.data()), chars.size());
    if (text.find_first_not_of('0') == std::string_view::npos) return m;
    std::string_view digits;
    if (text.starts_with("LZ")) {
        m.reg = Modifier::Register::LZ;
        digits = text.substr(2);
    } else if (text.starts_with("Z")) {
        m.reg = Modifier::Register::Z;
        digits = text.substr(width == 4 ? 2 : 1);
        if (width == 4 && text[1] != ' ' && text[1] != '0') digits = {};
    }
    if (digits.size() != 2 || digits.find_first_not_of("0123456789") != std::string_view::npos) {
        fail(EndCode::BadRequestContent, what);
        return {};
    }
    m.number = static_cast<std::uint8_t>((digits[0] - '0') * 10 + (digits[1] - '0'));
    return m;
}

DeviceField FieldReader::extended_device(DeviceForm form, std::string_view what) {
    DeviceField field;
    field.extended = true;
    auto& ext = field.extension;
    if (codec_ == Codec::Binary) {
        // device modification (2) | number | code | extension modification (2) |
        // extension (2) | direct memory (1): F9 J, F8 U, FA U3E, 00 none.
        auto device_mod = static_cast<std::uint16_t>(number(2, what));
        field.number = number(number_bytes(form), what);
        field.code = static_cast<std::uint16_t>(number(code_bytes(form), what));
        ext.target_modifier = binary_modifier(static_cast<std::uint16_t>(number(2, what)));
        ext.target = static_cast<std::uint16_t>(number(2, what));
        auto direct = number(1, what);
        ext.device_modifier = binary_modifier(device_mod);
        ext.indirect = (device_mod >> 8 & 0x0F) == 0x8;
        field.spec = form == DeviceForm::Q ? devicemodel::find_by_q_code(static_cast<std::uint8_t>(field.code))
                                           : devicemodel::find_by_iqr_code(field.code);
        switch (direct) {
            case 0x00: ext.kind = DeviceExtension::Kind::None; break;
            case 0xF9: ext.kind = DeviceExtension::Kind::LinkDirect; break;
            case 0xF8: ext.kind = DeviceExtension::Kind::ModuleAccess; break;
            case 0xFA: ext.kind = DeviceExtension::Kind::CpuBuffer; break;
            default: fail(EndCode::BadRequestContent, what);
        }
        if (ext.kind == DeviceExtension::Kind::None && ext.target != 0) fail(EndCode::BadRequestContent, what);
        return field;
    }
    // ASCII: indirect (2) | extension (4) | extension modification (3/4) |
    // code (2/4) | number (6/10) | device modification (3/4).
    const std::size_t modifier_width = form == DeviceForm::Q ? 3 : 4;
    auto indirect = take(2, what);
    auto extension = take(4, what);
    ext.target_modifier = ascii_modifier(modifier_width, what);
    field.spec = ascii_code(take(ascii_code_chars(form), what));
    field.number = device_number(field.spec, form == DeviceForm::Q ? 6 : 10, what);
    ext.device_modifier = ascii_modifier(modifier_width, what);
    if (!ok()) return field;
    // The manual's figure is unreadable on where "@" sits; accept "@0" and "0@".
    std::string_view at(reinterpret_cast<const char*>(indirect.data()), 2);
    ext.indirect = at == "@0" || at == "0@";
    if (!ext.indirect && at != "00") fail(EndCode::BadRequestContent, what);
    std::string_view name(reinterpret_cast<const char*>(extension.data()), 4);
    if (name == "0000") return field;
    auto value = devicemodel::parse_hex(extension.subspan(1));
    if (!value || (name[0] != 'J' && name[0] != 'U')) {
        fail(EndCode::BadRequestContent, what);
        return field;
    }
    ext.target = static_cast<std::uint16_t>(*value);
    ext.kind = name[0] == 'J' ? DeviceExtension::Kind::LinkDirect
               : (*value >= 0x3E0 && *value <= 0x3E3) ? DeviceExtension::Kind::CpuBuffer
                                                      : DeviceExtension::Kind::ModuleAccess;
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
        devicemodel::append_hex(out_, value, static_cast<unsigned>(bytes * 2));
    }
}

void FieldWriter::octets(std::span<const std::uint8_t> value) {
    for (std::size_t i = 0; i < value.size(); ++i) number(value[codec_ == Codec::Binary ? value.size() - 1 - i : i], 1);
}

void FieldWriter::u64(std::uint64_t value) {
    const auto low = static_cast<std::uint32_t>(value), high = static_cast<std::uint32_t>(value >> 32);
    number(codec_ == Codec::Binary ? low : high, 4);
    number(codec_ == Codec::Binary ? high : low, 4);
}

void FieldWriter::device(DeviceForm form, const devicemodel::DeviceAddress& address) {
    const auto& spec = *address.spec;
    if (codec_ == Codec::Binary) {
        number(address.number, number_bytes(form));
        number(form == DeviceForm::Q ? static_cast<std::uint16_t>(spec.q_code) : spec.iqr_code, code_bytes(form));
        return;
    }
    text(devicemodel::ascii_name(spec, ascii_code_chars(form)));
    device_number(spec, address.number, ascii_number_digits(form));
}

void FieldWriter::text(std::string_view characters) { out_.insert(out_.end(), characters.begin(), characters.end()); }

void FieldWriter::device_number(const DeviceSpec& spec, std::uint32_t value, std::size_t digits) {
    auto radix = static_cast<std::uint32_t>(ascii_radix(spec, options_));
    std::string number(digits, '0');
    for (std::size_t i = digits; i-- > 0 && value != 0; value /= radix) number[i] = devicemodel::kHexDigits[value % radix];
    text(number);
}

void FieldWriter::ascii_modifier(const Modifier& modifier, DeviceForm form) {
    const bool q = form == DeviceForm::Q;
    if (modifier.reg == Modifier::Register::None) return text(q ? "000" : "0000");
    std::string digits{static_cast<char>('0' + modifier.number / 10), static_cast<char>('0' + modifier.number % 10)};
    if (modifier.reg == Modifier::Register::LZ) return text("LZ" + digits);
    text((q ? "Z" : "Z ") + digits);
}

void FieldWriter::extended_device(DeviceForm form, const devicemodel::DeviceAddress& address,
                                  const DeviceExtension& extension) {
    using Kind = DeviceExtension::Kind;
    const auto& spec = *address.spec;
    auto modifier_word = [](const Modifier& m) -> std::uint16_t {
        std::uint16_t kind = m.reg == Modifier::Register::Z ? 0x40 : m.reg == Modifier::Register::LZ ? 0x80 : 0x00;
        return static_cast<std::uint16_t>(kind << 8 | m.number);
    };
    if (codec_ == Codec::Binary) {
        number(static_cast<std::uint16_t>(modifier_word(extension.device_modifier) | (extension.indirect ? 0x0800 : 0)), 2);
        number(address.number, number_bytes(form));
        number(form == DeviceForm::Q ? static_cast<std::uint16_t>(spec.q_code) : spec.iqr_code, code_bytes(form));
        number(modifier_word(extension.target_modifier), 2);
        number(extension.target, 2);
        std::uint8_t direct = extension.kind == Kind::LinkDirect     ? 0xF9
                              : extension.kind == Kind::ModuleAccess ? 0xF8
                              : extension.kind == Kind::CpuBuffer    ? 0xFA
                                                                     : 0x00;
        number(direct, 1);
        return;
    }
    text(extension.indirect ? "@0" : "00");
    if (extension.kind == Kind::None) {
        text("0000");
    } else {
        text(extension.kind == Kind::LinkDirect ? "J" : "U");
        devicemodel::append_hex(out_, extension.target, 3);
    }
    ascii_modifier(extension.target_modifier, form);
    text(devicemodel::ascii_name(spec, ascii_code_chars(form)));
    device_number(spec, address.number, form == DeviceForm::Q ? 6 : 10);
    ascii_modifier(extension.device_modifier, form);
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

// Sized once and filled in place: a 960-word read answer is the bulk of the
// simulator's work, and a push_back per byte was most of that.
void FieldWriter::words(std::span<const std::uint16_t> values) {
    const auto at = out_.size();
    if (codec_ == Codec::Binary) {
        out_.resize(at + 2 * values.size());
        auto* p = out_.data() + at;
        if constexpr (std::endian::native == std::endian::little) {   // the wire's order already: one copy
            if (!values.empty()) std::memcpy(p, values.data(), 2 * values.size());
            return;
        }
        for (auto v : values) {
            *p++ = static_cast<std::uint8_t>(v);
            *p++ = static_cast<std::uint8_t>(v >> 8);
        }
        return;
    }
    out_.reserve(at + 4 * values.size());
    for (auto v : values) devicemodel::append_hex(out_, v, 4);
}

void FieldWriter::raw(std::span<const std::uint8_t> bytes) { out_.insert(out_.end(), bytes.begin(), bytes.end()); }

}  // namespace slmp::protocol
