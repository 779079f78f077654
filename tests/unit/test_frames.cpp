// Frame headers (scan_frame, encode_frame) and the client-side builders, against
// the complete-frame vectors of the SLMP Reference Manual ch. 4 (A–D).
#include "protocol/client.hpp"
#include "protocol/frame.hpp"
#include "protocol/message.hpp"

#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::protocol;
using namespace slmp::test;

namespace {

// §3.4 A–C: read D100..D102 (0401/0000), timer 0010, own station.
const Bytes kReqA = bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 03 00");
const Bytes kRespA = bytes("D0 00 00 FF FF 03 00 08 00 00 00 95 19 02 12 30 11");
const Bytes kReqB = text("500000FF03FF000018001004010000D*0001000003");
const Bytes kRespB = text("D00000FF03FF0000100000199512021130");
const Bytes kReqC = bytes("54 00 34 12 00 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 03 00");
const Bytes kRespC = bytes("D4 00 34 12 00 00 00 FF FF 03 00 08 00 00 00 95 19 02 12 30 11");
const Bytes kReqCa = text("54001234000000FF03FF000018001004010000D*0001000003");
const Bytes kRespCa = text("D4001234000000FF03FF0000100000199512021130");

FrameScan scan(const Bytes& data, Direction direction = Direction::Request,
               DataCodePolicy policy = DataCodePolicy::Auto) {
    return scan_frame(data, direction, policy, 8192);
}

}  // namespace

TEST_CASE("spec §3.4 byte tables agree with the vectors", "[frames]") {   // signposts: allow (the name ctest lists)
    // ASCII vector B, byte by byte as printed in the spec.
    CHECK(hex(kReqB) ==
          "35 30 30 30 30 30 46 46 30 33 46 46 30 30 30 30 31 38 30 30 31 30 30 34 30 31 30 30 30 30 44 2A 30 30 "
          "30 31 30 30 30 30 30 33");
    CHECK(header_size(FrameKind::E3, Codec::Binary) == 9);
    CHECK(header_size(FrameKind::E4, Codec::Binary) == 13);
    CHECK(header_size(FrameKind::E3, Codec::Ascii) == 18);
    CHECK(header_size(FrameKind::E4, Codec::Ascii) == 26);
}

TEST_CASE("scan_frame reads 3E/4E headers in both codecs", "[frames]") {
    struct Case {
        const char* name;
        const Bytes& frame;
        Direction direction;
        FrameKind kind;
        Codec codec;
        std::uint16_t serial;
        std::uint16_t length;
    };
    const Case cases[] = {
        {"A request", kReqA, Direction::Request, FrameKind::E3, Codec::Binary, 0, 12},
        {"A response", kRespA, Direction::Response, FrameKind::E3, Codec::Binary, 0, 8},
        {"B request", kReqB, Direction::Request, FrameKind::E3, Codec::Ascii, 0, 24},
        {"B response", kRespB, Direction::Response, FrameKind::E3, Codec::Ascii, 0, 16},
        {"C request", kReqC, Direction::Request, FrameKind::E4, Codec::Binary, 0x1234, 12},
        {"C response", kRespC, Direction::Response, FrameKind::E4, Codec::Binary, 0x1234, 8},
        {"C ASCII request", kReqCa, Direction::Request, FrameKind::E4, Codec::Ascii, 0x1234, 24},
        {"C ASCII response", kRespCa, Direction::Response, FrameKind::E4, Codec::Ascii, 0x1234, 16},
    };
    for (const auto& c : cases) {
        INFO(c.name);
        auto s = scan(c.frame, c.direction);
        REQUIRE(s.status == FrameScan::Status::Complete);
        CHECK(s.size == c.frame.size());
        CHECK(s.header.kind == c.kind);
        CHECK(s.header.codec == c.codec);
        CHECK(s.header.serial == c.serial);
        CHECK(s.header.data_length == c.length);
        CHECK(s.header.header_size == header_size(c.kind, c.codec));
        CHECK(s.header.route == Route{0x00, 0xFF, 0x03FF, 0x00});
        // A request is not a response and the other way round.
        auto other = c.direction == Direction::Request ? Direction::Response : Direction::Request;
        CHECK(scan(c.frame, other).status == FrameScan::Status::Garbage);
    }
}

TEST_CASE("scan_frame: route fields and a following frame", "[frames]") {
    SECTION("network 1A station 02 module 03E1 multidrop 1F") {
        auto frame = bytes("50 00 1A 02 E1 03 1F 06 00 10 00 01 01 00 00");
        auto s = scan(frame);
        REQUIRE(s.status == FrameScan::Status::Complete);
        CHECK(s.header.route == Route{0x1A, 0x02, 0x03E1, 0x1F});
        auto text_frame = text("50001A0203E11F000C001001010000");
        auto t = scan(text_frame);
        REQUIRE(t.status == FrameScan::Status::Complete);
        CHECK(t.header.route == Route{0x1A, 0x02, 0x03E1, 0x1F});
    }
    SECTION("the size stops at the end of the first frame") {
        auto two = kReqA;
        two.insert(two.end(), kReqA.begin(), kReqA.end());
        auto s = scan(two);
        CHECK(s.status == FrameScan::Status::Complete);
        CHECK(s.size == kReqA.size());
    }
}

TEST_CASE("scan_frame: data code policy of the port", "[frames]") {
    CHECK(scan(kReqA, Direction::Request, DataCodePolicy::Binary).status == FrameScan::Status::Complete);
    CHECK(scan(kReqB, Direction::Request, DataCodePolicy::Ascii).status == FrameScan::Status::Complete);
    auto wrong = scan(kReqB, Direction::Request, DataCodePolicy::Binary);
    CHECK(wrong.status == FrameScan::Status::Garbage);
    CHECK(wrong.size == kReqB.size());   // nothing in it can start a binary frame
    CHECK(scan(kReqA, Direction::Request, DataCodePolicy::Ascii).status == FrameScan::Status::Garbage);
}

TEST_CASE("scan_frame: length limit", "[frames]") {
    // 3E binary: 9 header bytes + data length.
    SECTION("9 + 8183 = 8192 bytes: allowed, waits for the body") {
        auto head = bytes("50 00 00 FF FF 03 00 F7 1F");
        auto s = scan(head);
        CHECK(s.status == FrameScan::Status::NeedMore);
        CHECK(s.needed == 8192);
    }
    SECTION("9 + 8184 = 8193 bytes: too large") {
        auto head = bytes("50 00 00 FF FF 03 00 F8 1F");
        CHECK(scan(head).status == FrameScan::Status::TooLarge);
    }
    SECTION("ASCII length FFFF: too large") {
        auto head = text("500000FF03FF00FFFF");
        CHECK(scan(head).status == FrameScan::Status::TooLarge);
    }
}

TEST_CASE("encode_frame builds the §3.4 responses", "[frames]") {
    auto data_bin = bytes("00 00 95 19 02 12 30 11");
    auto data_asc = text("0000199512021130");
    const Route own{};
    CHECK(hex(encode_frame(Direction::Response, FrameKind::E3, Codec::Binary, 0, own, data_bin)) == hex(kRespA));
    CHECK(str(encode_frame(Direction::Response, FrameKind::E3, Codec::Ascii, 0, own, data_asc)) == str(kRespB));
    CHECK(hex(encode_frame(Direction::Response, FrameKind::E4, Codec::Binary, 0x1234, own, data_bin)) == hex(kRespC));
    CHECK(str(encode_frame(Direction::Response, FrameKind::E4, Codec::Ascii, 0x1234, own, data_asc)) == str(kRespCa));
    SECTION("D: error response C059 to 0401/0000") {
        auto err_bin = bytes("59 C0 00 FF FF 03 00 01 04 00 00");
        auto err_asc = text("C05900FF03FF0004010000");
        CHECK(hex(encode_frame(Direction::Response, FrameKind::E3, Codec::Binary, 0, own, err_bin)) ==
              "D0 00 00 FF FF 03 00 0B 00 59 C0 00 FF FF 03 00 01 04 00 00");
        CHECK(str(encode_frame(Direction::Response, FrameKind::E3, Codec::Ascii, 0, own, err_asc)) ==
              "D00000FF03FF000016C05900FF03FF0004010000");
    }
}

TEST_CASE("client builders produce the §3.4 requests", "[frames][client]") {
    const auto d100 = *devicemodel::parse_address("D100");
    client::FrameOptions o;
    CHECK(hex(client::read_words(o, d100, 3)) == hex(kReqA));
    o.codec = Codec::Ascii;
    CHECK(str(client::read_words(o, d100, 3)) == str(kReqB));
    o.kind = FrameKind::E4;
    o.serial = 0x1234;
    CHECK(str(client::read_words(o, d100, 3)) == str(kReqCa));
    o.codec = Codec::Binary;
    CHECK(hex(client::read_words(o, d100, 3)) == hex(kReqC));

    SECTION("W1/W3 writes and R1 bit read (3E binary)") {
        client::FrameOptions b;
        const auto m100 = *devicemodel::parse_address("M100");
        std::vector<std::uint8_t> w1{1, 1, 0, 0, 1, 1, 0, 0};
        CHECK(hex(client::write_bits(b, m100, w1)) ==
              "50 00 00 FF FF 03 00 10 00 10 00 01 14 01 00 64 00 00 90 08 00 11 00 11 00");
        std::vector<std::uint16_t> w3{0x1995, 0x1202, 0x1130};
        CHECK(hex(client::write_words(b, d100, w3)) ==
              "50 00 00 FF FF 03 00 12 00 10 00 01 14 00 00 64 00 00 A8 03 00 95 19 02 12 30 11");
        CHECK(hex(client::read_bits(b, m100, 8)) == "50 00 00 FF FF 03 00 0C 00 10 00 01 04 01 00 64 00 00 90 08 00");
        CHECK(hex(client::read_words(b, d100, 3, DeviceForm::IQR)) ==
              "50 00 00 FF FF 03 00 0E 00 10 00 01 04 02 00 64 00 00 00 A8 00 03 00");
    }
}

TEST_CASE("client parses responses", "[frames][client]") {
    for (const Bytes* frame : {&kRespA, &kRespB, &kRespC, &kRespCa}) {
        bool garbage = true;
        auto r = client::parse_response(*frame, &garbage);
        REQUIRE(r.has_value());
        CHECK_FALSE(garbage);
        CHECK(r->end_code == 0);
        CHECK(r->size == frame->size());
        auto reader = r->reader();
        CHECK(reader.words(3, "read data") == std::vector<std::uint16_t>{0x1995, 0x1202, 0x1130});
        CHECK(reader.finish());
    }
    SECTION("an error response") {
        auto frame = bytes("D0 00 00 FF FF 03 00 0B 00 59 C0 00 FF FF 03 00 01 04 00 00");
        auto r = client::parse_response(frame);
        REQUIRE(r.has_value());
        CHECK(r->end_code == 0xC059);
        CHECK(hex(r->data) == "00 FF FF 03 00 01 04 00 00");
    }
    SECTION("incomplete and garbage") {
        bool garbage = true;
        Bytes half(kRespA.begin(), kRespA.begin() + 10);
        CHECK_FALSE(client::parse_response(half, &garbage).has_value());
        CHECK_FALSE(garbage);
        CHECK_FALSE(client::parse_response(kReqA, &garbage).has_value());   // a request, not a response
        CHECK(garbage);
    }
}
