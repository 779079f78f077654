// The client-side decoders of protocol/client_commands.hpp against the
// simulator's own answers, in both codecs and both frames: what the slmp CLI
// reads back is what the engine wrote. (The request bytes of these builders are
// checked against the manuals' examples in tests/integration/test_cli_request_bytes.cpp.)
#include "protocol/client_commands.hpp"
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;
namespace client = protocol::client;

namespace {

client::Response answer(devicemodel::Cpu& cpu, const std::vector<std::uint8_t>& request) {
    auto out = run(cpu, request);
    auto response = client::parse_response(out.response);
    REQUIRE(response);
    return *response;
}

client::FrameOptions frame(protocol::FrameKind kind, protocol::Codec codec) {
    client::FrameOptions options;
    options.kind = kind;
    options.codec = codec;
    options.serial = 0x4321;
    return options;
}

}  // namespace

TEST_CASE("client decoders read the engine's answers in every codec and frame", "[client]") {
    auto cpu = make_cpu("R08CPU");
    auto kind = GENERATE(protocol::FrameKind::E3, protocol::FrameKind::E4);
    auto codec = GENERATE(protocol::Codec::Binary, protocol::Codec::Ascii);
    auto options = frame(kind, codec);

    SECTION("0101 type name") {
        auto type = client::decode_type_name(answer(cpu, client::read_type_name(options)));
        REQUIRE(type);
        CHECK(type->model == "R08CPU");
        CHECK(type->model_code == 0x4801);
    }
    SECTION("0619 self test") {
        auto echoed = client::decode_self_test(answer(cpu, client::self_test(options, "ABCDE")));
        CHECK(echoed == std::optional<std::string>("ABCDE"));
    }
    SECTION("error information of an error answer") {
        auto start = devicemodel::parse_address("D0");
        auto response = answer(cpu, client::read_words(options, *start, 961));
        CHECK(response.end_code == 0xC051);
        auto info = client::decode_error_info(response);
        REQUIRE(info);
        CHECK(info->command == 0x0401);
        CHECK(info->subcommand == 0x0000);
        CHECK(info->route == protocol::Route{});
    }
}

TEST_CASE("client decoders refuse answers of the wrong shape", "[client]") {
    client::Response response;
    response.header.codec = protocol::Codec::Binary;
    response.data = {0x05, 0x00, 'A', 'B'};   // count 5, two bytes
    CHECK_FALSE(client::decode_self_test(response));
    CHECK_FALSE(client::decode_type_name(response));
    CHECK_FALSE(client::decode_error_info(response));
}

TEST_CASE("describe() names the end codes real CPUs send, and families it cannot tell apart", "[client][end_code]") {
    using protocol::describe;
    using protocol::end_code;
    CHECK(describe(end_code(0xC054)) == "random/monitor word point count out of range");
    CHECK(describe(end_code(0xC810)) == "remote password does not match");
    CHECK(describe(end_code(0xC813)) == "remote password error (retry/lock-out family C810-C815)");
    CHECK(describe(end_code(0x4A99)) == "error detected by the CPU module (4xxx: see the CPU's manual)");
    CHECK(describe(end_code(0xD123)) == "end code not described; see the CPU's or module's manual");
}
