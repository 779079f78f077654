#include "tools/slmp/options.hpp"

#include <boost/program_options.hpp>

#include <cctype>
#include <charconv>
#include <cmath>
#include <iostream>

#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {

namespace po = boost::program_options;

namespace {

// Route numbers: decimal, 0x-prefixed hex or MELSEC-style H-suffixed hex
// ("0xFF", "FFH"); `hex_default` (module I/O, always written in hex) reads bare
// digits as hex.
unsigned long route_number(const std::string& option, const std::string& text, unsigned long max, bool hex_default) {
    std::string digits = text;
    int base = hex_default ? 16 : 10;
    if (digits.size() > 2 && (digits.starts_with("0x") || digits.starts_with("0X"))) {
        digits = digits.substr(2);
        base = 16;
    } else if (digits.size() > 1 && (digits.back() == 'H' || digits.back() == 'h')) {
        digits.pop_back();
        base = 16;
    }
    unsigned long value = 0;
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value, base);
    if (digits.empty() || ec != std::errc{} || ptr != digits.data() + digits.size() || value > max)
        throw UsageError("--" + option + " '" + text + "' must be a number 0.." + std::to_string(max) +
                         " (decimal, 0x.. or ..H hex" + (hex_default ? "; bare digits are hex" : "") + ")");
    return value;
}

std::chrono::milliseconds duration_option(const std::string& option, const std::string& text) {
    auto value = parse_duration(text);
    if (!value) throw UsageError("--" + option + " '" + text + "' is not a duration; write it with a unit: 500ms, 2s, 1m");
    return *value;
}

const char* kUsageText =
    "slmp: an SLMP (MC protocol 3E/4E) client for MELSEC PLCs and slmp-sim. See docs/cli.md.\n"
    "Usage: slmp [global options] COMMAND [arguments] [command options]\n";

}  // namespace

std::optional<std::chrono::milliseconds> parse_duration(const std::string& text) {
    std::size_t split = 0;
    while (split < text.size() && (std::isdigit(static_cast<unsigned char>(text[split])) || text[split] == '.')) ++split;
    auto number = text.substr(0, split);
    auto unit = text.substr(split);
    if (number.find_first_of("0123456789") == std::string::npos || number.find('.') != number.rfind('.'))
        return std::nullopt;
    // "0" needs no unit: zero is zero in any of them.
    if (unit.empty() && number.find_first_not_of("0.") == std::string::npos) return std::chrono::milliseconds(0);
    double scale = unit == "ms" ? 1 : unit == "s" ? 1000 : unit == "m" ? 60000 : -1;
    if (scale < 0) return std::nullopt;
    double value = std::stod(number) * scale;
    if (value > 24.0 * 3600 * 1000) return std::nullopt;
    return std::chrono::milliseconds(static_cast<long long>(std::llround(value)));
}

std::optional<Options> parse_options(int argc, char** argv, int& exit_code) {
    Options o;
    std::string host = o.target.host, timeout = "3s", interval = "1s", silence;
    std::string network, station, module_io, multidrop, serial;
    unsigned long count = 0;
    bool udp = false, ascii = false, e4 = false, iqr = false, octal_xy = false;

    po::options_description global("Global options");
    // clang-format off
    global.add_options()
        ("help", "show this help")
        ("host", po::value(&host)->default_value(host), "PLC address or host name")
        ("port", po::value(&o.target.port)->default_value(o.target.port), "SLMP port")
        ("udp", po::bool_switch(&udp), "UDP instead of TCP")
        ("ascii", po::bool_switch(&ascii), "ASCII data code instead of binary")
        ("4e", po::bool_switch(&e4), "4E frame (with serial number) instead of 3E")
        ("serial", po::value(&serial), "4E serial number of the first request (default 0; +1 per request)")
        ("network", po::value(&network), "request destination network No. (default 0)")
        ("station", po::value(&station), "request destination station No. (default 255 = FFH, own station)")
        ("module-io", po::value(&module_io), "request destination module I/O No., hex (default 03FF)")
        ("multidrop", po::value(&multidrop), "request destination multidrop station No. (default 0)")
        ("timeout", po::value(&timeout)->default_value(timeout), "wait at most this long for each answer (500ms, 2s)")
        ("iqr", po::bool_switch(&iqr), "iQ-R device subcommands 0002/0003 instead of 0000/0001")
        ("octal-xy", po::bool_switch(&octal_xy), "X/Y numbered in octal, as on an iQ-F (FX5): X7 is followed by X10")
        ("password", po::value<std::string>(), "send Remote Unlock (1630) with this password first")
        ("plant-station", po::value(&o.plant_station), "slmp-sim plant: talk to the station of this name (its port from the HTTP API)")
        ("api-port", po::value(&o.api_port)->default_value(o.api_port), "slmp-sim's HTTP port, for --plant-station")
        ("json", po::bool_switch(&o.json), "print JSON instead of a table");
    po::options_description specific("Command options");
    specific.add_options()
        ("bits", po::bool_switch(&o.bits), "read/write/random write: bit units (0/1 per device)")
        ("dword", po::value(&o.dwords), "random: a double-word device (read) or DEVICE=VALUE (write); repeatable")
        ("interval", po::value(&interval), "monitor: time between polls (default 1s)")
        ("count", po::value(&count), "monitor: stop after this many polls (default: until Ctrl-C)")
        ("wait", po::bool_switch(&o.wait), "ondemand: wait for Ondemand (2101) pushes and print each (--count N, default 1)")
        ("broadcast", po::bool_switch(&o.broadcast), "nodes: send the node search as a UDP broadcast to --host:--port "
                                                       "(e.g. 127.255.255.255) and list every node answering within --timeout")
        ("force", po::bool_switch(&o.force), "run/pause: mode 0003, even if another client holds STOP/PAUSE")
        ("clear", po::value(&o.clear), "run: clear devices first: none (default), nonlatch, all")
        ("file-password", po::value(&o.file_password), "file: the file's password (Q/L: up to 4 characters, iQ-R: 6-32)")
        ("out", po::value(&o.out), "probe: write the probed profile to this file")
        ("allow-writes", po::value(&o.allow_writes), "probe: scratch ranges it may write and restores (D9000-D9999,M9000-M9999)")
        ("record", po::value(&o.record), "probe, diff: save every exchange as a recording (JSON lines, slmp-replay reads it)")
        ("against", po::value(&o.against), "diff: HOST:PORT of the server to compare with (same transport)")
        ("profile", po::value(&o.profile), "diff: the profile (name or file) whose limits and sizes the requests test")
        ("silence", po::value(&silence), "probe, diff: no answer for this long counts as silence (default: --timeout)");
    po::options_description hidden;
    hidden.add_options()
        ("command", po::value(&o.command))
        ("args", po::value(&o.args));
    // clang-format on
    po::options_description all;
    all.add(global).add(specific).add(hidden);
    po::positional_options_description positional;
    positional.add("command", 1).add("args", -1);

    auto help = [&](std::ostream& out) { out << kUsageText << '\n' << commands_help() << '\n' << global << '\n' << specific; };
    po::variables_map vm;
    try {
        for (int i = 1; i < argc; ++i) {
            if (std::string_view(argv[i]) == "-h") {
                help(std::cout);
                exit_code = kOk;
                return std::nullopt;
            }
        }
        // No short options: "-5" is a value to write, not an option.
        auto style = po::command_line_style::unix_style & ~po::command_line_style::allow_short;
        po::store(po::command_line_parser(argc, argv).options(all).positional(positional).style(style).run(), vm);
        po::notify(vm);
        if (vm.count("help")) {
            help(std::cout);
            exit_code = kOk;
            return std::nullopt;
        }
        if (o.command.empty()) throw UsageError("no command given; e.g. slmp read D100 10 (try --help)");
        o.target.host = host;
        o.target.udp = udp;
        o.target.timeout = duration_option("timeout", timeout);
        if (o.target.timeout.count() <= 0) throw UsageError("--timeout must be above 0");
        o.frame.codec = ascii ? protocol::Codec::Ascii : protocol::Codec::Binary;
        o.frame.kind = e4 ? protocol::FrameKind::E4 : protocol::FrameKind::E3;
        if (!serial.empty()) {
            if (!e4) throw UsageError("--serial needs --4e: only 4E frames carry a serial number");
            o.frame.serial = static_cast<std::uint16_t>(route_number("serial", serial, 0xFFFF, false));
        }
        if (!network.empty()) o.frame.route.network = static_cast<std::uint8_t>(route_number("network", network, 0xFF, false));
        if (!station.empty()) o.frame.route.station = static_cast<std::uint8_t>(route_number("station", station, 0xFF, false));
        if (!module_io.empty())
            o.frame.route.module_io = static_cast<std::uint16_t>(route_number("module-io", module_io, 0xFFFF, true));
        if (!multidrop.empty())
            o.frame.route.multidrop = static_cast<std::uint8_t>(route_number("multidrop", multidrop, 0xFF, false));
        o.form = iqr ? protocol::DeviceForm::IQR : protocol::DeviceForm::Q;
        if (octal_xy) o.frame.numbering.xy = devicemodel::Radix::Oct;
        if (vm.count("password")) o.password = vm["password"].as<std::string>();
        if (vm.count("interval")) o.interval = duration_option("interval", interval);
        if (vm.count("silence")) o.silence = duration_option("silence", silence);
        if (vm.count("count")) {
            if (count == 0) throw UsageError("--count must be at least 1");
            o.count = count;
        }
        for (const auto& option : specific.options()) {
            const auto& name = option->long_name();
            if (vm.count(name) && !vm[name].defaulted()) o.given.push_back(name);
        }
    } catch (const po::error& e) {
        std::cerr << "slmp: " << e.what() << " (try --help)\n";
        exit_code = kUsage;
        return std::nullopt;
    } catch (const UsageError& e) {
        std::cerr << "slmp: " << e.what() << '\n';
        exit_code = kUsage;
        return std::nullopt;
    }
    return o;
}

}  // namespace slmp::cli
