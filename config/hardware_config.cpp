// What is mounted beside CPU No.1: intelligent function modules (buffer
// memory), network modules (link devices), and CPU No.2–4 of a multi-CPU
// system. Keys: docs/configuration.md "Modules, networks and CPUs".
#include <algorithm>

#include "config/config_parts.hpp"
#include "config/settings.hpp"

namespace slmp::config {

using devicemodel::Area;

namespace {

// A 4-hex-digit start I/O number such as "0030"; the module is U3.
std::uint16_t io_number(const JsonAt& at) {
    auto text = at.string();
    bool hex = !text.empty() && text.size() <= 4 && text.find_first_not_of("0123456789ABCDEFabcdef") == std::string::npos;
    if (!hex) at.fail("'" + text + "' is not a start I/O number", "write 4 hex digits, e.g. \"0030\"");
    auto value = std::stoul(text, nullptr, 16);
    if (value % 16 != 0) at.fail("start I/O " + text + " is not a multiple of 10H", "use e.g. \"0030\"");
    return static_cast<std::uint16_t>(value / 16);
}

std::uint32_t hex_number(const JsonAt& at) {
    auto text = at.string();
    bool hex = !text.empty() && text.size() <= 8 && text.find_first_not_of("0123456789ABCDEFabcdef") == std::string::npos;
    if (!hex) at.fail("'" + text + "' is not a hexadecimal address", "write hex digits, e.g. \"1008\"");
    return static_cast<std::uint32_t>(std::stoul(text, nullptr, 16));
}

ModuleConfig module(const JsonAt& at) {
    check_keys(at, Section::Module);
    ModuleConfig m;
    m.io_number = io_number(at["start_io"]);
    if (at.has("model")) m.model = at["model"].string();
    m.buffer_words = static_cast<std::uint32_t>(bounded_setting(at, Section::Module, "buffer_words"));
    if (at.has("head_address")) m.head_address = hex_number(at["head_address"]);
    return m;
}

// One send range, "W100-W1FF" or "B0-BFF": link devices B or W of the
// network, B in whole words (16 points from a multiple of 16).
NetworkConfig::Range send_range(const JsonAt& at, const devicemodel::DeviceSizes& sizes) {
    const auto text = at.string();
    const auto dash = text.find('-');
    std::string error;
    auto first = devicemodel::parse_address(text.substr(0, dash), &error);
    auto last = dash == std::string::npos ? first : devicemodel::parse_address(text.substr(dash + 1), &error);
    if (!first || !last || first->spec != last->spec || last->number < first->number)
        at.fail("'" + text + "' is not a range of link devices", "write it like \"W100-W1FF\" or \"B0-BFF\"");
    const auto area = first->spec->area;
    if (area != Area::B && area != Area::W) at.fail("a station sends only LB and LW", "use B or W, e.g. \"W100-W1FF\"");
    NetworkConfig::Range r{first->spec, first->number, last->number - first->number + 1};
    if (area == Area::B && (r.first % 16 != 0 || r.count % 16 != 0))
        at.fail("'" + text + "' is not whole words of B", "start at a multiple of 16 and send 16 points a word, e.g. \"B100-B1FF\"");
    if (std::uint64_t{r.first} + r.count > sizes[static_cast<std::size_t>(area)])
        at.fail("'" + text + "' runs past the network's " + std::string(devicemodel::area_name(area)) + " size",
                "send inside its device_sizes");
    return r;
}

// Link device sizes of a CC-Link IE Control network module unless given.
NetworkConfig network(const JsonAt& at) {
    check_keys(at, Section::Network);
    NetworkConfig n;
    n.number = static_cast<std::uint16_t>(bounded_setting(at, Section::Network, "number"));
    if (at.has("station")) n.station = static_cast<std::uint16_t>(bounded_setting(at, Section::Network, "station"));
    if (at.has("master")) {
        n.master = at["master"].boolean();
        if (n.master && n.station == 0) at["master"].fail("a master station needs its station No.", "add \"station\": 1-65534");
    }
    auto set = [&](Area a, std::uint32_t points) { n.sizes[static_cast<std::size_t>(a)] = points; };
    set(Area::X, 16384);
    set(Area::Y, 16384);
    set(Area::B, 32768);
    set(Area::SB, 512);
    set(Area::W, 131072);
    set(Area::SW, 512);
    if (at.has("device_sizes"))
        for (auto [area, points] : parse_device_sizes(at["device_sizes"])) {
            if (area != Area::X && area != Area::Y && area != Area::B && area != Area::SB && area != Area::W &&
                area != Area::SW)
                at["device_sizes"].fail("a network module has only X, Y, B, SB, W and SW", "remove the other devices");
            set(area, points);
        }
    if (at.has("send")) {
        if (n.station == 0) at["send"].fail("only a station with a station No. sends", "add \"station\": 1-65534");
        auto list = at["send"];
        list.expect_array();
        for (std::size_t i = 0; i < list.json().size(); ++i) n.send.push_back(send_range(list[i], n.sizes));
    } else if (n.station != 0) {   // chosen default: 256 LB and 256 LW a station, in station order (docs/plants.md)
        const std::uint32_t first = (n.station - 1u) * 256u;   // none past the link devices (station 129 on)
        for (const char* symbol : {"B", "W"}) {
            const auto* spec = devicemodel::find_by_symbol(symbol);
            if (first + 256u <= n.sizes[static_cast<std::size_t>(spec->area)]) n.send.push_back({spec, first, 256});
        }
    }
    return n;
}

CpuConfig cpu(const JsonAt& at) {
    check_keys(at, Section::MultiCpu);
    CpuConfig c;
    c.number = static_cast<int>(bounded_setting(at, Section::MultiCpu, "number"));
    c.profile = at["profile"].string();
    if (at.has("device_sizes")) c.device_sizes = parse_device_sizes(at["device_sizes"]);
    if (at.has("devices")) c.devices = parse_initial_values(at["devices"]);
    return c;
}

// One tracked range of a redundant pair, "D0-D999", "M0-M1023", "TN0-TN63" or a
// whole device, "W" (docs/plants.md, "Tracking"): bit devices in whole words.
RedundantConfig::Range tracking_range(const JsonAt& at) {
    const auto text = at.string();
    const std::string example = "write it like \"D0-D999\", \"M0-M1023\" or \"W\" (all of W)";
    std::string error;
    const bool whole = text.find_first_of("0123456789") == std::string::npos;
    if (whole) {
        const auto* spec = devicemodel::find_by_symbol(text);
        if (!spec) at.fail("'" + text + "' is no device", example);
        RedundantConfig::Range r{spec, 0, ~std::uint32_t{0}};
        if (spec->area == Area::SM || spec->area == Area::SD)
            at.fail("SM and SD are each CPU's own; a pair does not track them", "remove '" + text + "'");
        return r;
    }
    const auto dash = text.find('-');
    auto first = devicemodel::parse_address(text.substr(0, dash), &error);
    auto last = dash == std::string::npos ? first : devicemodel::parse_address(text.substr(dash + 1), &error);
    if (!first || !last || first->spec != last->spec || last->number < first->number)
        at.fail("'" + text + "' is not a range of devices", example);
    const auto area = first->spec->area;
    if (area == Area::SM || area == Area::SD)
        at.fail("SM and SD are each CPU's own; a pair does not track them", "remove '" + text + "'");
    RedundantConfig::Range r{first->spec, first->number, last->number - first->number + 1};
    if (first->spec->unit == devicemodel::Unit::Bit && (r.first % 16 != 0 || r.count % 16 != 0))
        at.fail("'" + text + "' is not whole words of " + std::string(first->spec->symbol),
                "start at a multiple of 16 and track 16 points a word, e.g. \"M0-M1023\"");
    return r;
}

// "redundant": {"pair": "press-b", "system": "A", "switchover_ms": 100} (docs/plants.md, "Redundant pairs").
RedundantConfig redundant(const JsonAt& at) {
    check_keys(at, Section::Redundant);
    RedundantConfig r;
    r.pair = at["pair"].string();
    if (r.pair.empty()) at["pair"].fail("the pair needs the other station's name", "write \"pair\": \"press-b\"");
    if (at.has("system")) r.system = choice_setting(at, Section::Redundant, "system")[0];
    if (at.has("switchover_ms")) r.switchover_ms = number_setting(at, Section::Redundant, "switchover_ms");
    if (at.has("tracking")) {
        auto list = at["tracking"];
        list.expect_array();
        r.tracking.emplace();
        for (std::size_t i = 0; i < list.json().size(); ++i) r.tracking->push_back(tracking_range(list[i]));
    }
    return r;
}

// "multidrop": {"via": "line-1", "start_io": "0040", "number": 3} (docs/plants.md, "Multidrop stations").
MultidropConfig multidrop(const JsonAt& at) {
    check_keys(at, Section::Multidrop);
    MultidropConfig m;
    m.via = at["via"].string();
    if (m.via.empty()) at["via"].fail("a multidrop station needs the station whose serial module it hangs on", "write \"via\": \"line-1\"");
    m.module_io = io_number(at["start_io"]);
    if (m.module_io > 0x01FF) at["start_io"].fail("a serial module's start I/O is at most 1FF0", "use \"0000\"-\"1FF0\"");
    m.number = static_cast<std::uint8_t>(bounded_setting(at, Section::Multidrop, "number"));
    return m;
}

// {"network": 3, "via_network": 1, "via_station": 2} (docs/plants.md, "Routing parameters").
RouteConfig route(const JsonAt& at) {
    check_keys(at, Section::Route);
    RouteConfig r;
    r.network = static_cast<std::uint16_t>(bounded_setting(at, Section::Route, "network"));
    r.via_network = static_cast<std::uint16_t>(bounded_setting(at, Section::Route, "via_network"));
    r.via_station = static_cast<std::uint16_t>(bounded_setting(at, Section::Route, "via_station"));
    return r;
}

// A routing parameter leaves through one of the station's own network modules
// for a network it is not on, once per network (GX Works' table has one row a
// destination). Whether the relay station exists is the plant's check.
void check_routes(const JsonAt& root, const ServerConfig& config) {
    auto module_on = [&](std::uint16_t number) {
        return std::any_of(config.networks.begin(), config.networks.end(),
                           [&](const NetworkConfig& n) { return n.number == number && n.station != 0; });
    };
    for (std::size_t i = 0; i < config.routes.size(); ++i) {
        const auto& r = config.routes[i];
        auto at = root["routes"][i];
        if (module_on(r.network))
            at["network"].fail("this station is on network " + std::to_string(r.network) + " itself",
                               "a routing parameter is for another network; remove it");
        if (!module_on(r.via_network))
            at["via_network"].fail("this station has no module with a station No. on network " +
                                       std::to_string(r.via_network),
                                   "name one of its \"networks\" entries with a \"station\"");
        for (std::size_t j = 0; j < i; ++j)
            if (config.routes[j].network == r.network)
                at["network"].fail("network " + std::to_string(r.network) + " has a routing parameter already",
                                   "give one route a destination network");
    }
}

NodeSearchConfig node_search(const JsonAt& at) {
    check_keys(at, Section::NodeSearch);
    NodeSearchConfig n;
    n.port = static_cast<std::uint16_t>(bounded_setting(at, Section::NodeSearch, "port"));
    if (at.has("max_delay_ms"))
        n.max_delay_ms = static_cast<std::uint32_t>(bounded_setting(at, Section::NodeSearch, "max_delay_ms"));
    return n;
}

template <typename T, typename Parse>
std::vector<T> list(const JsonAt& root, std::string_view key, Parse parse) {
    std::vector<T> items;
    if (!root.has(key)) return items;
    auto array = root[key];
    array.expect_array();
    for (std::size_t i = 0; i < array.json().size(); ++i) items.push_back(parse(array[i]));
    return items;
}

}  // namespace

void parse_hardware(const JsonAt& root, ServerConfig& config) {
    config.modules = list<ModuleConfig>(root, "modules", module);
    config.networks = list<NetworkConfig>(root, "networks", network);
    for (std::size_t i = 0; i < config.networks.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (config.networks[i].number == config.networks[j].number)
                root["networks"][i]["number"].fail("network " + std::to_string(config.networks[i].number) + " is configured twice",
                                                   "a station has one module on each network");
    config.routes = list<RouteConfig>(root, "routes", route);
    check_routes(root, config);
    config.cpus = list<CpuConfig>(root, "cpus", cpu);
    for (std::size_t i = 0; i < config.cpus.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (config.cpus[i].number == config.cpus[j].number)
                root["cpus"][i]["number"].fail("CPU No." + std::to_string(config.cpus[i].number) + " is configured twice",
                                               "give each CPU its own number");
    if (root.has("node_search")) config.node_search = node_search(root["node_search"]);
    if (root.has("redundant")) config.redundant = redundant(root["redundant"]);
    if (root.has("multidrop")) config.multidrop = multidrop(root["multidrop"]);
    if (config.redundant && config.multidrop)
        root["multidrop"].fail("a CPU of a redundant pair is reached by its network modules, not as a multidrop station",
                               "remove \"multidrop\" or \"redundant\"");
}

void attach_hardware(devicemodel::Cpu& cpu, const ServerConfig& config) {
    for (const auto& m : config.modules) cpu.add_module(m.io_number, m.model, m.buffer_words, m.head_address);
    for (const auto& n : config.networks) cpu.add_network(n.number, n.sizes);
}

Profile resolve_profile(const CpuConfig& cpu) {
    auto profile = load_profile(cpu.profile);
    for (const auto& [area, points] : cpu.device_sizes) profile.cpu.sizes[static_cast<std::size_t>(area)] = points;
    return profile;
}

}  // namespace slmp::config
