// The exact bytes the slmp CLI sends, caught by a loopback capture server: the
// commands slmp-sim does not serve yet (remote control, password, random
// access) and the frame options (route, 4E serial, iQ-R form, --password).
// Expected frames are spelled out from the manuals' examples
// (SLMP Reference Manual ch. 5, §5.6, §5.7; SLMP Reference Manual §5.2),
// independently of the encoder under test.
#include <catch2/catch.hpp>

#include <string>

#include "cli_support.hpp"
#include "frames.hpp"

using namespace slmp::test;
using Args = std::vector<std::string>;

namespace {

// 3E binary request to the own station, monitoring timer 0010, around `body`
// (command, subcommand, data).
Bytes binary_3e(const std::string& body_hex) {
    auto body = hex("10 00 " + body_hex);
    auto out = hex("50 00 00 FF FF 03 00");
    out.push_back(static_cast<std::uint8_t>(body.size()));
    out.push_back(static_cast<std::uint8_t>(body.size() >> 8));
    out.insert(out.end(), body.begin(), body.end());
    return out;
}

// The same in ASCII: `body` is command, subcommand and data as characters.
Bytes ascii_3e(const std::string& body) {
    auto with_timer = "0010" + body;
    char length[5];
    std::snprintf(length, sizeof length, "%04X", static_cast<unsigned>(with_timer.size()));
    return text("500000FF03FF00" + std::string(length) + with_timer);
}

// Runs the CLI against a capture server and returns what it sent.
std::vector<Bytes> capture(const Args& args, int expected_exit = 0, CaptureServer::Reply reply = CaptureServer::Reply::Ok,
                           const Bytes& data = {}, RunResult* result = nullptr) {
    CaptureServer server(reply, data, 0xC059);
    auto r = run_cli(target(server.port()) + args);
    INFO("stdout: " << r.out << "\nstderr: " << r.err);
    CHECK(r.exit_code == expected_exit);
    if (result) *result = r;
    return server.requests();
}

}  // namespace

TEST_CASE("slmp run: 1001 with mode and clear mode", "[cli][bytes][remote]") {
    CHECK(capture({"run"}) == std::vector<Bytes>{binary_3e("01 10 00 00 01 00 00 00")});
    // The manual's example: mode 0001 (do not force), clear all — §1.6 full frame.
    CHECK(capture({"run", "--clear", "all"}) ==
          std::vector<Bytes>{hex("50 00 00 FF FF 03 00 0A 00 10 00 01 10 00 00 01 00 02 00")});
    CHECK(capture({"run", "--force", "--clear", "nonlatch"}) == std::vector<Bytes>{binary_3e("01 10 00 00 03 00 01 00")});
    CHECK(capture({"--ascii", "run", "--clear", "all"}) ==
          std::vector<Bytes>{text("500000FF03FF000014" "0010" "1001000000010200")});
    RunResult r;
    capture({"--json", "run", "--force"}, 0, CaptureServer::Reply::Ok, {}, &r);
    CHECK(json_of(r) == nlohmann::json({{"command", "run"}, {"force", true}, {"clear", "none"}, {"ok", true}}));
}

TEST_CASE("slmp stop, pause, latch-clear: 1002, 1003, 1005", "[cli][bytes][remote]") {
    CHECK(capture({"stop"}) == std::vector<Bytes>{binary_3e("02 10 00 00 01 00")});
    CHECK(capture({"--ascii", "stop"}) == std::vector<Bytes>{ascii_3e("100200000001")});
    CHECK(capture({"pause"}) == std::vector<Bytes>{binary_3e("03 10 00 00 01 00")});
    CHECK(capture({"--ascii", "pause", "--force"}) == std::vector<Bytes>{ascii_3e("100300000003")});
    CHECK(capture({"latch-clear"}) == std::vector<Bytes>{binary_3e("05 10 00 00 01 00")});
    RunResult r;
    capture({"stop"}, 0, CaptureServer::Reply::Ok, {}, &r);
    CHECK(r.out == "remote STOP: OK\n");
}

TEST_CASE("slmp reset: 1006, silence is success, an end code is not", "[cli][bytes][remote]") {
    RunResult r;
    CHECK(capture({"--json", "reset"}, 0, CaptureServer::Reply::Silent, {}, &r) ==
          std::vector<Bytes>{binary_3e("06 10 00 00 01 00")});
    CHECK(json_of(r) == nlohmann::json({{"command", "reset"}, {"ok", true}, {"answered", false}}));

    capture({"--ascii", "reset"}, 1, CaptureServer::Reply::EndCode, {}, &r);
    CHECK(r.err == "slmp: the PLC answered end code C059: command or subcommand not supported "
                   "(command 1006/0000, answered by network 00 station FF module I/O 03FF multidrop 00)\n");
}

TEST_CASE("slmp lock/unlock: 1631/1630 with the password as characters", "[cli][bytes][password]") {
    const std::string password = "abcdefghijklmnopqrstuvwxyz";
    CHECK(capture({"--ascii", "unlock", password}) == std::vector<Bytes>{ascii_3e("16300000001A" + password)});
    CHECK(capture({"lock", password}) ==
          std::vector<Bytes>{binary_3e("31 16 00 00 1A 00 61 62 63 64 65 66 67 68 69 6A 6B 6C 6D 6E 6F 70 71 72 73 74 "
                                       "75 76 77 78 79 7A")});
    // --password unlocks on the same connection before the command.
    auto sent = capture({"--password", "pass", "read", "D0"}, 0, CaptureServer::Reply::Ok, hex("2A 00"));
    CHECK(sent == std::vector<Bytes>{binary_3e("30 16 00 00 04 00 70 61 73 73"),
                                     binary_3e("01 04 00 00 00 00 00 A8 01 00")});
}

TEST_CASE("slmp random read: 0403, the manual's example in binary and ASCII", "[cli][bytes][random]") {
    const Args devices{"random", "read", "D0", "TN0", "M100", "X20", "--dword", "D1500", "--dword", "Y160",
                       "--dword", "M1111"};
    const nlohmann::json expected = {
        {"values",
         {{{"device", "D0"}, {"access", "word"}, {"value", 0x1995}},
          {{"device", "TN0"}, {"access", "word"}, {"value", 0x1202}},
          {{"device", "M100"}, {"access", "word"}, {"value", 0x2030}},
          {{"device", "X20"}, {"access", "word"}, {"value", 0x4849}},
          {{"device", "D1500"}, {"access", "dword"}, {"value", 0x4C544F4E}},
          {{"device", "Y160"}, {"access", "dword"}, {"value", 0xC3DEB9AFu}},
          {{"device", "M1111"}, {"access", "dword"}, {"value", 0xBADDBCB7u}}}}};
    RunResult r;
    CHECK(capture(Args{"--json"} + devices, 0, CaptureServer::Reply::Ok,
                  hex("95 19 02 12 30 20 49 48 4E 4F 54 4C AF B9 DE C3 B7 BC DD BA"), &r) ==
          std::vector<Bytes>{binary_3e("03 04 00 00 04 03 00 00 00 A8 00 00 00 C2 64 00 00 90 20 00 00 9C DC 05 00 A8 "
                                       "60 01 00 9D 57 04 00 90")});
    CHECK(json_of(r) == expected);

    CHECK(capture(Args{"--ascii", "--json"} + devices, 0, CaptureServer::Reply::Ok,
                  text("1995120220304849" "4C544F4E" "C3DEB9AF" "BADDBCB7"), &r) ==
          std::vector<Bytes>{ascii_3e("04030000" "04" "03" "D*000000" "TN000000" "M*000100" "X*000020" "D*001500"
                                      "Y*000160" "M*001111")});
    CHECK(json_of(r) == expected);

    capture({"random", "read", "D0", "--dword", "D10"}, 0, CaptureServer::Reply::Ok, hex("01 00 02 00 00 00"), &r);
    CHECK(lines_of(r.out) == std::vector<std::string>{"device  access  value  hex", "D0      word    1      0001",
                                                      "D10     dword   2      00000002"});
}

TEST_CASE("slmp random write: 1402 words/dwords and bits", "[cli][bytes][random]") {
    // The manual's WR1 example: M50 OFF, Y2F ON.
    CHECK(capture({"random", "write", "--bits", "M50=0", "Y2F=1"}) ==
          std::vector<Bytes>{binary_3e("02 14 01 00 02 32 00 00 90 00 2F 00 00 9D 01")});
    CHECK(capture({"--ascii", "random", "write", "--bits", "M50=0", "Y2F=1"}) ==
          std::vector<Bytes>{ascii_3e("14020001" "02" "M*000050" "00" "Y*00002F" "01")});
    // iQ-R form: 2-byte codes, 4-byte numbers, set/reset as a word.
    CHECK(capture({"--iqr", "random", "write", "--bits", "Y2F=1"}) ==
          std::vector<Bytes>{binary_3e("02 14 03 00 01 2F 00 00 00 9D 00 01 00")});

    RunResult r;
    CHECK(capture({"--json", "random", "write", "D0=1", "--dword", "D1500=0x12345678"}, 0, CaptureServer::Reply::Ok, {},
                  &r) == std::vector<Bytes>{binary_3e("02 14 00 00 01 01 00 00 00 A8 01 00 DC 05 00 A8 78 56 34 12")});
    CHECK(json_of(r)["written"] == nlohmann::json({{{"device", "D0"}, {"access", "word"}, {"value", 1}},
                                                  {{"device", "D1500"}, {"access", "dword"}, {"value", 0x12345678}}}));
    CHECK(capture({"--ascii", "random", "write", "W1F=-1"}) ==
          std::vector<Bytes>{ascii_3e("14020000" "01" "00" "W*00001F" "FFFF")});
}

TEST_CASE("slmp frame options: route, 4E serial, iQ-R subcommands", "[cli][bytes][frame]") {
    CHECK(capture({"--network", "1", "--station", "2", "--module-io", "03E0", "--multidrop", "0x10", "type"}, 0,
                  CaptureServer::Reply::Ok, concat({text("R08CPU          "), hex("01 48")})) ==
          std::vector<Bytes>{hex("50 00 01 02 E0 03 10 06 00 10 00 01 01 00 00")});
    CHECK(capture({"--4e", "--serial", "0x1234", "--ascii", "type"}, 0, CaptureServer::Reply::Ok,
                  text("R08CPU          4801")) ==
          std::vector<Bytes>{text("54001234000000FF03FF00000C" "0010" "01010000")});
    CHECK(capture({"--iqr", "read", "D100", "3"}, 0, CaptureServer::Reply::Ok, hex("01 00 02 00 03 00")) ==
          std::vector<Bytes>{binary_3e("01 04 02 00 64 00 00 00 A8 00 03 00")});
    CHECK(capture({"--iqr", "--ascii", "write", "M0", "1", "0", "--bits"}) ==
          std::vector<Bytes>{ascii_3e("14010003" "M***00000000" "0002" "10")});
}

TEST_CASE("slmp exits 3 when the answer does not match the request", "[cli][bytes][connection]") {
    // A self-test echo that differs from what was sent is a broken link, not success.
    RunResult bad;
    capture({"selftest", "ABC"}, 3, CaptureServer::Reply::Ok, concat({hex("03 00"), text("ABD")}), &bad);
    CHECK(bad.err == "slmp: the PLC echoed 'ABD' instead of 'ABC'\n");
    // Read data shorter than the points asked for.
    capture({"read", "D0", "2"}, 3, CaptureServer::Reply::Ok, hex("01 00"), &bad);
    CHECK(bad.err == "slmp: the read data does not hold 2 words\n");
}
