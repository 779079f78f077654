// slmp-replay: sends a recorded session (slmp-sim --record FILE) to any SLMP
// server — slmp-sim, another simulator, a real PLC — and reports where the
// answers differ from the recorded ones, in the kinds slmp-sim --compare
// reports (protocol/differential.hpp: close, silence, end_code, bytes). One
// connection per recorded connection, requests in the recorded order, one
// answer awaited per request.
// Exit: 0 every answer identical, 1 differences, 2 bad options or no server.
// --to-scenario: no server; the recording's reads become a scenario (to_scenario.hpp).
// Reference: docs/scenarios.md "Record & replay", docs/twin.md.
#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <thread>

#include <boost/program_options.hpp>

#include "config/config.hpp"
#include "config/config_error.hpp"
#include "protocol/client.hpp"
#include "protocol/differential.hpp"
#include "scenarios/difference_json.hpp"
#include "scenarios/recording.hpp"
#include "tools/replay/to_scenario.hpp"
#include "tools/replay/wire.hpp"

namespace po = boost::program_options;
using slmp::replay::Bytes;
using slmp::replay::Wire;

namespace {

struct Options {
    std::string file, host = "127.0.0.1";
    std::uint16_t port = 5000;
    std::optional<std::uint16_t> udp_port;   // when UDP is served on another port than TCP
    std::chrono::milliseconds timeout{2000}, silence{200};
    bool pace = false;
    std::size_t max_shown = 20;
    bool json = false;                  // the report as one JSON document on stdout
    bool to_scenario = false;           // no replay: the recording's reads as a scenario
    std::string out;                    // --to-scenario's file (empty: stdout)
    std::string profile;                // --to-scenario's decoding profile (empty: the recording's)
};

namespace differential = slmp::protocol::differential;
using Observed = differential::Observed;

std::string hex(const Bytes& b) { return slmp::scenarios::to_hex(b); }

// A recorded or a replayed answer as the comparison sees it. A recording
// tells no silence from a close ("response": null): silence.
Observed observed(const std::optional<Bytes>& answer, const std::string& why = "timeout") {
    Observed o;
    if (!answer) {
        o.kind = why == "timeout" ? Observed::Kind::Silence : Observed::Kind::Close;
        return o;
    }
    o.bytes = *answer;
    auto parsed = slmp::protocol::client::parse_response(*answer);
    o.end_code = parsed ? parsed->end_code : 0xFFFF;   // no frame to read an end code from
    return o;
}

Options parse(int argc, char** argv) {
    po::options_description named("Options");
    named.add_options()
        ("help,h", "print this help")
        ("host", po::value<std::string>(), "server address (default 127.0.0.1)")
        ("port", po::value<unsigned>(), "SLMP port (default 5000); TCP or UDP as recorded")
        ("udp-port", po::value<unsigned>(), "port for the recorded UDP exchanges (default: --port)")
        ("timeout-ms", po::value<unsigned>(), "longest wait for each answer (default 2000)")
        ("silence-ms", po::value<unsigned>(), "how long to listen where the recording has no answer (default 200)")
        ("pace", "keep the recorded time between requests (default: as fast as answers come)")
        ("max-shown", po::value<std::size_t>(), "differences printed in full (default 20)")
        ("json", "the report as one JSON document on stdout (every difference, as GET /api/compare lists them)")
        ("to-scenario", "send nothing: turn what the recording's clients read into a scenario timeline (docs/twin.md)")
        ("out", po::value<std::string>(), "--to-scenario: write the scenario to this file (default: stdout)")
        ("profile", po::value<std::string>(), "--to-scenario: the profile that decodes the requests and names the devices "
                                              "(default: the recording's, if built in; else R08CPU)");
    po::options_description hidden;
    hidden.add_options()("recording", po::value<std::string>());
    po::positional_options_description positional;
    positional.add("recording", 1);
    po::options_description all;
    all.add(named).add(hidden);
    po::variables_map vm;
    po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
    if (!vm.count("help") && !vm.count("recording"))
        throw std::runtime_error("no recording given; usage: slmp-replay RECORDING.jsonl [options] (--help for more)");
    if (vm.count("help")) {
        std::cout << "slmp-replay — send a recorded SLMP session to a server and report differing answers\n\n"
                  << "Usage: slmp-replay RECORDING.jsonl [options]\n\n"
                  << "       slmp-replay --to-scenario RECORDING.jsonl [--out SCENARIO.json] [--profile NAME]\n\n"
                  << "RECORDING.jsonl is a recording made with slmp-sim --record FILE.\n"
                  << "Differences are named by kind: close, silence, end_code, bytes (as slmp-sim --compare names them).\n\n"
                  << named
                  << "\nExit status: 0 every answer identical, 1 some answers differ or are missing,\n"
                     "2 bad options, an unreadable recording or no server.\n"
                     "--to-scenario: 0 the scenario written, 2 bad options, an unreadable recording\n"
                     "or a file it cannot write.\n"
                     "Reference: docs/scenarios.md \"Record & replay\", docs/twin.md.\n";
        std::exit(0);
    }
    Options o;
    o.file = vm["recording"].as<std::string>();
    if (vm.count("host")) o.host = vm["host"].as<std::string>();
    auto port = [&](const char* name) {
        auto p = vm[name].as<unsigned>();
        if (p == 0 || p > 65535) throw std::runtime_error(std::string("--") + name + " " + std::to_string(p) + ": use 1-65535");
        return static_cast<std::uint16_t>(p);
    };
    if (vm.count("port")) o.port = port("port");
    if (vm.count("udp-port")) o.udp_port = port("udp-port");
    if (vm.count("timeout-ms")) o.timeout = std::chrono::milliseconds(vm["timeout-ms"].as<unsigned>());
    if (vm.count("silence-ms")) o.silence = std::chrono::milliseconds(vm["silence-ms"].as<unsigned>());
    o.pace = vm.count("pace") > 0;
    if (vm.count("max-shown")) o.max_shown = vm["max-shown"].as<std::size_t>();
    o.json = vm.count("json") > 0;
    o.to_scenario = vm.count("to-scenario") > 0;
    if (vm.count("out")) o.out = vm["out"].as<std::string>();
    if (vm.count("profile")) o.profile = vm["profile"].as<std::string>();
    if (!o.to_scenario && (vm.count("out") || vm.count("profile")))
        throw std::runtime_error("--out and --profile go with --to-scenario");
    return o;
}

// --to-scenario: the recording's reads as a scenario (to_scenario.hpp); the
// summary on stderr, so the scenario alone can go to stdout.
int write_scenario(const Options& o, const slmp::scenarios::Recording& recording) {
    slmp::config::Profile profile;
    const std::string wanted = !o.profile.empty() ? o.profile : !recording.profile.empty() ? recording.profile : "R08CPU";
    try {
        profile = slmp::config::load_profile(wanted);
    } catch (const slmp::config::ConfigError& e) {
        if (!o.profile.empty()) {
            std::cerr << "slmp-replay: error: --profile " << o.profile << ": " << e.what() << "\n";
            return 2;
        }
        std::cerr << "slmp-replay: the recording's profile '" << wanted
                  << "' is not a built-in one; the requests are decoded as R08CPU's (--profile FILE names yours)\n";
        profile = slmp::config::load_profile("R08CPU");
    }
    auto result = slmp::replay::to_scenario(recording, profile, std::filesystem::path(o.file).stem().string());
    const auto text = result.scenario.dump(2) + "\n";
    if (o.out.empty()) {
        std::cout << text;
    } else {
        std::ofstream file(o.out, std::ios::binary | std::ios::trunc);
        file << text;
        if (!file) {
            std::cerr << "slmp-replay: error: cannot write " << o.out << "\n";
            return 2;
        }
    }
    std::cerr << "slmp-replay: " << result.reads << " read(s) of " << result.devices << " device(s): "
              << result.steps << " timeline step(s)" << (result.ramps ? " (" + std::to_string(result.ramps) + " ramp(s))" : std::string())
              << (o.out.empty() ? std::string() : " in " + o.out) << "\n";
    for (const auto& [why, count] : result.skipped) std::cerr << "  " << count << " read(s) not used: " << why << "\n";
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    slmp::scenarios::Recording recording;
    try {
        o = parse(argc, argv);
        recording = slmp::scenarios::read_recording(o.file);
    } catch (const std::exception& e) {
        std::cerr << "slmp-replay: error: " << e.what() << "\n";
        return 2;
    }
    if (o.to_scenario) return write_scenario(o, recording);
    std::map<std::uint64_t, std::unique_ptr<Wire>> wires;   // recorded connection -> our connection
    std::size_t same = 0, different = 0, shown = 0;
    std::array<std::size_t, 6> kinds{};   // by differential::DifferenceKind
    auto differences = nlohmann::json::array();
    double previous_ms = recording.exchanges.empty() ? 0 : recording.exchanges.front().t_ms;
    for (std::size_t i = 0; i < recording.exchanges.size(); ++i) {
        const auto& e = recording.exchanges[i];
        if (o.pace && e.t_ms > previous_ms)
            std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(e.t_ms - previous_ms));
        previous_ms = e.t_ms;
        auto& wire = wires[e.connection];
        try {
            bool udp = e.transport == slmp::scenarios::Transport::Udp;
            if (!wire) wire = std::make_unique<Wire>(o.host, udp ? o.udp_port.value_or(o.port) : o.port, udp);
        } catch (const std::exception& ex) {
            std::cerr << "slmp-replay: error: " << ex.what() << "\n";
            return 2;
        }
        std::string why;
        std::optional<Bytes> got;
        if (wire->send(e.request)) got = wire->receive(e.response ? o.timeout : o.silence, why);
        else why = "send failed";
        if (wire->refused()) {   // no server at all is not a difference: it is exit 2, like a refused TCP connect
            std::cerr << "slmp-replay: error: nothing answers on UDP " << o.host << ":" << o.udp_port.value_or(o.port)
                      << " (port unreachable)\n";
            return 2;
        }
        const auto recorded = observed(e.response), now = observed(got, why);
        const auto d = differential::classify(recorded, now);
        if (d.same()) {
            ++same;
            continue;
        }
        ++different;
        ++kinds[static_cast<std::size_t>(d.kind)];
        if (!got) wire.reset();   // closed or silent: the next request of this connection starts afresh
        if (o.json) {
            auto entry = slmp::scenarios::difference_json(d, e.request, "recorded", recorded, "now", now);
            entry["exchange"] = i + 1;
            entry["connection"] = e.connection;
            entry["t_ms"] = e.t_ms;
            if (!got) entry["why"] = why;
            differences.push_back(std::move(entry));
            continue;
        }
        if (shown++ >= o.max_shown) continue;
        std::cout << "#" << i + 1 << " (connection " << e.connection << ", " << e.t_ms << " ms) request " << hex(e.request) << "\n"
                  << "  recorded: " << (e.response ? hex(*e.response) : std::string("(no answer)")) << "\n"
                  << "  now:      " << (got ? hex(*got) : "(" + why + ")") << "\n"
                  << "  " << differential::kind_name(d.kind) << ": recorded vs now: " << d.text << "\n";
    }
    auto count = [&](differential::DifferenceKind kind) { return kinds[static_cast<std::size_t>(kind)]; };
    if (o.json) {
        std::cout << nlohmann::json{{"exchanges", recording.exchanges.size()}, {"same", same}, {"different", different},
                                    {"kinds", slmp::scenarios::kinds_json(count)}, {"differences", std::move(differences)}}
                         .dump(2)
                  << "\n";
        return different ? 1 : 0;
    }
    std::cout << recording.exchanges.size() << " exchange(s): " << same << " identical, " << different << " different";
    std::string by_kind;
    for (auto kind : differential::kDifferenceKinds)
        if (count(kind)) by_kind += (by_kind.empty() ? "" : ", ") + std::string(differential::kind_name(kind)) + " " + std::to_string(count(kind));
    std::cout << (by_kind.empty() ? "" : " (" + by_kind + ")") << "\n";
    return different ? 1 : 0;
}
