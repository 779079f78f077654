// The instruction table (docs/program.md "Instructions"). One row per
// mnemonic as the CPU names it; the P forms are the rows with
// pulse_form set (the compiler strips the trailing P only for those, so LDP,
// MPP, NOP, STOP and OUTHS stay instructions of their own).
#include "program/instruction_table.hpp"

#include <algorithm>
#include <array>

#include "program/handlers.hpp"

namespace slmp::program::detail {
namespace {

constexpr Form none{"", ""};

constexpr InstructionInfo row(std::string_view mnemonic, Role role, Cost cost, std::uint8_t families, bool pulse,
                              Form form, Handler handler, std::uint8_t variant = 0) {
    return {mnemonic, role, cost, families, pulse, false, false, 1, {form, none}, handler, "", variant};
}
constexpr InstructionInfo edge_row(std::string_view mnemonic, Role role, std::uint8_t families, Form form, Handler handler) {
    return {mnemonic, role, Cost::Basic, families, false, true, false, 1, {form, none}, handler, "", 0};
}
// "s d" (d := d op s) or "s1 s2 d".
constexpr InstructionInfo two_or_three(std::string_view mnemonic, Cost cost, std::string_view short_types,
                                       std::string_view long_types, Handler handler, std::uint8_t variant = 0) {
    return {mnemonic, Role::Output, cost, ALL, true, false, true, 2,
            {Form{short_types, "s d"}, Form{long_types, "s1 s2 d"}}, handler, "", variant};
}
// An FX name of iQ-F (docs/program.md "Instructions"): elsewhere the load error names the Q instruction.
constexpr InstructionInfo fx(std::string_view mnemonic, Cost cost, Form form, Handler handler, std::string_view q_name,
                             std::uint8_t variant = 0) {
    return {mnemonic, Role::Output, cost, IQF, true, false, false, 1, {form, none}, handler, q_name, variant};
}

constexpr std::uint8_t cmp(CompareKind kind, CompareOp op) { return static_cast<std::uint8_t>(kind | op << 2); }

#define SLMP_COMPARE_ROWS(prefix, role, handler, kind_text, kind, types)                                   \
    row(prefix kind_text "=", role, Cost::Basic, ALL, false, {types, "s1 s2"}, handler, cmp(kind, CmpEq)), \
    row(prefix kind_text "<>", role, Cost::Basic, ALL, false, {types, "s1 s2"}, handler, cmp(kind, CmpNe)), \
    row(prefix kind_text ">", role, Cost::Basic, ALL, false, {types, "s1 s2"}, handler, cmp(kind, CmpGt)), \
    row(prefix kind_text "<=", role, Cost::Basic, ALL, false, {types, "s1 s2"}, handler, cmp(kind, CmpLe)), \
    row(prefix kind_text "<", role, Cost::Basic, ALL, false, {types, "s1 s2"}, handler, cmp(kind, CmpLt)), \
    row(prefix kind_text ">=", role, Cost::Basic, ALL, false, {types, "s1 s2"}, handler, cmp(kind, CmpGe))
#define SLMP_COMPARE_KINDS(prefix, role, handler)                          \
    SLMP_COMPARE_ROWS(prefix, role, handler, "", CmpI16, "ww"),            \
    SLMP_COMPARE_ROWS(prefix, role, handler, "D", CmpI32, "dd"),           \
    SLMP_COMPARE_ROWS(prefix, role, handler, "E", CmpFloat, "ee"),         \
    SLMP_COMPARE_ROWS(prefix, role, handler, "$", CmpString, "ss")

const auto kTable = std::to_array<InstructionInfo>({
    // contacts and rung structure
    row("LD", Role::Load, Cost::Basic, ALL, false, {"b", "s"}, ld),
    row("LDI", Role::Load, Cost::Basic, ALL, false, {"b", "s"}, ldi),
    row("AND", Role::Combine, Cost::Basic, ALL, false, {"b", "s"}, and_),
    row("ANI", Role::Combine, Cost::Basic, ALL, false, {"b", "s"}, ani),
    row("OR", Role::Combine, Cost::Basic, ALL, false, {"b", "s"}, or_),
    row("ORI", Role::Combine, Cost::Basic, ALL, false, {"b", "s"}, ori),
    edge_row("LDP", Role::Load, ALL, {"b", "s"}, ldp),
    edge_row("LDF", Role::Load, ALL, {"b", "s"}, ldf),
    edge_row("ANDP", Role::Combine, ALL, {"b", "s"}, andp),
    edge_row("ANDF", Role::Combine, ALL, {"b", "s"}, andf),
    edge_row("ORP", Role::Combine, ALL, {"b", "s"}, orp),
    edge_row("ORF", Role::Combine, ALL, {"b", "s"}, orf),
    edge_row("LDPI", Role::Load, IQR | IQF, {"b", "s"}, ldpi),
    edge_row("LDFI", Role::Load, IQR | IQF, {"b", "s"}, ldfi),
    edge_row("ANDPI", Role::Combine, IQR | IQF, {"b", "s"}, andpi),
    edge_row("ANDFI", Role::Combine, IQR | IQF, {"b", "s"}, andfi),
    edge_row("ORPI", Role::Combine, IQR | IQF, {"b", "s"}, orpi),
    edge_row("ORFI", Role::Combine, IQR | IQF, {"b", "s"}, orfi),
    row("ANB", Role::Join, Cost::Basic, ALL, false, none, anb),
    row("ORB", Role::Join, Cost::Basic, ALL, false, none, orb),
    row("MPS", Role::BranchPush, Cost::Basic, ALL, false, none, mps),
    row("MRD", Role::BranchRead, Cost::Basic, ALL, false, none, mrd),
    row("MPP", Role::BranchPop, Cost::Basic, ALL, false, none, mpp),
    row("INV", Role::Modify, Cost::Basic, ALL, false, none, inv),
    edge_row("MEP", Role::Modify, ALL, none, mep),
    edge_row("MEF", Role::Modify, ALL, none, mef),
    // outputs; OUT and RST of timers, counters and words are chosen by operand in compile.cpp
    row("OUT", Role::Output, Cost::Basic, ALL, false, {"o", "d"}, out_bit),
    row("OUTH", Role::Output, Cost::Basic, ALL, false, {"tw", "d preset"}, out_timer),
    row("OUTHS", Role::Output, Cost::Basic, IQF, false, {"tw", "d preset"}, out_timer),
    row("SET", Role::Output, Cost::Basic, ALL, false, {"o", "d"}, set_bit),
    row("RST", Role::Output, Cost::Basic, ALL, false, {"o", "d"}, rst_bit),
    edge_row("PLS", Role::Output, ALL, {"o", "d"}, pls),
    edge_row("PLF", Role::Output, ALL, {"o", "d"}, plf),
    edge_row("FF", Role::Output, ALL, {"o", "d"}, ff),
    {"ALT", Role::Output, Cost::Basic, IQF, false, true, false, 1, {Form{"o", "d"}, none}, ff, "FF", 0},
    row("MC", Role::Master, Cost::Basic, ALL, false, {"No", "n d"}, mc),
    row("MCR", Role::Free, Cost::Basic, ALL, false, {"N", "n"}, mcr),
    row("NOP", Role::Free, Cost::Basic, ALL, false, none, nop),
    row("NOPLF", Role::Free, Cost::Basic, ALL, false, none, nop),
    row("PAGE", Role::Free, Cost::Basic, ALL, false, {"n", "n"}, nop),
    row("END", Role::Free, Cost::Basic, ALL, false, none, end),
    row("FEND", Role::Free, Cost::Basic, ALL, false, none, fend),

    // comparison contacts
    SLMP_COMPARE_KINDS("LD", Role::Load, compare_ld),
    SLMP_COMPARE_KINDS("AND", Role::Combine, compare_and),
    SLMP_COMPARE_KINDS("OR", Role::Combine, compare_or),

    // arithmetic
    two_or_three("+", Cost::Arith, "wW", "wwW", add16),
    two_or_three("-", Cost::Arith, "wW", "wwW", sub16),
    row("*", Role::Output, Cost::Arith, ALL, true, {"wwD", "s1 s2 d"}, mul16),
    row("/", Role::Output, Cost::Arith, ALL, true, {"wwv", "s1 s2 d"}, div16),
    two_or_three("D+", Cost::Arith, "dD", "ddD", add32),
    two_or_three("D-", Cost::Arith, "dD", "ddD", sub32),
    row("D*", Role::Output, Cost::Arith, ALL, true, {"ddV", "s1 s2 d"}, mul32),
    row("D/", Role::Output, Cost::Arith, ALL, true, {"ddV", "s1 s2 d"}, div32),
    row("INC", Role::Output, Cost::Move, ALL, true, {"W", "d"}, inc16),
    row("DEC", Role::Output, Cost::Move, ALL, true, {"W", "d"}, dec16),
    row("DINC", Role::Output, Cost::Move, ALL, true, {"D", "d"}, inc32),
    row("DDEC", Role::Output, Cost::Move, ALL, true, {"D", "d"}, dec32),
    row("NEG", Role::Output, Cost::Arith, ALL, true, {"W", "d"}, neg16),
    row("DNEG", Role::Output, Cost::Arith, ALL, true, {"D", "d"}, neg32),
    two_or_three("E+", Cost::Float, "eE", "eeE", fadd),
    two_or_three("E-", Cost::Float, "eE", "eeE", fsub),
    two_or_three("E*", Cost::Float, "eE", "eeE", fmul),
    two_or_three("E/", Cost::Float, "eE", "eeE", fdiv),
    row("ENEG", Role::Output, Cost::Float, ALL, true, {"E", "d"}, fneg),
    fx("ADD", Cost::Arith, {"wwW", "s1 s2 d"}, add16, "+"),
    fx("SUB", Cost::Arith, {"wwW", "s1 s2 d"}, sub16, "-"),
    fx("MUL", Cost::Arith, {"wwD", "s1 s2 d"}, mul16, "*"),
    fx("DIV", Cost::Arith, {"wwv", "s1 s2 d"}, div16, "/"),
    fx("DADD", Cost::Arith, {"ddD", "s1 s2 d"}, add32, "D+"),
    fx("DSUB", Cost::Arith, {"ddD", "s1 s2 d"}, sub32, "D-"),
    fx("DMUL", Cost::Arith, {"ddV", "s1 s2 d"}, mul32, "D*"),
    fx("DDIV", Cost::Arith, {"ddV", "s1 s2 d"}, div32, "D/"),

    // conversion
    row("BCD", Role::Output, Cost::Arith, ALL, true, {"wW", "s d"}, bcd16),
    row("DBCD", Role::Output, Cost::Arith, ALL, true, {"dD", "s d"}, bcd32),
    row("BIN", Role::Output, Cost::Arith, ALL, true, {"wW", "s d"}, bin16),
    row("DBIN", Role::Output, Cost::Arith, ALL, true, {"dD", "s d"}, bin32),
    row("FLT", Role::Output, Cost::Float, ALL, true, {"wE", "s d"}, flt16),
    row("DFLT", Role::Output, Cost::Float, ALL, true, {"dE", "s d"}, flt32),
    row("INT", Role::Output, Cost::Float, ALL, true, {"eW", "s d"}, int16),
    row("DINT", Role::Output, Cost::Float, ALL, true, {"eD", "s d"}, int32),
    row("INT2FLT", Role::Output, Cost::Float, IQR | IQF, true, {"wE", "s d"}, flt16),
    row("DINT2FLT", Role::Output, Cost::Float, IQR | IQF, true, {"dE", "s d"}, flt32),
    row("FLT2INT", Role::Output, Cost::Float, IQR | IQF, true, {"eW", "s d"}, int16),
    row("FLT2DINT", Role::Output, Cost::Float, IQR | IQF, true, {"eD", "s d"}, int32),

    // transfer
    row("MOV", Role::Output, Cost::Move, ALL, true, {"wW", "s d"}, mov16),
    row("DMOV", Role::Output, Cost::Move, ALL, true, {"dD", "s d"}, mov32),
    row("EMOV", Role::Output, Cost::Move, ALL, true, {"eE", "s d"}, mov32),
    row("$MOV", Role::Output, Cost::Move, ALL, true, {"sq", "s d"}, smov),
    row("CML", Role::Output, Cost::Move, ALL, true, {"wW", "s d"}, cml16),
    row("DCML", Role::Output, Cost::Move, ALL, true, {"dD", "s d"}, cml32),
    row("BMOV", Role::Output, Cost::Block, ALL, true, {"qqn", "s d n"}, bmov),
    row("FMOV", Role::Output, Cost::Block, ALL, true, {"wqn", "s d n"}, fmov16),
    row("DFMOV", Role::Output, Cost::Block, ALL, true, {"dqn", "s d n"}, fmov32),
    row("XCH", Role::Output, Cost::Move, ALL, true, {"WW", "d1 d2"}, xch16),
    row("DXCH", Role::Output, Cost::Move, ALL, true, {"DD", "d1 d2"}, xch32),
    row("SWAP", Role::Output, Cost::Move, ALL, true, {"W", "d"}, swap),

    // logic
    two_or_three("WAND", Cost::Arith, "wW", "wwW", logic16, 0),
    two_or_three("WOR", Cost::Arith, "wW", "wwW", logic16, 1),
    two_or_three("WXOR", Cost::Arith, "wW", "wwW", logic16, 2),
    two_or_three("WXNR", Cost::Arith, "wW", "wwW", logic16, 3),
    two_or_three("DAND", Cost::Arith, "dD", "ddD", logic32, 0),
    two_or_three("DOR", Cost::Arith, "dD", "ddD", logic32, 1),
    two_or_three("DXOR", Cost::Arith, "dD", "ddD", logic32, 2),
    two_or_three("DXNR", Cost::Arith, "dD", "ddD", logic32, 3),

    // rotation and shift: variant bit 0 = left, bit 1 = through the carry
    row("ROR", Role::Output, Cost::Arith, ALL, true, {"Wn", "d n"}, rotate16, 0),
    row("ROL", Role::Output, Cost::Arith, ALL, true, {"Wn", "d n"}, rotate16, 1),
    row("RCR", Role::Output, Cost::Arith, ALL, true, {"Wn", "d n"}, rotate16, 2),
    row("RCL", Role::Output, Cost::Arith, ALL, true, {"Wn", "d n"}, rotate16, 3),
    row("DROR", Role::Output, Cost::Arith, ALL, true, {"Dn", "d n"}, rotate32, 0),
    row("DROL", Role::Output, Cost::Arith, ALL, true, {"Dn", "d n"}, rotate32, 1),
    row("DRCR", Role::Output, Cost::Arith, ALL, true, {"Dn", "d n"}, rotate32, 2),
    row("DRCL", Role::Output, Cost::Arith, ALL, true, {"Dn", "d n"}, rotate32, 3),
    row("SFR", Role::Output, Cost::Arith, ALL, true, {"Wn", "d n"}, shift_word, 0),
    row("SFL", Role::Output, Cost::Arith, ALL, true, {"Wn", "d n"}, shift_word, 1),
    row("SFT", Role::Output, Cost::Arith, ALL, true, {"o", "d"}, sft),
    row("BSFR", Role::Output, Cost::Block, ALL, true, {"xn", "d n"}, bit_shift, 0),
    row("BSFL", Role::Output, Cost::Block, ALL, true, {"xn", "d n"}, bit_shift, 1),
    row("DSFR", Role::Output, Cost::Block, ALL, true, {"qn", "d n"}, word_shift, 0),
    row("DSFL", Role::Output, Cost::Block, ALL, true, {"qn", "d n"}, word_shift, 1),
    fx("SFTR", Cost::Block, {"yxnn", "s d n1 n2"}, fx_bit_shift, "BSFR", 0),
    fx("SFTL", Cost::Block, {"yxnn", "s d n1 n2"}, fx_bit_shift, "BSFL", 1),

    // bit and data processing
    row("BSET", Role::Output, Cost::Move, ALL, true, {"Wn", "d n"}, bset),
    row("BRST", Role::Output, Cost::Move, ALL, true, {"Wn", "d n"}, brst),
    row("TEST", Role::Output, Cost::Arith, ALL, true, {"wno", "s1 s2 d"}, test16),
    row("DTEST", Role::Output, Cost::Arith, ALL, true, {"dno", "s1 s2 d"}, test32),
    row("BKRST", Role::Output, Cost::Block, ALL, true, {"xn", "d n"}, bkrst),
    row("ZRST", Role::Output, Cost::Block, IQR | IQF, true, {"zz", "d1 d2"}, zrst),
    row("SUM", Role::Output, Cost::Arith, ALL, true, {"wW", "s d"}, sum16),
    row("DSUM", Role::Output, Cost::Arith, ALL, true, {"dW", "s d"}, sum32),
    row("DECO", Role::Output, Cost::Arith, ALL, true, {"wzn", "s d n"}, deco),
    row("ENCO", Role::Output, Cost::Arith, ALL, true, {"zWn", "s d n"}, enco),
    row("SEG", Role::Output, Cost::Arith, ALL, true, {"wW", "s d"}, seg),

    // program control
    row("CJ", Role::Output, Cost::Basic, ALL, false, {"p", "Pn"}, cj),
    edge_row("SCJ", Role::Output, ALL, {"p", "Pn"}, scj),
    row("JMP", Role::Free, Cost::Basic, ALL, false, {"p", "Pn"}, jmp),
    row("GOEND", Role::Output, Cost::Basic, ALL, false, none, goend),
    row("CALL", Role::Output, Cost::Basic, ALL, true, {"p", "Pn"}, call),
    row("RET", Role::Free, Cost::Basic, ALL, false, none, ret),
    row("FOR", Role::Free, Cost::Basic, ALL, false, {"n", "n"}, for_),
    row("NEXT", Role::Free, Cost::Basic, ALL, false, none, next),
    row("BREAK", Role::Output, Cost::Basic, ALL, false, {"Wp", "d Pn"}, break_),
    row("WDT", Role::Output, Cost::Basic, ALL, false, none, wdt),
    row("STOP", Role::Output, Cost::Basic, ALL, false, none, stop),
});

#undef SLMP_COMPARE_KINDS
#undef SLMP_COMPARE_ROWS

}  // namespace

const InstructionInfo* find_instruction(std::string_view mnemonic) {
    for (const auto& info : kTable)
        if (info.mnemonic == mnemonic) return &info;
    return nullptr;
}

}  // namespace slmp::program::detail

namespace slmp::program {

std::optional<InstructionShape> instruction_shape(std::string_view mnemonic) {
    using detail::Role;
    const auto* info = detail::find_instruction(mnemonic);
    if (!info && mnemonic.size() > 1 && mnemonic.back() == 'P') {
        info = detail::find_instruction(mnemonic.substr(0, mnemonic.size() - 1));
        if (info && !info->pulse_form) info = nullptr;
    }
    if (!info) return std::nullopt;
    InstructionShape shape;
    for (std::size_t i = 0; i < info->form_count; ++i) {
        shape.forms.push_back(info->forms[i].types);
        shape.names.push_back(info->forms[i].names);
    }
    const bool takes_pointer = std::any_of(shape.forms.begin(), shape.forms.end(),
                                           [](std::string_view types) { return types.find('p') != std::string_view::npos; });
    const bool flow = info->handler == detail::stop || info->handler == detail::goend || info->handler == detail::wdt;
    switch (info->role) {
        case Role::Load: shape.role = InstructionShape::Role::Load; break;
        case Role::Combine: shape.role = InstructionShape::Role::Combine; break;
        case Role::Join: shape.role = InstructionShape::Role::Join; break;
        case Role::BranchPush: shape.role = InstructionShape::Role::BranchPush; break;
        case Role::BranchRead: shape.role = InstructionShape::Role::BranchRead; break;
        case Role::BranchPop: shape.role = InstructionShape::Role::BranchPop; break;
        case Role::Modify: shape.role = InstructionShape::Role::Modify; break;
        case Role::Output: shape.role = InstructionShape::Role::Output; break;
        case Role::Master:
        case Role::Free: shape.role = InstructionShape::Role::Control; break;
    }
    if (takes_pointer || flow) shape.role = InstructionShape::Role::Control;
    return shape;
}

}  // namespace slmp::program

namespace slmp::program::detail {

bool known_but_unsupported(std::string_view mnemonic) {
    // Unsigned (LD=_U ...) and double-float (LDED= ...) compare contacts are phase 2 (docs/program.md "Instructions").
    if (mnemonic.ends_with("_U")) return true;
    for (std::string_view prefix : {"LDED", "ANDED", "ORED"})
        if (mnemonic.starts_with(prefix)) return true;
    // Interrupts (docs/program.md "Instructions") and a few common instructions not in phase 1.
    static constexpr std::array<std::string_view, 22> kKnown{
        "DI", "EI", "IRET", "IMASK", "RFS", "COM", "PID", "SORT", "ABS", "DABS", "LIMIT", "DLIMIT",
        "UDCNT1", "UDCNT2", "TTMR", "STMR", "RAMP", "SPD", "PLSY", "PWM", "SER", "DSER"};
    return std::find(kKnown.begin(), kKnown.end(), mnemonic) != kKnown.end();
}

std::uint8_t family_bit(devicemodel::Family family) {
    switch (family) {
        case devicemodel::Family::IQR: return IQR;
        case devicemodel::Family::IQF: return IQF;
        default: return QL;
    }
}

std::string_view family_name(devicemodel::Family family) {
    switch (family) {
        case devicemodel::Family::IQR: return "iQ-R";
        case devicemodel::Family::IQF: return "iQ-F";
        case devicemodel::Family::L: return "L";
        case devicemodel::Family::QJ71E71: return "QJ71E71";
        default: return "QnU";
    }
}

// SD0 codes by cause and family (docs/program.md "Operation errors"): Q/L codes are decimal numbers
// stored as binary (4100 -> 0x1004), iQ-R/iQ-F codes hexadecimal. Every iQ
// code and the Q nest codes are inferred (docs/program.md "Operation errors"
// lists them as unverified); a profile key may override them later.
namespace {
struct ErrorCodes {
    Cause cause;
    std::uint16_t q_l;   // QnU, L (and a QJ71E71's CPU)
    std::uint16_t iq;    // iQ-R, iQ-F
};
constexpr std::array<ErrorCodes, 10> kErrorCodes{{
    {Cause::DivideByZero, 4100, 0x3400},
    {Cause::Range, 4100, 0x3405},
    {Cause::Device, 4101, 0x2820},
    {Cause::Float, 4140, 0x3402},
    {Cause::NextWithoutFor, 4201, 0x3300},
    {Cause::ForNest, 4202, 0x3300},
    {Cause::BreakWithoutFor, 4203, 0x3300},
    {Cause::ReturnWithoutCall, 4212, 0x3300},
    {Cause::CallNest, 4213, 0x3300},
    {Cause::Watchdog, 5001, 0x1810},   // iQ: placeholder of docs/program.md "Modelled time"
}};
}  // namespace

std::uint16_t error_code(devicemodel::Family family, Cause cause) {
    const bool iq = family == devicemodel::Family::IQR || family == devicemodel::Family::IQF;
    for (const auto& entry : kErrorCodes)
        if (entry.cause == cause) return iq ? entry.iq : entry.q_l;
    return 0;
}

std::string_view cause_text(Cause cause) {
    switch (cause) {
        case Cause::DivideByZero: return "division by 0";
        case Cause::Range: return "value outside what the instruction accepts";
        case Cause::Device: return "device outside the configured size after index modification";
        case Cause::Float: return "floating-point operand or result not a normal number";
        case Cause::CallNest: return "CALL nested deeper than 16";
        case Cause::ReturnWithoutCall: return "RET without CALL";
        case Cause::ForNest: return "FOR nested deeper than 16";
        case Cause::NextWithoutFor: return "NEXT without FOR";
        case Cause::BreakWithoutFor: return "BREAK outside FOR/NEXT";
        case Cause::Watchdog: return "watchdog";
        case Cause::None: break;
    }
    return "";
}

// docs/program.md "Modelled time", in picoseconds (END processing in µs there).
Costs costs_for(devicemodel::Family family) {
    switch (family) {
        case devicemodel::Family::IQR: return {980, 1960, 4000, 20000, 1000, 50'000'000};
        case devicemodel::Family::IQF: return {34000, 34000, 200000, 1000000, 50000, 200'000'000};
        default: return {9500, 19000, 40000, 200000, 10000, 150'000'000};
    }
}

}  // namespace slmp::program::detail
