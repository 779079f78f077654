// compile(): Source lines into the flat step array (docs/program.md "Engine",
// "Load errors", "Instructions", "The scan"). Every problem is collected, one
// line each, and thrown together as LoadError.
#include <algorithm>
#include <map>
#include <set>

#include "program/handlers.hpp"
#include "program/instruction_table.hpp"
#include "program/operands.hpp"

namespace slmp::program {

using devicemodel::Area;
using devicemodel::Part;
using devicemodel::Unit;
using namespace detail;

namespace {

std::string upper(std::string_view text) {
    std::string out(text);
    for (auto& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

constexpr std::uint16_t kScratchSlot = 63;   // a rung start writes its covered value here
constexpr int kMaxOpenBlocks = 62;
constexpr int kMaxBranches = 16;             // MPS depth (docs/program.md "Instructions", inferred)

struct Compiler {
    Compiler(const Source& s, const devicemodel::CpuProfile& p, const ProgramOptions& o, const devicemodel::LabelTable* l)
        : source(s), profile(p), options(o), global_labels(l) {}
    const Source& source;
    const devicemodel::CpuProfile& profile;
    const ProgramOptions& options;
    const devicemodel::LabelTable* global_labels;   // operands that are no device may name these
    std::shared_ptr<Program> program = std::make_shared<Program>();
    std::vector<std::string> problems;
    std::vector<std::string> warnings;

    // labels: pointer number -> step index, and the line that defined it
    std::map<std::int64_t, std::pair<std::uint32_t, std::size_t>> labels;
    std::size_t fend_index = SIZE_MAX;   // first FEND: the main routine ends there

    // rung structure (docs/program.md "Instructions")
    int open = 0;
    bool after_output = false;
    int branches = 0;
    std::array<int, kMaxBranches> branch_open{};
    // MC levels open, with their lines; FOR lines open
    std::vector<std::pair<std::uint32_t, std::size_t>> mc_levels;
    std::vector<std::size_t> for_lines;
    // double coils (docs/program.md "The scan")
    std::map<std::tuple<int, int, std::uint32_t, int>, std::size_t> bit_coils;
    std::map<std::pair<int, std::uint32_t>, std::size_t> timer_coils;
    std::map<std::pair<int, std::uint32_t>, std::uint32_t> timer_slots;
    struct PendingJump {
        std::size_t step;
        int operand;
        std::int64_t pointer;
        const SourceLine* line;
    };
    std::vector<PendingJump> jumps;

    std::string where(const SourceLine& line) const {
        if (source.format == Format::GxWorksCsv) {
            std::string text = source.file + ": row " + std::to_string(line.row);
            if (line.step) text += " (step " + std::to_string(*line.step) + ")";
            return text;
        }
        return source.file + ": line " + std::to_string(line.row);
    }
    std::string lines_word() const { return source.format == Format::GxWorksCsv ? "rows" : "lines"; }
    void problem(const SourceLine& line, const std::string& text) { problems.push_back(where(line) + ": " + text); }
    std::string cpu() const {
        return profile.name + " (family " + std::string(family_name(profile.family)) + ")";
    }

    std::uint32_t cost_of(Cost cost) const {
        const auto& c = program->costs;
        switch (cost) {
            case Cost::Basic: return c.basic_ps;
            case Cost::Move: return c.move_ps;
            case Cost::Arith: return c.arith_ps;
            case Cost::Float: return c.float_ps;
            case Cost::Block: return 1;   // the handler adds `block` per word
            case Cost::Label: return 0;
        }
        return 1;
    }

    // ---- operand resolution ----

    bool in_range(const SourceLine& line, const std::string& text, Area area, std::uint64_t first, std::uint64_t count) {
        const auto size = profile.size(area);
        if (first + count <= size) return true;
        problem(line, text + " is outside " + std::string(devicemodel::area_name(area)) + " (" + std::to_string(size) +
                          " points) for " + profile.name);
        return false;
    }

    // The operand `text` as operand type `type` of `mnemonic` (types: instruction_table.hpp).
    std::optional<Operand> resolve(const SourceLine& line, std::string_view mnemonic, const std::string& text, char type) {
        std::string error;
        auto parsed = parse_operand(text, profile.numbering, error);
        if (!parsed) {
            if (auto ref = label_of(text)) return label_operand(line, mnemonic, text, type, *ref);
            problem(line, error);
            return std::nullopt;
        }
        const std::string shown = upper(text);
        const std::string m(mnemonic);
        auto fail = [&](const std::string& why) -> std::optional<Operand> {
            problem(line, why);
            return std::nullopt;
        };
        Operand o;
        o.index = parsed->index;
        o.index_long = parsed->index_long;
        if (o.index != kNoIndex) {
            const Area reg = o.index_long ? Area::LZ : Area::Z;
            if (o.index >= profile.size(reg))
                return fail(shown + ": index register " + std::string(devicemodel::area_name(reg)) + std::to_string(o.index) +
                            " is outside " + std::string(devicemodel::area_name(reg)) + " (" +
                            std::to_string(profile.size(reg)) + " points) for " + profile.name);
        }
        using K = ParsedOperand::Kind;
        const bool wide32 = type == 'd' || type == 'D' || type == 'V';
        const bool source16 = type == 'w' || type == 'n';
        const bool integer_source = source16 || type == 'd';
        const bool word_like = source16 || wide32 || type == 'W' || type == 'v';

        switch (parsed->kind) {
            case K::Pointer:
                if (type != 'p') return fail("'" + m + "' takes no pointer here (" + shown + ")");
                o.kind = OperandKind::Pointer;
                o.value = static_cast<std::uint32_t>(parsed->integer);
                return o;
            case K::Nesting:
                if (type != 'N') return fail("'" + m + "' takes no nesting level here (" + shown + ")");
                if (parsed->integer > 14) return fail(shown + ": nesting levels are N0 to N14");
                o.kind = OperandKind::Nesting;
                o.value = static_cast<std::uint32_t>(parsed->integer);
                return o;
            case K::String:
                if (type != 's') return fail("'" + m + "' takes no string constant here (" + text + ")");
                o.kind = OperandKind::String;
                o.value = static_cast<std::uint32_t>(program->strings.size());
                program->strings.push_back(parsed->text);
                return o;
            case K::Real:
                if (type != 'e') return fail(shown + " is a real number; '" + m + "' needs an integer (K or H) here");
                o.kind = OperandKind::Constant;
                o.value = std::bit_cast<std::uint32_t>(parsed->real);
                return o;
            case K::Integer: {
                if (type == 'e')
                    return fail("'" + m + "' takes a real number here; write E" + std::to_string(parsed->integer) +
                                " instead of " + shown);
                if (!integer_source) return fail(shown + " is a constant; '" + m + "' needs a device here");
                const auto v = parsed->integer;
                if (type == 'd') {
                    if (!parsed->hex && (v < INT32_MIN || v > INT32_MAX))
                        return fail(shown + " does not fit 32 bits (K-2147483648 to K2147483647)");
                } else if (parsed->hex ? v > 0xFFFF : (v < -32768 || v > 32767)) {
                    return fail(shown + " does not fit 16 bits (K-32768 to K32767, H0 to HFFFF); use the D form of '" + m + "'");
                }
                o.kind = OperandKind::Constant;
                o.value = static_cast<std::uint32_t>(v);
                return o;
            }
            case K::Digits: {
                if (!word_like) return fail(shown + ": '" + m + "' takes no digit designation here");
                if (parsed->spec == nullptr || parsed->spec->unit != Unit::Bit || is_timer_or_counter(parsed->area))
                    return fail(shown + ": digit designation needs a bit device (X, Y, M, L, B, F, SB, S, SM)");
                const unsigned max = wide32 ? 8 : 4;
                if (parsed->digits > max) {
                    std::string base = m;
                    if (base.size() > 1 && base.back() == 'P' && find_instruction("D" + base.substr(0, base.size() - 1)))
                        base.pop_back();
                    return fail(shown + " is too wide for " + m + " (K1-K4); use D" + base + " for K5-K8");
                }
                o.kind = OperandKind::Digits;
                o.area = parsed->area;
                o.plane = Plane::Bits;
                o.digits = parsed->digits;
                o.number = parsed->number;
                if ((type == 'W' || type == 'D' || type == 'v' || type == 'V') && parsed->area == Area::X)
                    return fail(shown + ": X is an input; '" + m + "' cannot write it");
                if (!in_range(line, shown, o.area, o.number, o.digits * 4u)) return std::nullopt;
                return o;
            }
            case K::Device: break;
        }

        // A device.
        const auto* spec = parsed->spec;
        const Area area = parsed->area;
        o.area = area;
        o.number = parsed->number;
        const bool bare_timer = spec == nullptr;   // T0, C5, LT0 ...
        const Part part = spec ? spec->part : Part::Plain;
        const Unit unit = spec ? spec->unit : Unit::Bit;
        const bool bit_device = !bare_timer && unit == Unit::Bit;

        if (parsed->bit >= 0) {   // D0.F
            if (bare_timer || unit != Unit::Word || part != Part::Plain)
                return fail(shown + ": a bit number (.n) needs a word device such as D or W");
            if (type != 'b' && type != 'o') return fail(shown + ": '" + m + "' takes no bit of a word here");
            o.kind = OperandKind::BitOfWord;
            o.bit = static_cast<std::uint8_t>(parsed->bit);
            if (!in_range(line, shown, area, o.number, 1)) return std::nullopt;
            return o;
        }

        switch (type) {
            case 'b':
            case 'o':
            case 'x':
            case 'y':
                if (!bare_timer && !bit_device)
                    return fail(shown + " is a word device; '" + m + "' needs a bit here (e.g. " + shown + ".0)");
                if ((type == 'o' || type == 'x') && (bare_timer || is_timer_or_counter(area)))
                    return fail("'" + m + "' cannot write " + shown + " (timers and counters change through OUT and RST)");
                if ((type == 'o' || type == 'x') && area == Area::X)
                    return fail(shown + " is an input; '" + m + "' cannot write it");
                o.kind = OperandKind::Bit;
                o.plane = part == Part::Coil ? Plane::Coils : Plane::Bits;
                if (!in_range(line, shown, area, o.number, 1)) return std::nullopt;
                return o;
            case 'z':
                o.kind = bit_device ? OperandKind::Bit : OperandKind::Word;
                o.plane = bit_device ? (part == Part::Coil ? Plane::Coils : Plane::Bits) : Plane::Values;
                if (bare_timer) o.kind = OperandKind::Word;
                else if (unit == Unit::DoubleWord) o.kind = OperandKind::Wide;
                if (!in_range(line, shown, area, o.number, 1)) return std::nullopt;
                return o;
            case 'p':
            case 'N': return fail("'" + m + "' needs a " + std::string(type == 'p' ? "pointer (P)" : "nesting level (N)") +
                                  " here, not " + shown);
            default: break;
        }
        // word types
        if (bit_device)
            return fail(shown + " is a bit device; '" + m + "' needs a word here (e.g. K4" + shown + ")");
        const bool wide = (spec && unit == Unit::DoubleWord) ||
                          (bare_timer && (area == Area::LT || area == Area::LST || area == Area::LC));
        if (type == 'q' || type == 's' || type == 'e' || type == 'E') {
            if (wide || bare_timer || part != Part::Plain)
                return fail(shown + ": '" + m + "' needs a word device such as D, W, R or ZR here");
        }
        o.plane = Plane::Values;
        o.kind = wide ? OperandKind::Wide : OperandKind::Word;
        std::uint32_t span = 1;
        if (!wide) {
            if (type == 'd' || type == 'D' || type == 'e' || type == 'E' || type == 'v') span = 2;
            if (type == 'V') span = 4;
        }
        if (!in_range(line, shown, area, o.number, span)) return std::nullopt;
        return o;
    }

    // ---- global labels (names as written: labels keep their case) ----

    std::optional<devicemodel::LabelRef> label_of(const std::string& text) const {
        if (!global_labels) return std::nullopt;
        devicemodel::LabelFault fault{};
        return global_labels->resolve(text, {}, fault, /*external_only=*/false);
    }

    // A label element as operand type `type`: the device it is laid out on,
    // or its words/bit in the label area (OperandKind::LabelWord/LabelBit).
    std::optional<Operand> label_operand(const SourceLine& line, std::string_view mnemonic, const std::string& text, char type,
                                         const devicemodel::LabelRef& ref) {
        using devicemodel::BasicType;
        const std::string m(mnemonic);
        const auto basic = ref.basic;
        const bool bit = type == 'b' || type == 'o';
        const bool word16 = type == 'w' || type == 'W' || type == 'n';
        const bool word32 = type == 'd' || type == 'D';
        const bool real = type == 'e' || type == 'E';
        const bool writes = type == 'o' || type == 'W' || type == 'D' || type == 'E';
        bool fits = false;
        if (bit) fits = basic == BasicType::Bit && m != "SFT" && m != "SFTP";   // SFT walks neighbouring devices
        if (word16) fits = basic == BasicType::Word || basic == BasicType::UWord;
        if (word32) fits = basic == BasicType::DWord || basic == BasicType::UDWord || basic == BasicType::Time;
        if (real) fits = basic == BasicType::Real;
        devicemodel::LabelType shown_type{};
        shown_type.basic = basic;
        shown_type.chars = ref.chars;
        if (!fits) {
            problem(line, "label '" + text + "' is of type " + devicemodel::format_label_type(shown_type) + "; '" + m +
                              "' needs " + (bit ? "a Bit label" : word16 ? "a Word [Signed] or Word [Unsigned] label"
                                                                  : word32 ? "a Double Word or Time label"
                                                                  : real   ? "a FLOAT [Single Precision] label"
                                                                           : "a device") + " here");
            return std::nullopt;
        }
        if (writes && ref.timer_member) {
            problem(line, "'" + m + "' cannot write " + text + " (timers and counters change through OUT and RST)");
            return std::nullopt;
        }
        const auto& cell = ref.first;
        const auto at = static_cast<std::uint32_t>(cell.at);
        Operand o;
        o.plane = Plane::Values;
        if (cell.spec) o.area = cell.spec->area;
        switch (cell.kind) {
            case devicemodel::LabelCell::Kind::Words:
                o.kind = !cell.spec ? OperandKind::LabelWord
                                    : (cell.spec->unit == Unit::DoubleWord ? OperandKind::Wide : OperandKind::Word);
                o.number = at;
                break;
            case devicemodel::LabelCell::Kind::BitInWord:
                o.kind = cell.spec ? OperandKind::BitOfWord : OperandKind::LabelBit;
                o.number = cell.spec ? at / 16 : at;
                o.bit = static_cast<std::uint8_t>(cell.spec ? at % 16 : 0);
                break;
            case devicemodel::LabelCell::Kind::Bit:
                o.kind = OperandKind::Bit;
                o.plane = cell.spec->part == Part::Coil ? Plane::Coils : Plane::Bits;
                o.number = at;
                break;
            case devicemodel::LabelCell::Kind::Value:
                o.kind = cell.spec->unit == Unit::DoubleWord ? OperandKind::Wide : OperandKind::Word;
                o.number = at;
                break;
        }
        return o;
    }

    // RST of a Word label clears it, as RST D0 does.
    bool names_word_label(const std::string& text) const {
        auto ref = label_of(text);
        return ref && (ref->basic == devicemodel::BasicType::Word || ref->basic == devicemodel::BasicType::UWord);
    }

    // ---- rung structure ----

    bool rung(const SourceLine& line, Role role, Step& step, const std::string& shown) {
        switch (role) {
            case Role::Load:
                if (open == 0 || (after_output && branches == 0)) {
                    step.slot = kScratchSlot;
                    open = 1;
                    branches = 0;
                } else {
                    if (open >= kMaxOpenBlocks) {
                        problem(line, shown + ": more than " + std::to_string(kMaxOpenBlocks) + " open blocks");
                        return false;
                    }
                    step.slot = static_cast<std::uint16_t>(open - 1);
                    ++open;
                }
                after_output = false;
                return true;
            case Role::Combine:
            case Role::Modify:
            case Role::BranchPush:
                if (open == 0) {
                    problem(line, shown + " has nothing to work on; start the rung with LD");
                    return false;
                }
                after_output = false;
                if (role == Role::BranchPush) {
                    if (branches >= kMaxBranches) {
                        problem(line, "MPS nested deeper than 16");
                        return false;
                    }
                    branch_open[static_cast<std::size_t>(branches)] = open;
                    step.slot = static_cast<std::uint16_t>(branches++);
                }
                return true;
            case Role::Join:
                if (open < 2) {
                    problem(line, shown + " needs two open blocks, found " + std::to_string(open));
                    return false;
                }
                step.slot = static_cast<std::uint16_t>(open - 2);
                --open;
                after_output = false;
                return true;
            case Role::BranchRead:
            case Role::BranchPop:
                if (branches == 0) {
                    problem(line, shown + " without MPS");
                    return false;
                }
                step.slot = static_cast<std::uint16_t>(branches - 1);
                open = branch_open[static_cast<std::size_t>(branches - 1)];
                if (role == Role::BranchPop) --branches;
                after_output = false;
                return true;
            case Role::Output:
            case Role::Master:
                if (open == 0) {
                    problem(line, shown + " has no condition; start the rung with LD");
                    return false;
                }
                if (open > 1) {
                    problem(line, shown + " with " + std::to_string(open) + " open blocks; join them with ANB or ORB first");
                    return false;
                }
                after_output = true;
                if (role == Role::Master) end_rung();
                return true;
            case Role::Free: end_rung(); return true;
        }
        return true;
    }
    void end_rung() {
        open = 0;
        after_output = false;
        branches = 0;
    }

    // ---- one instruction ----

    const InstructionInfo* lookup(const SourceLine& line, const std::string& mnemonic, bool& pulse) {
        pulse = false;
        const auto* info = find_instruction(mnemonic);
        if (!info && mnemonic.size() > 1 && mnemonic.back() == 'P') {
            const auto* base = find_instruction(mnemonic.substr(0, mnemonic.size() - 1));
            if (base && base->pulse_form) {
                info = base;
                pulse = true;
            }
        }
        if (!info) {
            if (known_but_unsupported(mnemonic)) problem(line, "'" + mnemonic + "' is not supported by slmp-sim yet");
            else problem(line, "'" + mnemonic + "' is no instruction of " + cpu());
            return nullptr;
        }
        if (!(info->families & family_bit(profile.family))) {
            if (!info->q_name.empty())
                problem(line, "'" + mnemonic + "' is an FX instruction; write '" + std::string(info->q_name) +
                                  (pulse ? "P" : "") + "'");
            else problem(line, "'" + mnemonic + "' is no instruction of " + cpu());
            return nullptr;
        }
        return info;
    }

    const Form* form_for(const SourceLine& line, const std::string& mnemonic, const InstructionInfo& info, std::size_t count,
                         std::size_t& form_index) {
        for (std::size_t i = 0; i < info.form_count; ++i)
            if (info.forms[i].types.size() == count) {
                form_index = i;
                return &info.forms[i];
            }
        std::string counts, names;
        std::size_t most = 0;
        for (std::size_t i = 0; i < info.form_count; ++i) {
            counts += (i ? " or " : "") + std::to_string(info.forms[i].types.size());
            names += (i ? " | " : "") + std::string(info.forms[i].names);
            most = std::max(most, info.forms[i].types.size());
        }
        const bool single = info.form_count == 1 && info.forms[0].types.size() == 1;
        const std::string noun = single ? " operand" : " operands";
        std::string text;
        if (count < most) {
            text = "'" + mnemonic + "' needs " + counts + noun + " (" + names + "), found " + std::to_string(count);
            if (source.format == Format::GxWorksCsv) text += "; add a continuation row";
        } else {
            text = "'" + mnemonic + "' takes " + counts + noun + (names.empty() ? "" : " (" + names + ")") + ", found " +
                   std::to_string(count);
        }
        problem(line, text);
        return nullptr;
    }

    // After a line that does not compile, the rung goes on as if it had a
    // condition, so one mistake gives one message, not one per later line.
    void instruction(const SourceLine& line) {
        const auto before = problems.size();
        compile_instruction(line);
        if (problems.size() != before) {
            open = 1;
            after_output = true;
            branches = 0;
        }
    }

    void compile_instruction(const SourceLine& line) {
        const std::string mnemonic = upper(line.mnemonic);
        bool pulse = false;
        const auto* info = lookup(line, mnemonic, pulse);
        if (!info) return;
        const auto& operands = line.operands;
        std::string shown = mnemonic;
        for (const auto& op : operands) shown += " " + upper(op);

        Step step;
        step.run = info->handler;
        step.cost_ps = cost_of(info->cost);
        step.variant = info->variant;
        const std::size_t index = program->steps.size();

        // OUT/OUTH/OUTHS and RST of timers and counters, RST of words: by operand (docs/program.md "Instructions").
        std::string ignored;
        std::optional<ParsedOperand> first;
        if (!operands.empty()) first = parse_operand(operands[0], profile.numbering, ignored);
        const bool first_is_timer_or_counter = first && first->kind == ParsedOperand::Kind::Device &&
                                               is_timer_or_counter(first->area) &&
                                               (first->spec == nullptr || first->spec->part != Part::Contact);
        if ((mnemonic == "OUT" && first_is_timer_or_counter) || mnemonic == "OUTH" || mnemonic == "OUTHS") {
            if (!timer_or_counter_coil(line, mnemonic, *info, shown, first, step)) return;
        } else if (mnemonic == "RST" && operands.size() == 1 &&
                   ((first && first->kind == ParsedOperand::Kind::Device &&
                     (first_is_timer_or_counter || (first->spec && first->spec->unit != Unit::Bit && first->bit < 0))) ||
                    (!first && names_word_label(operands[0])))) {
            if (!rung(line, info->role, step, shown)) return;
            if (first_is_timer_or_counter) {
                auto o = resolve(line, mnemonic, operands[0], 'z');
                if (!o) return;
                step.op[0] = *o;
                step.operand_count = 1;
                const bool counter = first->area == Area::C || first->area == Area::LC;
                step.run = rst_timer_counter;
                if (!counter && o->index == kNoIndex) {
                    auto slot = timer_slots.find({static_cast<int>(o->area), o->number});
                    step.aux = slot == timer_slots.end() ? 0 : slot->second + 1;
                    if (slot == timer_slots.end()) pending_timer_resets.push_back(index);
                }
            } else {
                auto o = resolve(line, mnemonic, operands[0], 'W');
                if (!o) return;
                step.op[0] = *o;
                step.operand_count = 1;
                step.run = rst_word;
            }
        } else {
            std::size_t form_index = 0;
            const Form* form = form_for(line, mnemonic, *info, operands.size(), form_index);
            if (!form) return;
            bool ok = true;
            std::array<Operand, 4> resolved{};
            for (std::size_t i = 0; i < operands.size(); ++i) {
                auto o = resolve(line, mnemonic, operands[i], form->types[i]);
                if (!o) {
                    ok = false;
                    continue;
                }
                resolved[i] = *o;
            }
            if (!ok) return;
            if (!rung(line, info->role, step, shown)) return;
            for (std::size_t i = 0; i < operands.size(); ++i)
                if (resolved[i].kind == OperandKind::Pointer)
                    jumps.push_back({index, static_cast<int>(i), resolved[i].value, &line});
            if (info->swap_two && form_index == 0) {   // "s d": d := d op s
                step.op[0] = resolved[1];
                step.op[1] = resolved[0];
                step.op[2] = resolved[1];
                step.operand_count = 3;
            } else {
                step.op = resolved;
                step.operand_count = static_cast<std::uint8_t>(operands.size());
            }
            if (mnemonic == "OUT") double_bit_coil(line, step.op[0], upper(operands[0]));
            if (info->handler == mc) open_mc(line, step.op[0].value);
            if (info->handler == mcr) close_mc(line, step.op[0].value);
        }
        if (info->handler == for_) for_lines.push_back(line.row);
        if (info->handler == next) {
            if (for_lines.empty()) problem(line, "NEXT without FOR");
            else for_lines.pop_back();
        }
        if (info->handler == ret && fend_index == SIZE_MAX) problem(line, "RET outside a subroutine (subroutines follow FEND)");
        if (info->handler == fend || info->handler == end) {
            for (auto open_for : for_lines)
                problem(line, "FOR at " + std::string(source.format == Format::GxWorksCsv ? "row " : "line ") +
                                  std::to_string(open_for) + " has no NEXT before " + mnemonic);
            for_lines.clear();
        }
        if (info->handler == fend && fend_index == SIZE_MAX) fend_index = index;
        if (info->edge || pulse) step.edge = program->edge_count++;
        step.run = specialised(step.run, step);
        if (pulse) {
            step.body = step.run;
            step.run = pulse_handler();
        }
        program->steps.push_back(step);
        program->info.push_back(CompiledStep{mnemonic, operands, line.row, line.step});
    }
    std::vector<std::size_t> pending_timer_resets;
    static Handler pulse_handler() { return detail::pulse; }

    bool timer_or_counter_coil(const SourceLine& line, const std::string& mnemonic, const InstructionInfo& info,
                               const std::string& shown, const std::optional<ParsedOperand>& first, Step& step) {
        const auto& operands = line.operands;
        if (operands.size() != 2) {
            std::size_t ignored = 0;
            const InstructionInfo two{info.mnemonic, info.role, info.cost, info.families, false, false, false, 1,
                                      {Form{"tw", "d preset"}, Form{}}, info.handler, "", 0};
            form_for(line, mnemonic, two, operands.size(), ignored);
            return false;
        }
        if (!first || first->kind != ParsedOperand::Kind::Device || !is_timer_or_counter(first->area)) {
            problem(line, "'" + mnemonic + "' drives a timer (T, ST, LT, LST); " + upper(operands[0]) + " is none");
            return false;
        }
        const Area area = first->area;
        const bool counter = area == Area::C || area == Area::LC;
        if (counter && mnemonic != "OUT") {
            problem(line, "'" + mnemonic + "' drives timers only; count with OUT " + upper(operands[0]));
            return false;
        }
        if (first->index != kNoIndex) {
            problem(line, shown + ": a timer or counter coil cannot be index-modified in slmp-sim");
            return false;
        }
        const std::string name = upper(operands[0]);
        if (!in_range(line, name, area, first->number, 1)) return false;
        const bool wide = area == Area::LT || area == Area::LST || area == Area::LC;
        auto preset = resolve(line, mnemonic, operands[1], wide ? 'd' : 'w');
        if (!preset) return false;
        if (preset->kind == OperandKind::Digits) {
            problem(line, upper(operands[1]) + ": a preset is a constant or a word device");
            return false;
        }
        if (!rung(line, info.role, step, shown)) return false;
        Operand coil;
        coil.kind = OperandKind::Bit;
        coil.area = area;
        coil.number = first->number;
        step.op[0] = coil;
        step.op[1] = *preset;
        step.operand_count = 2;
        const auto key = std::pair{static_cast<int>(area), first->number};
        if (auto seen = timer_coils.find(key); seen != timer_coils.end()) {
            if (!options.allow_double_timer_coils) {
                problem(line, std::string(devicemodel::area_name(area)) + std::to_string(first->number) + " has OUT at " +
                                  lines_word() + " " + std::to_string(seen->second) + " and " + std::to_string(line.row) +
                                  " (set allow_double_timer_coils to permit)");
                return false;
            }
        } else {
            timer_coils.emplace(key, line.row);
        }
        step.variant = wide ? 2 : 0;
        if (counter) {
            step.run = out_counter;
            return true;
        }
        step.run = out_timer;
        if (area == Area::ST || area == Area::LST) step.variant |= 1;
        std::uint64_t base_us = std::uint64_t{options.timer_low_ms} * 1000;
        if (mnemonic == "OUTH") base_us = std::uint64_t{options.timer_high_ms} * 1000;
        if (mnemonic == "OUTHS") base_us = 1000;
        if (wide) base_us = 1;   // LT/LST count µs (docs/program.md "Timers")
        step.aux = static_cast<std::uint32_t>(std::max<std::uint64_t>(base_us, 1));
        auto [slot, added] = timer_slots.emplace(key, static_cast<std::uint32_t>(program->timers.size()));
        if (added) program->timers.push_back(TimerSlot{area, first->number});
        step.edge = slot->second;
        return true;
    }

    void double_bit_coil(const SourceLine& line, const Operand& o, const std::string& name) {
        if (o.index != kNoIndex || o.kind == OperandKind::LabelBit) return;
        const auto key = std::tuple{static_cast<int>(o.area), static_cast<int>(o.plane), o.number,
                                    o.kind == OperandKind::BitOfWord ? static_cast<int>(o.bit) : -1};
        auto [seen, added] = bit_coils.emplace(key, line.row);
        if (!added)
            warnings.push_back(where(line) + ": " + name + " has OUT at " + lines_word() + " " + std::to_string(seen->second) +
                               " and " + std::to_string(line.row) + " (double coil: the last one executed wins)");
    }

    void open_mc(const SourceLine& line, std::uint32_t level) {
        if (!mc_levels.empty() && level <= mc_levels.back().first)
            problem(line, "MC N" + std::to_string(level) + " inside MC N" + std::to_string(mc_levels.back().first) +
                              ": nested levels must increase");
        mc_levels.emplace_back(level, line.row);
    }
    void close_mc(const SourceLine& line, std::uint32_t level) {
        auto it = std::find_if(mc_levels.begin(), mc_levels.end(), [&](const auto& e) { return e.first == level; });
        if (it == mc_levels.end()) {
            problem(line, "MCR N" + std::to_string(level) + " without MC N" + std::to_string(level));
            return;
        }
        mc_levels.erase(it, mc_levels.end());
    }

    // ---- the whole program ----

    void collect_labels() {
        std::uint32_t index = 0;
        for (const auto& line : source.lines) {
            if (line.kind == SourceLine::Kind::Pointer) {
                std::string error;
                auto parsed = parse_operand(line.mnemonic, profile.numbering, error);
                if (!parsed || parsed->kind != ParsedOperand::Kind::Pointer) {
                    problem(line, "'" + line.mnemonic + "' is no pointer label (write e.g. P10)");
                    continue;
                }
                auto [it, added] = labels.emplace(parsed->integer, std::pair{index, line.row});
                if (!added)
                    problem(line, "P" + std::to_string(parsed->integer) + " is defined twice (" + lines_word() + " " +
                                      std::to_string(it->second.second) + " and " + std::to_string(line.row) + ")");
            } else if (line.kind == SourceLine::Kind::Instruction) {
                ++index;
                if (upper(line.mnemonic) == "END") break;
            }
        }
    }

    void resolve_jumps() {
        for (const auto& jump : jumps) {
            auto& step = program->steps[jump.step];
            const auto& info = program->info[jump.step];
            auto label = labels.find(jump.pointer);
            const std::string shown = info.mnemonic + " P" + std::to_string(jump.pointer);
            if (label == labels.end()) {
                problem(*jump.line, "'" + shown + "' jumps to a pointer that is not defined");
                continue;
            }
            const auto target = label->second.first;
            const bool is_call = step.run == call || step.body == call;
            if (!is_call && fend_index != SIZE_MAX && ((jump.step < fend_index) != (target <= fend_index)))
                problem(*jump.line, "'" + shown + "' jumps between the main routine and the subroutines after FEND");
            step.op[static_cast<std::size_t>(jump.operand)].value = target;
        }
    }

    std::shared_ptr<const Program> run() {
        program->source = source;
        program->profile = profile;
        program->options = options;
        program->costs = costs_for(profile.family);
        for (const auto& spec : devicemodel::all_devices()) {
            const auto plane = spec.part == Part::Coil ? Plane::Coils
                               : (spec.unit == Unit::Bit ? Plane::Bits : Plane::Values);
            auto& slot = program->specs[static_cast<std::size_t>(plane)][static_cast<std::size_t>(spec.area)];
            if (!slot) slot = &spec;
        }
        collect_labels();
        bool ended = false;
        for (const auto& line : source.lines) {
            if (line.kind == SourceLine::Kind::Statement) continue;
            if (line.kind == SourceLine::Kind::Pointer) {
                end_rung();
                continue;
            }
            const bool is_end = upper(line.mnemonic) == "END";
            instruction(line);
            if (is_end) {
                ended = true;
                program->end_step = program->steps.size() - 1;
                break;
            }
        }
        if (!ended) problems.push_back(source.file + ": no END instruction");
        resolve_jumps();
        for (auto index : pending_timer_resets) {   // RST T before that timer's OUT
            auto& step = program->steps[index];
            auto slot = timer_slots.find({static_cast<int>(step.op[0].area), step.op[0].number});
            if (slot != timer_slots.end()) step.aux = slot->second + 1;
        }
        for (const auto& [level, row] : mc_levels)
            warnings.push_back(source.file + ": " + (source.format == Format::GxWorksCsv ? "row " : "line ") +
                               std::to_string(row) + ": MC N" + std::to_string(level) +
                               " has no MCR; it stays in force to END");
        if (!problems.empty()) throw LoadError(problems);
        return program;
    }
};

}  // namespace

namespace {
std::shared_ptr<const Program> compile_with(const Source& source, const devicemodel::CpuProfile& profile,
                                            const ProgramOptions& options, const devicemodel::LabelTable* labels,
                                            std::vector<std::string>* warnings) {
    Compiler compiler(source, profile, options, labels);
    auto program = compiler.run();
    if (warnings) warnings->insert(warnings->end(), compiler.warnings.begin(), compiler.warnings.end());
    return program;
}
}  // namespace

std::shared_ptr<const Program> compile(const Source& source, const devicemodel::CpuProfile& profile,
                                       const ProgramOptions& options, std::vector<std::string>* warnings) {
    return compile_with(source, profile, options, nullptr, warnings);
}

std::shared_ptr<const Program> compile(const Source& source, const devicemodel::CpuProfile& profile,
                                       const ProgramOptions& options, const devicemodel::LabelTable& labels,
                                       std::vector<std::string>* warnings) {
    return compile_with(source, profile, options, &labels, warnings);
}

const Source& source_of(const Program& program) { return program.source; }
std::size_t step_count(const Program& program) { return program.steps.size(); }
const std::vector<CompiledStep>& compiled_steps(const Program& program) { return program.info; }

}  // namespace slmp::program
