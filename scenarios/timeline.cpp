#include "scenarios/timeline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "devicemodel/overloaded.hpp"
#include "scenarios/device_values.hpp"
#include "scenarios/runner.hpp"

namespace slmp::scenarios {
namespace {

using devicemodel::overloaded;

void copy_devices(devicemodel::DeviceMemory& memory, const CopyStep& c) {
    // Read everything first: an overlapping copy moves the old values, as BMOV does.
    std::vector<std::uint32_t> values;
    for (std::uint32_t i = 0; i < c.points; ++i) values.push_back(memory.value(*c.from.spec, c.from.number + i));
    for (std::uint32_t i = 0; i < c.points; ++i) memory.set_value(*c.to.spec, c.to.number + i, values[i]);
}

}  // namespace

void apply_values(devicemodel::DeviceMemory& memory, const std::vector<config::InitialValue>& values,
                  const std::vector<LabelValue>& labels) {
    for (const auto& v : values)
        for (std::size_t i = 0; i < v.values.size(); ++i)
            memory.set_value(*v.address.spec, v.address.number + static_cast<std::uint32_t>(i), v.values[i]);
    for (const auto& l : labels) write_number(memory, l.target, l.value);
}

TimelineRunner::TimelineRunner(const Timeline& timeline, std::uint64_t seed, Station* station)
    : timeline_(timeline), station_(station) {
    for (std::size_t i = 0; i < timeline.steps.size(); ++i) walks_.push_back(Walk{Rng(Rng::stream(seed, 1000 + i))});
}

void TimelineRunner::advance(devicemodel::DeviceMemory& memory, double now_ms, const EventSink& log) {
    if (finished_ || (last_ms_ >= 0 && now_ms <= last_ms_)) return;
    const double pass_ms = timeline_.duration_ms;
    if (pass_ms == 0) {   // one endless pass
        window(memory, 0, last_ms_, now_ms, true, log);
        last_ms_ = now_ms;
        return;
    }
    const double end_ms = timeline_.loops == 0 ? kForever : static_cast<double>(timeline_.loops) * pass_ms;
    const double to = std::min(now_ms, end_ms);
    auto first = last_ms_ < 0 ? std::int64_t{0} : static_cast<std::int64_t>(std::floor(last_ms_ / pass_ms));
    auto last = static_cast<std::int64_t>(std::floor(to / pass_ms));
    if (to >= end_ms) last = static_cast<std::int64_t>(timeline_.loops) - 1;   // the final pass ends exactly at end_ms
    for (auto pass = first; pass <= last; ++pass) {
        double base = static_cast<double>(pass) * pass_ms;
        double from = pass == first && last_ms_ >= 0 ? last_ms_ - base : -1;
        double until = pass == last ? to - base : pass_ms;
        window(memory, pass, from, until, pass == last && to < end_ms, log);
    }
    last_ms_ = now_ms;
    if (now_ms >= end_ms) {
        finished_ = true;
        if (log) log(EventLevel::Info, "timeline finished after " + std::to_string(timeline_.loops) + " pass(es)");
    }
}

// Applies what happens in (from, to] of one pass. `current`: `to` is now, so
// lasting steps write their present value; otherwise only their ends count.
void TimelineRunner::window(devicemodel::DeviceMemory& memory, std::int64_t pass, double from, double to, bool current,
                            const EventSink& log) {
    const double pass_ms = timeline_.duration_ms == 0 ? kForever : timeline_.duration_ms;
    for (std::size_t i = 0; i < timeline_.steps.size(); ++i) {
        const auto& step = timeline_.steps[i];
        if (step.duration_ms == 0) {
            if (step.start_ms > from && step.start_ms <= to) instant(memory, step, log);
            continue;
        }
        const double end = std::min(step.start_ms + step.duration_ms, pass_ms);
        if (current && step.start_ms <= to && to < end)
            lasting(memory, i, pass, to - step.start_ms);
        else if (end > from && end <= to && step.start_ms + step.duration_ms <= pass_ms)
            lasting(memory, i, pass, step.duration_ms);   // the step ended in this window: its final value
    }
}

void TimelineRunner::instant(devicemodel::DeviceMemory& memory, const Step& step, const EventSink& log) {
    std::visit(overloaded{
                   [&](const SetStep& s) { apply_values(memory, s.values, s.labels); },
                   [&](const IncrementStep& s) { write_number(memory, s.device, read_number(memory, s.device) + s.by); },
                   [&](const CopyStep& s) { copy_devices(memory, s); },
                   [&](const OndemandAction& s) {
                       if (station_) station_->ondemand(s, "timeline " + step.pointer);
                   },
                   [](const auto&) {},
               },
               step.action);
    if (log) log(EventLevel::Debug, "timeline " + step.pointer);
}

void TimelineRunner::lasting(devicemodel::DeviceMemory& memory, std::size_t index, std::int64_t pass, double t) {
    const auto& step = timeline_.steps[index];
    std::visit(overloaded{
                   [&](const RampStep& s) {
                       double f = std::min(t / step.duration_ms, 1.0);
                       write_number(memory, s.device, s.from + (s.to - s.from) * f);
                   },
                   [&](const SineStep& s) {
                       write_number(memory, s.device, s.center + s.amplitude * std::sin(2 * std::numbers::pi * t / s.period_ms));
                   },
                   [&](const SquareStep& s) {
                       double phase = std::fmod(t, s.period_ms) / s.period_ms;
                       write_number(memory, s.device, phase < s.duty ? s.high : s.low);
                   },
                   [&](const RandomWalkStep& s) {
                       walk_to(index, pass, t);
                       write_number(memory, s.device, walks_[index].value);
                   },
                   [](const auto&) {},
               },
               step.action);
}

// Makes every move due by `t` (moves at every_ms, 2·every_ms, ...), so the
// walk is the same whatever the scan time.
void TimelineRunner::walk_to(std::size_t index, std::int64_t pass, double t) {
    const auto& s = std::get<RandomWalkStep>(timeline_.steps[index].action);
    auto& w = walks_[index];
    if (w.pass != pass) {
        w.pass = pass;
        w.moves = 0;
        w.value = s.start;
    }
    auto due = static_cast<std::uint64_t>(std::floor(t / s.every_ms));
    for (; w.moves < due; ++w.moves) w.value = std::clamp(w.value + w.rng.between(-s.step, s.step), s.min, s.max);
}

}  // namespace slmp::scenarios
