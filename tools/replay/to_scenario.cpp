// slmp-replay --to-scenario (to_scenario.hpp).
#include "tools/replay/to_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "devicemodel/cpu.hpp"
#include "devicemodel/hex.hpp"
#include "protocol/client.hpp"
#include "protocol/engine.hpp"

namespace slmp::replay {

using devicemodel::DeviceAddress;
using nlohmann::json;
using protocol::DeviceOperand;

namespace {

// One device's value as a read showed it (a bit: 0/1).
struct Seen {
    DeviceAddress device;
    std::uint16_t value = 0;
};

// A device in a map: by its table row and number.
struct DeviceKey {
    const devicemodel::DeviceSpec* spec;
    std::uint32_t number;
    friend bool operator<(const DeviceKey& a, const DeviceKey& b) {
        return a.spec != b.spec ? a.spec < b.spec : a.number < b.number;
    }
};

// The values one operand's `words` (its share of the answer) show: a word
// device one word a device; a bit device read in words 16 bits a word, the
// lowest first; a bit device in bit units one bit a point.
void spread(const DeviceOperand& operand, const std::vector<std::uint16_t>& words, std::vector<Seen>& out) {
    const auto* spec = operand.field.spec;
    const auto first = operand.field.number;
    if (spec->unit == devicemodel::Unit::Bit) {
        for (std::size_t w = 0; w < words.size(); ++w)
            for (unsigned bit = 0; bit < 16; ++bit)
                out.push_back({{spec, first + static_cast<std::uint32_t>(16 * w + bit)},
                               static_cast<std::uint16_t>(words[w] >> bit & 1)});
        return;
    }
    for (std::size_t w = 0; w < words.size(); ++w) out.push_back({{spec, first + static_cast<std::uint32_t>(w)}, words[w]});
}

// Why an operand's values cannot be set by a scenario as they were read; empty: they can.
std::string unusable(const DeviceOperand& operand) {
    const auto& field = operand.field;
    if (!field.spec) return "an unknown device";
    if (field.extended || field.extension.kind != protocol::DeviceExtension::Kind::None ||
        field.extension.device_modifier.reg != protocol::Modifier::Register::None || field.extension.indirect)
        return "an extended, indexed or indirect device (008x)";
    if (field.spec->unit != devicemodel::Unit::Bit && devicemodel::words_per_device(*field.spec) != 1)
        return "a device of more than one word (" + std::string(field.spec->symbol) + ")";
    return {};
}

// The values a read request and its 0000 answer show; nullopt and `why` when
// it shows none this tool takes.
std::optional<std::vector<Seen>> values_read(const protocol::Request& request, const protocol::client::Response& answer,
                                             std::string& why) {
    const auto& devices = request.operands.devices;
    auto reader = answer.reader();
    std::vector<Seen> seen;
    for (const auto& operand : devices) {
        if (auto problem = unusable(operand); !problem.empty()) {
            why = "naming " + problem;
            return std::nullopt;
        }
    }
    if (request.command == 0x0401) {
        if (devices.size() != 1) {
            why = "a batch read that did not decode";
            return std::nullopt;
        }
        const auto& operand = devices.front();
        if (operand.unit == DeviceOperand::Unit::Bit) {
            auto bits = reader.bits(operand.points, "bits");
            if (!reader.ok()) {
                why = "an answer shorter than its points";
                return std::nullopt;
            }
            for (std::size_t i = 0; i < bits.size(); ++i)
                seen.push_back({{operand.field.spec, operand.field.number + static_cast<std::uint32_t>(i)}, bits[i]});
        } else {
            auto words = reader.words(operand.points, "words");
            if (!reader.ok()) {
                why = "an answer shorter than its points";
                return std::nullopt;
            }
            spread(operand, words, seen);
        }
        return seen;
    }
    // 0403: the word devices' values, then the double words' (low word first); each names one point.
    for (auto unit : {DeviceOperand::Unit::Word, DeviceOperand::Unit::DoubleWord}) {
        for (const auto& operand : devices) {
            if (operand.unit != unit) continue;
            auto words = reader.words(unit == DeviceOperand::Unit::Word ? 1 : 2, "words");
            if (!reader.ok()) {
                why = "an answer shorter than its points";
                return std::nullopt;
            }
            spread(operand, words, seen);
        }
    }
    return seen;
}

// One device's value as one read showed it, at whole ms from the first exchange.
struct Observation {
    std::int64_t at_ms = 0;
    std::uint16_t value = 0;
};

// The value a scenario `ramp` from `from` at 0 ms to `to` at `over_ms` writes
// at `t` ms: the timeline's formula, rounded as a word is written
// (scenarios/timeline.cpp, scenarios/device_values.cpp).
double ramp_value(double from, double to, double over_ms, double t) {
    return std::round(from + (to - from) * std::min(t / over_ms, 1.0));
}

// Whether a ramp from observation `first` to observation `last` shows every
// read in between exactly as it was read: then it replays the same reads.
bool on_one_ramp(const std::vector<Observation>& seen, std::size_t first, std::size_t last) {
    const auto& a = seen[first];
    const auto& b = seen[last];
    const double over = static_cast<double>(b.at_ms - a.at_ms);
    for (std::size_t i = first + 1; i < last; ++i)
        if (ramp_value(a.value, b.value, over, static_cast<double>(seen[i].at_ms - a.at_ms)) != seen[i].value) return false;
    return true;
}

// The furthest observation a ramp from `first` can end on — three or more
// distinct values read on one line (two changes or more in one direction:
// a value that moved, not one that jumped) — or `first` when there is none.
std::size_t ramp_end(const std::vector<Observation>& seen, std::size_t first) {
    std::size_t end = first;
    for (std::size_t last = first + 2; last < seen.size() && on_one_ramp(seen, first, last); ++last) {
        const auto low = std::min(seen[first].value, seen[last].value);
        const auto high = std::max(seen[first].value, seen[last].value);
        const bool between = std::any_of(seen.begin() + static_cast<std::ptrdiff_t>(first) + 1,
                                         seen.begin() + static_cast<std::ptrdiff_t>(last),
                                         [&](const Observation& o) { return o.value > low && o.value < high; });
        if (between) end = last;
    }
    return end;
}

}  // namespace

ScenarioFromRecording to_scenario(const scenarios::Recording& recording, const config::Profile& profile,
                                  const std::string& name) {
    ScenarioFromRecording result;
    devicemodel::Cpu cpu(profile.cpu);   // decoding touches no memory; the engine wants a CPU to decode for
    protocol::Engine engine(cpu, profile.port, protocol::EngineOptions{1u << 20});
    const auto numbering = profile.cpu.numbering;

    // Each device's values in the order they were read; of two reads in one ms the later.
    std::map<DeviceKey, std::vector<Observation>> seen;
    std::map<DeviceKey, std::string> names;
    const double start = recording.exchanges.empty() ? 0 : recording.exchanges.front().t_ms;
    for (const auto& exchange : recording.exchanges) {
        auto request = engine.decode(exchange.request, protocol::DataCodePolicy::Auto);
        if (!request.complete() || !request.has_command) continue;
        if (request.command != 0x0401 && request.command != 0x0403) continue;
        auto skip = [&](const std::string& why) { ++result.skipped[why]; };
        if (request.header.kind == protocol::FrameKind::E1) {   // its answer has another shape
            skip("a 1E frame");
            continue;
        }
        if (request.elsewhere || request.route_error != protocol::EndCode::Ok) {
            skip("addressed to another station");
            continue;
        }
        if (request.operands.error != protocol::EndCode::Ok) {
            skip("refused when decoded (" + devicemodel::hex4(static_cast<std::uint16_t>(request.operands.error)) + ")");
            continue;
        }
        if (!exchange.response) {
            skip("not answered");
            continue;
        }
        auto answer = protocol::client::parse_response(*exchange.response);
        if (!answer) {
            skip("an answer that is no response frame");
            continue;
        }
        if (answer->end_code != 0) {
            skip("answered " + devicemodel::hex4(answer->end_code));
            continue;
        }
        std::string why;
        auto values = values_read(request, *answer, why);
        if (!values) {
            skip(why);
            continue;
        }
        ++result.reads;
        // Whole ms from the first exchange, rounded down: a step is in place when the read was made.
        const auto at = static_cast<std::int64_t>(std::floor(exchange.t_ms - start));
        for (const auto& v : *values) {
            DeviceKey key{v.device.spec, v.device.number};
            auto& name_of = names[key];
            if (name_of.empty()) name_of = devicemodel::format_address(v.device, numbering);
            auto& reads = seen[key];
            if (!reads.empty() && reads.back().at_ms == at) reads.back().value = v.value;
            else reads.push_back({at, v.value});
        }
    }
    // Per device: its first value is its initial value; then, from each read
    // on, a ramp where the next reads lie on one (the value moved linearly
    // between them), else a `set` where the next read shows another value.
    json initial = json::object();
    std::map<std::int64_t, json> sets;   // by at_ms: the devices set then
    std::vector<json> ramps;
    for (const auto& [key, reads] : seen) {
        const auto& device = names[key];
        initial[device] = reads.front().value;
        for (std::size_t i = 0; i + 1 < reads.size();) {
            if (auto end = ramp_end(reads, i); end != i) {
                ramps.push_back(json{{"at_ms", reads[i].at_ms}, {"ramp", device}, {"from", reads[i].value},
                                     {"to", reads[end].value}, {"over_ms", reads[end].at_ms - reads[i].at_ms}});
                i = end;
                continue;
            }
            if (reads[i + 1].value != reads[i].value) sets[reads[i + 1].at_ms][device] = reads[i + 1].value;
            ++i;
        }
    }
    // The steps in time order; at one time the values set first, then the ramps (by device).
    json steps = json::array();
    auto at_of = [](const json& step) { return step["at_ms"].get<std::int64_t>(); };
    std::sort(ramps.begin(), ramps.end(), [&](const json& a, const json& b) {
        return at_of(a) != at_of(b) ? at_of(a) < at_of(b) : a["ramp"].get<std::string>() < b["ramp"].get<std::string>();
    });
    auto ramp = ramps.begin();
    for (auto& [at, set] : sets) {
        for (; ramp != ramps.end() && at_of(*ramp) < at; ++ramp) steps.push_back(*ramp);
        steps.push_back(json{{"at_ms", at}, {"set", std::move(set)}});
    }
    for (; ramp != ramps.end(); ++ramp) steps.push_back(*ramp);
    result.devices = seen.size();
    result.steps = steps.size();
    result.ramps = ramps.size();
    auto& s = result.scenario;
    s["name"] = name;
    s["description"] = "What the clients of a recorded session read (" + std::to_string(result.reads) + " read(s) of " +
                       std::to_string(result.devices) + " device(s), recorded with profile " +
                       (recording.profile.empty() ? std::string("unknown") : recording.profile) +
                       "): each device's first value, then each change at the time a read showed it, as a ramp "
                       "where the reads lie on one (slmp-replay --to-scenario)";
    if (!initial.empty()) s["initial"] = json{{"devices", std::move(initial)}};
    if (!steps.empty()) s["timeline"] = json{{"steps", std::move(steps)}};
    return result;
}

}  // namespace slmp::replay
