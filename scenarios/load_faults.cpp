// "faults": what to match, what to do, and how often.
#include <cctype>
#include <initializer_list>
#include <string_view>

#include "frontends/face.hpp"
#include "scenarios/load_parts.hpp"

namespace slmp::scenarios::load {
namespace {

// A face's command in its own form (frontends/face.hpp: Face::scenario_command).
std::string frontend_command(const JsonAt& at, Protocol protocol) {
    auto text = at.string();
    const auto& face = *frontends::find_face(protocol);
    if (!face.scenario_command(text))
        at.fail("'" + at.string() + "' is not a " + std::string(to_string(protocol)) + " command", face.command_fix());
    return text;
}

FaultMatch match(const JsonAt& at) {
    FaultMatch m;
    if (at.has("protocol")) {
        auto p = at["protocol"].string();
        if (p == kSlmp) m.request_protocol = kSlmp;
        else if (const auto* face = frontends::find_face(p)) m.request_protocol = face->name();
        else at["protocol"].fail("unknown protocol '" + p + "'", "use " + frontends::face_names(kSlmp));
    }
    if (m.request_protocol != kSlmp) {
        // A front end's request has a command and a peer; nothing SLMP decodes.
        at.only_keys({"protocol", "command", "transport", "connection", "client"});
        if (at.has("command")) {
            auto c = at["command"];
            if (c.json().is_array())
                for (std::size_t i = 0; i < c.json().size(); ++i) m.frontend_commands.push_back(frontend_command(c[i], m.request_protocol));
            else
                m.frontend_commands.push_back(frontend_command(c, m.request_protocol));
        }
    } else {
        at.only_keys({"protocol", "command", "subcommand", "devices", "access", "frame", "code", "transport", "connection", "client",
                      "route"});
    }
    if (at.has("command") && m.request_protocol == kSlmp) m.commands = codes(at["command"]);
    if (at.has("subcommand")) m.subcommands = codes(at["subcommand"]);
    if (at.has("devices")) m.devices = ranges(at["devices"]);
    if (at.has("access")) m.access = access(at["access"]);
    if (at.has("frame")) {
        auto f = at["frame"].string();
        if (f == "3E" || f == "3e") m.frame = protocol::FrameKind::E3;
        else if (f == "4E" || f == "4e") m.frame = protocol::FrameKind::E4;
        else at["frame"].fail("unknown frame '" + f + "'", "use \"3E\" or \"4E\"");
    }
    if (at.has("code")) {
        auto c = at["code"].string();
        if (c == "binary") m.code = protocol::Codec::Binary;
        else if (c == "ascii") m.code = protocol::Codec::Ascii;
        else at["code"].fail("unknown data code '" + c + "'", "use \"binary\" or \"ascii\"");
    }
    if (at.has("transport")) {
        auto t = at["transport"].string();
        if (t == "tcp") m.transport = Transport::Tcp;
        else if (t == "udp") m.transport = Transport::Udp;
        else at["transport"].fail("unknown transport '" + t + "'", "use \"tcp\" or \"udp\"");
    }
    if (at.has("connection")) {
        m.connection = at["connection"].unsigned_int(1ull << 53);
        if (*m.connection == 0) at["connection"].fail("connections are counted from 1", "write 1 for the first connection");
    }
    if (at.has("client")) m.client = at["client"].string();
    if (at.has("route")) {   // {"network": 2, "station": 3}, either or both, as the request's route names them
        auto route = at["route"];
        route.only_keys({"network", "station"});
        if (route.has("network")) m.route_network = static_cast<std::uint8_t>(route["network"].unsigned_int(0xFF));
        if (route.has("station")) m.route_station = static_cast<std::uint8_t>(route["station"].unsigned_int(0xFF));
        if (!m.route_network && !m.route_station)
            route.fail("a route match needs \"network\" or \"station\"", "write {\"network\": 2} or {\"network\": 2, \"station\": 3}");
    }
    return m;
}

struct KindInfo {
    std::string_view name;
    FaultKind kind;
    std::initializer_list<std::string_view> keys;   // the kind's own keys
};

const KindInfo kKinds[] = {
    {"end_code", FaultKind::EndCode, {"end_code"}},
    {"delay", FaultKind::Delay, {"delay_ms"}},
    {"no_response", FaultKind::NoResponse, {}},
    {"close", FaultKind::Close, {}},
    {"reset", FaultKind::Reset, {}},
    {"split", FaultKind::Split, {"chunks", "chunk_bytes", "pause_ms"}},
    {"coalesce", FaultKind::Coalesce, {"responses", "hold_ms"}},
    {"corrupt", FaultKind::Corrupt, {"corrupt", "bytes"}},
    {"refuse_connections", FaultKind::RefuseConnections, {"for_ms"}},
    {"power_cycle", FaultKind::PowerCycle, {"off_ms"}},
};

const KindInfo& kind(const JsonAt& at) {
    auto name = at.string();
    for (const auto& k : kKinds)
        if (k.name == name) return k;
    std::string list;
    for (const auto& k : kKinds) list += (list.empty() ? "" : ", ") + std::string(k.name);
    at.fail("unknown fault '" + name + "'", "use one of: " + list);
}

// Only the common keys and the kind's own, so a "delay_ms" on a "split" fault
// (a likely copy-and-paste slip) is reported instead of ignored.
void check_keys(const JsonAt& at, const KindInfo& k) {
    static constexpr std::string_view common[] = {"id", "enabled", "match", "do", "skip", "count", "probability", "from_ms", "until_ms"};
    for (const auto& [key, _] : at.json().items()) {
        bool ok = false;
        for (auto c : common) ok = ok || c == key;
        for (auto c : k.keys) ok = ok || c == key;
        if (ok) continue;
        std::string list;
        for (auto c : k.keys) list += (list.empty() ? "" : ", ") + std::string(c);
        at[key].fail("not a key of a \"" + std::string(k.name) + "\" fault",
                     list.empty() ? "remove it" : "its own keys are: " + list);
    }
}

// The kinds a front end's request can have: an answer, a delay, a drop.
bool frontend_kind(FaultKind kind) {
    return kind == FaultKind::EndCode || kind == FaultKind::Delay || kind == FaultKind::NoResponse ||
           kind == FaultKind::Close || kind == FaultKind::Reset;
}

// "end_code" on a front end: the host link's response code or the JW RSLT, two hex digits.
std::uint8_t frontend_code(const JsonAt& at, Protocol protocol) {
    auto text = at.string();
    auto fix = frontends::find_face(protocol)->code_fix();
    if (text.size() != 2 || !std::isxdigit(static_cast<unsigned char>(text[0])) || !std::isxdigit(static_cast<unsigned char>(text[1])))
        at.fail("'" + text + "' is not a " + std::string(to_string(protocol)) + " response code", fix);
    auto code = static_cast<std::uint8_t>(std::stoul(text, nullptr, 16));
    if (code == 0) at.fail("00 is success", fix);
    return code;
}

FaultAction action(const JsonAt& at, const KindInfo& k, Protocol request_protocol) {
    FaultAction a;
    a.kind = k.kind;
    if (request_protocol != kSlmp && !frontend_kind(k.kind))
        at["do"].fail("a \"" + std::string(k.name) + "\" fault does not act on " + std::string(to_string(request_protocol)) + " requests",
                      "use end_code, delay, no_response, close or reset");
    switch (k.kind) {
        case FaultKind::EndCode:
            if (request_protocol != kSlmp) {
                a.frontend_code = frontend_code(at["end_code"], request_protocol);
                break;
            }
            a.end_code = protocol::end_code(at["end_code"].hex_code());
            if (a.end_code == protocol::EndCode::Ok) at["end_code"].fail("0000 is success", "use an error end code such as \"C051\"");
            break;
        case FaultKind::Delay: {
            auto d = at["delay_ms"];
            if (d.json().is_array()) {
                if (d.json().size() != 2) d.fail("expected [min, max]", "write e.g. [100, 500] or one number");
                a.delay_min_ms = millis(d[0]);
                a.delay_max_ms = millis(d[1]);
                if (a.delay_max_ms < a.delay_min_ms) d.fail("max is below min", "write [min, max]");
            } else {
                a.delay_min_ms = a.delay_max_ms = millis(d);
            }
            break;
        }
        case FaultKind::Split:
            if (at.has("chunks") && at.has("chunk_bytes")) at.fail("both \"chunks\" and \"chunk_bytes\"", "give one");
            if (at.has("chunks") && (a.chunks = at["chunks"].unsigned_int(65535)) < 2)
                at["chunks"].fail("fewer than 2 pieces splits nothing", "write 2 or more");
            if (at.has("chunk_bytes") && (a.chunk_bytes = at["chunk_bytes"].unsigned_int(65535)) == 0)
                at["chunk_bytes"].fail("0-byte pieces", "write 1 or more");
            if (at.has("pause_ms")) a.pause_ms = millis(at["pause_ms"]);
            break;
        case FaultKind::Coalesce:
            if (at.has("responses") && (a.responses = at["responses"].unsigned_int(1000)) < 2)
                at["responses"].fail("fewer than 2 responses coalesces nothing", "write 2 or more");
            if (at.has("hold_ms")) a.hold_ms = millis(at["hold_ms"]);
            break;
        case FaultKind::Corrupt: {
            auto c = at["corrupt"].string();
            if (c == "length") a.corruption = Corruption::Length;
            else if (c == "subheader") a.corruption = Corruption::Subheader;
            else if (c == "random") a.corruption = Corruption::Random;
            else at["corrupt"].fail("unknown corruption '" + c + "'", "use \"length\", \"subheader\" or \"random\"");
            if (at.has("bytes") && (a.bytes = at["bytes"].unsigned_int(65535)) == 0) at["bytes"].fail("0 changes nothing", "write 1 or more");
            break;
        }
        case FaultKind::RefuseConnections: a.period_ms = millis(at["for_ms"]); break;
        case FaultKind::PowerCycle: a.period_ms = at.has("off_ms") ? millis(at["off_ms"]) : 1000; break;
        default: break;
    }
    return a;
}

Fault fault(const JsonAt& at) {
    at.expect_object();
    Fault f;
    f.pointer = at.pointer();
    const auto& k = kind(at["do"]);
    check_keys(at, k);
    if (at.has("id")) f.id = at["id"].string();
    if (at.has("enabled")) f.enabled = at["enabled"].boolean();
    if (at.has("match")) f.match = match(at["match"]);
    f.action = action(at, k, f.match.request_protocol);
    if (at.has("skip")) f.skip = at["skip"].unsigned_int(1ull << 53);
    if (at.has("count")) {
        f.count = at["count"].unsigned_int(1ull << 53);
        if (f.count == 0) at["count"].fail("0 would never fire", "write 1 or more, or leave it out (no limit)");
    }
    if (at.has("probability")) f.probability = probability(at["probability"]);
    if (at.has("from_ms")) f.from_ms = millis(at["from_ms"]);
    if (at.has("until_ms")) {
        f.until_ms = millis(at["until_ms"]);
        if (f.until_ms <= f.from_ms) at["until_ms"].fail("the window closes before it opens", "make until_ms larger than from_ms");
    }
    return f;
}

}  // namespace

std::vector<Fault> faults(const JsonAt& at) {
    at.expect_array();
    std::vector<Fault> list;
    for (std::size_t i = 0; i < at.json().size(); ++i) list.push_back(fault(at[i]));
    return list;
}

}  // namespace slmp::scenarios::load
