// Scenarios, faults and recording through the HTTP API against the real
// binary (docs/api.md): list, load (file or body) and stop scenarios; fault
// counts and switching; the faults-fired metric; starting and stopping a
// JSON-lines recording; and bad input with its exact status and message.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "frames.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "sim_process.hpp"
#include "sockets.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
using nlohmann::json;

namespace {

const Wire kBinary{FrameKind::E3, Codec::Binary, 0};

// A fault that answers C051 to every 0401 read of D100-D199.
const char* kRefuser = R"({"name": "refuser", "faults": [
  {"id": "no-d100", "do": "end_code", "end_code": "C051", "match": {"command": "0401", "devices": "D100-D199"}}]})";

HttpResponse http_post(std::uint16_t port, const std::string& target, const std::string& body) {
    return http(port, "POST", target, body);
}
HttpResponse http_delete(std::uint16_t port, const std::string& target) { return http(port, "DELETE", target); }

void expect_error(const HttpResponse& r, int status, const std::string& message) {
    INFO(r.body);
    CHECK(r.status == status);
    CHECK(r.error() == message);
}

std::uint16_t end_code_of_read(TcpLink& link, const std::string& device) {
    auto parsed = client::parse_response(link.exchange(client::read_words(kBinary.options(), addr(device), 1)));
    REQUIRE(parsed);
    return parsed->end_code;
}

}  // namespace

TEST_CASE("HTTP scenarios: a --scenario file is listed with its faults and their counts", "[http][scenarios]") {
    TempDir dir;
    auto file = dir.write("refuser.json", kRefuser);
    SimProcess sim(with_args({"--scenario", file.string()}));
    auto port = sim.http_port();

    auto list = http_get(port, "/api/scenarios").json()["scenarios"];
    REQUIRE(list.size() == 1);
    CHECK(list[0]["name"] == "refuser");
    CHECK(list[0]["source"] == file.string());
    CHECK(list[0]["faults"] == json{"no-d100"});

    TcpLink link(sim.tcp_port());
    CHECK(end_code_of_read(link, "D150") == 0xC051);
    CHECK(end_code_of_read(link, "D150") == 0xC051);
    CHECK(end_code_of_read(link, "D99") == 0x0000);
    CHECK(http_get(port, "/api/faults").json() ==
          json{{"faults", {{{"id", "no-d100"}, {"scenario", "refuser"}, {"kind", "end_code"}, {"enabled", true},
                            {"matched", 2}, {"fired", 2}}}}});
    auto metrics = http_get(port, "/metrics").body;
    CHECK(metrics.find("slmp_faults_fired_total{scenario=\"refuser\",fault=\"no-d100\",kind=\"end_code\"} 2\n") !=
          std::string::npos);

    SECTION("PUT /api/faults/{id} turns a fault off and on") {
        auto r = http_put(port, "/api/faults/no-d100", R"({"enabled": false})");
        CHECK(r.status == 200);
        CHECK(r.json()["enabled"] == false);
        CHECK(end_code_of_read(link, "D150") == 0x0000);
        CHECK(http_put(port, "/api/faults/no-d100", R"({"enabled": true})").json()["enabled"] == true);
        CHECK(end_code_of_read(link, "D150") == 0xC051);
        CHECK(http_get(port, "/api/faults").json()["faults"][0]["fired"] == 3);
    }
    SECTION("bad fault switches") {
        expect_error(http_put(port, "/api/faults/nope", R"({"enabled": false})"), 404, "no fault 'nope'; the faults are no-d100");
        expect_error(http_put(port, "/api/faults/no-d100", R"({"enabled": "no"})"), 400,
                     "the body must be {\"enabled\": true} or {\"enabled\": false}");
        expect_error(http_put(port, "/api/faults/no-d100", "{"), 400, "the body must be {\"enabled\": true} or {\"enabled\": false}");
    }
    SECTION("DELETE stops it: the fault is gone, requests pass") {
        CHECK(http_delete(port, "/api/scenarios/refuser").json() == json{{"stopped", "refuser"}});
        CHECK(http_get(port, "/api/scenarios").json()["scenarios"].empty());
        CHECK(http_get(port, "/api/faults").json()["faults"].empty());
        CHECK(end_code_of_read(link, "D150") == 0x0000);
        expect_error(http_delete(port, "/api/scenarios/refuser"), 404, "no running scenario 'refuser'; none is running");
    }
}

TEST_CASE("HTTP scenarios: load from the body and from a file, then stop", "[http][scenarios]") {
    SimProcess sim;
    auto port = sim.http_port();
    TcpLink link(sim.tcp_port());
    CHECK(http_get(port, "/api/scenarios").json() == json{{"scenarios", json::array()}});

    auto r = http_post(port, "/api/scenarios",
                       R"({"name": "inline", "initial": {"devices": {"D5": 42}}, "faults": [{"id": "f1", "do": "end_code", "end_code": "C051", "match": {"devices": "D7"}}]})");
    CHECK(r.status == 201);
    CHECK(r.json()["name"] == "inline");
    CHECK(r.json()["source"] == "request body (inline)");
    // Its initial devices are applied at once, its faults act.
    CHECK(http_get(port, "/api/devices/D5").json()["values"] == json{42});
    CHECK(end_code_of_read(link, "D7") == 0xC051);

    TempDir dir;
    auto file = dir.write("refuser.json", kRefuser);
    r = http_post(port, "/api/scenarios", json{{"file", file.string()}}.dump());
    CHECK(r.status == 201);
    CHECK(r.json()["source"] == file.string());
    CHECK(end_code_of_read(link, "D150") == 0xC051);
    auto listed = http_get(port, "/api/scenarios").json()["scenarios"];
    REQUIRE(listed.size() == 2);
    CHECK(listed[0]["name"] == "inline");
    CHECK(listed[1]["name"] == "refuser");
    CHECK(http_get(port, "/api/faults").json()["faults"].size() == 2);

    // The same name twice is refused.
    expect_error(http_post(port, "/api/scenarios", json{{"file", file.string()}}.dump()), 409,
                 "a scenario named 'refuser' is already running (" + file.string() +
                     "); DELETE /api/scenarios/refuser first, or give this one another \"name\"");
    // Fault ids are unique across every running scenario.
    expect_error(http_post(port, "/api/scenarios", R"({"name": "other", "faults": [{"id": "f1", "do": "no_response"}]})"), 400,
                 "request body (other): /faults/0/id: fault id 'f1' is also used at request body (inline): /faults/0; give "
                 "each fault its own id");

    CHECK(http_delete(port, "/api/scenarios/inline").status == 200);
    CHECK(end_code_of_read(link, "D7") == 0x0000);
    CHECK(end_code_of_read(link, "D150") == 0xC051);   // the other one runs on
    expect_error(http_delete(port, "/api/scenarios/inline"), 404, "no running scenario 'inline'; the running ones are refuser");
}

TEST_CASE("HTTP scenarios: a bad scenario gets the --scenario loader's message", "[http][scenarios]") {
    TempDir dir;
    auto bad = dir.write("bad.json", R"({"faults": [{"do": "end_code", "end_code": "C051", "match": {"command": "04O1"}}]})");
    auto cli = run_sim({"--scenario", bad.string(), "--tcp-port", "0", "--no-http"});
    CHECK(cli.exit_code != 0);

    SimProcess sim;
    auto port = sim.http_port();
    auto message = bad.string() +
                   ": /faults/0/match/command: '04O1' is not a 4-digit hexadecimal code; write it like \"C059\"";
    expect_error(http_post(port, "/api/scenarios", json{{"file", bad.string()}}.dump()), 400, message);
    CHECK(cli.err.find(message) != std::string::npos);

    expect_error(http_post(port, "/api/scenarios", R"({"name": "x", "faults": [{"do": "end_code", "end_code": "C051", "match": {"command": "04O1"}}]})"),
                 400, "request body: /faults/0/match/command: '04O1' is not a 4-digit hexadecimal code; write it like \"C059\"");
    expect_error(http_post(port, "/api/scenarios", R"({"faults": []})"), 400,
                 "request body: /name: a scenario sent as the body needs a \"name\"; DELETE /api/scenarios/{name} stops it by that name");
    expect_error(http_post(port, "/api/scenarios", R"({"file": 3})"), 400,
                 "send {\"file\": \"path/to/scenario.json\"} alone, or the scenario itself as the body (a scenario has no \"file\" key)");
    auto missing = (dir.path() / "missing.json").string();
    expect_error(http_post(port, "/api/scenarios", json{{"file", missing}}.dump()), 400,
                 missing + ": cannot open the scenario file; check the path given to --scenario");
    auto devices = http_post(port, "/api/scenarios", R"({"name": "big", "initial": {"devices": {"D99999999": 1}}})");
    CHECK(devices.status == 400);
    CHECK(http_get(port, "/api/scenarios").json()["scenarios"].empty());
}

TEST_CASE("HTTP recording: start, see, stop, the file holds the exchanges", "[http][recording]") {
    SimProcess sim;
    auto port = sim.http_port();
    TempDir dir;
    auto file = (dir.path() / "session.jsonl").string();
    CHECK(http_get(port, "/api/recording").json() == json{{"recording", false}, {"file", nullptr}});

    auto r = http_post(port, "/api/recording", json{{"file", file}}.dump());
    CHECK(r.status == 201);
    CHECK(r.json() == json{{"recording", true}, {"file", file}});
    CHECK(http_get(port, "/api/recording").json() == json{{"recording", true}, {"file", file}});
    expect_error(http_post(port, "/api/recording", json{{"file", file}}.dump()), 409,
                 "already recording to " + file + "; DELETE /api/recording stops it first");
    {
        TcpLink link(sim.tcp_port());
        CHECK(end_code_of_read(link, "D0") == 0x0000);
    }
    CHECK(http_delete(port, "/api/recording").json() == json{{"recording", false}, {"file", file}});
    CHECK(http_get(port, "/api/recording").json()["recording"] == false);
    // Closed and complete: the header line, then open / exchange (and maybe close).
    auto text = read_text(file);
    CHECK(text.substr(0, text.find('\n')).find("\"slmp_recording\":1") != std::string::npos);
    CHECK(text.find("\"event\":\"exchange\"") != std::string::npos);

    expect_error(http_delete(port, "/api/recording"), 409,
                 "no recording is running; POST /api/recording {\"file\": \"...\"} starts one");
    expect_error(http_post(port, "/api/recording", R"({"path": "x"})"), 400,
                 "the body must be {\"file\": \"path/to/recording.jsonl\"}");
    auto r2 = http_post(port, "/api/recording", json{{"file", (dir.path() / "no/such/dir/x.jsonl").string()}}.dump());
    CHECK(r2.status == 400);
    CHECK(http_get(port, "/api/recording").json()["recording"] == false);
}
