// Loading the rung language (logic.hpp): tokens separated by blanks, split
// into instructions by the operand counts of the engine's instruction table
// (program::instruction_shape), checked as a whole so that a rung that would
// not run (an unclosed block, contacts after the last output, a timer without
// a preset) is refused at load time with the rung's JSON pointer and the fix.
// The CPU is not known here: device sizes, label types and family
// restrictions are checked when the scenario starts (check_devices,
// bind_labels, the engine's compile).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>

#include "config/config_error.hpp"
#include "program/program.hpp"
#include "scenarios/load_parts.hpp"
#include "scenarios/logic.hpp"

namespace slmp::scenarios {
namespace {

using devicemodel::Area;
using Role = program::InstructionShape::Role;
using Use = RungOperand::Use;

std::string upper(std::string text) {
    for (auto& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

// The rung language's own names: ADD/SUB s1 s2 d were its 16-bit addition and
// subtraction on every family; the engine names them + and - (ADD is an FX
// name that only iQ-F knows).
std::string engine_mnemonic(const std::string& m) {
    if (m == "ADD") return "+";
    if (m == "ADDP") return "+P";
    if (m == "SUB") return "-";
    if (m == "SUBP") return "-P";
    return m;
}

bool is_mnemonic(const std::string& token) { return program::instruction_shape(engine_mnemonic(upper(token))).has_value(); }

struct Parser {
    std::vector<std::string> timer_coils;   // "T0", "C5": every OUT of a timer/counter in the program so far
    const std::string& source;
    const std::string& pointer;
    std::string token;   // the instruction being parsed, for messages

    [[noreturn]] void fail(const std::string& problem, const std::string& fix) const {
        throw config::ConfigError(source + ": " + pointer + ": " + (token.empty() ? "" : "'" + token + "': ") + problem +
                                  "; " + fix);
    }

    // K123, K-5, H7F
    std::optional<std::int32_t> constant(const std::string& text) const {
        if (text.size() < 2 || (text[0] != 'K' && text[0] != 'H')) return std::nullopt;
        std::int64_t value = 0;
        auto digits = std::string_view(text).substr(1);
        auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value, text[0] == 'K' ? 10 : 16);
        if (ec != std::errc{} || end != digits.data() + digits.size())
            fail("'" + text + "' is not a constant", "write K followed by a decimal number or H followed by hex digits");
        if (text[0] == 'K' && (value < -32768 || value > 32767)) fail("K" + std::string(digits) + " does not fit 16 bits", "use K-32768 to K32767");
        if (text[0] == 'H' && (value < 0 || value > 0xFFFF)) fail("H" + std::string(digits) + " does not fit 16 bits", "use H0 to HFFFF");
        return static_cast<std::int32_t>(value);
    }

    // T5, ST5, C5: a timer or counter by number (its part follows from where
    // it is used); the address is its contact, for the size check at start.
    std::optional<devicemodel::DeviceAddress> timer(const std::string& text) const {
        std::size_t letters = 0;
        while (letters < text.size() && std::isalpha(static_cast<unsigned char>(text[letters]))) ++letters;
        auto prefix = text.substr(0, letters);
        if ((prefix != "T" && prefix != "ST" && prefix != "C") || letters == text.size()) return std::nullopt;
        auto digits = text.substr(letters);
        if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9)
            fail("'" + text + "' is not a timer or counter number", "write e.g. T0, ST5, C10");
        devicemodel::DeviceAddress a;
        a.number = static_cast<std::uint32_t>(std::stoul(digits));
        a.spec = devicemodel::find_by_symbol(prefix == "T" ? "TS" : prefix == "ST" ? "STS" : "CS");
        return a;
    }

    devicemodel::DeviceAddress device(const std::string& text) const {
        std::string error;
        auto address = devicemodel::parse_address(text, &error);
        if (!address) fail(error, "write a device such as X0, M10, D100, T0 or a constant K10 / H1F");
        if (address->spec->unit == devicemodel::Unit::DoubleWord)
            fail(text + " is a 32-bit device", "use 16-bit word devices (D, W, R, ZR, TN, CN …) in 16-bit operands");
        return *address;
    }

    // Not a device but a possible label name: bind_labels() checks it against the CPU.
    static std::optional<RungOperand> label(const std::string& text, const std::string& raw, Use use) {
        if (devicemodel::parse_address(text) || !load::may_be_label(raw)) return std::nullopt;
        return RungOperand{use, raw, std::nullopt, true};
    }

    RungOperand bit(const std::string& text, const std::string& raw, Use use = Use::Bit) const {
        if (auto t = timer(text)) return {use, text, *t};   // T0 as a contact: TS0
        if (constant(text)) fail("a constant cannot be a contact", "name a bit device such as X0, M0, T0");
        if (auto l = label(text, raw, use)) return *l;
        auto d = device(text);
        if (d.spec->unit != devicemodel::Unit::Bit)
            fail(text + " is a word device", "name a bit device here, or use a compare contact such as LD<> " + text + " K0");
        return {use, text, d};
    }

    RungOperand word(const std::string& text, const std::string& raw, bool destination) const {
        if (auto k = constant(text)) {
            if (destination) fail("a constant cannot be a destination", "name a word device such as D100");
            return {Use::Word, text, std::nullopt};
        }
        if (auto t = timer(text)) return {Use::Word, text, *t};   // T0 as a word: its current value TN0
        if (auto l = label(text, raw, Use::Word)) return *l;
        auto d = device(text);
        if (d.spec->unit != devicemodel::Unit::Word)
            fail(text + " is a bit device", "name a word device (D, W, R, ZR, SD, TN, CN …); digit designation such as K4M0 is not supported");
        return {Use::Word, text, d};
    }

    // Operand types beyond bits and 16-bit words (32-bit, real, string, block
    // operands): the engine checks them against the CPU when the scenario starts.
    static RungOperand other(const std::string& text, const std::string& raw) {
        // K100000, H1F, E1.5, "text": constants the engine reads, not labels
        const bool constant = raw.starts_with('"') || (text.size() > 1 && (text[0] == 'K' || text[0] == 'H' || text[0] == 'E') &&
                                                        (std::isdigit(static_cast<unsigned char>(text[1])) || text[1] == '-' ||
                                                         text[1] == '+' || text[1] == '.'));
        if (constant) return {Use::Other, raw, std::nullopt};
        if (auto l = label(text, raw, Use::Other)) return *l;
        RungOperand o{Use::Other, text, devicemodel::parse_address(text)};
        return o;
    }

    RungOperand operand(char type, const std::string& text, const std::string& raw) const {
        switch (type) {
            case 'b':
            case 'o': return bit(text, raw);
            case 'w':
            case 'n': return word(text, raw, false);
            case 'W': return word(text, raw, true);
            default: return other(text, raw);
        }
    }

    // Records the OUT of timer/counter `t` (as "T0", "ST5", "C3"), refusing a second one.
    void timer_coil(const std::string& name) {
        if (std::find(timer_coils.begin(), timer_coils.end(), name) != timer_coils.end())
            fail("this timer/counter already has an OUT in the program", "give each timer or counter one OUT (a double coil would count twice)");
        timer_coils.push_back(name);
    }
};

constexpr const char* kInstructionList =
    "use contacts (LD LDI LDP LDF, AND…, OR…, compare contacts such as LD>=), ANB ORB MPS MRD MPP, "
    "OUT SET RST and application instructions such as MOV, ADD/+, SUB/-, INC, DEC and their P forms "
    "(docs/scenarios.md \"Logic\")";

}  // namespace

void parse_rung(LogicProgram& program, const std::string& text, const std::string& source, const std::string& pointer) {
    Parser p{{}, source, pointer, {}};
    // Timer/counter coils of the rungs loaded before this one (one OUT per timer in the program).
    for (const auto& rung : program.rungs)
        for (const auto& ins : rung.code)
            if (ins.mnemonic == "OUT" && ins.operands.size() == 2) p.timer_coils.push_back(ins.operands[0].text);

    std::vector<std::string> tokens, raw;
    std::istringstream in(text);
    for (std::string t; in >> t;) raw.push_back(t), tokens.push_back(upper(t));
    if (tokens.empty()) p.fail("an empty rung", "write instructions such as \"LD X0 OUT Y0\"");

    Rung rung{{}, text, pointer};
    std::size_t i = 0;
    std::size_t depth = 0;               // blocks on MELSEC's block stack
    std::vector<std::size_t> branches;   // the depth at each open MPS
    bool last_was_output = false;
    auto need_one_block = [&] {
        if (depth == 0) p.fail("no condition before this output", "start the rung with LD, LDI, LDP, LDF or a compare LD");
        if (depth > 1) p.fail(std::to_string(depth) + " open blocks before this output", "join them with ANB or ORB");
    };

    while (i < tokens.size()) {
        const auto m = tokens[i++];
        p.token = m;
        RungInstruction ins{engine_mnemonic(m), {}};
        const auto shape = program::instruction_shape(ins.mnemonic);
        if (!shape) {
            if (auto cmp = m.find_first_of("=<>"); cmp != std::string::npos && cmp > 0)
                p.fail("unknown compare instruction", "write LD=, LD<>, LD<, LD<=, LD>, LD>= (or AND…/OR…)");
            p.fail("unknown instruction", kInstructionList);
        }
        if (shape->role == Role::Control)
            p.fail("unknown instruction in the rung language",
                   "program control (jumps, calls, FOR/NEXT, MC/MCR, END, STOP) needs a program (cpu.program, "
                   "docs/program.md); " + std::string(kInstructionList));

        // The operands: OUT of a timer/counter takes its preset; otherwise the
        // longest form whose operands are all there and none is an instruction.
        auto have = [&](std::size_t count) {
            for (std::size_t k = 0; k < count; ++k)
                if (i + k >= tokens.size() || is_mnemonic(tokens[i + k])) return false;
            return true;
        };
        const bool timer_out = m == "OUT" && i < tokens.size() && p.timer(tokens[i]);
        if (timer_out) {
            const auto t = *p.timer(tokens[i]);   // its name normalised ("T00" is T0) for the double-coil check
            const auto target = std::string(tokens[i].substr(0, tokens[i].find_first_of("0123456789"))) + std::to_string(t.number);
            ins.operands.push_back({Use::Other, target, t});
            ++i;
            if (!have(1)) p.fail("OUT " + target + " needs a preset", "write e.g. OUT " + target + " K20");
            if (auto preset = p.constant(tokens[i]); preset && *preset < 0) p.fail("a negative preset", "use K0 to K32767");
            ins.operands.push_back(p.word(tokens[i], raw[i], false));
            ++i;
            p.timer_coil(target);
        } else {
            // ADD/SUB of the rung language always have s1 s2 d.
            const bool three_only = ins.mnemonic != m && (m.starts_with("ADD") || m.starts_with("SUB"));
            std::size_t form = shape->forms.size();
            for (std::size_t f = 0; f < shape->forms.size(); ++f)
                if (have(shape->forms[f].size()) && (!three_only || shape->forms[f].size() == 3) &&
                    (form == shape->forms.size() || shape->forms[f].size() > shape->forms[form].size()))
                    form = f;
            if (form == shape->forms.size()) {   // not enough operands: name the first one missing
                std::size_t longest = 0;   // the form the written operands fall short of
                for (std::size_t f = 0; f < shape->forms.size(); ++f)
                    if (shape->forms[f].size() > shape->forms[longest].size()) longest = f;
                const auto types = shape->forms[longest];
                std::size_t present = 0;
                while (present < types.size() && have(present + 1)) ++present;
                const bool bit = types[present] == 'b' || types[present] == 'o';
                p.fail(bit ? "missing device" : "missing operand " + std::to_string(present + 1) + " (" +
                                                     std::string(shape->names[longest]) + ")",
                       "complete the instruction");
            }
            const auto types = shape->forms[form];
            for (std::size_t k = 0; k < types.size(); ++k, ++i) {
                char type = types[k];
                // RST of a word device clears it (RST D0), of a timer/counter its value and contact.
                if (m == "RST" && type == 'o') {
                    if (auto t = p.timer(tokens[i])) {
                        ins.operands.push_back({Use::Other, tokens[i], *t});
                        continue;
                    }
                    auto d = devicemodel::parse_address(tokens[i]);
                    if (d && d->spec->unit == devicemodel::Unit::Word) {
                        ins.operands.push_back(p.word(tokens[i], raw[i], true));
                        continue;
                    }
                    ins.operands.push_back(p.bit(tokens[i], raw[i], Use::Either));
                    continue;
                }
                ins.operands.push_back(p.operand(type, tokens[i], raw[i]));
            }
        }

        bool output = false;
        switch (shape->role) {
            case Role::Load:
                if (last_was_output && branches.empty()) depth = 1;   // "LD X0 OUT Y0 LD X1 OUT Y1": two lines in one rung
                else ++depth;
                break;
            case Role::Combine:
            case Role::Modify:
            case Role::BranchPush:
                if (depth == 0) p.fail("no condition to continue", "start the rung with LD (or LDI, LDP, LDF, a compare LD)");
                if (shape->role == Role::BranchPush) branches.push_back(depth);
                break;
            case Role::Join:
                if (depth < 2) p.fail("needs two blocks", "start the second block with LD before " + m);
                --depth;
                break;
            case Role::BranchRead:
            case Role::BranchPop:
                if (branches.empty()) p.fail("no branch to return to", "open it with MPS before " + m);
                depth = branches.back();
                if (shape->role == Role::BranchPop) branches.pop_back();
                break;
            case Role::Output:
                need_one_block();
                output = true;
                break;
            case Role::Control: break;
        }
        last_was_output = output;
        rung.code.push_back(std::move(ins));
    }
    p.token.clear();
    if (!last_was_output)
        p.fail("the rung ends without an output", "end it with OUT, SET, RST, MOV, ADD, SUB, INC, DEC or another output");
    if (!branches.empty()) p.fail("MPS without MPP", "close the branch with MPP before the rung ends");
    program.rungs.push_back(std::move(rung));
}

}  // namespace slmp::scenarios
