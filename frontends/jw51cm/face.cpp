// The JW-51CM computer link's face: its settings (docs/configuration.md,
// docs/jw51cm.md) and its unit, the ComputerLink of one station.
#include "frontends/jw51cm/face.hpp"

#include <algorithm>
#include <array>
#include <cctype>

#include "config/json_path.hpp"
#include "devicemodel/byte_reader.hpp"
#include "devicemodel/hex.hpp"
#include "frontends/jw51cm/addresses.hpp"
#include "frontends/jw51cm/buffers.hpp"
#include "frontends/jw51cm/command_table.hpp"
#include "frontends/jw51cm/computer_link.hpp"
#include "frontends/jw51cm/send_receive.hpp"
#include "frontends/jw51cm/unit_reports.hpp"

namespace slmp::jw51cm {

namespace {

using config::DataCode;
using config::JsonAt;
using config::PortConfig;
using config::Transport;

const PortConfig kTcp{Transport::Tcp, 3000, DataCode::Binary, 8};   // TCP_Passive
const PortConfig kUdp{Transport::Udp, 3001, DataCode::Binary};

Options& options_of(const frontends::Settings& s) { return *std::static_pointer_cast<Options>(s.options); }

// An optional port: a number, or null for none.
std::optional<PortConfig> optional_port(const JsonAt& at, PortConfig port) {
    if (at.json().is_null()) return std::nullopt;
    port.port = static_cast<std::uint16_t>(at.unsigned_int(65535));
    return port;
}

constexpr std::size_t kClockBytes = 17;

// Hex bytes, spaces allowed between them: "00 08 00 01 0C 00 04 80".
std::optional<std::vector<std::uint8_t>> hex_bytes(std::string_view text) {
    std::vector<std::uint8_t> out;
    std::string digits;
    for (char c : text) {
        if (c == ' ') continue;
        if (!std::isxdigit(static_cast<unsigned char>(c))) return std::nullopt;
        digits += c;
    }
    if (digits.size() % 2 != 0) return std::nullopt;
    for (std::size_t i = 0; i < digits.size(); i += 2) out.push_back(static_cast<std::uint8_t>(std::stoul(digits.substr(i, 2), nullptr, 16)));
    return out;
}

std::string hex_text(std::span<const std::uint8_t> bytes) {
    std::string out;
    for (auto b : bytes) out += devicemodel::hex2(b);
    return out;
}

// The parts of the network parameter image (§15) that act in the simulated
// unit, so the only ones a configuration may give; the rest (the unit's IP
// address, its connections, routing, TCP timers) is the simulator's own
// (tcp_port, udp_port, the bind address).
struct ParameterBlock {
    std::uint32_t first, end;   // octal addresses, end exclusive
    std::string_view what;
};
constexpr std::array kParameterBlocks{
    ParameterBlock{kDesignatedParameters, kRingParameters + 8 * kRingBuffers, "1000-1377 (designated buffers), 1400-1577 (ring buffers)"},
    ParameterBlock{kConnectionParameters, kConnectionParameters + 4 * kConnections, "0100-0137 (SEND/RECEIVE's connection)"},
    ParameterBlock{kMappingParameter, kStationTables + 8 * kStationEntries, "0400-0777 (station mapping and tables)"},
    ParameterBlock{kCompletionParameters, kCompletionParameters + 8, "3660-3667 (command completion information)"},
    ParameterBlock{kStatusFlagParameters, kStatusFlagParameters + 4, "3764-3767 (connection status flags)"},
    ParameterBlock{kControlBlockParameters, kControlBlockParameters + 4, "3770-3773 (SEND/RECEIVE control block)"},
};

std::string parameter_blocks() {
    std::string text;
    for (const auto& block : kParameterBlocks) text += (text.empty() ? "" : ", ") + std::string(block.what);
    return text;
}

// "parameters": {"1410": "00 08 00 01 0C 00 04 80"} — the network parameter
// image (§15) by octal address, as the JW-14PG and JW-52SP write it; only the
// blocks above may be given, and they are checked as the unit checks them when
// they are written.
void parse_parameters(const JsonAt& at, Options& options, bool udp_port) {
    at.expect_object();
    for (const auto& [key, _] : at.json().items()) {
        auto value = at[key];
        const auto address = octal(key);
        const auto* block = address ? std::find_if(kParameterBlocks.begin(), kParameterBlocks.end(),
                                                   [&](const ParameterBlock& b) { return *address >= b.first && *address < b.end; })
                                    : kParameterBlocks.end();
        if (block == kParameterBlocks.end())
            value.fail("'" + key + "' is not a parameter address the simulated unit uses",
                       "write it in octal, in " + parameter_blocks() + ", e.g. \"1410\"");
        auto bytes = value.json().is_string() ? hex_bytes(value.string()) : std::nullopt;
        if (!bytes || bytes->empty()) value.fail("not hex bytes", "write the bytes from this address on, e.g. \"00 08 00 01 0C 00 04 80\"");
        if (*address + bytes->size() > block->end)
            value.fail("runs past parameter " + octal(block->end - 1, 4), "the block " + std::string(block->what) + " ends there");
        std::copy(bytes->begin(), bytes->end(), options.parameters.begin() + static_cast<std::ptrdiff_t>(*address));
    }
    MemoryMap map(options.file_bytes, options.timers);
    auto problem = check_parameters(options.parameters, map);
    if (problem.empty()) problem = check_report_parameters(options.parameters, map);
    if (problem.empty()) problem = check_send_receive_parameters(options.parameters, map, udp_port);
    if (!problem.empty()) at.fail(problem, "the unit refuses such parameters when they are written (its ERROR lamp); docs/jw51cm.md");
}

// A TCP client's connection: its number among the unit's 8 (§12) while it
// lasts, and who it is, for the completion record (§11).
struct Session final : frontends::SessionState {
    Session(ComputerLink& link, std::weak_ptr<void> alive, const protocol::Peer& peer)
        : link(link), alive(std::move(alive)), caller{peer.ipv4, peer.port, link.open_connection()} {}
    ~Session() override {
        if (alive.lock()) link.close_connection(caller.connection);   // not once the unit is gone (shutdown)
    }
    ComputerLink& link;
    std::weak_ptr<void> alive;
    Caller caller;
};

class Unit final : public frontends::Unit {
public:
    Unit(devicemodel::Cpu& cpu, const Options& options, bool udp) : link_(cpu, options), send_receive_(link_) {
        // SEND/RECEIVE's connection: a UDP one is on from power-on, a TCP_Active one while it is open.
        const auto& channel = send_receive_.channel();
        const auto bit = channel.on ? static_cast<std::uint8_t>(1u << channel.connection) : std::uint8_t{0};
        link_.assign_connections(udp, channel.tcp ? 0 : bit, channel.tcp ? bit : 0);
    }

    const frontends::Face& face() const override { return jw51cm::face(); }

    std::unique_ptr<frontends::SessionState> new_session(const protocol::Peer& peer) override {
        return std::make_unique<Session>(link_, alive_, peer);
    }
    void power_on() override {
        send_receive_.power_on();
        link_.power_on();
    }
    void attach(frontends::StationServices& services) override { send_receive_.attach(services); }
    void end_of_scan() override { send_receive_.end_of_scan(); }

    frontends::Exchange stream(std::span<const std::uint8_t> pending, frontends::SessionState* session,
                               const frontends::Gate& gate) override {
        auto* connection = dynamic_cast<Session*>(session);
        auto result = link_.handle_stream(pending, gate, connection ? connection->caller : Caller{});
        if (result.kind == ComputerLink::Result::Kind::NeedMore) return frontends::Exchange::more();
        return report(pending.first(result.consumed), result);
    }
    frontends::Exchange datagram(std::span<const std::uint8_t> datagram, const frontends::Gate& gate,
                                 const protocol::Peer& from) override {
        auto result = link_.handle_datagram(datagram, gate, Caller{from.ipv4, from.port, link_.udp_connection()});
        return report(datagram, result);
    }

    std::optional<frontends::DeviceName> resolve_name(std::string_view text, std::string* error) const override {
        auto cell = jw51cm::resolve_name(link_.map(), text, error);
        if (!cell) return std::nullopt;
        return frontends::DeviceName{*cell};
    }

    void save(frontends::Parts& parts) const override {
        parts["jw51cm write mode"] = {link_.write_mode_};
        parts["jw51cm system memory"] = link_.system_memory;
        parts["jw51cm program"] = link_.program;
        parts["jw51cm clock"] = clock();
    }
    std::vector<std::pair<std::string, std::size_t>> part_sizes() const override {
        return {{"jw51cm write mode", 1},
                {"jw51cm system memory", link_.system_memory.size()},
                {"jw51cm program", link_.program.size()},
                {"jw51cm clock", kClockBytes}};
    }
    std::string check(const frontends::Parts& parts) const override {
        auto mode = parts.find("jw51cm write mode");
        if (mode != parts.end() && mode->second[0] > 2) return "the snapshot's 'jw51cm write mode' is not 0, 1 or 2";
        return {};
    }
    void restore(const frontends::Parts& parts) override {
        link_.ring_confirms = {};   // the unit's RAM; the pointers in memory are the snapshot's now
        if (auto it = parts.find("jw51cm write mode"); it != parts.end()) link_.write_mode_ = it->second[0];
        if (auto it = parts.find("jw51cm system memory"); it != parts.end()) link_.system_memory = it->second;
        if (auto it = parts.find("jw51cm program"); it != parts.end()) link_.program = it->second;
        if (auto it = parts.find("jw51cm clock"); it != parts.end()) {
            devicemodel::ByteReader clock(it->second);   // kClockBytes, checked by check()
            link_.clock_offset = std::chrono::seconds(static_cast<std::int64_t>(*clock.u64()));
            const auto stopped = *clock.u8();
            const auto at = static_cast<std::int64_t>(*clock.u64());
            if (stopped)
                link_.clock_stopped = std::chrono::system_clock::time_point(std::chrono::seconds(at));
            else
                link_.clock_stopped.reset();
        }
    }

    ComputerLink& link() { return link_; }

private:
    // A result reported: the COM (when the request reached it) and the RSLT answered.
    static frontends::Exchange report(std::span<const std::uint8_t> request, ComputerLink::Result& result) {
        constexpr std::size_t kCom = kHeaderBytes + 2;
        const bool has_com = request.size() > kCom;
        const auto* row = has_com ? find_command(result.command) : nullptr;
        frontends::Exchange e;
        e.consumed = result.consumed;
        e.code = result.response.size() > kCom + 1 ? devicemodel::hex2(result.response[kCom + 1]) : std::string();
        e.command = has_com ? devicemodel::hex2(result.command) : std::string();
        e.known = row != nullptr;
        e.name = row ? row->name : std::string_view();
        e.response.assign(result.response.begin(), result.response.end());
        return e;
    }

    // The clock: the offset in seconds, then 1 and the stop instant (s since
    // the epoch) when B3 CTRL 01 stopped it, else 0 and 0. 17 bytes.
    std::vector<std::uint8_t> clock() const {
        devicemodel::ByteWriter out;
        out.u64(static_cast<std::uint64_t>(link_.clock_offset.count()));
        out.u8(link_.clock_stopped ? 1 : 0);
        auto stopped = link_.clock_stopped
                           ? std::chrono::duration_cast<std::chrono::seconds>(link_.clock_stopped->time_since_epoch()).count()
                           : 0;
        out.u64(static_cast<std::uint64_t>(stopped));
        return std::move(out.out);
    }

    ComputerLink link_;
    SendReceive send_receive_;
    std::shared_ptr<void> alive_ = std::make_shared<int>(0);   // the sessions' sign that the unit is still there
};

class Face final : public frontends::Face {
public:
    std::string_view name() const override { return "jw51cm"; }
    std::string_view title() const override { return "JW-51CM computer link"; }
    std::string_view log_name() const override { return "JW-51CM"; }
    std::string_view port_name() const override { return "JW-51CM"; }
    std::string port_fix(Transport transport) const override {
        return std::string("\"jw51cm\": {\"") + (transport == Transport::Tcp ? "tcp" : "udp") + "_port\": ...}";
    }
    bool has_udp() const override { return true; }

    std::string_view station_kind() const override { return "sharp-jw"; }
    std::string_view missing_noun() const override { return "JW-51CM unit"; }
    std::string ports_fix() const override {
        return "remove \"ports\" (the unit's ports are \"jw51cm\": {\"tcp_port\": ..., \"udp_port\": ...}), "
               "or use \"kind\": \"melsec\" with a \"jw51cm\" section to serve both on one memory";
    }
    std::string command_line_refusal() const override {
        return "a sharp-jw station serves only the JW-51CM computer link; leave out --tcp-port/--udp-port/"
               "--hostlink-port (its ports are \"jw51cm\": {\"tcp_port\": ..., \"udp_port\": ...}), or use "
               "\"kind\": \"melsec\" to serve several protocols";
    }

    frontends::Settings defaults() const override {
        frontends::Settings s;
        s.face = this;
        s.tcp = kTcp;
        s.udp = kUdp;
        s.options = std::make_shared<Options>();   // file sizes, T/C attributes
        return s;
    }

    void parse(const JsonAt& at, frontends::Settings& j) const override {
        at.only_keys({"tcp_port", "udp_port", "max_connections", "idle_timeout_ms", "partial_frame_timeout_ms",
                      "file_bytes", "timers", "timer_attributes", "parameters"});
        auto& options = options_of(j);
        if (at.has("tcp_port")) j.tcp = optional_port(at["tcp_port"], j.tcp.value_or(kTcp));
        if (at.has("udp_port")) j.udp = optional_port(at["udp_port"], j.udp.value_or(kUdp));
        if (!j.tcp && !j.udp) at.fail("no port left", "give \"tcp_port\" or \"udp_port\" a number (the unit needs a TCP_Passive or UDP connection)");
        if (j.tcp) {
            if (at.has("max_connections")) {
                j.tcp->max_connections = static_cast<unsigned>(at["max_connections"].unsigned_int(8));
                if (*j.tcp->max_connections == 0) at["max_connections"].fail("must be 1-8", "the unit has 8 connections; use 1-8");
            }
            if (at.has("idle_timeout_ms")) j.tcp->idle_timeout_ms = static_cast<unsigned>(at["idle_timeout_ms"].unsigned_int(86400000));
            if (at.has("partial_frame_timeout_ms"))
                j.tcp->partial_frame_timeout_ms = static_cast<unsigned>(at["partial_frame_timeout_ms"].unsigned_int(86400000));
        }
        if (at.has("file_bytes")) {
            options.file_bytes = static_cast<std::uint32_t>(at["file_bytes"].unsigned_int(65536));
            if (options.file_bytes % 2 != 0) at["file_bytes"].fail("must be even", "use e.g. 16384 or 65536");
        }
        if (at.has("timers")) options.timers = static_cast<std::uint32_t>(at["timers"].unsigned_int(1024));
        if (at.has("timer_attributes")) {
            auto attributes = at["timer_attributes"];
            attributes.expect_object();
            for (const auto& [number, _] : attributes.json().items()) {
                const auto value = octal(number);
                if (!value || *value >= options.timers)
                    attributes[number].fail("'" + number + "' is not a T/C number", "write it in octal, 0000-1777 (TMR0002 is \"0002\")");
                auto code = attributes[number].hex_code();
                if (code > 0x0F) attributes[number].fail("not a T/C attribute", "use 0000-000F (04 TMR, 02 CNT, 08 DTMR BCD, ...)");
                options.timer_attributes[*value] = static_cast<std::uint8_t>(code);
            }
        }
        if (at.has("parameters")) parse_parameters(at["parameters"], options, j.udp.has_value());
    }

    // A JW-51CM COM is two hex digits, compared in uppercase.
    bool scenario_command(std::string& text) const override {
        bool ok = text.size() == 2;
        for (auto& c : text) {
            ok = ok && std::isxdigit(static_cast<unsigned char>(c));
            c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        }
        return ok;
    }
    std::string_view command_fix() const override { return "write the COM as two hex digits, e.g. \"24\""; }
    std::string_view code_fix() const override { return "write the RSLT as two hex digits, e.g. \"10\""; }

    std::string check(devicemodel::Cpu& cpu, const frontends::Settings& s) const override {
        ComputerLink link(cpu, options_of(s));
        return link.map().check(cpu.memory());
    }
    std::unique_ptr<frontends::Unit> make_unit(devicemodel::Cpu& cpu, const frontends::Settings& s) const override {
        return std::make_unique<Unit>(cpu, options_of(s), s.udp.has_value());
    }

    std::span<const frontends::ApiRoute> api_routes() const override;
};

// The ring buffers seen from the PLC side (docs/api.md#jw-51cm-ring-buffers):
// the ladder program of the real unit fills a PLC -> host ring and empties a
// host -> PLC one; here a test or a tool does it over HTTP.
using frontends::ApiAnswer;
using nlohmann::json;

ApiAnswer refused(unsigned status, std::string message) { return {status, std::move(message)}; }

std::optional<unsigned> ring_number(const std::string& text) {
    std::size_t used = 0;
    unsigned long number = kRingBuffers;
    try {
        number = std::stoul(text, &used, 16);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || number >= kRingBuffers) return std::nullopt;
    return static_cast<unsigned>(number);
}

RingBuffer read_ring(ComputerLink& link, unsigned number) {
    return ring_buffer(link.options().parameters, link.map(), ByteAccess(link.cpu().memory(), link.map()), number);
}

json ring_json(const ComputerLink& link, const RingBuffer& r, unsigned number) {
    json out{{"ring", number},
             {"definition", r.defined() ? ((r.dinf & ~kDinfInvalid) == kDinfDirect ? "direct" : "indirect") : "none"}};
    if (!r.defined()) return out;
    out["valid"] = r.valid();
    out["info"] = {{"file", r.info.file}, {"address", octal(r.info.address, 6)}};
    out["direction"] = r.to_host() ? "plc-to-host" : r.direction == kToPlc ? "host-to-plc" : "invalid";
    out["file"] = r.file;
    out["address"] = octal(r.address(), 6);
    out["bytes"] = r.size();
    out["wp"] = r.wp;
    out["rp"] = r.rp;
    if (r.valid() && r.pointers_inside()) {
        out["unread"] = r.unread();
        out["free"] = r.free();
    }
    const auto& pending = link.ring_confirms[number];
    out["awaiting_confirm"] = pending.open ? json{{"from", pending.from}, {"bytes", pending.length}} : json(nullptr);
    return out;
}

// The checks both PLC-side actions make: the ring exists, is valid, runs the way wanted.
std::optional<ApiAnswer> unusable(const RingBuffer& r, unsigned number, bool to_host, std::string_view other_way) {
    auto name = "ring buffer " + octal(number, 1);
    if (!r.defined())
        return refused(404, name + " is not defined; give it in the configuration's \"jw51cm\": {\"parameters\": {\"" +
                                octal(kRingParameters + 8 * number, 4) + "\": ...}} (docs/jw51cm.md)");
    if (!r.valid()) return refused(409, name + "'s indirect definition (its info area +4..+7) is invalid; fix it with 79 or /api/devices");
    if (r.to_host() != to_host) return refused(409, name + " runs " + (to_host ? "host -> PLC" : "PLC -> host") + "; " + std::string(other_way));
    if (!r.pointers_inside())
        return refused(409, name + "'s WP " + std::to_string(r.wp) + " or RP " + std::to_string(r.rp) + " is outside its " +
                                std::to_string(r.size()) + " bytes; set them with 79 or /api/devices");
    return std::nullopt;
}

json body_of(const std::string& text) {
    if (text.empty()) return json::object();
    auto body = json::parse(text, nullptr, false);
    return body.is_discarded() ? json() : body;
}

Unit& unit_of(frontends::Unit& unit) { return static_cast<Unit&>(unit); }

ApiAnswer list_rings(frontends::Unit& unit, const std::vector<std::string>&, const std::string&) {
    auto& link = unit_of(unit).link();
    auto list = json::array();
    for (unsigned n = 0; n < kRingBuffers; ++n) list.push_back(ring_json(link, read_ring(link, n), n));
    return {200, json{{"rings", std::move(list)}}.dump()};
}

ApiAnswer get_ring(frontends::Unit& unit, const std::vector<std::string>& captures, const std::string&) {
    auto number = ring_number(captures.at(0));
    if (!number) return refused(400, "'" + captures.at(0) + "' is not a ring buffer; use 0-F");
    auto& link = unit_of(unit).link();
    return {200, ring_json(link, read_ring(link, *number), *number).dump()};
}

// The PLC puts data into a PLC -> host ring at WP and moves WP, never onto RP.
ApiAnswer put_ring(frontends::Unit& unit, const std::vector<std::string>& captures, const std::string& text) {
    auto number = ring_number(captures.at(0));
    if (!number) return refused(400, "'" + captures.at(0) + "' is not a ring buffer; use 0-F");
    auto body = body_of(text);
    std::optional<std::vector<std::uint8_t>> data;
    if (body.is_object() && body.size() == 1 && body.contains("data") && body["data"].is_string())
        data = hex_bytes(body["data"].get<std::string>());
    if (!data || data->empty()) return refused(400, "give the bytes as {\"data\": \"01020304\"} (hex, at least one byte)");
    auto& link = unit_of(unit).link();
    auto r = read_ring(link, *number);
    if (auto no = unusable(r, *number, true, "the host writes it (39); take its data with POST /api/jw51cm/rings/N/take"))
        return *no;
    if (data->size() > r.free())
        return refused(409, "ring buffer " + octal(*number, 1) + " has " + std::to_string(r.free()) + " bytes free, not " +
                                std::to_string(data->size()) + "; the host reads it with 29 first");
    ByteAccess memory(link.cpu().memory(), link.map());
    put_ring_bytes(r, memory, r.wp, *data);
    set_write_pointer(r, memory, r.wp + static_cast<std::uint32_t>(data->size()));
    auto out = ring_json(link, r, *number);
    out["written"] = data->size();
    return {200, out.dump()};
}

// The PLC takes what the host wrote into a host -> PLC ring: from RP, then RP moves.
ApiAnswer take_ring(frontends::Unit& unit, const std::vector<std::string>& captures, const std::string& text) {
    auto number = ring_number(captures.at(0));
    if (!number) return refused(400, "'" + captures.at(0) + "' is not a ring buffer; use 0-F");
    auto body = body_of(text);
    std::uint32_t wanted = 0;
    bool good = body.is_object() && (body.empty() || (body.size() == 1 && body.contains("count") &&
                                                       body["count"].is_number_unsigned() && body["count"].get<std::uint64_t>() <= 65536));
    if (!good) return refused(400, "give {\"count\": N} (bytes, 0 or none for all unread) or no body");
    if (body.contains("count")) wanted = body["count"].get<std::uint32_t>();
    auto& link = unit_of(unit).link();
    auto r = read_ring(link, *number);
    if (auto no = unusable(r, *number, false, "the host reads it (29); fill it with POST /api/jw51cm/rings/N")) return *no;
    auto count = wanted == 0 ? r.unread() : std::min(wanted, r.unread());
    ByteAccess memory(link.cpu().memory(), link.map());
    auto data = ring_bytes(r, memory, r.rp, count);
    set_read_pointer(r, memory, r.rp + count);
    auto out = ring_json(link, r, *number);
    out["data"] = hex_text(data);
    return {200, out.dump()};
}

constexpr std::array kRoutes{
    frontends::ApiRoute{false, "rings", list_rings},
    frontends::ApiRoute{false, "rings/{number}", get_ring},
    frontends::ApiRoute{true, "rings/{number}", put_ring},
    frontends::ApiRoute{true, "rings/{number}/take", take_ring},
};

std::span<const frontends::ApiRoute> Face::api_routes() const { return kRoutes; }

}  // namespace

const frontends::Face& face() {
    static const Face instance;
    return instance;
}

}  // namespace slmp::jw51cm
