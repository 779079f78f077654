// Proxy mode's reading of the upstream's answers (station/upstream.hpp;
// docs/twin.md, "Proxy"): where a whole answer ends — 3E/4E by its length
// field, 1E (no length field) by the request's command and points — and the
// "upstream" address form.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "config/config.hpp"
#include "config/config_error.hpp"
#include "protocol/engine.hpp"
#include "station/upstream.hpp"

using slmp::station::whole_answer;
using Bytes = std::vector<std::uint8_t>;

namespace {

// The request as a station decodes it (Q26UDEHCPU's port takes 1E).
struct Decoded {
    explicit Decoded(Bytes frame) : bytes(std::move(frame)) {
        request = engine().decode(bytes, slmp::protocol::DataCodePolicy::Auto, {}, false);
        REQUIRE(request.complete());
    }
    static slmp::protocol::Engine& engine() {
        static auto profile = slmp::config::load_profile("Q26UDEHCPU");
        static slmp::devicemodel::Cpu cpu(profile.cpu);
        static slmp::protocol::Engine engine(cpu, profile.port, {});
        return engine;
    }
    Bytes bytes;
    slmp::protocol::Request request;
};

Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }

}  // namespace

TEST_CASE("upstream answer: 3E/4E end at their length field, bytes after it are not theirs", "[upstream]") {
    Decoded read(text("5000" "00" "FF" "03FF" "00" "0018" "0010" "0401" "0000" "D*000100" "0003"));
    const auto answer = text("D000" "00" "FF" "03FF" "00" "0010" "0000" "111122223333" "D000");
    CHECK(whole_answer(Bytes(answer.begin(), answer.begin() + 10), read.request, 0) == std::size_t{0});
    CHECK(whole_answer(answer, read.request, 0) == std::size_t{34});
    CHECK(whole_answer(text("hello, world"), read.request, 0) == std::nullopt);
    CHECK(whole_answer(Bytes{0xD4, 0x00, 0x34, 0x12, 0x00, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, 0x02, 0x00, 0x00, 0x00},
                       read.request, 0) == std::size_t{15});
}

TEST_CASE("upstream answer: 1E from the request's command and points", "[upstream]") {
    Decoded words({0x01, 0xFF, 0x0A, 0x00, 0x64, 0x00, 0x00, 0x00, 0x20, 0x44, 0x03, 0x00});   // D100, 3 words
    CHECK(whole_answer(Bytes{0x81, 0x00, 0x11, 0x11, 0x22}, words.request, 0) == std::size_t{0});
    CHECK(whole_answer(Bytes{0x81, 0x00, 0x11, 0x11, 0x22, 0x22, 0x33, 0x33}, words.request, 0) == std::size_t{8});
    CHECK(whole_answer(Bytes{0x81, 0x50}, words.request, 0) == std::size_t{2});               // an error: its code only
    CHECK(whole_answer(Bytes{0x81, 0x5B}, words.request, 0) == std::size_t{0});
    CHECK(whole_answer(Bytes{0x81, 0x5B, 0x10}, words.request, 0) == std::size_t{3});         // 5B and its abnormal code
    CHECK(whole_answer(Bytes{0x80, 0x00}, words.request, 0) == std::nullopt);                 // another command's answer

    Decoded bits({0x00, 0xFF, 0x0A, 0x00, 0x64, 0x00, 0x00, 0x00, 0x20, 0x4D, 0x05, 0x00});   // M100, 5 points
    CHECK(whole_answer(Bytes{0x80, 0x00, 0x10, 0x01, 0x10}, bits.request, 0) == std::size_t{5});   // a nibble a point

    Decoded monitor({0x09, 0xFF, 0x0A, 0x00});
    CHECK(whole_answer(Bytes{0x89, 0x00, 0x01, 0x00, 0x02, 0x00}, monitor.request, 2) == std::size_t{6});
}

TEST_CASE("upstream address: HOST:PORT, or an error that says the form", "[upstream][config]") {
    using slmp::config::parse_upstream;
    CHECK(parse_upstream("192.168.3.39:5000", "--upstream").text() == "192.168.3.39:5000");
    CHECK(parse_upstream("plc-line3:1025", "--upstream").host == "plc-line3");
    CHECK(parse_upstream("[::1]:5000", "--upstream").host == "::1");
    CHECK(parse_upstream("[::1]:5000", "--upstream").text() == "[::1]:5000");
    for (const char* bad : {"192.168.3.39", ":5000", "plc:0", "plc:65536", "plc:50x", "udp://plc:5000"}) {
        INFO(bad);
        CHECK_THROWS_WITH(parse_upstream(bad, "--upstream"),
                          Catch::Contains("not HOST:PORT") && Catch::Contains("192.168.3.39:5000"));
    }
}
