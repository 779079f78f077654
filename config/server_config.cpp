// The server configuration file. Keys and defaults: docs/configuration.md.
#include <cctype>
#include <fstream>
#include <optional>
#include <sstream>

#include "config/config.hpp"
#include "config/config_parts.hpp"
#include "config/drive_config.hpp"
#include "config/json_path.hpp"
#include "config/settings.hpp"
#include "frontends/face.hpp"

namespace slmp::config {

using devicemodel::Area;
using devicemodel::Unit;

namespace {

PortConfig port(const JsonAt& at) {
    check_keys(at, Section::Port);
    PortConfig p;
    p.transport = choice_setting(at, Section::Port, "transport") == "tcp" ? Transport::Tcp : Transport::Udp;
    auto whole = [&](std::string_view key) { return static_cast<unsigned>(whole_setting(at, Section::Port, key)); };
    p.port = static_cast<std::uint16_t>(whole("port"));
    if (at.has("data_code")) p.data_code = parse_data_code(at["data_code"].string(), at["data_code"].pointer());
    if (at.has("max_connections")) p.max_connections = whole("max_connections");
    if (at.has("idle_timeout_ms")) p.idle_timeout_ms = whole("idle_timeout_ms");
    if (at.has("partial_frame_timeout_ms")) p.partial_frame_timeout_ms = whole("partial_frame_timeout_ms");
    if (at.has("max_connections_per_address")) p.max_connections_per_address = whole("max_connections_per_address");
    if (at.has("remote_password")) p.remote_password = at["remote_password"].boolean();
    if (at.has("online_change")) p.online_change = at["online_change"].boolean();
    if (at.has("network") || at.has("station")) {
        // Read up to a byte, then checked as a pair (checked_station_numbers).
        auto network = at.has("network") ? static_cast<unsigned>(at["network"].unsigned_int(255)) : 0u;
        auto station = at.has("station") ? static_cast<unsigned>(at["station"].unsigned_int(255)) : 0u;
        try {
            p.numbers = checked_station_numbers(network, station, "network/station");
        } catch (const ConfigError& e) {
            at.fail(e.what(), "give both, network 1-239 and station 1-120");
        }
    }
    return p;
}

HttpConfig http_config(const JsonAt& at) {
    check_keys(at, Section::Http);
    HttpConfig h;
    if (at.has("enabled")) h.enabled = at["enabled"].boolean();
    if (at.has("port")) h.port = static_cast<std::uint16_t>(whole_setting(at, Section::Http, "port"));
    if (at.has("bind")) h.bind = at["bind"].string();
    return h;
}

// "ports", or its short form: only the port numbers ("tcp_port", "udp_port"); a transport left out is not served.
void parse_ports(const JsonAt& root, ServerConfig& c) {
    if (root.has("ports")) {
        auto ports = root["ports"];
        ports.expect_array();
        c.ports.clear();
        for (std::size_t i = 0; i < ports.json().size(); ++i) c.ports.push_back(port(ports[i]));
    }
    if (root.has("tcp_port") || root.has("udp_port")) {
        if (root.has("ports"))
            root["ports"].fail("\"ports\" and \"tcp_port\"/\"udp_port\" both given",
                               "give one: \"ports\" for every port setting, or tcp_port/udp_port for the numbers");
        c.ports.clear();
        if (root.has("tcp_port"))
            c.ports.push_back({Transport::Tcp, static_cast<std::uint16_t>(whole_setting(root, Section::Station, "tcp_port"))});
        if (root.has("udp_port"))
            c.ports.push_back({Transport::Udp, static_cast<std::uint16_t>(whole_setting(root, Section::Station, "udp_port"))});
    }
}

// Proxy mode ("upstream") and, with it, differential mode ("compare"; docs/twin.md).
void parse_upstream_keys(const JsonAt& root, ServerConfig& c) {
    if (root.has("upstream")) {
        c.upstream = root["upstream"].string();
        if (!split_upstream(c.upstream)) root["upstream"].fail("'" + c.upstream + "' is not HOST:PORT", kUpstreamFix);
    }
    if (root.has("upstream_timeout_ms"))
        c.upstream_timeout_ms = static_cast<unsigned>(whole_setting(root, Section::Station, "upstream_timeout_ms"));
    if (root.has("compare")) c.compare = root["compare"].boolean();
    if (root.has("compare_slack_ms"))
        c.compare_slack_ms = static_cast<unsigned>(whole_setting(root, Section::Station, "compare_slack_ms"));
    if (c.compare && c.upstream.empty())
        root["compare"].fail("\"compare\" without \"upstream\"", "differential mode compares this station with its upstream: "
                                                                   "give \"upstream\": \"HOST:PORT\" too, or drop \"compare\"");
}

}  // namespace

std::vector<std::pair<Area, std::uint32_t>> parse_device_sizes(const JsonAt& sizes) {
    sizes.expect_object();
    std::vector<std::pair<Area, std::uint32_t>> list;
    for (const auto& [name, _] : sizes.json().items()) {
        auto a = devicemodel::area_by_name(name);
        if (!a) sizes[name].fail("unknown device '" + name + "'", "use a device area such as X, M, D, T, ZR, LZ");
        list.emplace_back(*a, static_cast<std::uint32_t>(sizes[name].unsigned_int(0x7FFFFFFF)));
    }
    return list;
}

// One device's initial values: a number, a list of numbers (consecutive
// devices), or for word devices a string packed two characters a word, low
// byte first (as the manual stores "12AB" in D2-D3).
InitialValue parse_initial_value(const std::string& address_text, const JsonAt& at) {
    std::string error;
    auto address = devicemodel::parse_address(address_text, &error);
    if (!address) at.fail(error, "write an address such as D100, M0, X1F, ZR1000");
    InitialValue v{*address, {}};
    const auto& j = at.json();
    auto number = [&](const JsonAt& item) -> std::uint32_t {
        if (item.json().is_boolean()) return item.json().get<bool>() ? 1 : 0;
        if (item.json().is_number_integer() && item.json().get<std::int64_t>() < 0) {
            auto s = item.json().get<std::int64_t>();
            if (s < -2147483648LL) item.fail("value too small", "use a 32-bit value");
            return static_cast<std::uint32_t>(s);   // two's complement, as a PLC stores it
        }
        return static_cast<std::uint32_t>(item.unsigned_int(0xFFFFFFFF));
    };
    if (j.is_array()) {
        for (std::size_t i = 0; i < j.size(); ++i) v.values.push_back(number(at[i]));
    } else if (j.is_string()) {
        if (address->spec->unit != Unit::Word) at.fail("a string needs a word device", "use e.g. D100");
        auto text = j.get<std::string>();
        for (std::size_t i = 0; i < text.size(); i += 2) {
            std::uint32_t low = static_cast<unsigned char>(text[i]);
            std::uint32_t high = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0;
            v.values.push_back(low | high << 8);
        }
    } else {
        v.values.push_back(number(at));
    }
    return v;
}

std::vector<InitialValue> parse_initial_values(const JsonAt& devices) {
    devices.expect_object();
    std::vector<InitialValue> list;
    for (const auto& [address, _] : devices.json().items()) list.push_back(parse_initial_value(address, devices[address]));
    return list;
}

protocol::StationNumbers checked_station_numbers(unsigned network, unsigned station, const std::string& where) {
    // The rows' ranges: network No. 01-EF (1-239), station No. 01-78 (1-120).
    const auto& net = setting(Section::Port, "network");
    const auto& sta = setting(Section::Port, "station");
    auto range = [](const Setting& row) { return std::to_string(unsigned(row.min)) + "-" + std::to_string(unsigned(row.max)); };
    if (network < net.min || network > net.max)
        throw ConfigError(where + ": network No. " + std::to_string(network) + " is out of range; set \"network\" (--network-no) to " +
                          range(net) + " together with the station No.");
    if (station < sta.min || station > sta.max)
        throw ConfigError(where + ": station No. " + std::to_string(station) + " is out of range; set \"station\" (--station-no) to " +
                          range(sta) + " together with the network No.");
    return {static_cast<std::uint8_t>(network), static_cast<std::uint8_t>(station)};
}

bool valid_log_level(const std::string& level) {
    return is_choice(setting(Section::Station, "log_level"), level);
}

DataCode parse_data_code(const std::string& text, const std::string& where) {
    if (text == "binary") return DataCode::Binary;
    if (text == "ascii") return DataCode::Ascii;
    if (text == "auto") return DataCode::Auto;
    throw ConfigError(where + ": unknown data code '" + text + "'; use binary, ascii or auto");
}

ServerConfig parse_server_config(const JsonAt& root, const std::filesystem::path& directory) {
    // The extras: "kind" and the faces' sections (parse_frontends_config).
    std::vector<std::string_view> extra{"kind"};
    for (const auto* face : frontends::faces()) extra.push_back(face->name());
    check_keys(root, Section::Station, extra);
    ServerConfig c;
    if (root.has("name")) c.name = checked_station_name(root["name"]);
    if (root.has("profile")) c.profile = root["profile"].string();
    // The file's addresses follow its CPU's numbering (FX5: X/Y in octal).
    std::optional<devicemodel::NumberingScope> numbering;
    if (root.has("devices") || root.has("labels") || root.has("cpu"))
        numbering.emplace(load_profile(c.profile).cpu.numbering);
    if (root.has("bind")) c.bind = root["bind"].string();
    parse_ports(root, c);
    if (root.has("max_request_bytes")) c.max_request_bytes = whole_setting(root, Section::Station, "max_request_bytes");
    parse_upstream_keys(root, c);
    if (root.has("device_sizes")) c.device_sizes = parse_device_sizes(root["device_sizes"]);
    if (root.has("devices")) c.devices = parse_initial_values(root["devices"]);
    if (root.has("log_level")) c.log_level = choice_setting(root, Section::Station, "log_level");
    if (root.has("http")) c.http = http_config(root["http"]);
    if (root.has("timing")) c.timing = parse_timing_config(root["timing"]);
    if (root.has("scenarios")) {
        auto list = root["scenarios"];
        list.expect_array();
        for (std::size_t i = 0; i < list.json().size(); ++i) {
            std::filesystem::path file(list[i].string());
            c.scenarios.push_back((file.is_relative() ? directory / file : file).string());
        }
    }
    parse_hardware(root, c);
    parse_drives(root, c);
    parse_cpu_runtime(root, c);
    for (auto* file : {&c.cpu.program.file, &c.cpu.program.comments})   // relative to the configuration file
        if (!file->empty() && std::filesystem::path(*file).is_relative()) *file = (directory / *file).string();
    parse_labels(root, directory, c.labels);
    return c;
}

std::optional<UpstreamAddress> split_upstream(std::string_view text) {
    const auto colon = text.rfind(':');
    UpstreamAddress address;
    if (colon != std::string_view::npos) {
        address.host = std::string(text.substr(0, colon));
        if (address.host.size() > 2 && address.host.front() == '[' && address.host.back() == ']')
            address.host = address.host.substr(1, address.host.size() - 2);
        const auto digits = text.substr(colon + 1);
        unsigned long port = 0;
        const bool numeric = !digits.empty() && digits.size() <= 5 && digits.find_first_not_of("0123456789") == std::string_view::npos;
        if (numeric) port = std::stoul(std::string(digits));
        // No scheme ("udp://"): the upstream is reached over TCP only (docs/twin.md).
        if (numeric && port >= 1 && port <= 65535 && !address.host.empty() && address.host.find('/') == std::string::npos) {
            address.port = static_cast<std::uint16_t>(port);
            return address;
        }
    }
    return std::nullopt;
}

UpstreamAddress parse_upstream(std::string_view text, std::string_view where) {
    if (auto address = split_upstream(text)) return *address;
    throw ConfigError(std::string(where) + " " + std::string(text) + ": not HOST:PORT; " + kUpstreamFix);
}

std::string UpstreamAddress::text() const {
    return (host.find(':') != std::string::npos ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

ServerConfig parse_server_config(const std::string& json_text, const std::string& source) {
    auto json = parse_json(json_text, source);
    return parse_server_config(JsonAt(json, source), std::filesystem::path(source).parent_path());
}

std::string read_config_file(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw ConfigError(file.string() + ": cannot open the configuration file; check the path given to --config");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

ServerConfig load_server_config(const std::filesystem::path& file) {
    return parse_server_config(read_config_file(file), file.string());
}

std::string checked_station_name(const JsonAt& at) {
    auto name = at.string();
    bool ok = !name.empty() && name.size() <= 64;
    for (char ch : name)
        ok = ok && (std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_' || ch == '.');
    if (!ok)
        at.fail("station name '" + name + "' is not usable in URLs and metrics labels",
                "use 1-64 letters, digits, '-', '_' or '.', e.g. \"press-7\"");
    return name;
}

Profile resolve_profile(const ServerConfig& config) {
    auto profile = load_profile(config.profile);
    for (const auto& [area, points] : config.device_sizes) profile.cpu.sizes[static_cast<std::size_t>(area)] = points;
    return profile;
}

void apply_initial_values(devicemodel::Cpu& cpu, const ServerConfig& config) {
    apply_initial_values(cpu, config.devices);
}

void apply_initial_values(devicemodel::Cpu& cpu, const std::vector<InitialValue>& values) {
    for (const auto& v : values) {
        const auto& spec = *v.address.spec;
        if (!cpu.memory().contains(spec.area, v.address.number, v.values.size()))
            throw ConfigError("devices: " + devicemodel::format_address(v.address) + " with " +
                              std::to_string(v.values.size()) + " value(s) runs past the " +
                              std::string(devicemodel::area_name(spec.area)) + " size of " +
                              std::to_string(cpu.memory().size(spec.area)) + " in profile " + cpu.profile().name +
                              "; shorten the list or raise device_sizes");
        for (std::size_t i = 0; i < v.values.size(); ++i)
            cpu.memory().set_value(spec, v.address.number + static_cast<std::uint32_t>(i), v.values[i]);
    }
}

}  // namespace slmp::config
