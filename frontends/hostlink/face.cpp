// The host link's face: its settings (docs/configuration.md, docs/hostlink.md)
// and its unit, the HostLink of one station.
#include "frontends/hostlink/face.hpp"

#include <cctype>

#include <boost/program_options.hpp>

#include "config/json_path.hpp"
#include "frontends/hostlink/addresses.hpp"
#include "frontends/hostlink/command_table.hpp"
#include "frontends/hostlink/host_link.hpp"

namespace slmp::hostlink {

namespace {

namespace po = boost::program_options;
using config::ConfigError;
using config::JsonAt;

std::string response_code(const JsonAt& at) {
    auto code = at.string();
    bool hex = code.size() == 2;
    for (char ch : code) hex = hex && ((ch >= '0' && ch <= '9') || (ch >= 'A' && ch <= 'F'));
    if (!hex) at.fail("'" + code + "' is not a response code", "write two uppercase hex digits, e.g. \"01\" or \"15\"");
    return code;
}

void parse_areas(const JsonAt& areas, MemoryMap& map) {
    areas.expect_object();
    for (const auto& [key, _] : areas.json().items()) {
        auto at = areas[key];
        auto area = area_by_key(key);
        if (!area) at.fail("unknown host-link area '" + key + "'", "use CIO, HR, LR, AR, DM, VR, TC, TC_SET or TC_UP");
        at.only_keys({"device", "size"});
        auto binding = map.binding(*area);
        if (at.has("device")) {
            std::string error;
            auto address = devicemodel::parse_address(at["device"].string(), &error);
            if (!address) at["device"].fail(error, "write the first device of the area, e.g. D0, M4096, TN0");
            binding.base = *address;
        }
        if (at.has("size")) {
            binding.size = static_cast<std::uint32_t>(at["size"].unsigned_int(10000));
            if (binding.size == 0) at["size"].fail("must be at least 1", "give the number of channels, words or T/C numbers");
        }
        map.bind(*area, binding);
    }
}

Options& options_of(const frontends::Settings& s) { return *std::static_pointer_cast<Options>(s.options); }

struct Session final : frontends::SessionState {
    LinkState state;   // its QQMR list
};

class Unit final : public frontends::Unit {
public:
    Unit(devicemodel::Cpu& cpu, const Options& options) : link_(cpu, options) {}

    const frontends::Face& face() const override { return hostlink::face(); }

    std::unique_ptr<frontends::SessionState> new_session(const protocol::Peer&) override { return std::make_unique<Session>(); }

    frontends::Exchange stream(std::span<const std::uint8_t> pending, frontends::SessionState* session,
                               const frontends::Gate& gate) override {
        LinkState none;
        auto& state = session ? static_cast<Session*>(session)->state : none;
        auto result = link_.handle(pending, state, gate);
        if (result.kind == Cut::Kind::NeedMore) return frontends::Exchange::more();
        frontends::Exchange e;
        const auto* row = result.command.empty() ? nullptr : find_command(result.command);
        e.consumed = result.consumed;
        e.response = std::move(result.response);
        e.command = std::move(result.command);
        e.known = row != nullptr;
        e.name = row ? row->function : std::string_view();
        e.code = std::move(result.code);
        return e;
    }

    std::optional<frontends::DeviceName> resolve_name(std::string_view text, std::string* error) const override {
        auto cell = hostlink::resolve_name(link_.options().map, text, error);
        if (!cell) return std::nullopt;
        frontends::DeviceName named{cell->device};
        if (cell->long_word) named.view = frontends::DeviceName::View::Dwords;
        else if (cell->device.spec->unit == devicemodel::Unit::Bit) named.view = frontends::DeviceName::View::Words;   // 16 bits a channel
        return named;
    }

    void save(frontends::Parts& parts) const override {
        parts["hostlink environment"] = link_.environment();
        parts["hostlink object"] = link_.object();
    }
    std::vector<std::pair<std::string, std::size_t>> part_sizes() const override {
        return {{"hostlink environment", link_.environment().size()}, {"hostlink object", link_.object().size()}};
    }
    void restore(const frontends::Parts& parts) override {
        if (auto it = parts.find("hostlink environment"); it != parts.end()) link_.environment() = it->second;
        if (auto it = parts.find("hostlink object"); it != parts.end()) link_.object() = it->second;
    }

private:
    HostLink link_;
};

class Face final : public frontends::Face {
public:
    std::string_view name() const override { return "hostlink"; }
    std::string_view title() const override { return "Ladder Motion host link"; }
    std::string_view log_name() const override { return "host link"; }
    std::string_view port_name() const override { return "host-link"; }
    std::string port_fix(config::Transport) const override { return "\"hostlink\": {\"tcp_port\": ...} or --hostlink-port"; }

    std::string_view station_kind() const override { return "ladder-motion"; }
    std::string_view missing_noun() const override { return "host-link port"; }
    std::string ports_fix() const override {
        return "remove \"ports\" (the host-link port is \"hostlink\": {\"tcp_port\": ...}), or use "
               "\"kind\": \"melsec\" with a \"hostlink\" section to serve both on one memory";
    }
    std::string command_line_refusal() const override {
        return "a ladder-motion station serves no SLMP ports; leave out --tcp-port/--udp-port (its port is "
               "--hostlink-port or \"hostlink\": {\"tcp_port\": ...}), or use \"kind\": \"melsec\" to serve both";
    }

    frontends::Settings defaults() const override {
        frontends::Settings s;
        s.face = this;
        s.tcp = config::PortConfig{config::Transport::Tcp, 9600, config::DataCode::Ascii, 8};   // TCP only; 8 clients (inferred)
        s.options = std::make_shared<Options>();   // memory map, codes, image sizes
        return s;
    }

    void parse(const JsonAt& at, frontends::Settings& s) const override {
        at.only_keys({"tcp_port", "max_connections", "idle_timeout_ms", "partial_frame_timeout_ms", "refused_code",
                      "fcs_error_code", "environment_bytes", "object_bytes", "version", "areas"});
        auto& port = *s.tcp;
        auto& options = options_of(s);
        if (at.has("tcp_port")) port.port = static_cast<std::uint16_t>(at["tcp_port"].unsigned_int(65535));
        if (at.has("max_connections")) {
            port.max_connections = static_cast<unsigned>(at["max_connections"].unsigned_int(4096));
            if (*port.max_connections == 0) at["max_connections"].fail("must be at least 1", "use e.g. 8");
        }
        if (at.has("idle_timeout_ms")) port.idle_timeout_ms = static_cast<unsigned>(at["idle_timeout_ms"].unsigned_int(86400000));
        if (at.has("partial_frame_timeout_ms"))
            port.partial_frame_timeout_ms = static_cast<unsigned>(at["partial_frame_timeout_ms"].unsigned_int(86400000));
        if (at.has("refused_code")) options.refused_code = response_code(at["refused_code"]);
        if (at.has("fcs_error_code")) options.fcs_error_code = response_code(at["fcs_error_code"]);
        if (at.has("environment_bytes")) options.environment_bytes = at["environment_bytes"].unsigned_int(65536);
        if (at.has("object_bytes")) options.object_bytes = at["object_bytes"].unsigned_int(65536);
        if (at.has("version")) options.version = at["version"].hex_code();
        if (at.has("areas")) parse_areas(at["areas"], options.map);
    }

    void add_options(po::options_description& options) const override {
        options.add_options()
            ("hostlink-port", po::value<unsigned>(), "serve the Ladder Motion host link on this TCP port too; 0 = any free port (docs/hostlink.md)")
            ("serial", po::value<std::string>(), "also serve the host link on a pseudo-terminal and link PATH to it (RS-232C-style tools; needs a host link)");
    }
    std::vector<std::string_view> one_station_options() const override { return {"hostlink-port", "serial"}; }

    void apply_options(const po::variables_map& vm, frontends::Settings* s,
                       const std::function<frontends::Settings&()>& enable) const override {
        if (vm.count("hostlink-port")) {
            auto port = vm["hostlink-port"].as<unsigned>();
            if (port > 65535) throw ConfigError("--hostlink-port " + std::to_string(port) + ": not a port number; use 0-65535 (0 = any free port)");
            if (!s) s = &enable();
            s->tcp->port = static_cast<std::uint16_t>(port);
        }
        if (vm.count("serial")) {
            if (!s)
                throw ConfigError("--serial serves the Ladder Motion host link; give \"kind\": \"ladder-motion\", a \"hostlink\" "
                                  "section or --hostlink-port too");
            s->serial_path = vm["serial"].as<std::string>();
        }
    }

    // A host-link command is two letters, case counts ("Rr" is not "RR").
    bool scenario_command(std::string& text) const override {
        bool ok = text.size() == 2;
        for (auto c : text) ok = ok && std::isgraph(static_cast<unsigned char>(c));
        return ok;
    }
    std::string_view command_fix() const override { return "write the two-letter command, e.g. \"RD\""; }
    std::string_view code_fix() const override { return "write the response code as two hex digits, e.g. \"15\""; }

    std::string check(devicemodel::Cpu& cpu, const frontends::Settings& s) const override {
        return options_of(s).map.check(cpu.memory());
    }
    std::unique_ptr<frontends::Unit> make_unit(devicemodel::Cpu& cpu, const frontends::Settings& s) const override {
        return std::make_unique<Unit>(cpu, options_of(s));
    }
};

}  // namespace

const frontends::Face& face() {
    static const Face instance;
    return instance;
}

}  // namespace slmp::hostlink
