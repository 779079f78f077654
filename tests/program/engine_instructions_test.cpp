// Instruction groups of docs/program.md "Instructions" against their tables: wrap-around, remainder
// signs, digit designation, index range errors, P forms, floats, strings,
// shifts, data processing.
#include <catch2/catch.hpp>

#include <bit>
#include <cstring>

#include "engine_support.hpp"

using namespace engine_test;
using Kind = program::ScanOutcome::Kind;

namespace {
std::int32_t s16(std::uint32_t v) { return static_cast<std::int16_t>(v); }
std::uint32_t pair(const Rig& rig, int d) {
    return rig.get("D" + std::to_string(d)) | (rig.get("D" + std::to_string(d + 1)) << 16);
}
float real(const Rig& rig, int d) { return std::bit_cast<float>(pair(rig, d)); }
program::ProgramOptions continuing() {
    program::ProgramOptions options;
    options.operation_error = program::OnOperationError::Continue;
    return options;
}
}  // namespace

TEST_CASE("§5.4 16-bit arithmetic wraps, / truncates toward 0, remainder takes the dividend's sign",
          "[program][engine][arith]") {
    Rig rig(dotted("LD SM400 · + K32767 K1 D0 · - K-32768 K1 D1 · MOV K5 D2 · + K3 D2 · - K10 D2 · / K36 K-5 D10 · "
                   "/ K-36 K-5 D12 · / K-32768 K-1 D14 · * K-300 K400 D16 · MOV K32767 D20 · INC D20 · MOV K-32768 D21 · "
                   "DEC D21 · MOV K-32768 D22 · NEG D22 · MOV K7 D23 · NEG D23 · / K100 K7 K4M0 · END"));
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(s16(rig.get("D0")) == -32768);
    CHECK(s16(rig.get("D1")) == 32767);
    CHECK(s16(rig.get("D2")) == -2);
    CHECK(s16(rig.get("D10")) == -7);
    CHECK(s16(rig.get("D11")) == 1);
    CHECK(s16(rig.get("D12")) == 7);
    CHECK(s16(rig.get("D13")) == -1);
    CHECK(s16(rig.get("D14")) == -32768);
    CHECK(s16(rig.get("D15")) == 0);
    CHECK(static_cast<std::int32_t>(pair(rig, 16)) == -120000);
    CHECK(s16(rig.get("D20")) == -32768);
    CHECK(s16(rig.get("D21")) == 32767);
    CHECK(s16(rig.get("D22")) == -32768);
    CHECK(s16(rig.get("D23")) == -7);
    // A digit-designated d of / gets the quotient only ([FX3]): 14 = 0b1110 in M0-M15, M16 untouched.
    CHECK(rig.get("M0") == 0);
    CHECK(rig.get("M1") == 1);
    CHECK(rig.get("M3") == 1);
    CHECK(rig.get("M16") == 0);
}

TEST_CASE("§5.4 32-bit arithmetic: D+ D- D* D/ DINC DDEC DNEG", "[program][engine][arith]") {
    Rig rig(dotted("LD SM400 · D+ K2147483647 K1 D0 · D- K-2147483648 K1 D2 · D* K100000 K100000 D4 · D/ K-100000 K7 D8 · "
                   "DMOV K-1 D12 · DINC D12 · DMOV K0 D14 · DDEC D14 · DMOV K-2147483648 D16 · DNEG D16 · END"));
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(pair(rig, 0) == 0x80000000u);
    CHECK(pair(rig, 2) == 0x7FFFFFFFu);
    // 10^10 = 0x2_540B_E400 over D4..D7
    CHECK(rig.get("D4") == 0xE400);
    CHECK(rig.get("D5") == 0x540B);
    CHECK(rig.get("D6") == 0x0002);
    CHECK(rig.get("D7") == 0);
    CHECK(static_cast<std::int32_t>(pair(rig, 8)) == -14285);
    CHECK(static_cast<std::int32_t>(pair(rig, 10)) == -5);
    CHECK(pair(rig, 12) == 0);
    CHECK(pair(rig, 14) == 0xFFFFFFFFu);
    CHECK(pair(rig, 16) == 0x80000000u);
}

TEST_CASE("§5.4 float arithmetic and its errors", "[program][engine][arith]") {
    Rig rig(dotted("LD SM400 · EMOV E1.5 D0 · E+ E2.25 D0 · E- E10 D0 D2 · E* E1.234E+3 E2 D4 · E/ E1 E4 D6 · EMOV E3 D8 · "
                   "ENEG D8 · EMOV E1.5+2 D10 · END"));
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(real(rig, 0) == 3.75f);
    CHECK(real(rig, 2) == 6.25f);
    CHECK(real(rig, 4) == 2468.0f);
    CHECK(real(rig, 6) == 0.25f);
    CHECK(real(rig, 8) == -3.0f);
    CHECK(real(rig, 10) == 150.0f);   // GX Developer exponent style

    Rig zero(dotted("LD SM400 · E/ E1 E0 D0 · END"));
    auto outcome = zero.scan();
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 0x3400);
    // Overflow to infinity and a -0 operand are float errors.
    Rig overflow(dotted("LD SM400 · E* E3E+38 E10 D0 · END"));
    outcome = overflow.scan();
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 0x3402);
    Rig negative_zero(dotted("LD SM400 · MOV H8000 D1 · E+ D0 E1 D2 · END"));
    outcome = negative_zero.scan();
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 0x3402);
    CHECK(negative_zero.get("D3") == 0);
}

TEST_CASE("§5.5 conversion: BCD/BIN ranges, INT rounding and range", "[program][engine][conversion]") {
    Rig rig(dotted("LD SM400 · BCD K9999 D0 · DBCD K99999999 D2 · BIN H9999 D4 · DBIN H12345678 D6 · FLT K-7 D8 · "
                   "DFLT K-100000 D10 · INT E2.5 D12 · INT E-0.5 D13 · DINT E1E+6 D14 · INT E32767.4 D16 · END"));
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(rig.get("D0") == 0x9999);
    CHECK(pair(rig, 2) == 0x99999999u);
    CHECK(rig.get("D4") == 9999);
    CHECK(pair(rig, 6) == 12345678u);
    CHECK(real(rig, 8) == -7.0f);
    CHECK(real(rig, 10) == -100000.0f);
    CHECK(rig.get("D12") == 3);                   // half away from zero
    CHECK(s16(rig.get("D13")) == -1);
    CHECK(pair(rig, 14) == 1000000u);
    CHECK(rig.get("D16") == 32767);

    auto code_of = [](const std::string& text) -> std::uint16_t {
        Rig r(dotted(text));
        auto outcome = r.scan();
        return outcome.error ? outcome.error->code : 0;
    };
    CHECK(code_of("LD SM400 · BCD K10000 D0 · END") == 0x3405);
    CHECK(code_of("LD SM400 · BCD K-1 D0 · END") == 0x3405);
    CHECK(code_of("LD SM400 · DBCD K100000000 D0 · END") == 0x3405);
    CHECK(code_of("LD SM400 · BIN H000A D0 · END") == 0x3405);
    CHECK(code_of("LD SM400 · INT E32767.5 D0 · END") == 0x3405);
    CHECK(code_of("LD SM400 · DINT E3E+9 D0 · END") == 0x3405);
    CHECK(code_of("LD SM400 · INT2FLT K3 D0 · FLT2INT D0 D2 · END") == 0);
}

TEST_CASE("§2.6 digit designation: zero-extended sources, partial destinations", "[program][engine][digits]") {
    Rig rig(dotted("LD SM400 · MOV HFFFF K4M0 · MOV K1M0 D0 · MOV K4M0 D1 · DMOV K4M0 D2 · MOV HFFFF K1Y0 · "
                   "MOV K-1 K3M100 · DMOV K-1 K5M200 · + K1M0 K1 D4 · END"));
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(rig.get("D0") == 15);        // not -1
    CHECK(rig.get("D1") == 0xFFFF);
    CHECK(pair(rig, 2) == 0xFFFF);     // zero-extended to 32 bits
    CHECK(rig.get("Y3") == 1);
    CHECK(rig.get("Y4") == 0);
    CHECK(rig.get("M111") == 1);
    CHECK(rig.get("M112") == 0);
    CHECK(rig.get("M219") == 1);
    CHECK(rig.get("M220") == 0);
    CHECK(rig.get("D4") == 16);
}

TEST_CASE("index modification: Z and LZ, negative offsets, past the end", "[program][engine][index]") {
    Rig rig(dotted("LD SM400 · MOV K-2 Z0 · MOV K7 D12Z0 · DMOV K100 LZ0 · MOV K9 D0LZ0 · MOV K2 Z1 · OUT Y0Z1 · "
                   "LD M2Z1 · OUT M10 · END"));
    rig.set("M4", 1);
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(rig.get("D10") == 7);
    CHECK(rig.get("D100") == 9);
    CHECK(rig.get("Y2") == 1);
    CHECK(rig.get("M10") == 1);

    auto error_of = [](const std::string& text, devicemodel::CpuProfile profile = r08()) -> std::uint16_t {
        Rig r(dotted(text), profile);
        auto outcome = r.scan();
        return outcome.error ? outcome.error->code : 0;
    };
    CHECK(error_of("LD SM400 · MOV K1 Z0 · MOV K5 D10239Z0 · END") == 0x2820);
    CHECK(error_of("LD SM400 · MOV K0 Z0 · DMOV K5 D10238Z0 · END") == 0);
    CHECK(error_of("LD SM400 · MOV K1 Z0 · DMOV K5 D10238Z0 · END") == 0x2820);   // the high word is D10240
    CHECK(error_of("LD SM400 · MOV K-1 Z0 · MOV D0Z0 D1 · END") == 0x2820);
    CHECK(error_of("LD SM400 · MOV K12280 Z0 · MOV K4M0Z0 D0 · END") == 0x2820);   // M12280..M12295: past 12288
    CHECK(error_of("LD SM400 · MOV K1 Z0 · LD X2FFFZ0 · OUT Y0 · END") == 0x2820);
    CHECK(error_of("LD SM400 · MOV K1 Z0 · MOV K5 D12287Z0 · END", q26()) == 4101);

    // With continue the failing instruction writes nothing and the scan goes on.
    program::ProgramOptions options = continuing();
    Rig cont(dotted("LD SM400 · MOV K9000 Z0 · BMOV D0 D2000Z0 K2000 · MOV K1 D1 · END"), r08(), options);
    auto outcome = cont.scan();
    CHECK(outcome.kind == Kind::Ok);
    CHECK(cont.get("D1") == 1);
    CHECK(cont.get("SD0") == 0x2820);
}

TEST_CASE("§5.11 every P form fires once per rising edge", "[program][engine][pulse]") {
    Rig rig(dotted("LD X0 · MOVP K5 D0 · +P K1 D1 · D+P K1 D2 · INCP D4 · BMOVP D1 D10 K1 · FMOVP K3 D20 K2 · "
                   "EMOVP E1.5 D30 · CALLP P1 · $MOVP \"AB\" D40 · WANDP HFF D50 · SFTP M1 · FEND · P1 · LD SM400 · INC D60 · "
                   "RET · END"));
    rig.set("D50", 0x1234);
    rig.set("M0", 1);
    rig.set("X0", 1);
    rig.scan(3);
    CHECK(rig.get("D0") == 5);
    CHECK(rig.get("D1") == 1);
    CHECK(pair(rig, 2) == 1);
    CHECK(rig.get("D4") == 1);
    CHECK(rig.get("D10") == 1);
    CHECK(rig.get("D21") == 3);
    CHECK(real(rig, 30) == 1.5f);
    CHECK(rig.get("D60") == 1);
    CHECK(rig.get("D40") == 0x4241);
    CHECK(rig.get("D50") == 0x34);
    CHECK(rig.get("M1") == 1);
    rig.set("X0", 0);
    rig.scan();
    rig.set("X0", 1);
    rig.scan(2);
    CHECK(rig.get("D1") == 2);
    CHECK(rig.get("D4") == 2);
    CHECK(rig.get("D60") == 2);
}

TEST_CASE("§5.3 comparison contacts: 16, 32, float, string", "[program][engine][compare]") {
    Rig rig(dotted("LD= D0 K-1 · OUT M0 · LD<> D0 K-1 · OUT M1 · LD> D0 K-2 · AND< D0 K0 · OUT M2 · LDD> D2 K65535 · OUT M3 · "
                   "LDE>= D4 E1.5 · OUT M4 · LD$= D10 \"OK\" · OUT M5 · LD$< D10 \"OKAY\" · OUT M6 · LD<= K1 K0 · "
                   "OR>= K1 K1 · OUT M7 · LD X0 · ANDD= D2 K65536 · ORE< D4 E2 · OUT M8 · END"));
    rig.set("D0", 0xFFFF);
    rig.set("D2", 0);
    rig.set("D3", 1);   // 65536
    const auto f = std::bit_cast<std::uint32_t>(1.5f);
    rig.set("D4", f & 0xFFFF);
    rig.set("D5", f >> 16);
    rig.set("D10", 'O' | ('K' << 8));
    rig.set("D11", 0);
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(rig.get("M0") == 1);
    CHECK(rig.get("M1") == 0);
    CHECK(rig.get("M2") == 1);
    CHECK(rig.get("M3") == 1);
    CHECK(rig.get("M4") == 1);
    CHECK(rig.get("M5") == 1);
    CHECK(rig.get("M6") == 1);   // "OK" is a prefix of "OKAY": smaller
    CHECK(rig.get("M7") == 1);
    CHECK(rig.get("M8") == 1);
}

TEST_CASE("§5.6 transfer: BMOV overlap, FMOV, DFMOV, XCH, SWAP, CML, $MOV", "[program][engine][transfer]") {
    Rig rig(dotted("LD SM400 · BMOV D0 D1 K3 · BMOV D11 D10 K3 · FMOV K7 D20 K3 · DFMOV K65537 D30 K2 · XCH D40 D41 · "
                   "DXCH D42 D44 · SWAP D46 · CML K0 D47 · DCML K0 D48 · $MOV \"ABC\" D50 · $MOV \"AB\" D52 · $MOV D50 D60 · "
                   "END"));
    for (int i = 0; i < 4; ++i) rig.set("D" + std::to_string(i), static_cast<std::uint32_t>(i + 1));
    for (int i = 10; i < 14; ++i) rig.set("D" + std::to_string(i), static_cast<std::uint32_t>(i));
    rig.set("D40", 1);
    rig.set("D41", 2);
    rig.set("D42", 3);
    rig.set("D44", 4);
    rig.set("D46", 0x1234);
    rig.set("D53", 0x5555);
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(rig.get("D1") == 1);   // as if through a buffer: 1 2 3 -> D1..D3
    CHECK(rig.get("D2") == 2);
    CHECK(rig.get("D3") == 3);
    CHECK(rig.get("D10") == 11);
    CHECK(rig.get("D11") == 12);
    CHECK(rig.get("D12") == 13);
    CHECK(rig.get("D22") == 7);
    CHECK(rig.get("D23") == 0);
    CHECK(pair(rig, 32) == 65537);
    CHECK(rig.get("D40") == 2);
    CHECK(rig.get("D41") == 1);
    CHECK(rig.get("D42") == 4);
    CHECK(rig.get("D44") == 3);
    CHECK(rig.get("D46") == 0x3412);
    CHECK(rig.get("D47") == 0xFFFF);
    CHECK(pair(rig, 48) == 0xFFFFFFFFu);
    CHECK(rig.get("D50") == 0x4241);
    CHECK(rig.get("D51") == 0x0043);
    CHECK(rig.get("D52") == 0x4241);
    CHECK(rig.get("D53") == 0x0000);
    CHECK(rig.get("D60") == 0x4241);
    CHECK(rig.get("D61") == 0x0043);

    Rig past(dotted("LD SM400 · BMOV D0 D10230 K20 · END"));
    auto outcome = past.scan();
    REQUIRE(outcome.error);
    CHECK(outcome.error->code == 0x2820);
    CHECK(past.get("D10230") == 0);   // nothing written
}

TEST_CASE("§5.7 logic, §5.8 rotation and shift", "[program][engine][logic]") {
    Rig rig(dotted("LD SM400 · WAND HFF0F H0FF0 D0 · WOR H00F0 H0F00 D1 · WXOR HFFFF H0F0F D2 · WXNR H00FF H0F0F D3 · "
                   "DAND HFFFF0000 H12345678 D4 · MOV H8001 D10 · ROR D10 K1 · MOV H8001 D11 · ROL D11 K4 · MOV H0001 D12 · "
                   "SFR D12 K1 · MOV H00F0 D13 · SFL D13 K4 · END"));
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(rig.get("D0") == 0x0F00);
    CHECK(rig.get("D1") == 0x0FF0);
    CHECK(rig.get("D2") == 0xF0F0);
    CHECK(rig.get("D3") == 0xF00F);
    CHECK(pair(rig, 4) == 0x12340000u);
    CHECK(rig.get("D10") == 0xC000);
    CHECK(rig.get("D11") == 0x0018);
    CHECK(rig.get("D12") == 0);
    CHECK(rig.get("D13") == 0x0F00);
    CHECK(rig.get("SM700") == 0);   // SFL's last bit out was 0

    Rig carry(dotted("LD SM400 · MOV H0001 D0 · RCR D0 K1 · END"));
    carry.set("SM700", 0);
    carry.scan();
    CHECK(carry.get("D0") == 0);
    CHECK(carry.get("SM700") == 1);

    Rig bits(dotted("LD SM400 · BSFR M0 K4 · BSFL M10 K4 · DSFR D0 K3 · DSFL D10 K3 · END"));
    bits.set("M1", 1);
    bits.set("M3", 1);
    bits.set("M10", 1);
    for (int i = 0; i < 3; ++i) {
        bits.set("D" + std::to_string(i), static_cast<std::uint32_t>(i + 1));
        bits.set("D" + std::to_string(10 + i), static_cast<std::uint32_t>(i + 1));
    }
    bits.scan();
    CHECK(bits.get("M0") == 1);
    CHECK(bits.get("M2") == 1);
    CHECK(bits.get("M3") == 0);
    CHECK(bits.get("M10") == 0);
    CHECK(bits.get("M11") == 1);
    CHECK(bits.get("D0") == 2);
    CHECK(bits.get("D2") == 0);
    CHECK(bits.get("D10") == 0);
    CHECK(bits.get("D12") == 2);

    Rig sft(dotted("LDP X0 · SFT M3 · SFT M2 · END"));
    sft.set("M1", 1);
    sft.set("X0", 1);
    sft.scan();
    CHECK(sft.get("M1") == 0);   // SFT M3 took M2 (OFF), then SFT M2 took M1
    CHECK(sft.get("M2") == 1);
    CHECK(sft.get("M3") == 0);
}

TEST_CASE("§5.8 SFTR/SFTL on iQ-F (octal X/Y)", "[program][engine][logic]") {
    Rig rig(dotted("LDP X10 · SFTL X0 M0 K8 K2 · END"), fx5u());
    rig.set("X10", 1);   // octal X10 = input 8
    rig.set("X0", 1);
    rig.set("M0", 1);
    rig.scan();
    CHECK(rig.get("M0") == 1);   // X0
    CHECK(rig.get("M1") == 0);   // X1
    CHECK(rig.get("M2") == 1);   // old M0
    Rig add(dotted("LD SM400 · ADD K2 K3 D0 · ALT M5 · END"), fx5u());
    add.scan();
    CHECK(add.get("D0") == 5);
    CHECK(add.get("M5") == 1);
}

TEST_CASE("§5.9 bit and data processing", "[program][engine][data]") {
    Rig rig(dotted("LD SM400 · BSET D0 K3 · BSET D0 K19 · MOV HFFFF D1 · BRST D1 K0 · TEST H0004 K2 M0 · DTEST H00010000 K16 M1 · "
                   "BKRST M10 K3 · ZRST D10 D12 · ZRST M20 M22 · SUM H0F0F D20 · DSUM HFFFFFFFF D21 · DECO K5 M30 K3 · "
                   "DECO K17 D30 K5 · ENCO M40 D22 K3 · SEG K10 D23 · END"));
    for (auto m : {"M10", "M11", "M12", "M13", "M20", "M22", "M44", "M41"}) rig.set(m, 1);
    rig.set("D10", 5);
    rig.set("D12", 5);
    rig.set("D13", 5);
    rig.set("D23", 0x1200);
    rig.set("M31", 1);
    REQUIRE(rig.scan().kind == Kind::Ok);
    CHECK(rig.get("D0") == 0x0008);
    CHECK(rig.get("D1") == 0xFFFE);
    CHECK(rig.get("M0") == 1);
    CHECK(rig.get("M1") == 1);
    CHECK(rig.get("M10") == 0);
    CHECK(rig.get("M12") == 0);
    CHECK(rig.get("M13") == 1);
    CHECK(rig.get("D10") == 0);
    CHECK(rig.get("D12") == 0);
    CHECK(rig.get("D13") == 5);
    CHECK(rig.get("M20") == 0);
    CHECK(rig.get("M22") == 0);
    CHECK(rig.get("D20") == 8);
    CHECK(rig.get("D21") == 32);
    CHECK(rig.get("M35") == 1);
    CHECK(rig.get("M31") == 0);
    CHECK(rig.get("D31") == 0x0002);   // bit 17 of the 32 bits at D30
    CHECK(rig.get("D30") == 0);
    CHECK(rig.get("D22") == 4);
    CHECK(rig.get("D23") == 0x1277);

    auto code_of = [](const std::string& text) -> std::uint16_t {
        Rig r(dotted(text));
        auto outcome = r.scan();
        return outcome.error ? outcome.error->code : 0;
    };
    CHECK(code_of("LD SM400 · ENCO M0 D0 K3 · END") == 0x3405);   // no bit ON
    CHECK(code_of("LD SM400 · DECO K1 M0 K9 · END") == 0x3405);
}

TEST_CASE("writes reach the observer only when a value changes", "[program][engine][observer]") {
    struct Counting : devicemodel::WriteObserver {
        std::vector<std::string> seen;
        void written(const devicemodel::DeviceSpec& spec, std::uint32_t first, std::uint32_t count) override {
            seen.push_back(std::string(spec.symbol) + std::to_string(first) + "x" + std::to_string(count));
        }
    } observer;
    Rig rig(dotted("LD SM400 · OUT Y0 · MOV K5 D0 · LD X0 · OUT T0 K1 · END"));
    rig.memory.set_write_observer(&observer);
    rig.scan();
    rig.set("SM402", 0);
    observer.seen.clear();
    rig.execution.scan(rig.memory);
    CHECK(observer.seen.empty());
    rig.set("X0", 1);
    observer.seen.clear();
    rig.execution.scan(rig.memory);
    CHECK(observer.seen == std::vector<std::string>{"TC0x1"});   // the coil turned ON; value 0 and contact OFF unchanged
    rig.set("X0", 0);
    observer.seen.clear();
    rig.execution.scan(rig.memory);
    CHECK(observer.seen == std::vector<std::string>{"TC0x1"});
}
