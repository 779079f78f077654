// Framing through the engine: every proper prefix of a valid frame waits for
// more, garbage is skipped up to the next possible frame, an oversized length
// closes the connection, and a stream of frames is taken one at a time.
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

// Feeds a byte stream through the engine as a TCP session would: handle one
// frame, drop what it consumed, repeat until it needs more.
struct StreamResult {
    std::vector<std::string> responses;
    std::vector<std::size_t> silent;   // bytes consumed by each Silent outcome
    std::size_t left = 0;
};

StreamResult feed(devicemodel::Cpu& cpu, const Bytes& stream, const Wire& shown_as) {
    StreamResult result;
    protocol::Session session;
    auto engine = engine_for(cpu);
    std::span<const std::uint8_t> rest(stream);
    while (!rest.empty()) {
        auto out = engine.process(rest, DataCodePolicy::Auto, session);
        if (out.action == Outcome::Action::NeedMore) break;
        REQUIRE(out.consumed > 0);
        REQUIRE(out.consumed <= rest.size());
        if (out.action == Outcome::Action::Respond) result.responses.push_back(shown_as.show(out.response));
        if (out.action == Outcome::Action::Silent) result.silent.push_back(out.consumed);
        rest = rest.subspan(out.consumed);
    }
    result.left = rest.size();
    return result;
}

}  // namespace

TEST_CASE("every proper prefix of a valid frame -> NeedMore", "[truncation]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    const Payload requests[] = {
        read_words_req(Form::Q, "D100", 3),
        write_bits_req(Form::Q, "M100", {1, 1, 0, 0, 1, 1, 0, 0}),
        write_words_req(Form::IQR, "D100", {0x1995, 0x1202, 0x1130}),
        {"01 01 00 00", "01010000"},
    };
    for (const auto& request : requests) {
        auto frame = wire.request(request);
        auto before = snapshot(cpu);
        for (std::size_t n = 0; n < frame.size(); ++n) {
            INFO(wire.name() << ": first " << n << " of " << frame.size() << " bytes");
            auto out = run(cpu, std::span(frame).first(n));
            CHECK(to_string(out.action) == "NeedMore");
            CHECK(out.consumed == 0);
            CHECK(out.response.empty());
        }
        CHECK((snapshot(cpu) == before));
        auto out = run(cpu, frame);
        CHECK(to_string(out.action) == "Respond");
        CHECK(out.consumed == frame.size());
    }
}

TEST_CASE("byte-at-a-time feeding answers exactly once, at the last byte", "[truncation]") {
    auto cpu = make_cpu("R08CPU");
    cpu.memory().set_value(*devicemodel::find_by_symbol("D"), 100, 0x1995);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    auto frame = wire.request(read_words_req(Form::Q, "D100", 1));
    Bytes buffer;
    int answers = 0;
    for (auto b : frame) {
        buffer.push_back(b);
        auto out = run(cpu, buffer);
        if (out.action == Outcome::Action::Respond) {
            ++answers;
            CHECK(buffer.size() == frame.size());
            CHECK(wire.show(out.response) == wire.expect(ok(words({0x1995}))));
        }
    }
    CHECK(answers == 1);
}

TEST_CASE("garbage is skipped up to the next frame", "[truncation]") {
    auto cpu = make_cpu("R08CPU");
    cpu.memory().set_value(*devicemodel::find_by_symbol("D"), 100, 0x1995);
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    auto frame = wire.request(read_words_req(Form::Q, "D100", 1));
    const auto answer = wire.expect(ok(words({0x1995})));

    SECTION("2 bytes FF FF before a frame -> Silent, consumed 2") {
        auto stream = bytes("FF FF");
        stream.insert(stream.end(), frame.begin(), frame.end());
        auto out = run(cpu, stream);
        CHECK(to_string(out.action) == "Silent");
        CHECK(out.consumed == 2);
        CHECK(out.response.empty());
        auto r = feed(cpu, stream, wire);
        CHECK(r.responses == std::vector<std::string>{answer});
        CHECK(r.silent == std::vector<std::size_t>{2});
        CHECK(r.left == 0);
    }
    SECTION("1 byte 0A before a frame -> Silent, consumed 1") {
        auto stream = bytes("0A");
        stream.insert(stream.end(), frame.begin(), frame.end());
        auto out = run(cpu, stream);
        CHECK(to_string(out.action) == "Silent");
        CHECK(out.consumed == 1);
        auto r = feed(cpu, stream, wire);
        CHECK(r.responses == std::vector<std::string>{answer});
        CHECK(r.left == 0);
    }
    SECTION("1 byte 0A alone -> Silent, consumed 1") {
        auto out = run(cpu, bytes("0A"));
        CHECK(to_string(out.action) == "Silent");
        CHECK(out.consumed == 1);
    }
    SECTION("garbage that looks like a subheader start: 50 01 / \"5001\"") {
        auto stream = wire.ascii() ? text("5001") : bytes("50 01");
        stream.insert(stream.end(), frame.begin(), frame.end());
        auto r = feed(cpu, stream, wire);
        CHECK(r.responses == std::vector<std::string>{answer});
        CHECK(r.left == 0);
        std::size_t skipped = 0;
        for (auto n : r.silent) skipped += n;
        CHECK(skipped == (wire.ascii() ? 4u : 2u));
    }
    SECTION("frame, garbage, frame, garbage, frame") {
        Bytes stream;
        for (int i = 0; i < 3; ++i) {
            stream.insert(stream.end(), frame.begin(), frame.end());
            if (i < 2) {
                auto junk = text(i == 0 ? "hello" : "\r\n");
                stream.insert(stream.end(), junk.begin(), junk.end());
            }
        }
        auto r = feed(cpu, stream, wire);
        CHECK(r.responses == std::vector<std::string>(3, answer));
        CHECK(r.left == 0);
    }
    SECTION("a frame followed by half a frame: one answer, the half is kept") {
        Bytes stream = frame;
        stream.insert(stream.end(), frame.begin(), frame.begin() + static_cast<long>(frame.size() / 2));
        auto r = feed(cpu, stream, wire);
        CHECK(r.responses == std::vector<std::string>{answer});
        CHECK(r.left == frame.size() / 2);
    }
}

TEST_CASE("ASCII header with non-hex characters -> Silent, subheader skipped", "[truncation]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kAscii3E, kAscii4E);
    auto frame = wire.request(read_words_req(Form::Q, "D100", 1));
    frame[5] = 'Z';   // inside the network number (3E) or the serial (4E)
    auto out = run(cpu, frame);
    CHECK(to_string(out.action) == "Silent");
    CHECK(out.consumed == 4);
}

TEST_CASE("response frames sent to the server are garbage", "[truncation]") {
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    auto frame = wire.response(ok(words({1})));
    auto r = feed(cpu, frame, wire);
    CHECK(r.responses.empty());
    CHECK(r.left == 0);
}

TEST_CASE("data code policy of the port", "[truncation]") {
    auto cpu = make_cpu("R08CPU");
    auto ascii_frame = kAscii3E.request(read_words_req(Form::Q, "D0", 1));
    auto binary_frame = kBinary3E.request(read_words_req(Form::Q, "D0", 1));
    SECTION("a binary port skips an ASCII frame") {
        auto out = run(cpu, ascii_frame, DataCodePolicy::Binary);
        CHECK(to_string(out.action) == "Silent");
        CHECK(out.consumed == ascii_frame.size());
        CHECK(to_string(run(cpu, binary_frame, DataCodePolicy::Binary).action) == "Respond");
    }
    SECTION("an ASCII port skips a binary frame") {
        auto out = run(cpu, binary_frame, DataCodePolicy::Ascii);
        CHECK(to_string(out.action) == "Silent");
        CHECK(out.consumed > 0);
        CHECK(to_string(run(cpu, ascii_frame, DataCodePolicy::Ascii).action) == "Respond");
    }
}

TEST_CASE("frame length limit (max_frame_bytes)", "[truncation]") {
    auto cpu = make_cpu("R08CPU");
    SECTION("length FFFF with the default 8192 -> Close") {
        auto out = run(cpu, bytes("50 00 00 FF FF 03 00 FF FF"));
        CHECK(to_string(out.action) == "Close");
        CHECK(out.response.empty());
        CHECK(out.note.find("8192") != std::string::npos);
        auto asc = run(cpu, text("500000FF03FF00FFFF"));
        CHECK(to_string(asc.action) == "Close");
    }
    SECTION("a frame of exactly max_frame_bytes is served, one byte more closes") {
        auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
        auto frame = wire.request(read_words_req(Form::Q, "D0", 1));
        protocol::EngineOptions exact{frame.size()};
        CHECK(to_string(run(cpu, frame, DataCodePolicy::Auto, exact).action) == "Respond");
        protocol::EngineOptions smaller{frame.size() - 1};
        CHECK(to_string(run(cpu, frame, DataCodePolicy::Auto, smaller).action) == "Close");
        // The header alone is enough to decide.
        auto header = Bytes(frame.begin(), frame.begin() + static_cast<long>(wire.header(false, 0).size()));
        CHECK(to_string(run(cpu, header, DataCodePolicy::Auto, smaller).action) == "Close");
    }
}

TEST_CASE("a request too short for timer, command and subcommand", "[truncation]") {
    // Not answered (the engine's choice: there is no command to echo).
    auto cpu = make_cpu("R08CPU");
    auto wire = GENERATE(kBinary3E, kBinary4E, kAscii3E, kAscii4E);
    auto frame = wire.request({"01 04", "0401"});   // timer + command, no subcommand
    auto out = run(cpu, frame);
    CHECK(to_string(out.action) == "Silent");
    CHECK(out.consumed == frame.size());
    auto empty = wire.header(false, 0);
    out = run(cpu, empty);
    CHECK(to_string(out.action) == "Silent");
    CHECK(out.consumed == empty.size());
}
