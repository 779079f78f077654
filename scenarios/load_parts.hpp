// Pieces of the scenario loader shared by its files (not for other modules).
#pragma once

#include <string_view>
#include <vector>

#include "config/json_path.hpp"
#include "scenarios/scenario.hpp"

namespace slmp::scenarios::load {

using config::JsonAt;

// A number within [min, max]; `fix` tells how to write a good one.
double number(const JsonAt& at, double min, double max, std::string_view fix);
// Milliseconds: a number from 0 to one day.
double millis(const JsonAt& at);
// A probability from 0 to 1.
double probability(const JsonAt& at);

devicemodel::DeviceAddress address(const JsonAt& at);
// The sibling key "as" of `owner` for a device: int16 (default), int32, float.
ValueFormat value_format(const JsonAt& owner, const devicemodel::DeviceAddress& device);
// Whether text that is not a device could be a label name (letter or '_' first).
bool may_be_label(std::string_view text);
// "D100" with the sibling key "as" ("int16", "int32", "float") of `owner`, or a
// label name ("Tank1.Level"), left for bind_labels() to resolve.
DeviceRef device(const JsonAt& at, const JsonAt& owner);
// "set": {"D100": 5, "M0": 1, "Tank1.Level": 50}: devices as the config's
// "devices" writes them, labels with one number each.
struct SetValues {
    std::vector<config::InitialValue> devices;
    std::vector<LabelValue> labels;
};
SetValues set_values(const JsonAt& at);
// "D100-D199", "X0-X1F" or a single "D100"; or a list of them.
std::vector<DeviceRange> ranges(const JsonAt& at);
// "0401" or ["0401", "1401"].
std::vector<std::uint16_t> codes(const JsonAt& at);
// "RUN" / "STOP".
devicemodel::RunSwitch run_switch(const JsonAt& at);
// {"code": "3100", "stop": true}
devicemodel::CpuError cpu_error(const JsonAt& at);
// {"data": "D100-D109", "to": "all"}: an Ondemand step or action.
OndemandAction ondemand(const JsonAt& at);
// "read" / "write"
Access access(const JsonAt& at);

Timeline timeline(const JsonAt& at);
std::vector<Trigger> triggers(const JsonAt& at);
std::vector<Fault> faults(const JsonAt& at);

}  // namespace slmp::scenarios::load
