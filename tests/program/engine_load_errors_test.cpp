// Spec §9 load errors, each with its exact message, and the warnings.
#include <catch2/catch.hpp>

#include "engine_support.hpp"
#include "program/operands.hpp"

using namespace engine_test;

namespace {

// Lines placed at given line numbers (the others blank), as the text form.
program::Source at_lines(std::initializer_list<std::pair<int, std::string>> placed, std::string file = "line1.il") {
    std::vector<std::string> lines;
    for (const auto& [row, text] : placed) {
        if (static_cast<int>(lines.size()) < row) lines.resize(static_cast<std::size_t>(row));
        lines[static_cast<std::size_t>(row - 1)] = text;
    }
    return text_source(lines, std::move(file));
}

program::SourceLine csv_row(std::size_t row, std::uint32_t step, std::string mnemonic, std::vector<std::string> operands) {
    program::SourceLine line;
    line.row = row;
    line.step = step;
    line.mnemonic = std::move(mnemonic);
    line.operands = std::move(operands);
    return line;
}

program::Source csv(std::vector<program::SourceLine> lines) {
    program::Source source;
    source.file = "line1.csv";
    source.format = program::Format::GxWorksCsv;
    source.lines = std::move(lines);
    return source;
}

}  // namespace

TEST_CASE("load error: unknown mnemonic (CSV location)", "[program][engine][load]") {
    auto problems = load_problems(csv({csv_row(13, 11, "LD", {"X0"}), csv_row(14, 12, "MOVV", {"K1", "D0"}),
                                       csv_row(17, 15, "END", {})}),
                                  r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.csv: row 14 (step 12): 'MOVV' is no instruction of R08CPU (family iQ-R)");
}

TEST_CASE("load error: missing operand row (CSV)", "[program][engine][load]") {
    auto problems = load_problems(
        csv({csv_row(19, 16, "LD", {"SM400"}), csv_row(20, 17, "/", {"K1", "D0"}), csv_row(22, 20, "END", {})}), r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.csv: row 20 (step 17): '/' needs 3 operands (s1 s2 d), found 2; add a continuation row");
}

TEST_CASE("load error: jump to an undefined pointer", "[program][engine][load]") {
    auto problems = load_problems(at_lines({{8, "LD X0"}, {9, "CJ P12"}, {10, "END"}}), r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.il: line 9: 'CJ P12' jumps to a pointer that is not defined");
}

TEST_CASE("load error: output with open blocks", "[program][engine][load]") {
    auto problems = load_problems(at_lines({{28, "LD X0"}, {29, "LD X1"}, {30, "OUT Y3"}, {31, "END"}}), r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.il: line 30: OUT Y3 with 2 open blocks; join them with ANB or ORB first");
}

TEST_CASE("load error: a timer driven by two OUT steps", "[program][engine][load]") {
    const auto source = at_lines({{11, "LD X0"}, {12, "OUT T5 K10"}, {43, "LD X1"}, {44, "OUT T5 K20"}, {45, "END"}});
    auto problems = load_problems(source, r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.il: line 44: T5 has OUT at lines 12 and 44 (set allow_double_timer_coils to permit)");
    program::ProgramOptions allowed;
    allowed.allow_double_timer_coils = true;
    CHECK(load_problems(source, r08(), allowed).empty());
}

TEST_CASE("load error: device outside the profile", "[program][engine][load]") {
    auto problems = load_problems(at_lines({{49, "LD SM400"}, {50, "MOV K1 D20000"}, {51, "END"}}), r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.il: line 50: D20000 is outside D (10240 points) for R08CPU");
    // The second word of a 32-bit operand counts; an area the CPU lacks has 0 points.
    problems = load_problems(at_lines({{1, "LD SM400"}, {2, "DMOV K1 D10239"}, {3, "OUT LT0 K5"}, {4, "END"}}), r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.il: line 2: D10239 is outside D (10240 points) for R08CPU");
    problems = load_problems(at_lines({{1, "LD SM400"}, {2, "OUT LT0 K5"}, {3, "END"}}), q26());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.il: line 2: LT0 is outside LT (0 points) for Q26UDEHCPU");
}

TEST_CASE("load error: digit designation too wide", "[program][engine][load]") {
    auto problems = load_problems(at_lines({{50, "LD SM400"}, {51, "MOV K5M0 D0"}, {52, "END"}}), r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.il: line 51: K5M0 is too wide for MOV (K1-K4); use DMOV for K5-K8");
    CHECK(load_problems(dotted("LD SM400 · DMOV K8M0 D0 · END"), r08()).empty());
}

TEST_CASE("load error: FX names outside iQ-F", "[program][engine][load]") {
    auto problems = load_problems(at_lines({{59, "LD SM400"}, {60, "ADD K1 D0 D1"}, {61, "END"}}), r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.il: line 60: 'ADD' is an FX instruction; write '+'");
    CHECK(load_problems(at_lines({{59, "LD SM400"}, {60, "ADD K1 D0 D1"}, {61, "END"}}), fx5u()).empty());
}

TEST_CASE("load error: no END", "[program][engine][load]") {
    auto problems = load_problems(at_lines({{1, "LD X0"}, {2, "OUT Y0"}}), r08());
    REQUIRE(problems.size() == 1);
    CHECK(problems[0] == "line1.il: no END instruction");
}

TEST_CASE("load errors are all collected, one line each", "[program][engine][load]") {
    auto problems = load_problems(at_lines({{1, "LD X0"}, {2, "MOVV K1 D0"}, {3, "CJ P12"}, {4, "MOV K1 D20000"}}), r08());
    REQUIRE(problems.size() == 4);
    CHECK(problems[0] == "line1.il: line 2: 'MOVV' is no instruction of R08CPU (family iQ-R)");
    CHECK(problems[1] == "line1.il: line 4: D20000 is outside D (10240 points) for R08CPU");
    CHECK(problems[2] == "line1.il: no END instruction");
    CHECK(problems[3] == "line1.il: line 3: 'CJ P12' jumps to a pointer that is not defined");
}

TEST_CASE("load errors: structure, availability, operands", "[program][engine][load]") {
    auto one = [](const std::string& text, devicemodel::CpuProfile profile = r08()) {
        auto problems = load_problems(dotted(text), profile);
        return problems.size() == 1 ? problems[0] : (problems.empty() ? "(loads)" : "(" + std::to_string(problems.size()) + " problems)");
    };
    CHECK(one("OUT Y0 · END") == "test.il: line 1: OUT Y0 has no condition; start the rung with LD");
    CHECK(one("LD X0 · ANB · OUT Y0 · END") == "test.il: line 2: ANB needs two open blocks, found 1");
    CHECK(one("LD X0 · MRD · OUT Y0 · END") == "test.il: line 2: MRD without MPS");
    CHECK(one("LD X0 · OUT X1 · END") == "test.il: line 2: X1 is an input; 'OUT' cannot write it");
    CHECK(one("LD X0 · MOV K1 M0 · END") == "test.il: line 2: M0 is a bit device; 'MOV' needs a word here (e.g. K4M0)");
    CHECK(one("LD X0 · MOV K1 K70000 · END") == "test.il: line 2: K70000 is a constant; 'MOV' needs a device here");
    CHECK(one("LD X0 · MOV K70000 D0 · END") ==
          "test.il: line 2: K70000 does not fit 16 bits (K-32768 to K32767, H0 to HFFFF); use the D form of 'MOV'");
    CHECK(one("LD X0 · E+ K1 D0 D2 · END") == "test.il: line 2: 'E+' takes a real number here; write E1 instead of K1");
    CHECK(one("LD X0 · MOV @D0 D1 · END") == "test.il: line 2: '@D0': indirect addressing (@) is not supported by slmp-sim yet");
    CHECK(one("LD X0 · DI · END") == "test.il: line 2: 'DI' is not supported by slmp-sim yet");
    CHECK(one("LD=_U D0 K1 · OUT Y0 · END") == "test.il: line 1: 'LD=_U' is not supported by slmp-sim yet");
    CHECK(one("LDED= D0 D4 · OUT Y0 · END") == "test.il: line 1: 'LDED=' is not supported by slmp-sim yet");
    CHECK(one("LD X0 · OUT Y0 · NOPLF · PAGE K1 · LD X1 · OUT Y1 · END") == "(loads)");
    CHECK(one("LD X0 · OUT T0 · END") == "test.il: line 2: 'OUT' needs 2 operands (d preset), found 1");
    CHECK(one("LD X0 · MOV K1 · END") == "test.il: line 2: 'MOV' needs 2 operands (s d), found 1");
    CHECK(one("LD X0 · + K1 · END") == "test.il: line 2: '+' needs 2 or 3 operands (s d | s1 s2 d), found 1");
    CHECK(one("LD X0 X1 · OUT Y0 · END") == "test.il: line 1: 'LD' takes 1 operand (s), found 2");
    CHECK(one("LD X0 · NEXT · END") == "test.il: line 2: NEXT without FOR");
    CHECK(one("FOR K3 · LD X0 · OUT Y0 · END") == "test.il: line 4: FOR at line 1 has no NEXT before END");
    CHECK(one("LD X0 · RET · END") == "test.il: line 2: RET outside a subroutine (subroutines follow FEND)");
    CHECK(one("LD X0 · MC N1 M0 · LD X1 · MC N0 M1 · MCR N0 · MCR N1 · END") ==
          "test.il: line 4: MC N0 inside MC N1: nested levels must increase");
    CHECK(one("LD X0 · MCR N3 · END") == "test.il: line 2: MCR N3 without MC N3");
    std::string branches = "LD X0";
    for (int i = 0; i < 17; ++i) branches += " · MPS";
    CHECK(one(branches + " · OUT Y0 · END") == "test.il: line 18: MPS nested deeper than 16");
    CHECK(one("LD X0 · MC N15 M0 · END") == "test.il: line 2: N15: nesting levels are N0 to N14");
    CHECK(one("P1 · LD X0 · OUT Y0 · P1 · END") == "test.il: line 4: P1 is defined twice (lines 1 and 4)");
    CHECK(one("LD X0 · CJ P1 · FEND · P1 · RET · END") ==
          "test.il: line 2: 'CJ P1' jumps between the main routine and the subroutines after FEND");
    CHECK(one("LD X0 · OUT C1 K1 · LD X1 · OUT C1 K2 · END") ==
          "test.il: line 4: C1 has OUT at lines 2 and 4 (set allow_double_timer_coils to permit)");
    CHECK(one("LD X0 · OUTH C1 K1 · END") == "test.il: line 2: 'OUTH' drives timers only; count with OUT C1");
    // availability by family (docs/program.md "Instructions")
    CHECK(one("LDPI X0 · OUT Y0 · END", q26()) == "test.il: line 1: 'LDPI' is no instruction of Q26UDEHCPU (family QnU)");
    CHECK(one("LDPI X0 · OUT Y0 · END") == "(loads)");
    CHECK(one("LD X0 · OUTHS T0 K1 · END") == "test.il: line 2: 'OUTHS' is no instruction of R08CPU (family iQ-R)");
    CHECK(one("LD X0 · OUTHS T0 K1 · END", fx5u()) == "(loads)");
    CHECK(one("LD X0 · ZRST D0 D9 · END", q26()) == "test.il: line 2: 'ZRST' is no instruction of Q26UDEHCPU (family QnU)");
    CHECK(one("LD X0 · ZRST D0 D9 · END") == "(loads)");
    CHECK(one("LD X0 · ALT Y0 · END") == "test.il: line 2: 'ALT' is an FX instruction; write 'FF'");
    CHECK(one("LD X0 · SFTRP X0 Y0 K4 K1 · END") == "test.il: line 2: 'SFTRP' is an FX instruction; write 'BSFRP'");
    CHECK(one("LD X8 · OUT Y0 · END", fx5u()) == "test.il: line 1: bad device number in 'X8' (X is numbered in octal)");
    CHECK(one("LD X0 · MOV Z0 D0 · INC LZ0 · END", q26()) == "test.il: line 3: LZ0 is outside LZ (0 points) for Q26UDEHCPU");
}

TEST_CASE("P forms come from the table, not from stripping every P", "[program][engine][load]") {
    CHECK(load_problems(dotted("LD X0 · MOVP K1 D0 · +P K1 D1 · D+P K1 D2 · EMOVP E1 D4 · $MOVP \"A\" D6 · BMOVP D0 D8 K2 · "
                               "INCP D0 · WANDP K1 D0 · RORP D0 K1 · DECOP K1 M0 K2 · SFTP M10 · CALLP P1 · FEND · P1 · RET · END"),
                        r08())
              .empty());
    CHECK(load_problems(dotted("LD X0 · CJP P1 · P1 · END"), r08()) ==
          std::vector<std::string>{"test.il: line 2: 'CJP' is no instruction of R08CPU (family iQ-R)"});
    CHECK(load_problems(dotted("LD X0 · OUTP Y0 · END"), r08()) ==
          std::vector<std::string>{"test.il: line 2: 'OUTP' is no instruction of R08CPU (family iQ-R)"});
}

TEST_CASE("load warnings: double coil of a bit, MC without MCR", "[program][engine][load]") {
    std::vector<std::string> warnings;
    CHECK(load_problems(dotted("LD X0 · OUT Y0 · LD X1 · OUT Y0 · LD X2 · MC N0 M0 · END"), r08(), {}, &warnings).empty());
    REQUIRE(warnings.size() == 2);
    CHECK(warnings[0] == "test.il: line 4: Y0 has OUT at lines 2 and 4 (double coil: the last one executed wins)");
    CHECK(warnings[1] == "test.il: line 6: MC N0 has no MCR; it stays in force to END");
}

TEST_CASE("a bit of a word device takes its hex digit in either case, anything else is refused", "[program][engine][load]") {
    std::string error;
    auto lower = slmp::program::detail::parse_operand("D0.a", slmp::devicemodel::Numbering{}, error);
    REQUIRE(lower);
    CHECK(lower->bit == 10);   // was bit 42, past the word
    auto upper = slmp::program::detail::parse_operand("D0.F", slmp::devicemodel::Numbering{}, error);
    REQUIRE(upper);
    CHECK(upper->bit == 15);
    CHECK_FALSE(slmp::program::detail::parse_operand("D0.G", slmp::devicemodel::Numbering{}, error));
    CHECK(error == "bad bit number in 'D0.G' (0-F, e.g. D0.F)");
}
