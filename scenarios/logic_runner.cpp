// Evaluating the rung language (logic.hpp) with MELSEC's block stack: LD
// pushes a block, AND/OR change the top one, ANB/ORB join the top two, an
// output uses the top one. Word arithmetic is 16-bit signed and wraps, as the
// CPU's BIN 16-bit instructions do.
#include "scenarios/logic.hpp"

namespace slmp::scenarios {
namespace {

using devicemodel::DeviceMemory;
using devicemodel::DeviceSpec;
using devicemodel::Part;

const DeviceSpec* part_of(devicemodel::Area area, Part part) {
    for (const auto& spec : devicemodel::all_devices())
        if (spec.area == area && spec.part == part) return &spec;
    return nullptr;
}

// Operands are devices or bound labels (one word or one bit, devicemodel's
// element access wherever the label lives).
std::int16_t read_word(const DeviceMemory& memory, const LogicOperand& o) {
    if (o.kind == LogicOperand::Kind::Constant) return static_cast<std::int16_t>(o.constant);
    if (o.bound) return static_cast<std::int16_t>(devicemodel::read_element(memory, *o.bound, 0)[0]);
    return static_cast<std::int16_t>(memory.value(*o.device.spec, o.device.number) & 0xFFFF);
}

void write_word(DeviceMemory& memory, const LogicOperand& o, std::int32_t value) {
    const std::uint16_t word = static_cast<std::uint16_t>(value);
    if (o.bound) return devicemodel::write_element(memory, *o.bound, 0, std::span(&word, 1));
    memory.set_value(*o.device.spec, o.device.number, word);
}

bool read_bit(const DeviceMemory& memory, const LogicOperand& o) {
    if (o.bound) return devicemodel::read_element(memory, *o.bound, 0)[0] & 1;
    return memory.bit(*o.device.spec, o.device.number);
}

void write_bit(DeviceMemory& memory, const LogicOperand& o, bool on) {
    if (o.bound) return write_word(memory, o, on ? 1 : 0);
    memory.set_bit(*o.device.spec, o.device.number, on);
}

}  // namespace

LogicRunner::LogicRunner(const LogicProgram& program) : program_(program), memory_(program.memory_slots) {
    timers_.configure(program.timers, program.counters);
}

void LogicRunner::stopped() {
    std::fill(memory_.begin(), memory_.end(), 0);
    timers_.reset_tracking();
}

bool LogicRunner::contact(const DeviceMemory& memory, const Instruction& ins) {
    if (ins.contact == Contact::Compare)
        return compare(read_word(memory, ins.operands[0]), ins.compare, read_word(memory, ins.operands[1]));
    bool on = read_bit(memory, ins.operands[0]);
    switch (ins.contact) {
        case Contact::Normal: return on;
        case Contact::Inverted: return !on;
        case Contact::Rising:
        case Contact::Falling: {
            bool before = memory_[ins.memory] != 0;
            memory_[ins.memory] = on ? 1 : 0;
            return ins.contact == Contact::Rising ? on && !before : !on && before;
        }
        case Contact::Compare: break;
    }
    return false;
}

void LogicRunner::output(DeviceMemory& memory, const Instruction& ins, bool power) {
    if (ins.pulse) {   // P forms run on the rung's rising edge only
        bool before = memory_[ins.memory] != 0;
        memory_[ins.memory] = power ? 1 : 0;
        power = power && !before;
    }
    const auto& o = ins.operands.empty() ? LogicOperand{} : ins.operands.back();
    switch (ins.op) {
        case LogicOp::Out:
            write_bit(memory, o, power);   // a bit, or a T/ST/C coil
            return;
        case LogicOp::Set:
            if (power) write_bit(memory, o, true);
            return;
        case LogicOp::Reset:
            if (!power) return;
            if (o.kind == LogicOperand::Kind::Timer) {   // RST T0 / C0: value 0, contact off
                auto area = o.device.spec->area;
                memory.set_value(*part_of(area, Part::Value), o.device.number, 0);
                memory.set_bit(*part_of(area, Part::Contact), o.device.number, false);
            } else if (o.kind == LogicOperand::Kind::Word) {
                write_word(memory, o, 0);
            } else {
                write_bit(memory, o, false);
            }
            return;
        case LogicOp::Move:
            if (power) write_word(memory, o, read_word(memory, ins.operands[0]));
            return;
        case LogicOp::Add:
        case LogicOp::Sub: {
            if (!power) return;
            std::int32_t a = read_word(memory, ins.operands[0]), b = read_word(memory, ins.operands[1]);
            write_word(memory, o, ins.op == LogicOp::Add ? a + b : a - b);
            return;
        }
        case LogicOp::Inc:
        case LogicOp::Dec:
            if (power) write_word(memory, o, read_word(memory, o) + (ins.op == LogicOp::Inc ? 1 : -1));
            return;
        default: return;
    }
}

void LogicRunner::scan(DeviceMemory& memory, std::chrono::microseconds elapsed) {
    std::vector<bool> blocks;
    for (const auto& rung : program_.rungs) {
        blocks.clear();
        for (const auto& ins : rung.code) {
            switch (ins.op) {
                case LogicOp::Load:
                    if (ins.new_line) blocks.clear();
                    blocks.push_back(contact(memory, ins));
                    break;
                case LogicOp::And: {
                    bool c = contact(memory, ins);   // always evaluated: edge memory must follow the device
                    blocks.back() = blocks.back() && c;
                    break;
                }
                case LogicOp::Or: {
                    bool c = contact(memory, ins);
                    blocks.back() = blocks.back() || c;
                    break;
                }
                case LogicOp::AndBlock:
                case LogicOp::OrBlock: {
                    bool top = blocks.back();
                    blocks.pop_back();
                    blocks.back() = ins.op == LogicOp::AndBlock ? blocks.back() && top : blocks.back() || top;
                    break;
                }
                default: output(memory, ins, blocks.back());
            }
        }
    }
    timers_.run(memory, elapsed);
}

}  // namespace slmp::scenarios
