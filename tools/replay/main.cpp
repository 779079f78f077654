// slmp-replay: sends a recorded session (slmp-sim --record FILE) to any SLMP
// server — slmp-sim, another simulator, a real PLC — and reports where the
// answers differ from the recorded ones. One connection per recorded
// connection, requests in the recorded order, one answer awaited per request.
// Exit: 0 every answer identical, 1 differences, 2 bad options or no server.
// Reference: docs/scenarios.md "Record & replay".
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <thread>

#include <boost/program_options.hpp>

#include "protocol/client.hpp"
#include "scenarios/recording.hpp"
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
};

std::string hex(const Bytes& b) { return slmp::scenarios::to_hex(b); }

// What differs, in a client's words: the end code, or the first differing byte.
std::string describe(const Bytes& want, const Bytes& got) {
    auto a = slmp::protocol::client::parse_response(want), b = slmp::protocol::client::parse_response(got);
    char text[64];
    if (a && b && a->end_code != b->end_code) {
        std::snprintf(text, sizeof text, "end code %04X recorded, %04X now", a->end_code, b->end_code);
        return text;
    }
    std::size_t i = 0;
    while (i < want.size() && i < got.size() && want[i] == got[i]) ++i;
    if (i == want.size() || i == got.size())
        return "length " + std::to_string(want.size()) + " recorded, " + std::to_string(got.size()) + " now";
    return "first difference at byte " + std::to_string(i);
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
        ("max-shown", po::value<std::size_t>(), "differences printed in full (default 20)");
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
                  << "RECORDING.jsonl is a recording made with slmp-sim --record FILE.\n\n" << named
                  << "\nExit status: 0 every answer identical, 1 some answers differ or are missing,\n"
                     "2 bad options, an unreadable recording or no server.\n"
                     "Reference: docs/scenarios.md \"Record & replay\".\n";
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
    return o;
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
    std::map<std::uint64_t, std::unique_ptr<Wire>> wires;   // recorded connection -> our connection
    std::size_t same = 0, different = 0, shown = 0;
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
        bool match = got ? (e.response && *got == *e.response) : !e.response;
        if (match) {
            ++same;
            continue;
        }
        ++different;
        if (!got) wire.reset();   // closed or silent: the next request of this connection starts afresh
        if (shown++ >= o.max_shown) continue;
        std::cout << "#" << i + 1 << " (connection " << e.connection << ", " << e.t_ms << " ms) request " << hex(e.request) << "\n"
                  << "  recorded: " << (e.response ? hex(*e.response) : std::string("(no answer)")) << "\n"
                  << "  now:      " << (got ? hex(*got) : "(" + why + ")") << "\n";
        if (got && e.response) std::cout << "  " << describe(*e.response, *got) << "\n";
    }
    std::cout << recording.exchanges.size() << " exchange(s): " << same << " identical, " << different << " different\n";
    return different ? 1 : 0;
}
