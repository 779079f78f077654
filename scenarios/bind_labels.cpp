#include "scenarios/bind_labels.hpp"

#include <cctype>

#include "config/config_error.hpp"
#include "devicemodel/overloaded.hpp"

namespace slmp::scenarios {
namespace {

using devicemodel::BasicType;

// How a number is stored in a label of this basic type; none for strings and
// LREAL, which scenarios do not drive.
std::optional<ValueFormat> format_of(BasicType type) {
    switch (type) {
        case BasicType::Bit:
        case BasicType::Word:
        case BasicType::UWord: return ValueFormat::Int16;
        case BasicType::DWord:
        case BasicType::UDWord:
        case BasicType::Time: return ValueFormat::Int32;
        case BasicType::Real: return ValueFormat::Float32;
        default: return std::nullopt;
    }
}

// "D1O0" (a device symbol, then a digit, letters and digits only) is more
// likely a mistyped device than a label: say what the device parser found.
bool looks_like_device(const std::string& text) {
    auto letters = text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz");
    if (letters == 0 || letters == std::string::npos || !std::isdigit(static_cast<unsigned char>(text[letters]))) return false;
    if (text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789") != std::string::npos) return false;
    return devicemodel::parse_address(text.substr(0, letters) + "0").has_value();
}

struct Binder {
    const Scenario& scenario;
    const devicemodel::LabelTable& labels;

    [[noreturn]] void fail(const std::string& where, const std::string& problem, const std::string& fix) const {
        throw config::ConfigError(scenario.source + ": " + where + ": " + problem + "; " + fix);
    }

    void bind(DeviceRef& ref, const std::string& where, bool bit_only = false) const {
        if (ref.label.empty()) return;
        devicemodel::LabelFault fault{};
        // The simulator drives its own labels, external access or not.
        auto resolved = labels.resolve(ref.label, {}, fault, /*external_only=*/false);
        if (!resolved) {
            std::string device_error;
            devicemodel::parse_address(ref.label, &device_error);
            fail(where, "'" + ref.label + "' is neither a device nor a global label (" +
                            std::string(devicemodel::describe(fault)) + ")" + (looks_like_device(ref.label) ? "; as a device: " + device_error : ""),
                 "name a device such as D100, or declare the label in \"labels\" / --labels (docs/labels.md)");
        }
        auto format = format_of(resolved->basic);
        devicemodel::LabelType type{};
        type.basic = resolved->basic;
        type.chars = resolved->chars;
        if (!format)
            fail(where, "label '" + ref.label + "' is of type " + devicemodel::format_label_type(type) +
                            ", which a scenario cannot write numbers to",
                 "drive a Bit, Word, Double Word, FLOAT [Single Precision] or Time label (or an element or member of one)");
        if (bit_only && resolved->basic != BasicType::Bit)
            fail(where, "label '" + ref.label + "' is of type " + devicemodel::format_label_type(type) + ", not Bit",
                 "name a Bit label or a bit device for \"rising\" / \"falling\"");
        ref.format = *format;
        ref.bound = *resolved;
    }
    void bind(std::optional<DeviceRef>& ref, const std::string& where) const {
        if (ref) bind(*ref, where);
    }
    void bind(std::vector<LabelValue>& values, const std::string& where) const {
        for (auto& v : values) bind(v.target, where + "/" + v.target.label);
    }

    // A contact or coil takes a Bit label, a 16-bit word operand a Word label,
    // RST either (as RST D0 / RST M0); other operand types are the engine's to
    // check when it compiles the rungs (docs/program.md: labels as operands).
    void bind(RungOperand& o, const std::string& where) const {
        if (!o.label) return;
        DeviceRef ref{{}, ValueFormat::Int16, o.text};
        bind(ref, where);
        if (o.use == RungOperand::Use::Other) return;
        const auto basic = ref.bound->basic;
        const bool word = basic == BasicType::Word || basic == BasicType::UWord;
        const bool bit = basic == BasicType::Bit;
        const bool needs_bit = o.use == RungOperand::Use::Bit || (o.use == RungOperand::Use::Either && !word);
        if (needs_bit ? bit : word) return;
        devicemodel::LabelType type{};
        type.basic = basic;
        fail(where, "label '" + o.text + "' is of type " + devicemodel::format_label_type(type) + ", where the rung needs " +
                        (needs_bit ? "a bit" : "a 16-bit word"),
             needs_bit ? "name a Bit label or a bit device here" : "name a Word [Signed] or Word [Unsigned] label, or a word device");
    }
};

using devicemodel::overloaded;

}  // namespace

void bind_labels(Scenario& s, const devicemodel::LabelTable& labels) {
    const Binder b{s, labels};
    for (auto& step : s.timeline.steps)
        std::visit(overloaded{
                       [&](SetStep& x) { b.bind(x.labels, step.pointer + "/set"); },
                       [](CopyStep&) {},
                       [](OndemandAction&) {},   // devices only
                       [&](auto& x) { b.bind(x.device, step.pointer); },
                   },
                   step.action);
    for (auto& t : s.triggers) {
        if (auto* d = std::get_if<DeviceCondition>(&t.when)) {
            if (d->kind == DeviceCondition::Kind::Compare) {
                b.bind(d->left.device, t.pointer + "/when");
                b.bind(d->right.device, t.pointer + "/when");
            } else {
                b.bind(*d->left.device, t.pointer + "/when", /*bit_only=*/true);
            }
        }
        for (std::size_t i = 0; i < t.actions.size(); ++i) {
            auto where = t.pointer + "/do/" + std::to_string(i);
            std::visit(overloaded{
                           [&](SetAction& a) { b.bind(a.labels, where + "/set"); },
                           [&](IncrementAction& a) { b.bind(a.device, where); },
                           [](auto&) {},
                       },
                       t.actions[i]);
        }
    }
    for (auto& rung : s.logic.rungs)
        for (auto& ins : rung.code)
            for (auto& o : ins.operands) b.bind(o, rung.pointer);
}

}  // namespace slmp::scenarios
