// slmp-bench's pure parts (docs/bench.md): --targets parsing, the CPU time
// read from /proc/PID/stat, and the baseline server's framing and answers —
// bytes in, bytes out, each answer spelled out from the frame layout
// (SLMP Reference Manual ch. 4), not from the code.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "tools/bench/baseline_answer.hpp"
#include "tools/bench/process_cpu.hpp"
#include "tools/bench/targets.hpp"

using namespace slmp::bench;
using Bytes = std::vector<std::uint8_t>;

namespace {

Bytes hex(const std::string& text) {
    Bytes out;
    for (std::size_t i = 0; i + 1 < text.size();) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        out.push_back(static_cast<std::uint8_t>(std::stoi(text.substr(i, 2), nullptr, 16)));
        i += 2;
    }
    return out;
}
Bytes text(const std::string& s) { return Bytes(s.begin(), s.end()); }

std::string refusal(const std::string& targets) {
    try {
        parse_targets(targets);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "(accepted)";
}

// The answer to `request` given whole, and the status of every proper prefix of it.
Bytes answer(const Bytes& request) {
    Bytes out;
    for (std::size_t n = 0; n < request.size(); ++n) {
        auto partial = baseline::answer_request(std::span(request).first(n), out);
        INFO("prefix of " << n << " bytes");
        REQUIRE(partial.status == baseline::Answered::Status::NeedMore);
        REQUIRE(out.empty());
    }
    auto whole = baseline::answer_request(request, out);
    REQUIRE(whole.status == baseline::Answered::Status::Done);
    CHECK(whole.size == request.size());
    return out;
}

}  // namespace

TEST_CASE("bench: --targets takes ranges, lists and both", "[bench]") {
    CHECK(parse_targets("127.0.0.1:20000-20003") == std::vector<Target>{{"127.0.0.1", 20000},
                                                                        {"127.0.0.1", 20001},
                                                                        {"127.0.0.1", 20002},
                                                                        {"127.0.0.1", 20003}});
    CHECK(parse_targets("127.0.0.1:5000,localhost:6000") ==
          std::vector<Target>{{"127.0.0.1", 5000}, {"localhost", 6000}});
    CHECK(parse_targets("127.0.1.1:5000,127.0.1.2:7-8,[::1]:9") ==
          std::vector<Target>{{"127.0.1.1", 5000}, {"127.0.1.2", 7}, {"127.0.1.2", 8}, {"::1", 9}});
    CHECK(parse_targets("h:65535-65535") == std::vector<Target>{{"h", 65535}});
    CHECK(parse_targets("h:1-4096").size() == kMaxTargets);
}

TEST_CASE("bench: --targets refuses bad entries, naming the entry and why", "[bench]") {
    const std::string form = " (write host:port, host:first-last or a comma list of them)";
    CHECK(refusal("") == "--targets is empty (write host:port, host:first-last or a comma list)");
    CHECK(refusal("127.0.0.1") == "--targets entry '127.0.0.1': no port" + form);
    CHECK(refusal(":5000") == "--targets entry ':5000': no host" + form);
    CHECK(refusal("h:") == "--targets entry 'h:': '' is not a port number" + form);
    CHECK(refusal("h:50x") == "--targets entry 'h:50x': '50x' is not a port number" + form);
    CHECK(refusal("h:0") == "--targets entry 'h:0': port 0 is outside 1-65535" + form);
    CHECK(refusal("h:65536") == "--targets entry 'h:65536': port 65536 is outside 1-65535" + form);
    CHECK(refusal("h:20999-20000") == "--targets entry 'h:20999-20000': the range runs backwards" + form);
    CHECK(refusal("h:1-2-3") == "--targets entry 'h:1-2-3': '2-3' is not a port number" + form);
    CHECK(refusal("h:1,,h:2") == "--targets 'h:1,,h:2' has an empty entry (a stray comma)");
    CHECK(refusal("h:1,") == "--targets 'h:1,' has an empty entry (a stray comma)");
    CHECK(refusal("::1:5000") == "--targets entry '::1:5000': write an IPv6 address in brackets: [::1]:5000" + form);
    CHECK(refusal("[::1]5000") == "--targets entry '[::1]5000': an IPv6 address needs ']:' and a port after it" + form);
    CHECK(refusal("h:1-4096,h:5000") == "--targets entry 'h:5000': more than 4096 targets in all" + form);
}

TEST_CASE("bench: CPU seconds from a /proc/PID/stat line (utime + stime)", "[bench]") {
    // Fields 14 and 15 are 250 and 50 ticks; the name holds ") (" to mislead a naive split.
    const std::string line =
        "4242 (slmp sim) (x)) S 1 4242 4242 0 -1 4194560 1234 0 0 0 250 50 0 0 20 0 3 0 12345 1000000 500 "
        "18446744073709551615 1 1 0 0 0 0 0 0 0 0 0 0 17 1 0 0 0 0 0";
    auto seconds = cpu_seconds_from_stat(line, 100.0);
    REQUIRE(seconds);
    CHECK(*seconds == Approx(3.0).epsilon(1e-12));
    CHECK_FALSE(cpu_seconds_from_stat("4242 (short) S 1 2 3", 100.0));
    CHECK_FALSE(cpu_seconds_from_stat("no parenthesis at all", 100.0));
    CHECK(process_cpu_seconds(::getpid()));   // this process exists
}

TEST_CASE("bench: the baseline answers a 3E binary word read with zeros, the route echoed", "[bench]") {
    // 0401/0000 D100, 3 words, to network 01 station 02, module I/O 03E0, multidrop 00.
    auto request = hex("5000 01 02 E003 00 0C00 1000 0104 0000 640000 A8 0300");
    CHECK(answer(request) == hex("D000 01 02 E003 00 0800 0000 000000000000"));
}

TEST_CASE("bench: the baseline answers 4E ASCII reads with the serial echoed", "[bench]") {
    // 0401/0000 D100, 3 words, serial 1234.
    CHECK(answer(text("5400" "1234" "0000" "00FF03FF00" "0018" "0010" "0401" "0000" "D*000100" "0003")) ==
          text("D400" "1234" "0000" "00FF03FF00" "0010" "0000" "000000000000"));
    // 0401/0001 M0, 5 bits: a character a point.
    CHECK(answer(text("5400" "0007" "0000" "00FF03FF00" "0018" "0010" "0401" "0001" "M*000000" "0005")) ==
          text("D400" "0007" "0000" "00FF03FF00" "0009" "0000" "00000"));
}

TEST_CASE("bench: the baseline's other answers — bits, iQ-R form, writes, other commands", "[bench]") {
    SECTION("binary 4E, 0401/0001 M0, 5 bits: a nibble a point, padded") {
        CHECK(answer(hex("5400 3412 0000 00 FF FF03 00 0C00 1000 0104 0100 000000 90 0500")) ==
              hex("D400 3412 0000 00 FF FF03 00 0500 0000 000000"));
    }
    SECTION("binary 3E, 0401/0002 (iQ-R form) D0, 2 words: the points are still the last field") {
        CHECK(answer(hex("5000 00 FF FF03 00 0E00 1000 0104 0200 00000000 A800 0200")) ==
              hex("D000 00 FF FF03 00 0600 0000 00000000"));
    }
    SECTION("1401 word write: the short OK, nothing stored") {
        CHECK(answer(hex("5000 00 FF FF03 00 0E00 1000 0114 0000 640000 A8 0100 3412")) ==
              hex("D000 00 FF FF03 00 0200 0000"));
        CHECK(answer(text("5000" "00FF03FF00" "001C" "0010" "1401" "0000" "D*000100" "0001" "1234")) ==
              text("D000" "00FF03FF00" "0004" "0000"));
    }
    SECTION("another command (0101): C059 and the error information block") {
        CHECK(answer(hex("5000 00 FF FF03 00 0600 1000 0101 0000")) ==
              hex("D000 00 FF FF03 00 0B00 59C0 00 FF FF03 00 0101 0000"));
        CHECK(answer(text("5000" "00FF03FF00" "000C" "0010" "0101" "0000")) ==
              text("D000" "00FF03FF00" "0016" "C059" "00FF03FF00" "0101" "0000"));
    }
    SECTION("961 words: C051, as R08CPU, never a larger answer than a real one") {
        CHECK(answer(hex("5000 00 FF FF03 00 0C00 1000 0104 0000 000000 A8 C103")) ==
              hex("D000 00 FF FF03 00 0B00 51C0 00 FF FF03 00 0104 0000"));
    }
}

TEST_CASE("bench: the baseline takes pipelined requests one at a time and refuses what is not SLMP", "[bench]") {
    auto one = hex("5000 00 FF FF03 00 0C00 1000 0104 0000 000000 A8 0100");
    Bytes two = one;
    two.insert(two.end(), one.begin(), one.end());
    Bytes out;
    auto first = baseline::answer_request(two, out);
    CHECK(first.status == baseline::Answered::Status::Done);
    CHECK(first.size == one.size());
    CHECK(out == hex("D000 00 FF FF03 00 0400 0000 0000"));

    using Status = baseline::Answered::Status;
    auto status = [](const Bytes& bytes) {
        Bytes ignored;
        return baseline::answer_request(bytes, ignored).status;
    };
    CHECK(status(hex("D000 00 FF FF03 00 0400 0000 0000")) == Status::Invalid);   // a response
    CHECK(status(hex("5001")) == Status::Invalid);
    CHECK(status(text("5001")) == Status::Invalid);
    CHECK(status(text("50")) == Status::NeedMore);
    CHECK(status(hex("5000 00 FF FF03 00 0400 1000 0104")) == Status::Invalid);   // no room for a subcommand
    CHECK(status(hex("5000 00 FF FF03 00 F81F")) == Status::Invalid);             // 8184 + 9 > 8192 bytes
    CHECK(status(hex("5000 00 FF FF03 00 F71F")) == Status::NeedMore);            // 8183 + 9 = 8192: waits
    CHECK(status(text("5000" "00FF03FF00" "00G0")) == Status::Invalid);           // not hex
}
