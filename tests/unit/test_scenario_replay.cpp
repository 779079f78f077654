// Recordings (JSON lines) and answering from them (docs/scenarios.md "Record & replay").
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "scenarios/recording.hpp"
#include "scenarios/replay.hpp"
#include "scenarios/runner.hpp"
#include "station/capture/recording_writer.hpp"
#include "scenarios/incoming.hpp"
#include "support/fixtures.hpp"
#include "support/scenario_fixtures.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

std::filesystem::path temp_file(const std::string& name) {
    return std::filesystem::temp_directory_path() / ("slmp-unit-" + std::to_string(::getpid()) + "-" + name);
}

const Bytes kRead3E = bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00");
const Bytes kRead4E = bytes("54 00 34 12 00 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00");
const Bytes kReadAscii4E = text("5400ABCD000000FF03FF000018001004010000D*0001000001");

}  // namespace

TEST_CASE("recording: written as JSON lines and read back", "[scenario][replay]") {
    auto file = temp_file("rec.jsonl");
    auto t0 = at(0);
    {
        station::RecordingWriter w(file, "R08CPU", t0);
        const station::RecordedLink link{2, scenarios::Transport::Tcp, "127.0.0.1:5555", 5000};
        w.opened(at(1), link);
        Bytes response = bytes("D0 00 00 FF FF 03 00 04 00 00 00 2A 00");
        w.exchange(at(2.5), link, kRead3E, &response, {"slow"}, "");
        w.exchange(at(3), link, kRead3E, nullptr, {}, "");
        w.exchange(at(3.5), link, kRead3E, nullptr, {}, "LabelW, DDD[0]");
        w.closed(at(4), link, "closed by the client");
    }
    std::ifstream in(file);
    std::string header, open, exchange, unanswered, labelled;
    std::getline(in, header);
    std::getline(in, open);
    std::getline(in, exchange);
    std::getline(in, unanswered);
    std::getline(in, labelled);
    CHECK(unanswered.find("named") == std::string::npos);   // only when the request named something
    CHECK(labelled.find(R"("named":"LabelW, DDD[0]")") != std::string::npos);
    CHECK(header.find(R"("slmp_recording":1)") != std::string::npos);
    CHECK(header.find(R"("profile":"R08CPU")") != std::string::npos);
    CHECK(open == R"({"conn":2,"event":"open","peer":"127.0.0.1:5555","t_ms":1.0,"transport":"tcp"})");
    CHECK(exchange ==
          R"({"conn":2,"event":"exchange","faults":["slow"],"peer":"127.0.0.1:5555","request":"500000ffff03000c00100001040000640000a80100","response":"d00000ffff0300040000002a00","t_ms":2.5,"transport":"tcp"})");

    auto r = scenarios::read_recording(file);
    CHECK(r.profile == "R08CPU");
    REQUIRE(r.exchanges.size() == 3);
    CHECK(r.exchanges[0].request == kRead3E);
    CHECK(r.exchanges[0].response == bytes("D0 00 00 FF FF 03 00 04 00 00 00 2A 00"));
    CHECK_FALSE(r.exchanges[1].response);
    CHECK(r.exchanges[0].t_ms == 2.5);
    std::filesystem::remove(file);
}

TEST_CASE("recording: a damaged line names the file and line", "[scenario][replay]") {
    auto file = temp_file("bad.jsonl");
    std::ofstream(file) << R"({"slmp_recording":1})" << "\n" << R"({"event":"exchange","request":"5x"})" << "\n";
    CHECK_THROWS_WITH(scenarios::read_recording(file), Catch::Contains("bad.jsonl:2: \"request\" is missing or not hex"));
    std::ofstream(file) << R"({"hello":1})" << "\n";
    CHECK_THROWS_WITH(scenarios::read_recording(file), Catch::Contains("bad.jsonl:1: not an slmp-sim recording"));
    std::filesystem::remove(file);
}

TEST_CASE("replay: recorded answers in order, the last one repeated, 4E serials echoed", "[scenario][replay]") {
    scenarios::Recording r;
    auto add = [&](const Bytes& request, std::optional<Bytes> response) {
        scenarios::RecordedExchange e;
        e.request = request;
        e.response = std::move(response);
        r.exchanges.push_back(e);
    };
    add(kRead3E, bytes("D0 00 00 FF FF 03 00 04 00 00 00 01 00"));
    add(kRead3E, bytes("D0 00 00 FF FF 03 00 04 00 00 00 02 00"));
    add(bytes("54 00 01 00 00 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 64 00 00 A8 01 00"),
        bytes("D4 00 01 00 00 00 00 FF FF 03 00 04 00 00 00 07 00"));
    add(text("54000001000000FF03FF000018001004010000D*0001000001"), text("D4000001000000FF03FF0000080000002A"));
    add(bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 65 00 00 A8 01 00"), std::nullopt);
    scenarios::ReplayBook book(r);
    auto header = [](const Bytes& frame) {
        return protocol::scan_frame(frame, protocol::Direction::Request, protocol::DataCodePolicy::Auto, 8192).header;
    };
    CHECK(*book.answer(kRead3E, header(kRead3E)).response == bytes("D0 00 00 FF FF 03 00 04 00 00 00 01 00"));
    CHECK(*book.answer(kRead3E, header(kRead3E)).response == bytes("D0 00 00 FF FF 03 00 04 00 00 00 02 00"));
    CHECK(*book.answer(kRead3E, header(kRead3E)).response == bytes("D0 00 00 FF FF 03 00 04 00 00 00 02 00"));
    CHECK(*book.answer(kRead4E, header(kRead4E)).response == bytes("D4 00 34 12 00 00 00 FF FF 03 00 04 00 00 00 07 00"));
    CHECK(str(*book.answer(kReadAscii4E, header(kReadAscii4E)).response) == "D400ABCD000000FF03FF0000080000002A");
    auto silent = bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 65 00 00 A8 01 00");
    auto a = book.answer(silent, header(silent));
    CHECK(a.found);
    CHECK_FALSE(a.response);
    auto other = bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 66 00 00 A8 01 00");
    CHECK_FALSE(book.answer(other, header(other)).found);
}

TEST_CASE("replay: a scenario answers from its recording, misses go by on_miss", "[scenario][replay]") {
    auto dir = std::filesystem::temp_directory_path() / ("slmp-unit-replay-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    {
        station::RecordingWriter w(dir / "session.jsonl", "R08CPU", at(0));
        Bytes response = bytes("D0 00 00 FF FF 03 00 04 00 00 00 2A 00");
        w.exchange(at(1), {1, scenarios::Transport::Tcp, "127.0.0.1:1", 5000}, kRead3E, &response, {}, "");
    }
    auto run_with = [&](const std::string& replay, const Bytes& frame) {
        std::ofstream(dir / "replay.json") << R"({"replay": )" << replay << "}";
        devicemodel::Cpu cpu(config::load_profile("R08CPU").cpu);
        std::vector<scenarios::Scenario> list{scenarios::load_scenario(dir / "replay.json")};
        scenarios::ScenarioRunner runner(std::move(list), cpu, nullptr);
        runner.scan(at(0));
        scenarios::Incoming incoming{engine_for(cpu).decode(frame, protocol::DataCodePolicy::Auto), {}, 0};
        return runner.before(incoming, frame);   // the plan is read only, never passed to after()
    };
    auto hit = run_with(R"({"file": "session.jsonl"})", kRead3E);
    REQUIRE(hit.answer);
    CHECK(*hit.answer == bytes("D0 00 00 FF FF 03 00 04 00 00 00 2A 00"));   // not the CPU's 0: the recorded 42
    auto other = bytes("50 00 00 FF FF 03 00 0C 00 10 00 01 04 00 00 66 00 00 A8 01 00");
    CHECK(run_with(R"({"file": "session.jsonl"})", other).pass());   // on_miss simulate (default): the CPU answers
    CHECK(run_with(R"({"file": "session.jsonl", "on_miss": "no_response"})", other).silent);
    auto coded = run_with(R"({"file": "session.jsonl", "on_miss": "end_code", "end_code": "C059"})", other);
    REQUIRE(coded.answer);
    CHECK(hex(*coded.answer) == "D0 00 00 FF FF 03 00 0B 00 59 C0 00 FF FF 03 00 01 04 00 00");

    std::ofstream(dir / "missing.json") << R"({"replay": {"file": "nope.jsonl"}})";
    devicemodel::Cpu cpu(config::load_profile("R08CPU").cpu);
    std::vector<scenarios::Scenario> list{scenarios::load_scenario(dir / "missing.json")};
    // The message names the scenario file, the JSON pointer of the key to fix, and the recording.
    CHECK_THROWS_WITH(scenarios::ScenarioRunner(std::move(list), cpu, nullptr),
                      Catch::Contains("missing.json: /replay/file: ") && Catch::Contains("nope.jsonl: cannot open the recording"));
    std::filesystem::remove_all(dir);
}
