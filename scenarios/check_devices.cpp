#include "scenarios/check_devices.hpp"

#include "config/config.hpp"
#include "devicemodel/overloaded.hpp"
#include "scenarios/device_values.hpp"

namespace slmp::scenarios {
namespace {

using devicemodel::overloaded;

struct Checker {
    const Scenario& scenario;
    const devicemodel::DeviceMemory& memory;
    const std::string& profile;

    void fits(const devicemodel::DeviceAddress& a, std::uint32_t count, const std::string& pointer) const {
        if (scenarios::fits(memory, a, count)) return;
        auto area = std::string(devicemodel::area_name(a.spec->area));
        throw config::ConfigError(scenario.source + ": " + pointer + ": " + devicemodel::format_address(a) +
                                  (count > 1 ? " with " + std::to_string(count) + " device(s)" : std::string()) +
                                  " is outside the " + area + " size of " + std::to_string(memory.size(a.spec->area)) +
                                  " in profile " + profile + "; use a smaller device number or raise device_sizes");
    }
    void fits(const DeviceRef& d, const std::string& pointer) const {
        if (d.label.empty()) fits(d.address, devices_per_value(d), pointer);   // a label was checked when declared
    }
    void fits(const std::vector<config::InitialValue>& values, const std::string& pointer) const {
        for (const auto& v : values) fits(v.address, static_cast<std::uint32_t>(v.values.size()), pointer);
    }
    void fits(const Operand& o, const std::string& pointer) const {
        if (o.device) fits(*o.device, pointer);
    }
};

}  // namespace

void check_devices(const Scenario& s, const devicemodel::DeviceMemory& memory, const std::string& profile) {
    Checker c{s, memory, profile};
    c.fits(s.initial.devices, "/initial/devices");
    for (const auto& step : s.timeline.steps)
        std::visit(overloaded{
                       [&](const SetStep& x) { c.fits(x.values, step.pointer); },
                       [&](const CopyStep& x) {
                           c.fits(x.from, x.points, step.pointer + "/copy");
                           c.fits(x.to, x.points, step.pointer + "/to");
                       },
                       [&](const OndemandAction& x) { c.fits(x.first, x.points, step.pointer + "/ondemand"); },
                       [&](const auto& x) { c.fits(x.device, step.pointer); },
                   },
                   step.action);
    for (const auto& t : s.triggers) {
        if (const auto* d = std::get_if<DeviceCondition>(&t.when)) {
            c.fits(d->left, t.pointer + "/when");
            c.fits(d->right, t.pointer + "/when");
        }
        for (std::size_t i = 0; i < t.actions.size(); ++i) {
            auto pointer = t.pointer + "/do/" + std::to_string(i);
            std::visit(overloaded{
                           [&](const SetAction& a) { c.fits(a.values, pointer); },
                           [&](const IncrementAction& a) { c.fits(a.device, pointer); },
                           [&](const PulseAction& a) { c.fits(a.device, 1, pointer); },
                           [&](const OndemandAction& a) { c.fits(a.first, a.points, pointer + "/ondemand"); },
                           [](const auto&) {},
                       },
                       t.actions[i]);
        }
    }
    for (const auto& rung : s.logic.rungs)
        for (const auto& ins : rung.code)
            for (const auto& o : ins.operands)
                if (o.device) c.fits(*o.device, 1, rung.pointer);
}

}  // namespace slmp::scenarios
