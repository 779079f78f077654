// HTTP requests -> the control API's Router::route() (control/http/router.hpp),
// with every endpoint registered as control/endpoints/station_side.cpp does, on a bare
// station (no sockets, no scan, no state directory). Input layout: requests
// separated by NUL bytes, each
//   [0] the method: byte % 5 indexes kMethods (ASCII '0'..'4' are GET, PUT,
//       POST, DELETE, PATCH)
//   [1..] the request-target ("/api/devices/D100?count=3") up to the first '\n'
//   then the body, up to the NUL or the end
// The requests of one input share a station, so one can load a scenario and
// the next switch its fault or stop it; each input gets a fresh station, so
// every run (and every crash-* file) reproduces alone.
// Checked for every request: nothing but a Reply leaves route(); the status
// is a real HTTP status; a JSON reply parses, and an error reply is
// {"error": "..."} (docs/api.md); a GET or a refused request (status >= 400)
// writes no device or buffer memory.
//
// Nothing here may touch files: a body holding a "file" key anywhere is not
// routed (see reaches_files()). Nothing blocks either: GET /api/events only
// answers with the event types (the HTTP session streams, not the router),
// and scenarios never run, as nothing scans or runs the io_context.
//
// Device areas but SM/SD are capped at 512 points, as fuzz_engine does, so
// a fresh station per input stays cheap (SM/SD keep their real sizes: the CPU
// writes special registers there).
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

#include <boost/beast/http/verb.hpp>
#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "config/config.hpp"
#include "control/endpoints/api.hpp"
#include "control/http/router.hpp"
#include "control/observers/device_waits.hpp"
#include "control/observers/event_hub.hpp"
#include "control/observers/metrics.hpp"
#include "devicemodel/cpu.hpp"
#include "devicemodel/device_table.hpp"
#include "scenarios/runner.hpp"
#include "station/station.hpp"
#include "tests/fuzz/fuzz_check.hpp"
#include "tests/fuzz/write_watch.hpp"

namespace {

using namespace slmp;
using control::Verb;
using nlohmann::json;

// Indexed by byte % 5; '0' is 48, so the digits '0'..'4' read GET, PUT, POST, DELETE, PATCH.
constexpr Verb kMethods[] = {Verb::post, Verb::delete_, Verb::patch, Verb::get, Verb::put};
// More requests than any endpoint sequence needs; bounds one input's time.
constexpr std::size_t kMaxRequests = 16;

config::Profile capped(config::Profile p) {
    for (std::size_t a = 0; a < p.cpu.sizes.size(); ++a)
        if (auto area = static_cast<devicemodel::Area>(a); area != devicemodel::Area::SM && area != devicemodel::Area::SD)
            p.cpu.sizes[a] = std::min<std::uint32_t>(p.cpu.sizes[a], 512);
    p.cpu.station_buffer_words = std::min<std::uint32_t>(p.cpu.station_buffer_words, 512);
    return p;
}

const config::Profile& profile() {
    static const auto p = capped(config::load_profile("R08CPU"));
    return p;
}

// Scenario power cuts and refusals act on the transports; there are none.
class NoTransports final : public scenarios::Station {
public:
    void power_off() override {}
    void power_on() override {}
    void refuse_connections(bool) override {}
};

// The snapshot compare below is independent of the write watch: a write that
// bypassed the observer would also be missing from the API's own change
// stream (/api/events).
using Watch = fuzz::WriteWatch;

// What the HTTP server builds around a station (http_server.cpp), plus an
// intelligent module (buffer U3) for /api/buffer.
struct Rig {
    Rig() : station(profile(), {}), metrics(station), events(home, station), waits(home, events),
            api{station, events, metrics, waits, {"127.0.0.1", {5000}, {5000}, 8080}, {}} {
        station.cpu().add_module(3, "Q62DA", 512, 0x1008);
        // What Station::connect() does when the HTTP API is on, so POST /api/scenarios can load.
        station.scenario().attach(station.cpu(), no_transports);
        control::add_device_endpoints(router, api);
        control::add_buffer_endpoints(router, api);
        control::add_scenario_endpoints(router, api);
        control::add_fault_endpoints(router, api);
        control::add_recording_endpoints(router, api);
        control::add_connection_endpoints(router, api);
        control::add_info_endpoint(router, api);
        control::add_state_endpoints(router, api);
        control::add_event_endpoint(router, api);
        control::add_metrics_endpoint(router, api);
        control::add_static_pages(router);
        for (auto* memory : memories()) memory->set_write_observer(&watch);
    }

    // Every store the API writes: the devices (and CPU buffer), the station buffer, the module's buffer.
    std::vector<devicemodel::DeviceMemory*> memories() {
        std::vector<devicemodel::DeviceMemory*> all{&station.cpu().memory()};
        if (&station.cpu().station_buffer() != &station.cpu().memory()) all.push_back(&station.cpu().station_buffer());
        for (const auto& [_, module] : station.cpu().modules()) all.push_back(&module->memory);
        return all;
    }

    // Declared first, destroyed last: the station and the memories point to them.
    Watch watch;
    NoTransports no_transports;
    // Never run: the event hub only needs it for timers it arms for subscribers.
    boost::asio::io_context io;
    slmp::station::Home home{boost::asio::make_strand(io)};
    station::Station station;
    control::Metrics metrics;
    control::EventHub events;
    // Not routed here: a wait's answer is deferred, which this harness does not await.
    control::DeviceWaits waits;
    control::Api api;
    control::Router router;
};

// Every stored value of every store, SM/SD and the R/ZR slack included: a
// copy (compared with DeviceMemory::operator==) costs a few memcpy, where
// reading ~40k values one by one as fuzz_engine's snapshot() does would cost
// more than everything else here.
std::vector<devicemodel::DeviceMemory> snapshot(Rig& rig) {
    std::vector<devicemodel::DeviceMemory> all;
    all.reserve(4);
    for (const auto* memory : rig.memories()) all.push_back(*memory);
    return all;
}

bool has_key(const json& value, const std::string& key) {
    if (value.is_object() && value.contains(key)) return true;
    if (value.is_structured())
        for (const auto& item : value)
            if (has_key(item, key)) return true;
    return false;
}

// A "file" key is how a body names a file: POST /api/scenarios {"file": ...}
// reads one (/dev/zero would never end), a scenario's "replay": {"file": ...}
// reads a recording, POST /api/recording {"file": ...} creates one. Such
// bodies are left out; without "file" those endpoints still run their
// checks (and refuse). Parsed as the endpoints parse, so escapes such as
// "\u0066ile" are caught too.
bool reaches_files(const std::string& body) {
    auto parsed = json::parse(body, nullptr, false);
    return !parsed.is_discarded() && has_key(parsed, "file");
}

void check_reply(const control::Reply& reply, const std::string& what) {
    const auto status = static_cast<unsigned>(reply.status);
    FUZZ_CHECK(status >= 100 && status <= 599, "%s answered status %u", what.c_str(), status);
    if (reply.event_types != 0) {
        // GET /api/events: the connection becomes the stream; this reply is never sent.
        FUZZ_CHECK(reply.status == control::Status::ok && reply.body.empty(), "%s: an event stream with status %u",
                   what.c_str(), status);
        return;
    }
    const bool is_json = reply.content_type.starts_with("application/json");
    FUZZ_CHECK(is_json || status < 400, "%s answered %u as %s", what.c_str(), status, reply.content_type.c_str());
    if (!is_json) return;
    auto body = json::parse(reply.body, nullptr, false);
    FUZZ_CHECK(!body.is_discarded(), "%s answered %u with JSON that does not parse: %s", what.c_str(), status,
               reply.body.c_str());
    if (status >= 400)
        FUZZ_CHECK(body.is_object() && body.size() == 1 && body.contains("error") && body["error"].is_string(),
                   "%s answered %u without {\"error\": \"...\"}: %s", what.c_str(), status, reply.body.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // A loaded scenario logs at info level; a million of those would bury the fuzzer's own output.
    spdlog::set_level(spdlog::level::off);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Rig rig;
    std::string_view rest(reinterpret_cast<const char*>(data), size);
    for (std::size_t n = 0; !rest.empty() && n < kMaxRequests; ++n) {
        auto end = std::min(rest.find('\0'), rest.size());
        auto request = rest.substr(0, end);
        rest.remove_prefix(std::min(end + 1, rest.size()));
        if (request.empty()) continue;

        const auto method = kMethods[static_cast<unsigned char>(request[0]) % 5];
        request.remove_prefix(1);
        auto newline = std::min(request.find('\n'), request.size());
        auto target = request.substr(0, newline);
        std::string body(request.substr(std::min(newline + 1, request.size())));
        if (reaches_files(body)) continue;

        // A GET reads; any other method may write, but only when it succeeds.
        const bool may_write = method != Verb::get;
        const auto before = snapshot(rig);
        rig.watch.changed = false;
        const std::string what = std::string(boost::beast::http::to_string(method)) + " " + std::string(target);
        control::Reply reply;
        try {
            reply = rig.router.route(method, target, std::move(body));
        } catch (const std::exception& e) {
            FUZZ_CHECK(false, "%s threw out of route(): %s", what.c_str(), e.what());
        } catch (...) {
            FUZZ_CHECK(false, "%s threw a non-std::exception out of route()", what.c_str());
        }
        check_reply(reply, what);

        const auto status = static_cast<unsigned>(reply.status);
        if (!may_write || status >= 400) {
            FUZZ_CHECK(!rig.watch.changed, "%s answered %u and changed %s", what.c_str(), status, rig.watch.what.c_str());
            FUZZ_CHECK(snapshot(rig) == before, "%s answered %u and changed memory unseen by the observer", what.c_str(),
                       status);
        }
    }
    return 0;
}
