// FieldReader / FieldWriter: the only code that knows binary from ASCII.
// A command handler is written once against these; it never asks which codec
// it has. Rules: SLMP Reference Manual ch. 4, §5.2.
//
// FieldReader has a sticky error: the first bad or missing field records an end
// code and a field name, later reads return zeros. A handler decodes every
// field, calls finish() once, and only then touches device memory — so a
// rejected request never changes anything.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "devicemodel/device_table.hpp"
#include "protocol/end_code.hpp"
#include "protocol/frame.hpp"

namespace slmp::protocol {

// Device specification forms. Q: subcommands 0000/0001 (binary code 1 byte,
// number 3 bytes; ASCII code 2 characters, number 6 digits). IQR: 0002/0003
// (2 bytes / 4 bytes; 4 characters / 8 digits).
enum class DeviceForm : std::uint8_t { Q, IQR };

// Codec choices that depend on the CPU rather than the frame.
struct CodecOptions {
    bool zr_ascii_hex = false;   // number ZR in hex in ASCII frames (the manuals' form)
    devicemodel::Numbering numbering;   // X/Y digits in ASCII frames: hex, or octal on iQ-F
};

// An index register that modifies a number: Z0–Z24 (16-bit) or LZ0–LZ12 (32-bit).
struct Modifier {
    enum class Register : std::uint8_t { None, Z, LZ };
    Register reg = Register::None;
    std::uint8_t number = 0;
    friend bool operator==(const Modifier&, const Modifier&) = default;
};

// What the extended forms (008x, Appendix 1) put around a device: which memory
// it lives in and the index registers that modify it.
struct DeviceExtension {
    enum class Kind : std::uint8_t {
        None,           // a plain device of the CPU
        LinkDirect,     // J(network)\X/Y/B/SB/W/SW
        ModuleAccess,   // U(start I/O ÷ 16)\G
        CpuBuffer,      // U3E0–U3E3\G or \HG
    };
    Kind kind = Kind::None;
    std::uint16_t target = 0;     // network No., start I/O ÷ 16, or 03E0–03E3
    Modifier target_modifier;     // indexes `target` (0403/1402/0801 only)
    Modifier device_modifier;     // indexes the device number
    bool indirect = false;        // "@": the device holds the address of the one meant
};

// A device as it arrived: `spec` is null when the code is not in the device table.
struct DeviceField {
    const devicemodel::DeviceSpec* spec = nullptr;
    std::uint32_t number = 0;
    std::uint16_t code = 0;       // the binary code, or 0 for ASCII
    bool extended = false;        // came in the 008x layout
    DeviceExtension extension;
};

class FieldReader {
public:
    FieldReader(Codec codec, std::span<const std::uint8_t> data, CodecOptions options = {});

    Codec codec() const { return codec_; }
    std::uint8_t u8(std::string_view what);
    std::uint16_t u16(std::string_view what);
    std::uint32_t u32(std::string_view what);
    // A 64-bit value (LREAL labels): 8 bytes little-endian / 16 hex digits, high first.
    std::uint64_t u64(std::string_view what);
    DeviceField device(DeviceForm form, std::string_view what);
    // The 008x layout (Appendix 1): binary 11 bytes (Q form) / 13 (iQ-R form),
    // ASCII 20 / 28 characters with a 10-digit device number in the iQ-R form.
    DeviceField extended_device(DeviceForm form, std::string_view what);
    // The A-compatible 1E layout: binary number (4 bytes) then code (2 bytes,
    // the name's two characters, e.g. 4420 = "D "); ASCII code (4 hex digits)
    // then number (8 hex digits, for every device). Only the A-compatible
    // devices are known (docs/frames.md).
    DeviceField device_1e(std::string_view what);
    // Bit-unit data: one nibble a point (first point high) or one '0'/'1' a point.
    std::vector<std::uint8_t> bits(std::size_t count, std::string_view what);
    std::vector<std::uint16_t> words(std::size_t count, std::string_view what);
    // Bytes carried as they are in both codecs (loopback data, model names).
    std::span<const std::uint8_t> raw(std::size_t count, std::string_view what);
    // A value of `count` octets written as SLMP writes numbers: binary least
    // significant octet first, ASCII two hex digits an octet, most significant
    // first (MAC and IP addresses, JA §3.12). Returned most significant first.
    std::vector<std::uint8_t> octets(std::size_t count, std::string_view what);

    // Fails with C061 when bytes are left over. Returns ok().
    bool finish();
    bool ok() const { return error_ == EndCode::Ok; }
    EndCode error() const { return error_; }
    std::string_view error_field() const { return error_field_; }
    std::size_t remaining() const { return data_.size() - pos_; }

private:
    std::span<const std::uint8_t> take(std::size_t count, std::string_view what);
    std::uint32_t number(std::size_t bytes, std::string_view what);
    std::uint32_t device_number(const devicemodel::DeviceSpec* spec, std::size_t digits, std::string_view what);
    Modifier ascii_modifier(std::size_t width, std::string_view what);
    void fail(EndCode code, std::string_view what);

    Codec codec_;
    std::span<const std::uint8_t> data_;
    CodecOptions options_;
    std::size_t pos_ = 0;
    EndCode error_ = EndCode::Ok;
    std::string_view error_field_;
};

class FieldWriter {
public:
    explicit FieldWriter(Codec codec, CodecOptions options = {}) : codec_(codec), options_(options) {}
    // Writes into `storage`, emptied first: a buffer kept between uses keeps its capacity.
    FieldWriter(Codec codec, CodecOptions options, std::vector<std::uint8_t> storage)
        : codec_(codec), options_(options), out_(std::move(storage)) {
        out_.clear();
    }

    Codec codec() const { return codec_; }
    void u8(std::uint8_t value) { number(value, 1); }
    void u16(std::uint16_t value) { number(value, 2); }
    void u32(std::uint32_t value) { number(value, 4); }
    void u64(std::uint64_t value);
    void device(DeviceForm form, const devicemodel::DeviceAddress& address);
    void extended_device(DeviceForm form, const devicemodel::DeviceAddress& address,
                         const DeviceExtension& extension = {});
    void bits(std::span<const std::uint8_t> points);
    void words(std::span<const std::uint16_t> values);
    void raw(std::span<const std::uint8_t> bytes);
    // The counterpart of FieldReader::octets: `value` most significant octet first.
    void octets(std::span<const std::uint8_t> value);

    std::vector<std::uint8_t>& bytes() { return out_; }

private:
    void number(std::uint32_t value, std::size_t bytes);
    void text(std::string_view characters);
    void device_number(const devicemodel::DeviceSpec& spec, std::uint32_t value, std::size_t digits);
    void ascii_modifier(const Modifier& modifier, DeviceForm form);

    Codec codec_;
    CodecOptions options_;
    std::vector<std::uint8_t> out_;
};

// How many decimal/hex digits an ASCII device number has in this form.
constexpr std::size_t ascii_number_digits(DeviceForm form) { return form == DeviceForm::Q ? 6 : 8; }

}  // namespace slmp::protocol
