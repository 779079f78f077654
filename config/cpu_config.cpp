// The "cpu" key (operating state, scan, timers/counters, latch, remote reset,
// remote password, a simulated error) and the persistence keys. Reference:
// docs/cpu-runtime.md. Parsing checks shapes; checked_runtime_config() checks
// numbers against the profile once it is known (the command line may change it).
#include <cctype>
#include <cmath>

#include "config/config_parts.hpp"
#include "config/settings.hpp"

namespace slmp::config {

using devicemodel::Area;

namespace {

std::string upper(std::string text) {
    for (auto& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

// "T0", "LST5", "C10", "D100", "W1F": an area and a device number. Storage
// names (T, ST, C, LT, LST, LC) are accepted as well as device symbols.
std::pair<Area, std::uint32_t> area_and_number(const JsonAt& at) {
    auto text = at.string();
    std::size_t letters = 0;
    while (letters < text.size() && std::isalpha(static_cast<unsigned char>(text[letters]))) ++letters;
    auto prefix = text.substr(0, letters);
    auto area = devicemodel::area_by_name(prefix);
    // Storage names that are not device symbols (T, ST, C, LT, LST, LC) are
    // decimal; everything else goes through the device table (W1F is hex).
    if (area && !devicemodel::find_by_symbol(prefix) && letters < text.size()) {
        auto digits = text.substr(letters);
        if (digits.find_first_not_of("0123456789") == std::string::npos && digits.size() <= 9)
            return {*area, static_cast<std::uint32_t>(std::stoul(digits))};
    }
    std::string error;
    auto address = devicemodel::parse_address(text, &error);
    if (!address) at.fail(error, "write a device such as T0, ST5, LT0, C10, D100");
    return {address->spec->area, address->number};
}

bool is_timer(Area a) { return a == Area::T || a == Area::ST || a == Area::LT || a == Area::LST; }
bool is_counter(Area a) { return a == Area::C || a == Area::LC; }
bool is_long(Area a) { return a == Area::LT || a == Area::LST || a == Area::LC; }

std::uint32_t preset(const JsonAt& at, Area area) {
    return static_cast<std::uint32_t>(at.unsigned_int(is_long(area) ? 0xFFFFFFFFu : 32767u));
}

void timers(const JsonAt& list, CpuRuntimeConfig& cpu) {
    list.expect_array();
    for (std::size_t i = 0; i < list.json().size(); ++i) {
        auto at = list[i];
        check_keys(at, Section::Timer);
        auto [area, first] = area_and_number(at["device"]);
        if (!is_timer(area)) at["device"].fail("not a timer", "use T, ST, LT or LST, e.g. \"T0\"");
        devicemodel::TimerRange r{area, first, 1, preset(at["preset"], area), {}};
        if (at.has("points")) r.count = static_cast<std::uint32_t>(bounded_setting(at, Section::Timer, "points"));
        // iQ-R defaults: low-speed timers 100 ms; long timers count in 1 µs units.
        double base_ms = area == Area::LT || area == Area::LST ? 0.001 : 100;
        if (at.has("base_ms")) base_ms = number_setting(at, Section::Timer, "base_ms");
        r.base = std::chrono::microseconds(static_cast<std::int64_t>(std::llround(base_ms * 1000)));
        cpu.runtime.timers.push_back(r);
        cpu.timer_keys.push_back(at.pointer());
    }
}

void counters(const JsonAt& list, CpuRuntimeConfig& cpu) {
    list.expect_array();
    for (std::size_t i = 0; i < list.json().size(); ++i) {
        auto at = list[i];
        check_keys(at, Section::Counter);
        auto [area, first] = area_and_number(at["device"]);
        if (!is_counter(area)) at["device"].fail("not a counter", "use C or LC, e.g. \"C0\"");
        devicemodel::CounterRange r{area, first, 1, preset(at["preset"], area)};
        if (at.has("points")) r.count = static_cast<std::uint32_t>(bounded_setting(at, Section::Counter, "points"));
        cpu.runtime.counters.push_back(r);
        cpu.counter_keys.push_back(at.pointer());
    }
}

// {"D": [0, 99]} or {"D": [[0, 99], [500, 599]]}; numbers or addresses ("W1F").
void latch(const JsonAt& object, CpuRuntimeConfig& cpu) {
    object.expect_object();
    // A named local rather than a structured binding: clang < 16 cannot
    // capture a binding in the lambdas below.
    for (const auto& item : object.json().items()) {
        const std::string name = item.key();
        auto at = object[name];
        auto area = devicemodel::area_by_name(name);
        if (!area) at.fail("unknown device area '" + name + "'", "use an area such as D, M, B, W, T, C, ZR");
        at.expect_array();
        auto one = [&](const JsonAt& pair) {
            pair.expect_array();
            if (pair.json().size() != 2) pair.fail("expected [first, last]", "write e.g. [0, 99]");
            auto bound = [&](const JsonAt& b) -> std::uint32_t {
                if (b.json().is_string()) {
                    auto [a, n] = area_and_number(b);
                    if (a != *area) b.fail("not a " + name + " device", "use numbers or " + name + " addresses");
                    return n;
                }
                return static_cast<std::uint32_t>(b.unsigned_int(0x7FFFFFFF));
            };
            auto first = bound(pair[0]);
            auto last = bound(pair[1]);
            if (last < first) pair.fail("last is before first", "write [first, last]");
            cpu.runtime.latch.push_back({*area, first, last - first + 1});
            cpu.latch_keys.push_back(pair.pointer());
        };
        if (!at.json().empty() && at.json()[0].is_array())
            for (std::size_t i = 0; i < at.json().size(); ++i) one(at[i]);
        else
            one(at);
    }
}

void lockout(const JsonAt& at, devicemodel::RuntimeConfig& runtime) {
    check_keys(at, Section::Lockout);
    if (at.has("attempts")) runtime.lockout_attempts = static_cast<unsigned>(bounded_setting(at, Section::Lockout, "attempts"));
    if (at.has("seconds")) runtime.lockout_period = std::chrono::seconds(bounded_setting(at, Section::Lockout, "seconds"));
}

// "program": {"file": ..., "operation_error": "stop", "wdt_ms": 200, ...}; the
// keys and their ranges are docs/program.md's "Configuration" table.
void program_object(const JsonAt& at, ProgramConfig& program) {
    check_keys(at, Section::Program);
    auto& o = program.options;
    program.file = at["file"].string();
    if (program.file.empty()) at["file"].fail("is empty", "name the program file (GX Works CSV list or text)");
    if (at.has("comments")) program.comments = at["comments"].string();
    if (at.has("operation_error"))
        o.operation_error = choice_setting(at, Section::Program, "operation_error") == "stop" ? program::OnOperationError::Stop
                                                                                              : program::OnOperationError::Continue;
    if (at.has("wdt_ms")) o.wdt_ms = static_cast<std::uint32_t>(bounded_setting(at, Section::Program, "wdt_ms"));
    if (at.has("timer_limit")) {
        auto limit = at["timer_limit"];
        check_keys(limit, Section::TimerLimit);
        if (limit.has("low_ms")) o.timer_low_ms = static_cast<std::uint32_t>(whole_setting(limit, Section::TimerLimit, "low_ms"));
        if (limit.has("high_ms"))
            o.timer_high_ms = static_cast<std::uint32_t>(whole_setting(limit, Section::TimerLimit, "high_ms"));
    }
    if (at.has("output_mode_at_run"))
        o.output_mode_at_run = choice_setting(at, Section::Program, "output_mode_at_run") == "previous"
                                   ? program::OutputModeAtRun::Previous
                                   : program::OutputModeAtRun::Recalculate;
    if (at.has("max_steps_per_scan")) o.max_steps_per_scan = whole_setting(at, Section::Program, "max_steps_per_scan");
    if (at.has("allow_double_timer_coils")) o.allow_double_timer_coils = at["allow_double_timer_coils"].boolean();
}

void cpu_object(const JsonAt& at, CpuRuntimeConfig& cpu) {
    check_keys(at, Section::Cpu);
    if (at.has("program")) program_object(at["program"], cpu.program);
    auto& r = cpu.runtime;
    if (at.has("switch")) r.run_switch = parse_run_switch(at["switch"].string(), at.pointer() + "/switch");
    if (at.has("scan_time_ms")) r.scan_time = std::chrono::milliseconds(whole_setting(at, Section::Cpu, "scan_time_ms"));
    if (at.has("remote_reset")) r.remote_reset_enabled = at["remote_reset"].boolean();
    if (at.has("output_off_at_stop")) r.output_off_at_stop = at["output_off_at_stop"].boolean();
    if (at.has("password")) r.password = at["password"].string();
    if (at.has("password_lockout")) lockout(at["password_lockout"], r);
    if (at.has("system_protect")) r.system_protect = at["system_protect"].boolean();
    if (at.has("latch")) latch(at["latch"], cpu);
    if (at.has("timers")) timers(at["timers"], cpu);
    if (at.has("counters")) counters(at["counters"], cpu);
    if (at.has("error")) {
        auto e = at["error"];
        check_keys(e, Section::CpuError);
        r.error = devicemodel::CpuError{e["code"].hex_code(), e.has("stop") && e["stop"].boolean()};
    }
}

}  // namespace

devicemodel::RunSwitch parse_run_switch(const std::string& text, const std::string& where) {
    auto u = upper(text);
    if (u == "RUN") return devicemodel::RunSwitch::Run;
    if (u == "STOP") return devicemodel::RunSwitch::Stop;
    throw ConfigError(where + ": unknown switch position '" + text + "'; use RUN or STOP");
}

void parse_cpu_runtime(const JsonAt& root, ServerConfig& c) {
    if (root.has("cpu")) cpu_object(root["cpu"], c.cpu);
    if (root.has("state_dir")) c.persistence.state_dir = root["state_dir"].string();
    if (root.has("clock_speed")) c.clock_speed = number_setting(root, Section::Station, "clock_speed");
    if (root.has("snapshot_interval_s"))
        c.persistence.snapshot_interval_s = number_setting(root, Section::Station, "snapshot_interval_s");
    if (root.has("restore")) c.persistence.restore_all = choice_setting(root, Section::Station, "restore") == "all";
}

devicemodel::RuntimeConfig checked_runtime_config(const CpuRuntimeConfig& cpu, const devicemodel::CpuProfile& profile) {
    auto r = cpu.runtime;
    auto fail = [&](const std::string& key, const std::string& problem, const std::string& fix) {
        throw ConfigError("configuration " + key + ": " + problem + "; " + fix);
    };
    auto check_span = [&](const std::string& key, Area area, std::uint32_t first, std::uint32_t count) {
        auto size = profile.size(area);
        if (std::uint64_t{first} + count > size)
            fail(key, std::string(devicemodel::area_name(area)) + std::to_string(first) + " with " + std::to_string(count) +
                          " point(s) runs past the " + std::string(devicemodel::area_name(area)) + " size of " +
                          std::to_string(size) + " in profile " + profile.name,
                 "shorten the range or raise device_sizes");
    };
    for (std::size_t i = 0; i < r.timers.size(); ++i)
        check_span(cpu.timer_keys.at(i), r.timers[i].area, r.timers[i].first, r.timers[i].count);
    for (std::size_t i = 0; i < r.counters.size(); ++i)
        check_span(cpu.counter_keys.at(i), r.counters[i].area, r.counters[i].first, r.counters[i].count);
    for (std::size_t i = 0; i < r.latch.size(); ++i)
        check_span(cpu.latch_keys.at(i), r.latch[i].area, r.latch[i].first, r.latch[i].count);
    if (!r.password.empty()) {
        auto n = r.password.size();
        if (profile.password_max_length == 0)
            fail("/cpu/password", profile.name + " has no remote password", "remove \"password\"");
        if (n < profile.password_min_length || n > profile.password_max_length)
            fail("/cpu/password",
                 "a " + std::to_string(n) + "-character password does not fit " + profile.name + "'s rule",
                 profile.password_min_length == profile.password_max_length
                     ? "use exactly " + std::to_string(profile.password_min_length) + " characters"
                     : "use " + std::to_string(profile.password_min_length) + " to " +
                           std::to_string(profile.password_max_length) + " characters");
        for (char ch : r.password)
            if (ch < 0x21 || ch > 0x7E)
                fail("/cpu/password", "contains a character that is not printable ASCII",
                     "use letters, digits and symbols only");
    }
    return r;
}

}  // namespace slmp::config
