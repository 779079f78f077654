// Parsing the rung language (logic.hpp): tokens separated by blanks, checked
// as a whole so that a rung that would not run (an unclosed block, contacts
// after the last output, a timer without a preset) is refused at load time
// with the rung's JSON pointer and the fix.
#include <cctype>
#include <charconv>
#include <sstream>

#include "config/config.hpp"
#include "scenarios/load_parts.hpp"
#include "scenarios/logic.hpp"

namespace slmp::scenarios {
namespace {

using devicemodel::Area;
using Kind = LogicOperand::Kind;

std::string upper(std::string text) {
    for (auto& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

struct Parser {
    LogicProgram& program;
    const std::string& source;
    const std::string& pointer;
    std::string token;   // the instruction being parsed, for messages
    std::string raw;     // the operand being parsed as written (labels keep their case)

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

    // T5, ST5, C5: a timer or counter by number (its part follows from where it is used).
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
        // Keep the contact spec for now; callers pick the part they need.
        a.spec = devicemodel::find_by_symbol(prefix == "T" ? "TS" : prefix == "ST" ? "STS" : "CS");
        return a;
    }

    static const devicemodel::DeviceSpec* part(const devicemodel::DeviceSpec* contact, devicemodel::Part want) {
        for (const auto& spec : devicemodel::all_devices())
            if (spec.area == contact->area && spec.part == want) return &spec;
        return nullptr;
    }

    devicemodel::DeviceAddress device(const std::string& text) const {
        std::string error;
        auto address = devicemodel::parse_address(text, &error);
        if (!address) fail(error, "write a device such as X0, M10, D100, T0 or a constant K10 / H1F");
        if (address->spec->unit == devicemodel::Unit::DoubleWord)
            fail(text + " is a 32-bit device", "use 16-bit word devices (D, W, R, ZR, TN, CN …) in the rung language");
        return *address;
    }

    // Not a device but a possible label name: bind_labels() checks it against the CPU.
    std::optional<LogicOperand> label(const std::string& text, Kind kind) const {
        if (devicemodel::parse_address(text) || !load::may_be_label(raw)) return std::nullopt;
        return LogicOperand{kind, {}, 0, raw};
    }

    LogicOperand bit(const std::string& text) const {
        if (auto t = timer(text)) return {Kind::Bit, *t, 0};   // T0 as a contact: TS0
        if (constant(text)) fail("a constant cannot be a contact", "name a bit device such as X0, M0, T0");
        if (auto l = label(text, Kind::Bit)) return *l;
        auto d = device(text);
        if (d.spec->unit != devicemodel::Unit::Bit)
            fail(text + " is a word device", "name a bit device here, or use a compare contact such as LD<> " + text + " K0");
        return {Kind::Bit, d, 0};
    }

    LogicOperand word(const std::string& text, bool destination) const {
        if (auto k = constant(text)) {
            if (destination) fail("a constant cannot be a destination", "name a word device such as D100");
            return {Kind::Constant, {}, *k};
        }
        if (auto t = timer(text)) {   // T0 as a word: its current value TN0
            t->spec = part(t->spec, devicemodel::Part::Value);
            return {Kind::Word, *t, 0};
        }
        if (auto l = label(text, Kind::Word)) return *l;
        auto d = device(text);
        if (d.spec->unit != devicemodel::Unit::Word)
            fail(text + " is a bit device", "name a word device (D, W, R, ZR, SD, TN, CN …); digit designation such as K4M0 is not supported");
        return {Kind::Word, d, 0};
    }

    void add_timer(const devicemodel::DeviceAddress& t, std::int32_t preset) {
        if (preset < 0) fail("a negative preset", "use K0 to K32767");
        auto area = t.spec->area;
        auto taken = [&](Area a, std::uint32_t n) {
            for (const auto& r : program.timers) if (r.area == a && r.first == n) return true;
            for (const auto& r : program.counters) if (r.area == a && r.first == n) return true;
            return false;
        };
        if (taken(area, t.number)) fail("this timer/counter already has an OUT in the program", "give each timer or counter one OUT (a double coil would count twice)");
        if (area == Area::C)
            program.counters.push_back({area, t.number, 1, static_cast<std::uint32_t>(preset)});
        else
            program.timers.push_back({area, t.number, 1, static_cast<std::uint32_t>(preset), std::chrono::milliseconds(100)});
    }
};

struct Mnemonic {
    LogicOp op;
    Contact contact;
};

std::optional<Mnemonic> contact_mnemonic(const std::string& m) {
    static const std::pair<const char*, Mnemonic> table[] = {
        {"LD", {LogicOp::Load, Contact::Normal}},    {"LDI", {LogicOp::Load, Contact::Inverted}},
        {"LDP", {LogicOp::Load, Contact::Rising}},   {"LDF", {LogicOp::Load, Contact::Falling}},
        {"AND", {LogicOp::And, Contact::Normal}},    {"ANI", {LogicOp::And, Contact::Inverted}},
        {"ANDP", {LogicOp::And, Contact::Rising}},   {"ANDF", {LogicOp::And, Contact::Falling}},
        {"OR", {LogicOp::Or, Contact::Normal}},      {"ORI", {LogicOp::Or, Contact::Inverted}},
        {"ORP", {LogicOp::Or, Contact::Rising}},     {"ORF", {LogicOp::Or, Contact::Falling}},
    };
    for (const auto& [name, m2] : table)
        if (m == name) return m2;
    return std::nullopt;
}

}  // namespace

void parse_rung(LogicProgram& program, const std::string& text, const std::string& source, const std::string& pointer) {
    Parser p{program, source, pointer, {}};
    std::vector<std::string> tokens, raw;
    std::istringstream in(text);
    for (std::string t; in >> t;) raw.push_back(t), tokens.push_back(upper(t));
    if (tokens.empty()) p.fail("an empty rung", "write instructions such as \"LD X0 OUT Y0\"");

    Rung rung{{}, text, pointer};
    std::size_t i = 0;
    std::size_t depth = 0;            // blocks on MELSEC's block stack
    bool last_was_output = false;
    auto operand = [&](const char* what) -> std::string {
        if (i >= tokens.size()) p.fail("missing " + std::string(what), "complete the instruction");
        p.raw = raw[i];
        return tokens[i++];
    };
    auto need_one_block = [&] {
        if (depth == 0) p.fail("no condition before this output", "start the rung with LD, LDI, LDP, LDF or a compare LD");
        if (depth > 1) p.fail(std::to_string(depth) + " open blocks before this output", "join them with ANB or ORB");
    };

    while (i < tokens.size()) {
        const auto m = tokens[i++];
        p.token = m;
        Instruction ins;
        bool output = false;
        if (auto c = contact_mnemonic(m)) {
            ins.op = c->op;
            ins.contact = c->contact;
            ins.operands.push_back(p.bit(operand("device")));
            if (c->contact == Contact::Rising || c->contact == Contact::Falling) ins.memory = program.memory_slots++;
        } else if (auto cmp = m.find_first_of("=<>"); cmp != std::string::npos && cmp > 0) {
            auto head = m.substr(0, cmp);
            auto op = parse_compare(m.substr(cmp));
            if (!op || (head != "LD" && head != "AND" && head != "OR"))
                p.fail("unknown compare instruction", "write LD=, LD<>, LD<, LD<=, LD>, LD>= (or AND…/OR…)");
            ins.op = head == "LD" ? LogicOp::Load : head == "AND" ? LogicOp::And : LogicOp::Or;
            ins.contact = Contact::Compare;
            ins.compare = *op;
            ins.operands.push_back(p.word(operand("first value"), false));
            ins.operands.push_back(p.word(operand("second value"), false));
        } else if (m == "ANB" || m == "ORB") {
            if (depth < 2) p.fail("needs two blocks", "start the second block with LD before " + m);
            ins.op = m == "ANB" ? LogicOp::AndBlock : LogicOp::OrBlock;
        } else {
            output = true;
            auto base = m;
            if (base.size() > 3 && base.back() == 'P' && base != "OUT") {
                ins.pulse = true;
                base.pop_back();
            }
            if (base == "OUT" && !ins.pulse) {
                ins.op = LogicOp::Out;
                auto target = operand("device");
                if (auto t = p.timer(target)) {
                    if (i >= tokens.size() || tokens[i][0] != 'K')
                        p.fail("OUT " + target + " needs a preset", "write e.g. OUT " + target + " K20");
                    auto preset = p.constant(tokens[i++]);
                    p.add_timer(*t, *preset);
                    t->spec = Parser::part(t->spec, devicemodel::Part::Coil);
                    ins.operands.push_back({LogicOperand::Kind::Timer, *t, *preset});
                } else {
                    ins.operands.push_back(p.bit(target));
                }
            } else if ((base == "SET" || base == "RST") && !ins.pulse) {
                ins.op = base == "SET" ? LogicOp::Set : LogicOp::Reset;
                auto target = operand("device");
                auto t = p.timer(target);
                if (t && base == "RST") ins.operands.push_back({LogicOperand::Kind::Timer, *t, 0});
                else if (base == "RST" && !t && devicemodel::parse_address(target) &&
                         devicemodel::parse_address(target)->spec->unit == devicemodel::Unit::Word)
                    ins.operands.push_back(p.word(target, true));
                else
                    ins.operands.push_back(p.bit(target));
            } else if (base == "MOV") {
                ins.op = LogicOp::Move;
                ins.operands.push_back(p.word(operand("source"), false));
                ins.operands.push_back(p.word(operand("destination"), true));
            } else if (base == "ADD" || base == "SUB") {
                ins.op = base == "ADD" ? LogicOp::Add : LogicOp::Sub;
                ins.operands.push_back(p.word(operand("first source"), false));
                ins.operands.push_back(p.word(operand("second source"), false));
                ins.operands.push_back(p.word(operand("destination"), true));
            } else if (base == "INC" || base == "DEC") {
                ins.op = base == "INC" ? LogicOp::Inc : LogicOp::Dec;
                ins.operands.push_back(p.word(operand("device"), true));
            } else {
                p.fail("unknown instruction",
                       "use LD LDI LDP LDF AND ANI ANDP ANDF OR ORI ORP ORF ANB ORB, compare contacts (LD>= …), "
                       "OUT SET RST MOV ADD SUB INC DEC and their P forms");
            }
            if (ins.pulse) ins.memory = program.memory_slots++;
            need_one_block();
        }
        if (!output) {
            if (ins.op == LogicOp::Load && last_was_output) {
                ins.new_line = true;   // "LD X0 OUT Y0 LD X1 OUT Y1": two lines in one rung
                depth = 1;
            } else if (ins.op == LogicOp::Load) {
                ++depth;
            } else if (ins.op == LogicOp::AndBlock || ins.op == LogicOp::OrBlock) {
                --depth;
            } else if (depth == 0) {
                p.fail("no condition to continue", "start the rung with LD (or LDI, LDP, LDF, a compare LD)");
            }
        }
        last_was_output = output;
        rung.code.push_back(std::move(ins));
    }
    p.token.clear();
    if (!last_was_output)
        p.fail("the rung ends without an output", "end it with OUT, SET, RST, MOV, ADD, SUB, INC or DEC");
    program.rungs.push_back(std::move(rung));
}

}  // namespace slmp::scenarios
