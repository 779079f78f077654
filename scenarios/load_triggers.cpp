// "triggers": a condition on devices, on traffic or on the clock, and the
// actions it starts.
#include <sstream>

#include "config/config_parts.hpp"
#include "scenarios/load_parts.hpp"

namespace slmp::scenarios::load {
namespace {

// "D100 >= 50", "D100 < D101", "M0", "M0 == 0": a device, optionally compared.
DeviceCondition device_condition(const JsonAt& at, const JsonAt& owner) {
    std::istringstream in(at.string());
    std::vector<std::string> tokens;
    for (std::string t; in >> t;) tokens.push_back(t);
    constexpr std::string_view fix = "write e.g. \"D100 >= 50\", \"M0\", \"D10 != D11\" (operators = == != <> < <= > >=)";
    if (tokens.size() != 1 && tokens.size() != 3) at.fail("cannot read the condition", fix);
    auto operand = [&](const std::string& text) -> Operand {
        std::string error;
        if (auto a = devicemodel::parse_address(text, &error)) {
            return {DeviceRef{*a, value_format(owner, *a)}, 0};
        }
        try {
            std::size_t used = 0;
            double v = std::stod(text, &used);
            if (used == text.size()) return {std::nullopt, v};
        } catch (const std::exception&) {
        }
        if (!may_be_label(text)) at.fail("'" + text + "' is neither a device nor a number (" + error + ")", fix);
        // Neither: a label, resolved by bind_labels() (which names both possibilities if it is not one).
        if (owner.has("as")) owner["as"].fail("\"as\" applies to devices; '" + text + "' is a label", "remove \"as\"");
        return {DeviceRef{{}, ValueFormat::Int16, text}, 0};
    };
    DeviceCondition c;
    c.left = operand(tokens[0]);
    if (!c.left.device) at.fail("the condition must start with a device", fix);
    if (tokens.size() == 1) return c;   // "M0": M0 != 0
    auto op = parse_compare(tokens[1]);
    if (!op) at.fail("unknown operator '" + tokens[1] + "'", fix);
    c.op = *op;
    c.right = operand(tokens[2]);
    return c;
}

TrafficCondition traffic_condition(const JsonAt& at) {
    at.only_keys({"command", "subcommand", "devices", "writes", "reads", "request", "client"});
    TrafficCondition t;
    if (at.has("command")) t.commands = codes(at["command"]);
    if (at.has("subcommand")) t.subcommands = codes(at["subcommand"]);
    int device_keys = at.has("devices") + at.has("writes") + at.has("reads");
    if (device_keys > 1) at.fail("more than one of \"devices\", \"reads\", \"writes\"", "keep one");
    if (at.has("devices")) t.devices = ranges(at["devices"]);
    if (at.has("writes")) t.devices = ranges(at["writes"]), t.access = Access::Write;
    if (at.has("reads")) t.devices = ranges(at["reads"]), t.access = Access::Read;
    if (at.has("client")) t.client = at["client"].string();
    if (at.has("request")) {
        t.nth = at["request"].unsigned_int(1ull << 53);
        if (t.nth == 0) at["request"].fail("requests are counted from 1", "write 1 for the first matching request");
    }
    return t;
}

Condition condition(const JsonAt& at, const JsonAt& owner) {
    if (at.json().is_string()) return device_condition(at, owner);
    at.expect_object();
    if (at.has("rising") || at.has("falling")) {
        at.only_keys({"rising", "falling"});
        if (at.has("rising") && at.has("falling")) at.fail("both \"rising\" and \"falling\"", "use two triggers");
        bool rising = at.has("rising");
        auto edge = at[rising ? "rising" : "falling"];
        auto bit = device(edge, edge);   // a bit device, or a Bit label (bind_labels() checks its type)
        if (bit.label.empty() && bit.address.spec->unit != devicemodel::Unit::Bit)
            edge.fail("not a bit device", "name a bit device such as M0, X1, Y10, or a Bit label");
        DeviceCondition c;
        c.kind = rising ? DeviceCondition::Kind::Rising : DeviceCondition::Kind::Falling;
        c.left = {bit, 0};
        return c;
    }
    if (at.has("at_ms")) {
        at.only_keys({"at_ms"});
        return TimeCondition{millis(at["at_ms"])};
    }
    return traffic_condition(at);
}

Action action(const JsonAt& at) {
    at.expect_object();
    static constexpr std::string_view kinds[] = {"set", "increment", "pulse", "switch", "error", "clear_error",
                                                 "start_fault", "stop_fault", "power_cycle", "refuse_connections", "log",
                                                 "ondemand", "drive", "system_switch"};
    std::string key;
    for (auto k : kinds)
        if (at.has(k)) {
            if (!key.empty()) at.fail("the action has both \"" + key + "\" and \"" + std::string(k) + "\"", "split it into two actions");
            key = k;
        }
    if (key.empty())
        at.fail("no action named",
                "use one of set, increment, pulse, switch, error, clear_error, start_fault, stop_fault, power_cycle, "
                "refuse_connections, log, ondemand, drive, system_switch");
    auto only = [&](std::initializer_list<std::string_view> keys) { at.only_keys(keys); };
    if (key == "set") {
        only({"set"});
        auto set = set_values(at["set"]);
        return SetAction{std::move(set.devices), std::move(set.labels)};
    }
    if (key == "increment") {
        only({"increment", "by", "as"});
        IncrementAction a{device(at["increment"], at), 1};
        if (at.has("by")) a.by = number(at["by"], -1e15, 1e15, "write a plain number");
        return a;
    }
    if (key == "pulse") {
        only({"pulse", "ms"});
        PulseAction a{address(at["pulse"]), 100};
        if (a.device.spec->unit != devicemodel::Unit::Bit) at["pulse"].fail("not a bit device", "pulse a bit device such as M5 or Y0");
        if (at.has("ms")) a.ms = millis(at["ms"]);
        return a;
    }
    if (key == "switch") {
        only({"switch"});
        return SwitchAction{run_switch(at["switch"])};
    }
    if (key == "error") {
        only({"error"});
        return ErrorAction{cpu_error(at["error"])};
    }
    if (key == "clear_error") {
        only({"clear_error"});
        if (!at["clear_error"].boolean()) at["clear_error"].fail("false does nothing", "write true or remove the action");
        return ClearErrorAction{};
    }
    if (key == "start_fault" || key == "stop_fault") {
        only({key});
        return FaultSwitchAction{at[key].string(), key == "start_fault"};
    }
    if (key == "power_cycle") {
        only({"power_cycle"});
        auto p = at["power_cycle"];
        p.only_keys({"off_ms"});
        return PowerCycleAction{p.has("off_ms") ? millis(p["off_ms"]) : 1000};
    }
    if (key == "refuse_connections") {
        only({"refuse_connections"});
        auto r = at["refuse_connections"];
        r.only_keys({"for_ms"});
        return RefuseAction{millis(r["for_ms"])};
    }
    if (key == "ondemand") {
        only({"ondemand"});
        return ondemand(at["ondemand"]);
    }
    if (key == "drive") {
        only({"drive"});
        auto d = at["drive"];
        d.only_keys({"number", "present", "write_protect"});
        DriveAction a{static_cast<std::uint16_t>(d["number"].unsigned_int(4)), {}, {}, d.pointer()};
        if (d.has("present")) a.present = d["present"].boolean();
        if (d.has("write_protect")) a.write_protect = d["write_protect"].boolean();
        if (!a.present && !a.write_protect)
            d.fail("changes nothing", "give \"present\" (the card in or out) or \"write_protect\" (its LOCK switch)");
        return a;
    }
    if (key == "system_switch") {
        only({"system_switch"});
        if (!at["system_switch"].boolean()) at["system_switch"].fail("false does nothing", "write true or remove the action");
        return SystemSwitchAction{};
    }
    only({"log"});
    return LogAction{at["log"].string()};
}

Trigger trigger(const JsonAt& at) {
    at.only_keys({"id", "when", "for_ms", "times", "as", "do"});
    Trigger t;
    t.pointer = at.pointer();
    if (at.has("id")) t.id = at["id"].string();
    t.when = condition(at["when"], at);
    if (at.has("for_ms")) {
        if (!std::holds_alternative<DeviceCondition>(t.when) ||
            std::get<DeviceCondition>(t.when).kind != DeviceCondition::Kind::Compare)
            at["for_ms"].fail("\"for_ms\" applies to device conditions such as \"D100 >= 50\"", "remove it");
        t.for_ms = millis(at["for_ms"]);
    }
    if (at.has("times")) {
        t.times = at["times"].unsigned_int(1ull << 53);
        if (t.times == 0) at["times"].fail("0 would never fire", "write 1 or more, or leave it out (no limit)");
    }
    auto list = at["do"];
    list.expect_array();
    if (list.json().empty()) list.fail("no actions", "add at least one action");
    for (std::size_t i = 0; i < list.json().size(); ++i) t.actions.push_back(action(list[i]));
    return t;
}

}  // namespace

std::vector<Trigger> triggers(const JsonAt& at) {
    at.expect_array();
    std::vector<Trigger> list;
    for (std::size_t i = 0; i < at.json().size(); ++i) list.push_back(trigger(at[i]));
    return list;
}

}  // namespace slmp::scenarios::load
