// FieldReader / FieldWriter: the encoding rules of the SLMP Reference Manual
// ch. 4 and §5.2, with the manual's own examples, in both codecs.
#include "protocol/fields.hpp"

#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::protocol;
using slmp::test::bytes;
using slmp::test::hex;
using slmp::test::str;
using slmp::test::text;

namespace {

devicemodel::DeviceAddress addr(const char* text) { return *devicemodel::parse_address(text); }

std::string write_device(Codec codec, DeviceForm form, const char* address, CodecOptions options = {}) {
    FieldWriter w(codec, options);
    w.device(form, addr(address));
    return codec == Codec::Binary ? hex(w.bytes()) : str(w.bytes());
}

}  // namespace

TEST_CASE("numbers: little-endian binary, upper-case hex text", "[fields]") {
    SECTION("writer") {
        FieldWriter b(Codec::Binary), a(Codec::Ascii);
        for (auto* w : {&b, &a}) {
            w->u8(0x1A);
            w->u16(0x03FF);
            w->u32(0x4C544F4E);
        }
        CHECK(hex(b.bytes()) == "1A FF 03 4E 4F 54 4C");
        CHECK(str(a.bytes()) == "1A03FF4C544F4E");
    }
    SECTION("reader") {
        auto bin = bytes("1A FF 03 4E 4F 54 4C");
        auto asc = text("1a03FF4C544F4E");   // lower case accepted (manual asks senders for upper case)
        for (auto [codec, data] : {std::pair{Codec::Binary, bin}, std::pair{Codec::Ascii, asc}}) {
            FieldReader r(codec, data);
            CHECK(r.u8("network") == 0x1A);
            CHECK(r.u16("module I/O") == 0x03FF);
            CHECK(r.u32("double word") == 0x4C544F4Eu);
            CHECK(r.finish());
        }
    }
}

TEST_CASE("device fields: the manual's examples (§5.3, §5.4)", "[fields]") {
    SECTION("M1234: decimal device, number converted to binary") {
        CHECK(write_device(Codec::Binary, DeviceForm::IQR, "M1234") == "D2 04 00 00 90 00");
        CHECK(write_device(Codec::Binary, DeviceForm::Q, "M1234") == "D2 04 00 90");
        CHECK(write_device(Codec::Ascii, DeviceForm::IQR, "M1234") == "M***00001234");
        CHECK(write_device(Codec::Ascii, DeviceForm::Q, "M1234") == "M*001234");
    }
    SECTION("B1234: hex device") {
        CHECK(write_device(Codec::Binary, DeviceForm::IQR, "B1234") == "34 12 00 00 A0 00");
        CHECK(write_device(Codec::Binary, DeviceForm::Q, "B1234") == "34 12 00 A0");
        CHECK(write_device(Codec::Ascii, DeviceForm::IQR, "B1234") == "B***00001234");
        CHECK(write_device(Codec::Ascii, DeviceForm::Q, "B1234") == "B*001234");
    }
    SECTION("X: code 9C / \"X***\" / \"X*\"") {
        CHECK(write_device(Codec::Binary, DeviceForm::IQR, "X0") == "00 00 00 00 9C 00");
        CHECK(write_device(Codec::Ascii, DeviceForm::IQR, "X2FFF") == "X***00002FFF");
        CHECK(write_device(Codec::Ascii, DeviceForm::Q, "X2FFF") == "X*002FFF");
    }
    SECTION("iQ-R only devices and 4-character names") {
        CHECK(write_device(Codec::Binary, DeviceForm::IQR, "LTN10") == "0A 00 00 00 52 00");
        CHECK(write_device(Codec::Ascii, DeviceForm::IQR, "LTN10") == "LTN*00000010");
        CHECK(write_device(Codec::Ascii, DeviceForm::IQR, "LSTN1") == "LSTN00000001");
        CHECK(write_device(Codec::Ascii, DeviceForm::Q, "STN1") == "SN000001");
    }
    SECTION("ZR: decimal by default, hex when the profile says so") {
        CHECK(write_device(Codec::Ascii, DeviceForm::Q, "ZR163839") == "ZR163839");
        CHECK(write_device(Codec::Ascii, DeviceForm::Q, "ZR163839", CodecOptions{.zr_ascii_hex = true}) == "ZR027FFF");
        CHECK(write_device(Codec::Binary, DeviceForm::Q, "ZR163839", CodecOptions{.zr_ascii_hex = true}) == "FF 7F 02 B0");
    }
    SECTION("reader, both forms and codecs") {
        struct Case {
            Codec codec;
            DeviceForm form;
            slmp::test::Bytes data;
            const char* symbol;
            std::uint32_t number;
        };
        const Case cases[] = {
            {Codec::Binary, DeviceForm::IQR, bytes("D2 04 00 00 90 00"), "M", 1234},
            {Codec::Binary, DeviceForm::Q, bytes("34 12 00 A0"), "B", 0x1234},
            {Codec::Ascii, DeviceForm::IQR, text("M***00001234"), "M", 1234},
            {Codec::Ascii, DeviceForm::Q, text("B*001234"), "B", 0x1234},
            {Codec::Ascii, DeviceForm::Q, text("D   1234"), "D", 1234},          // spaces for padding and zeros
            {Codec::Ascii, DeviceForm::IQR, text("D   " "    1234"), "D", 1234},
            {Codec::Ascii, DeviceForm::Q, text("X*00001f"), "X", 0x1F},          // lower-case hex digit
            {Codec::Ascii, DeviceForm::Q, text("SN000007"), "STN", 7},
        };
        for (const auto& c : cases) {
            INFO(str(c.data));
            FieldReader r(c.codec, c.data);
            auto field = r.device(c.form, "start device");
            REQUIRE(r.finish());
            REQUIRE(field.spec != nullptr);
            CHECK(field.spec->symbol == c.symbol);
            CHECK(field.number == c.number);
        }
    }
    SECTION("unknown code: the field decodes, spec is null, code kept (binary)") {
        auto data = bytes("64 00 00 00 FF 00");
        FieldReader r(Codec::Binary, data);
        auto field = r.device(DeviceForm::IQR, "start device");
        CHECK(r.finish());
        CHECK(field.spec == nullptr);
        CHECK(field.code == 0x00FF);
        CHECK(field.number == 100);
    }
    SECTION("ASCII digit outside the device's radix -> C050") {
        auto data = text("D*00010A");
        FieldReader r(Codec::Ascii, data);
        r.device(DeviceForm::Q, "start device");
        CHECK(r.error() == EndCode::AsciiConversion);
        CHECK(r.error_field() == "start device");
    }
}

TEST_CASE("bit-unit data: nibbles (first point high) or '0'/'1'", "[fields]") {
    const std::vector<std::uint8_t> points{1, 0, 1, 1, 0};   // §5.7 illustration: M10..M14
    SECTION("writer, odd count pads the last low nibble") {
        FieldWriter b(Codec::Binary), a(Codec::Ascii);
        b.bits(points);
        a.bits(points);
        CHECK(hex(b.bytes()) == "10 11 00");
        CHECK(str(a.bytes()) == "10110");
    }
    SECTION("reader") {
        auto bin = bytes("10 11 00");
        FieldReader rb(Codec::Binary, bin);
        CHECK(rb.bits(5, "write data") == points);
        CHECK(rb.finish());
        auto asc = text("10110");
        FieldReader ra(Codec::Ascii, asc);
        CHECK(ra.bits(5, "write data") == points);
        CHECK(ra.finish());
    }
    SECTION("a nibble above 1 -> C05C; a character other than 0/1 -> C050") {
        auto bin = bytes("12");
        FieldReader rb(Codec::Binary, bin);
        rb.bits(2, "write data");
        CHECK(rb.error() == EndCode::BadRequestContent);
        auto asc = text("1A");
        FieldReader ra(Codec::Ascii, asc);
        ra.bits(2, "write data");
        CHECK(ra.error() == EndCode::AsciiConversion);
    }
}

TEST_CASE("word data: LE bytes / 4 hex digits", "[fields]") {
    const std::vector<std::uint16_t> values{0x1995, 0x1202, 0x1130};
    FieldWriter b(Codec::Binary), a(Codec::Ascii);
    b.words(values);
    a.words(values);
    CHECK(hex(b.bytes()) == "95 19 02 12 30 11");
    CHECK(str(a.bytes()) == "199512021130");
    FieldReader rb(Codec::Binary, b.bytes()), ra(Codec::Ascii, a.bytes());
    CHECK(rb.words(3, "write data") == values);
    CHECK(ra.words(3, "write data") == values);
}

TEST_CASE("raw bytes are the same in both codecs", "[fields]") {
    auto data = text("ABCDE");
    for (auto codec : {Codec::Binary, Codec::Ascii}) {
        FieldReader r(codec, data);
        CHECK(str(r.raw(5, "loopback data")) == "ABCDE");
        FieldWriter w(codec);
        w.raw(data);
        CHECK(str(w.bytes()) == "ABCDE");
    }
}

TEST_CASE("reader errors are sticky and name the field", "[fields]") {
    SECTION("short data -> C061, later reads return zeros") {
        auto data = bytes("01 04 00");
        FieldReader r(Codec::Binary, data);
        CHECK(r.u16("command") == 0x0401);
        CHECK(r.u16("subcommand") == 0);
        CHECK(r.error() == EndCode::LengthMismatch);
        CHECK(r.error_field() == "subcommand");
        CHECK(r.u16("device points") == 0);
        CHECK(r.error_field() == "subcommand");
        CHECK_FALSE(r.finish());
    }
    SECTION("trailing data -> C061 from finish()") {
        auto data = bytes("01 04 00");
        FieldReader r(Codec::Binary, data);
        r.u16("command");
        CHECK(r.remaining() == 1);
        CHECK_FALSE(r.finish());
        CHECK(r.error() == EndCode::LengthMismatch);
    }
    SECTION("non-hex ASCII -> C050, the first error wins") {
        auto data = text("04G1000");
        FieldReader r(Codec::Ascii, data);
        CHECK(r.u16("command") == 0);
        CHECK(r.error() == EndCode::AsciiConversion);
        r.u16("subcommand");   // too short now, but C050 stays
        CHECK(r.error() == EndCode::AsciiConversion);
        CHECK(r.error_field() == "command");
    }
    SECTION("ASCII field with a space inside a number -> C050") {
        auto data = text("04 1");
        FieldReader r(Codec::Ascii, data);
        r.u16("command");
        CHECK(r.error() == EndCode::AsciiConversion);
    }
}
