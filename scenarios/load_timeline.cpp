// "timeline": steps at times or after one another, one pass or looping.
#include <algorithm>

#include "config/config_parts.hpp"
#include "scenarios/load_parts.hpp"

namespace slmp::scenarios::load {
namespace {

constexpr double kBig = 1e15;
constexpr std::string_view kValueFix = "write a plain number";

double value(const JsonAt& at) { return number(at, -kBig, kBig, kValueFix); }

double positive_ms(const JsonAt& at) {
    auto ms = millis(at);
    if (ms <= 0) at.fail("must be more than 0", "write a period or duration in milliseconds, e.g. 1000");
    return ms;
}

// The one key that names the step's kind.
std::string kind_of(const JsonAt& at) {
    static constexpr std::string_view kinds[] = {"set", "increment", "ramp", "sine", "square", "random_walk", "copy",
                                                 "ondemand"};
    std::string found;
    for (auto k : kinds) {
        if (!at.has(k)) continue;
        if (!found.empty()) at.fail("the step has both \"" + found + "\" and \"" + std::string(k) + "\"", "split it into two steps");
        found = k;
    }
    if (found.empty())
        at.fail("the step does nothing", "give it one of \"set\", \"increment\", \"ramp\", \"sine\", \"square\", \"random_walk\", \"copy\", \"ondemand\"");
    return found;
}

Step step(const JsonAt& at, double previous_end) {
    at.expect_object();
    Step s;
    s.pointer = at.pointer();
    const auto kind = kind_of(at);
    if (at.has("at_ms") && at.has("after_ms")) at.fail("both \"at_ms\" and \"after_ms\"", "give one: a time from the start, or a wait after the previous step");
    s.start_ms = at.has("at_ms") ? millis(at["at_ms"]) : previous_end + (at.has("after_ms") ? millis(at["after_ms"]) : 0);
    auto lasting = [&] { return at.has("for_ms") ? positive_ms(at["for_ms"]) : kForever; };

    if (kind == "set") {
        at.only_keys({"set", "at_ms", "after_ms"});
        auto set = set_values(at["set"]);
        s.action = SetStep{std::move(set.devices), std::move(set.labels)};
    } else if (kind == "increment") {
        at.only_keys({"increment", "by", "as", "at_ms", "after_ms"});
        IncrementStep i{device(at["increment"], at), 1};
        if (at.has("by")) i.by = value(at["by"]);
        s.action = i;
    } else if (kind == "ramp") {
        at.only_keys({"ramp", "from", "to", "over_ms", "as", "at_ms", "after_ms"});
        s.action = RampStep{device(at["ramp"], at), value(at["from"]), value(at["to"])};
        s.duration_ms = positive_ms(at["over_ms"]);
    } else if (kind == "sine") {
        at.only_keys({"sine", "center", "amplitude", "period_ms", "for_ms", "as", "at_ms", "after_ms"});
        SineStep w{device(at["sine"], at), 0, value(at["amplitude"]), positive_ms(at["period_ms"])};
        if (at.has("center")) w.center = value(at["center"]);
        s.action = w;
        s.duration_ms = lasting();
    } else if (kind == "square") {
        at.only_keys({"square", "low", "high", "period_ms", "duty", "for_ms", "as", "at_ms", "after_ms"});
        SquareStep w{device(at["square"], at), 0, 1, positive_ms(at["period_ms"]), 0.5};
        if (at.has("low")) w.low = value(at["low"]);
        if (at.has("high")) w.high = value(at["high"]);
        if (at.has("duty")) w.duty = probability(at["duty"]);
        s.action = w;
        s.duration_ms = lasting();
    } else if (kind == "random_walk") {
        at.only_keys({"random_walk", "start", "min", "max", "step", "every_ms", "for_ms", "as", "at_ms", "after_ms"});
        RandomWalkStep w{device(at["random_walk"], at), 0, value(at["min"]), value(at["max"]), 1, 100};
        if (w.max < w.min) at["max"].fail("max is below min", "write min <= max");
        w.start = at.has("start") ? value(at["start"]) : (w.min + w.max) / 2;
        if (w.start < w.min || w.start > w.max) at["start"].fail("start is outside [min, max]", "start between min and max");
        if (at.has("step")) w.step = number(at["step"], 0, kBig, "write the largest change per move, e.g. 2");
        if (at.has("every_ms")) w.every_ms = positive_ms(at["every_ms"]);
        s.action = w;
        s.duration_ms = lasting();
    } else if (kind == "ondemand") {
        at.only_keys({"ondemand", "at_ms", "after_ms"});
        s.action = ondemand(at["ondemand"]);
    } else {   // copy
        at.only_keys({"copy", "to", "points", "at_ms", "after_ms"});
        CopyStep c{address(at["copy"]), address(at["to"]), 1};
        if (at.has("points")) {
            c.points = static_cast<std::uint32_t>(at["points"].unsigned_int(65535));
            if (c.points == 0) at["points"].fail("copies nothing", "write 1 or more");
        }
        if ((c.from.spec->unit == devicemodel::Unit::Bit) != (c.to.spec->unit == devicemodel::Unit::Bit))
            at["to"].fail("copies between a bit device and a word device", "copy bits to bits and words to words");
        s.action = c;
    }
    return s;
}

}  // namespace

Timeline timeline(const JsonAt& at) {
    at.only_keys({"steps", "duration_ms", "loop"});
    Timeline t;
    auto steps = at["steps"];
    steps.expect_array();
    double previous_end = 0;
    for (std::size_t i = 0; i < steps.json().size(); ++i) {
        t.steps.push_back(step(steps[i], previous_end));
        const auto& s = t.steps.back();
        previous_end = s.start_ms + (s.duration_ms == kForever ? 0 : s.duration_ms);
    }
    if (at.has("duration_ms")) {
        t.duration_ms = positive_ms(at["duration_ms"]);
        for (const auto& s : t.steps)
            if (s.start_ms > t.duration_ms)
                at["duration_ms"].fail("step " + s.pointer + " starts at " + std::to_string(static_cast<long long>(s.start_ms)) +
                                           " ms, after the pass ends", "make duration_ms longer or start the step earlier");
    }
    if (at.has("loop")) {
        auto loop = at["loop"];
        if (loop.json().is_boolean()) t.loops = loop.boolean() ? 0 : 1;
        else if ((t.loops = loop.unsigned_int(1000000000)) == 0) loop.fail("0 passes", "write true (forever), false or a number of passes");
    }
    if (t.loops != 1 && t.duration_ms == 0) {
        // A pass ends when its last step ends; a step that lasts forever leaves no end.
        for (const auto& s : t.steps)
            if (s.duration_ms == kForever)
                at.fail("a looping timeline with a step that never ends (" + s.pointer + ")", "give \"duration_ms\" (the length of one pass) or \"for_ms\" to that step");
        for (const auto& s : t.steps) t.duration_ms = std::max(t.duration_ms, s.start_ms + s.duration_ms);
        if (t.duration_ms == 0) at.fail("a looping timeline whose pass lasts 0 ms", "give \"duration_ms\"");
    }
    return t;
}

}  // namespace slmp::scenarios::load
