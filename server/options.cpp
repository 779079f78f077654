#include "server/options.hpp"

#include "config/drive_config.hpp"
#include "config/settings.hpp"
#include "config/shard.hpp"

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <vector>

#include <boost/program_options.hpp>
#include <fmt/format.h>

namespace slmp::server {

namespace po = boost::program_options;
using config::ConfigError;
using config::PortConfig;
using config::Transport;

namespace {

constexpr const char* kVersion = "slmp-sim 0.1.0";

// Replaces the configured ports of one transport with the ones given on the
// command line; the other transport keeps its ports.
// Options that name one station's ports, files or identity: refused with a plant.
constexpr const char* kOneStationOptions[] = {"profile", "bind", "tcp-port", "udp-port", "drive", "labels", "snapshot",
                                              "record", "record-pcap", "network-no",
                                              "station-no", "program"};

// ... and the protocol faces' (frontends/face.hpp).
std::vector<std::string_view> one_station_options() {
    std::vector<std::string_view> options(std::begin(kOneStationOptions), std::end(kOneStationOptions));
    for (const auto* face : frontends::faces())
        for (auto option : face->one_station_options()) options.push_back(option);
    return options;
}

void replace_ports(config::ServerConfig& c, Transport transport, const std::vector<unsigned>& ports) {
    std::erase_if(c.ports, [&](const PortConfig& p) { return p.transport == transport; });
    for (auto port : ports) c.ports.push_back(PortConfig{transport, static_cast<std::uint16_t>(port)});
}

// The flags of the settings table (config/settings.cpp), in its order; the
// protocol faces' own flags follow --config.
void add_table_options(po::options_description& options) {
    for (const auto& row : config::all_settings()) {
        if (row.flag.empty()) continue;
        const std::string name(row.flag);
        const char* help = row.help.data();   // the table's literals end in '\0'
        auto add = options.add_options();
        switch (row.flag_arg) {
            case config::FlagArg::None: add(name.c_str(), help); break;
            case config::FlagArg::Text: add(name.c_str(), po::value<std::string>(), help); break;
            case config::FlagArg::Unsigned: add(name.c_str(), po::value<unsigned>(), help); break;
            case config::FlagArg::Size: add(name.c_str(), po::value<std::size_t>(), help); break;
            case config::FlagArg::Real: add(name.c_str(), po::value<double>(), help); break;
            case config::FlagArg::UnsignedList:
                add(name.c_str(), po::value<std::vector<unsigned>>()->multitoken(), help);
                break;
            case config::FlagArg::TextList: add(name.c_str(), po::value<std::vector<std::string>>(), help); break;
        }
        if (row.long_flag() == "config")
            for (const auto* face : frontends::faces()) face->add_options(options);
    }
}

// Every numeric flag given, against its row's range (in the flag's unit).
void check_table_ranges(const po::variables_map& vm) {
    for (const auto& row : config::all_settings()) {
        const std::string name(row.long_flag());
        if (row.flag.empty() || !vm.count(name)) continue;
        switch (row.flag_arg) {
            case config::FlagArg::Unsigned: config::check_flag_value(row, vm[name].as<unsigned>()); break;
            case config::FlagArg::Size: config::check_flag_value(row, static_cast<double>(vm[name].as<std::size_t>())); break;
            case config::FlagArg::Real: config::check_flag_value(row, vm[name].as<double>()); break;
            case config::FlagArg::UnsignedList:
                for (auto v : vm[name].as<std::vector<unsigned>>()) config::check_flag_value(row, v);
                break;
            default: break;
        }
    }
}

// The flags that set a key of every port (the settings table's port rows with a flag).
void apply_port_options(const po::variables_map& vm, config::ServerConfig& c) {
    if (vm.count("data-code")) {
        auto code = config::parse_data_code(vm["data-code"].as<std::string>(), "--data-code");
        for (auto& p : c.ports) p.data_code = code;
    }
    auto seconds_ms = [&](const char* flag) { return static_cast<unsigned>(vm[flag].as<double>() * 1000); };
    for (auto& p : c.ports) {
        if (vm.count("max-connections")) p.max_connections = vm["max-connections"].as<unsigned>();
        if (vm.count("idle-timeout")) p.idle_timeout_ms = seconds_ms("idle-timeout");
        if (vm.count("partial-frame-timeout")) p.partial_frame_timeout_ms = seconds_ms("partial-frame-timeout");
        if (vm.count("max-connections-per-address")) p.max_connections_per_address = vm["max-connections-per-address"].as<unsigned>();
    }
    if (vm.count("network-no") || vm.count("station-no")) {
        auto numbers = config::checked_station_numbers(vm.count("network-no") ? vm["network-no"].as<unsigned>() : 0,
                                                       vm.count("station-no") ? vm["station-no"].as<unsigned>() : 0,
                                                       "--network-no/--station-no");
        for (auto& p : c.ports) p.numbers = numbers;
    }
}

// Proxy mode and, with it, differential mode (docs/twin.md).
void apply_upstream_options(const po::variables_map& vm, config::ServerConfig& c) {
    if (vm.count("upstream")) {
        c.upstream = vm["upstream"].as<std::string>();
        config::parse_upstream(c.upstream, "--upstream");
    }
    if (vm.count("upstream-timeout")) c.upstream_timeout_ms = static_cast<unsigned>(vm["upstream-timeout"].as<double>() * 1000);
    if (vm.count("compare")) {
        if (c.upstream.empty())
            throw ConfigError("--compare without --upstream: differential mode compares this station with its upstream; "
                              "give --upstream HOST:PORT too");
        c.compare = true;
    }
    if (vm.count("compare-slack")) c.compare_slack_ms = static_cast<unsigned>(std::lround(vm["compare-slack"].as<double>() * 1000));
}

void apply_http_options(const po::variables_map& vm, config::ServerConfig& c) {
    if (vm.count("http-port")) {
        c.http.port = static_cast<std::uint16_t>(vm["http-port"].as<unsigned>());
        c.http.enabled = true;
    }
    if (vm.count("http-bind")) c.http.bind = vm["http-bind"].as<std::string>();
    if (vm.count("no-http")) {
        if (vm.count("http-port") || vm.count("http-bind"))
            throw ConfigError("--no-http contradicts --http-port/--http-bind; give one or the other");
        c.http.enabled = false;
    }
}

// The files a station reads and writes: state, drives, scenarios, labels, program, recordings, snapshot.
void apply_file_options(const po::variables_map& vm, bool plant, config::ServerConfig& c) {
    if (vm.count("state-dir")) {
        std::filesystem::path dir(vm["state-dir"].as<std::string>());
        c.persistence.state_dir = (plant ? dir / c.name : dir).string();   // a plant: a folder per station
    }
    if (vm.count("drive"))
        for (const auto& text : vm["drive"].as<std::vector<std::string>>()) c.drives.push_back(config::parse_drive_option(text));
    if (vm.count("scenario")) {
        auto files = vm["scenario"].as<std::vector<std::string>>();
        c.scenarios.insert(c.scenarios.end(), files.begin(), files.end());
    }
    if (vm.count("labels"))
        for (const auto& file : vm["labels"].as<std::vector<std::string>>()) {
            auto more = config::load_labels_file(file);
            c.labels.structures.insert(c.labels.structures.end(), more.structures.begin(), more.structures.end());
            c.labels.labels.insert(c.labels.labels.end(), more.labels.begin(), more.labels.end());
        }
    if (vm.count("program")) c.cpu.program.file = vm["program"].as<std::string>();
    if (vm.count("record")) c.record_file = vm["record"].as<std::string>();
    if (vm.count("record-pcap")) c.record_pcap_file = vm["record-pcap"].as<std::string>();
    if (vm.count("snapshot")) c.snapshot_file = vm["snapshot"].as<std::string>();
}

// The options that set every station (or the only one): behaviour, limits,
// the clock, logs, HTTP; in a plant the one-station options are refused first.
void apply_station_options(const po::variables_map& vm, bool plant, config::StationConfig& station) {
    auto& c = station.server;
    auto& frontends = station.frontends;
    if (vm.count("profile")) c.profile = vm["profile"].as<std::string>();
    if (vm.count("bind")) c.bind = vm["bind"].as<std::string>();
    if (vm.count("tcp-port")) replace_ports(c, Transport::Tcp, vm["tcp-port"].as<std::vector<unsigned>>());
    if (vm.count("udp-port")) replace_ports(c, Transport::Udp, vm["udp-port"].as<std::vector<unsigned>>());
    apply_port_options(vm, c);
    apply_upstream_options(vm, c);
    if (vm.count("max-request-bytes")) c.max_request_bytes = vm["max-request-bytes"].as<std::size_t>();
    if (vm.count("log-level")) {
        c.log_level = vm["log-level"].as<std::string>();
        if (!config::valid_log_level(c.log_level))
            throw ConfigError("--log-level " + c.log_level + ": unknown level; " +
                              std::string(config::setting(config::Section::Station, "log_level").fix));
    }
    if (vm.count("ready-file")) c.ready_file = vm["ready-file"].as<std::string>();
    apply_http_options(vm, c);
    if (vm.count("switch")) c.cpu.runtime.run_switch = config::parse_run_switch(vm["switch"].as<std::string>(), "--switch");
    apply_file_options(vm, plant, c);
    if (vm.count("clock-speed")) c.clock_speed = vm["clock-speed"].as<double>();
    if (vm.count("timing")) c.timing.mode = config::parse_timing_mode(vm["timing"].as<std::string>(), "--timing");
    if (vm.count("clock")) {
        auto mode = vm["clock"].as<std::string>();
        if (!config::is_choice(*config::setting_by_flag("clock"), mode))
            throw ConfigError("--clock " + mode + ": use realtime or frozen");
        c.clock_frozen = mode == "frozen";
    }
    // The protocol faces' own options (frontends/face.hpp), then: a station of a
    // face's kind serves that face alone.
    for (const auto* face : frontends::faces())
        face->apply_options(vm, frontends.find(face->name()), [&]() -> frontends::Settings& { return frontends.enable(*face); });
    if (const auto* only = frontends.kind_face(); only && (!c.ports.empty() || frontends.faces.size() > 1))
        throw ConfigError(only->command_line_refusal());
    if (c.ports.empty() && frontends.faces.empty())
        throw ConfigError((c.name.empty() ? std::string() : "station '" + c.name + "': ") + "no ports configured; give --tcp-port or --udp-port, or add \"ports\" to the configuration");
}

// --shard: keep the stations of this process's shard (docs/plants.md,
// "Shards"); without it the process serves the whole plant as shard 0 of 1.
void apply_shard_option(const po::variables_map& vm, config::PlantConfig& plant) {
    unsigned index = 0, count = 1;
    if (vm.count("shard")) {
        if (!plant.plant)
            throw ConfigError("--shard splits a plant, and the configuration is one station; give a file with "
                              "\"stations\" (docs/plants.md)");
        auto option = config::parse_shard_option(vm["shard"].as<std::string>());
        count = option.count.value_or(plant.layout.file_count);
        if (option.index) {
            index = *option.index;
        } else {
            char host[256] = {};
            gethostname(host, sizeof host - 1);
            index = config::ordinal_of_host_name(host);
        }
    }
    if (plant.plant) config::select_shard(plant, index, count);
}

// --help, --version, --list-profiles: print, and the caller exits.
bool print_info(const po::variables_map& vm, const po::options_description& options) {
    if (vm.count("help")) {
        std::cout << "slmp-sim — a MELSEC CPU that answers SLMP (3E/4E, binary/ASCII; 1E and the station-number-extended frame where its profile has them) over TCP and UDP\n\n"
                  << "Usage: slmp-sim [options]\n\n" << options << "\n";
        return true;
    }
    if (vm.count("version")) {
        std::cout << kVersion << "\n";
        return true;
    }
    if (vm.count("list-profiles")) {
        // One line each: the name to give --profile, what 0101 answers, the family, the description.
        for (const auto& name : config::builtin_profile_names()) {
            auto profile = config::load_profile(name);
            std::cout << fmt::format("{:<20} {:<16} {:04X}  {:<8} {}\n", name, profile.cpu.type_name,
                                     profile.cpu.model_code, config::family_name(profile.cpu.family),
                                     profile.description);
        }
        return true;
    }
    return false;
}

}  // namespace

CommandLine parse_command_line(int argc, char** argv) {
    po::options_description options("Options");
    add_table_options(options);
    po::variables_map vm;
    try {
        po::store(po::command_line_parser(argc, argv).options(options).run(), vm);
        po::notify(vm);
    } catch (const po::error& e) {
        throw ConfigError(std::string(e.what()) + "; see slmp-sim --help");
    }

    CommandLine cl;
    if (print_info(vm, options)) {
        cl.exit_now = true;
        return cl;
    }
    check_table_ranges(vm);
    // --profile is known before the file is read: the file's addresses follow its numbering.
    const auto profile = vm.count("profile") ? vm["profile"].as<std::string>() : std::string();
    if (vm.count("check-config")) {
        if (vm.count("config")) throw ConfigError("--check-config FILE checks FILE; leave --config out");
        cl.check_only = true;
        cl.plant = config::load_plant_config(vm["check-config"].as<std::string>(), profile);
    } else if (vm.count("config")) {
        cl.plant = config::load_plant_config(vm["config"].as<std::string>(), profile);
    } else {
        cl.plant.stations.emplace_back();
    }
    if (vm.count("threads")) cl.plant.threads = vm["threads"].as<unsigned>();
    if (cl.plant.plant)
        for (std::string_view option : one_station_options())
            if (vm.count(std::string(option)))
                throw ConfigError("--" + std::string(option) + " sets one station, and the configuration is a plant of " +
                                  std::to_string(cl.plant.stations.size()) + " stations; give it in each station's "
                                  "entry in the file instead (docs/plants.md)");
    apply_shard_option(vm, cl.plant);
    for (auto& station : cl.plant.stations) apply_station_options(vm, cl.plant.plant, station);
    return cl;
}

}  // namespace slmp::server
