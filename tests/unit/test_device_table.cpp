// The device table against the manual's code list (SLMP Reference Manual
// §5.2), and address text parsing/printing through it.
#include "devicemodel/device_table.hpp"

#include <catch2/catch.hpp>

#include <set>
#include <string>

using namespace slmp::devicemodel;

namespace {

// One row of §5.2, copied from the spec: symbol, iQ-R ASCII name, Q ASCII name,
// iQ-R binary code, Q binary code (-1: none), radix, unit.
struct Row {
    const char* symbol;
    const char* ascii_iqr;
    const char* ascii_q;
    std::uint16_t iqr;
    int q;
    Radix radix;
    Unit unit;
};

constexpr Radix H = Radix::Hex, De = Radix::Dec;
constexpr Unit B = Unit::Bit, W = Unit::Word, DW = Unit::DoubleWord;

// ZR: the manuals say hex; iQ-R numbers it in decimal (real-CPU measurements),
// and the table follows the CPU (a profile can switch its ASCII form to hex).
const Row kSpec[] = {
    {"SM", "SM**", "SM", 0x0091, 0x91, De, B},   {"SD", "SD**", "SD", 0x00A9, 0xA9, De, W},
    {"X", "X***", "X*", 0x009C, 0x9C, H, B},     {"Y", "Y***", "Y*", 0x009D, 0x9D, H, B},
    {"M", "M***", "M*", 0x0090, 0x90, De, B},    {"L", "L***", "L*", 0x0092, 0x92, De, B},
    {"F", "F***", "F*", 0x0093, 0x93, De, B},    {"V", "V***", "V*", 0x0094, 0x94, De, B},
    {"B", "B***", "B*", 0x00A0, 0xA0, H, B},     {"D", "D***", "D*", 0x00A8, 0xA8, De, W},
    {"W", "W***", "W*", 0x00B4, 0xB4, H, W},     {"TS", "TS**", "TS", 0x00C1, 0xC1, De, B},
    {"TC", "TC**", "TC", 0x00C0, 0xC0, De, B},   {"TN", "TN**", "TN", 0x00C2, 0xC2, De, W},
    {"LTS", "LTS*", "", 0x0051, -1, De, B},      {"LTC", "LTC*", "", 0x0050, -1, De, B},
    {"LTN", "LTN*", "", 0x0052, -1, De, DW},     {"STS", "STS*", "SS", 0x00C7, 0xC7, De, B},
    {"STC", "STC*", "SC", 0x00C6, 0xC6, De, B},  {"STN", "STN*", "SN", 0x00C8, 0xC8, De, W},
    {"LSTS", "LSTS", "", 0x0059, -1, De, B},     {"LSTC", "LSTC", "", 0x0058, -1, De, B},
    {"LSTN", "LSTN", "", 0x005A, -1, De, DW},    {"CS", "CS**", "CS", 0x00C4, 0xC4, De, B},
    {"CC", "CC**", "CC", 0x00C3, 0xC3, De, B},   {"CN", "CN**", "CN", 0x00C5, 0xC5, De, W},
    {"LCS", "LCS*", "", 0x0055, -1, De, B},      {"LCC", "LCC*", "", 0x0054, -1, De, B},
    {"LCN", "LCN*", "", 0x0056, -1, De, DW},     {"SB", "SB**", "SB", 0x00A1, 0xA1, H, B},
    {"SW", "SW**", "SW", 0x00B5, 0xB5, H, W},    {"DX", "DX**", "DX", 0x00A2, 0xA2, H, B},
    {"DY", "DY**", "DY", 0x00A3, 0xA3, H, B},    {"Z", "Z***", "Z*", 0x00CC, 0xCC, De, W},
    {"LZ", "LZ**", "", 0x0062, -1, De, DW},      {"R", "R***", "R*", 0x00AF, 0xAF, De, W},
    {"ZR", "ZR**", "ZR", 0x00B0, 0xB0, De, W},   {"RD", "RD**", "", 0x002C, -1, De, W},
    // S is not in §5.2 (JP: "cannot be specified in SLMP"), but real CPUs answer
    // it (real-CPU measurements: readable, write -> 4030); code 98H as in MC protocol.
    {"S", "S***", "S*", 0x0098, 0x98, De, B},
};

}  // namespace

TEST_CASE("device table matches the manual's code list", "[device_table]") {
    for (const auto& row : kSpec) {
        INFO("device " << row.symbol);
        const auto* spec = find_by_symbol(row.symbol);
        REQUIRE(spec != nullptr);
        CHECK(spec->iqr_code == row.iqr);
        CHECK(spec->q_code == row.q);
        CHECK(spec->radix == row.radix);
        CHECK(spec->unit == row.unit);
        CHECK(ascii_name(*spec, 4) == row.ascii_iqr);
        if (row.q >= 0) CHECK(ascii_name(*spec, 2) == row.ascii_q);
        CHECK(find_by_iqr_code(row.iqr) == spec);
        if (row.q >= 0) CHECK(find_by_q_code(static_cast<std::uint8_t>(row.q)) == spec);
        CHECK(find_by_ascii(row.ascii_iqr, 4) == spec);
        if (row.q >= 0) CHECK(find_by_ascii(row.ascii_q, 2) == spec);
    }
    // Every plain device of the table is in the list above; the rest exist only
    // behind an extension (U\G, U3E\HG) and are checked below.
    std::size_t plain = 0;
    for (const auto& spec : all_devices()) plain += spec.extension_only ? 0 : 1;
    CHECK(plain == std::size(kSpec));
}

TEST_CASE("buffer-memory devices exist only behind an extension", "[device_table]") {
    // Codes from the English iQ-R manual (G 00ABH/ABH, HG 002EH); as plain devices
    // real CPUs answer C05B (real-CPU measurements).
    const auto* g = find_by_symbol("G");
    REQUIRE(g != nullptr);
    CHECK(g->extension_only);
    CHECK(g->iqr_code == 0x00AB);
    CHECK(g->q_code == 0xAB);
    CHECK(g->unit == Unit::Word);
    const auto* hg = find_by_symbol("HG");
    REQUIRE(hg != nullptr);
    CHECK(hg->extension_only);
    CHECK(hg->iqr_code == 0x002E);
    CHECK(hg->q_code == -1);
    for (const auto& row : kSpec) CHECK_FALSE(find_by_symbol(row.symbol)->extension_only);
}

TEST_CASE("device table lookups", "[device_table]") {
    SECTION("symbols are case-insensitive") {
        CHECK(find_by_symbol("zr") == find_by_symbol("ZR"));
        CHECK(find_by_symbol("ltn") == find_by_symbol("LTN"));
    }
    SECTION("unknown codes and names") {
        CHECK(find_by_symbol("FX") == nullptr);   // JP: cannot be specified in SLMP
        CHECK(find_by_symbol("FD") == nullptr);   // JP: cannot be specified in SLMP
        CHECK(find_by_iqr_code(0x0000) == nullptr);
        CHECK(find_by_iqr_code(0x00FF) == nullptr);
        CHECK(find_by_q_code(0x52) == nullptr);   // LTN has no Q-form code
        CHECK(find_by_q_code(0x00) == nullptr);
        CHECK(find_by_ascii("Q*", 2) == nullptr);
        CHECK(find_by_ascii("LTN*", 2) == nullptr);
    }
    SECTION("ASCII padding: '*' or space, only after the name") {
        CHECK(find_by_ascii("D ", 2) == find_by_symbol("D"));
        CHECK(find_by_ascii("D   ", 4) == find_by_symbol("D"));
        CHECK(find_by_ascii("D* *", 4) == find_by_symbol("D"));
        CHECK(find_by_ascii("*D**", 4) == nullptr);
        CHECK(find_by_ascii("****", 4) == nullptr);
        CHECK(find_by_ascii("D*", 4) == nullptr);   // wrong width
    }
    SECTION("Q-form names of retentive timers differ from their symbols") {
        CHECK(find_by_ascii("SS", 2) == find_by_symbol("STS"));
        CHECK(find_by_ascii("SC", 2) == find_by_symbol("STC"));
        CHECK(find_by_ascii("SN", 2) == find_by_symbol("STN"));
    }
    SECTION("words per device on the wire") {
        CHECK(words_per_device(*find_by_symbol("D")) == 1);
        CHECK(words_per_device(*find_by_symbol("M")) == 1);
        CHECK(words_per_device(*find_by_symbol("LTN")) == 4);
        CHECK(words_per_device(*find_by_symbol("LSTN")) == 4);
        CHECK(words_per_device(*find_by_symbol("LCN")) == 2);
        CHECK(words_per_device(*find_by_symbol("LZ")) == 2);
    }
    SECTION("areas") {
        CHECK(find_by_symbol("TS")->area == Area::T);
        CHECK(find_by_symbol("TC")->area == Area::T);
        CHECK(find_by_symbol("TN")->area == Area::T);
        CHECK(find_by_symbol("DX")->area == Area::X);
        CHECK(find_by_symbol("DY")->area == Area::Y);
        CHECK(area_name(Area::LST) == "LST");
        CHECK(area_by_name("lt") == Area::LT);
        CHECK_FALSE(area_by_name("TN").has_value());
        std::set<std::string> names;
        for (std::size_t i = 0; i < static_cast<std::size_t>(Area::Count); ++i) {
            auto name = std::string(area_name(static_cast<Area>(i)));
            CHECK(area_by_name(name) == static_cast<Area>(i));
            names.insert(name);
        }
        CHECK(names.size() == static_cast<std::size_t>(Area::Count));
    }
}

TEST_CASE("address text parses and prints through the table", "[device_table]") {
    struct Case {
        const char* text;
        const char* symbol;
        std::uint32_t number;
        const char* printed;
    };
    const Case cases[] = {
        {"D100", "D", 100, "D100"},         {"X1F", "X", 0x1F, "X1F"},       {"x1f", "X", 0x1F, "X1F"},
        {"ZR1000", "ZR", 1000, "ZR1000"},   {"TN5", "TN", 5, "TN5"},         {"LTN0", "LTN", 0, "LTN0"},
        {"LSTS3", "LSTS", 3, "LSTS3"},      {"SM400", "SM", 400, "SM400"},   {"SB7FF", "SB", 0x7FF, "SB7FF"},
        {"W1FFF", "W", 0x1FFF, "W1FFF"},    {"B0", "B", 0, "B0"},            {"LZ1", "LZ", 1, "LZ1"},
        {"L8191", "L", 8191, "L8191"},      {"RD524287", "RD", 524287, "RD524287"},
        {"DX10", "DX", 0x10, "DX10"},       {"STN7", "STN", 7, "STN7"},      {"D0100", "D", 100, "D100"},
    };
    for (const auto& c : cases) {
        INFO(c.text);
        auto address = parse_address(c.text);
        REQUIRE(address.has_value());
        CHECK(address->spec->symbol == c.symbol);
        CHECK(address->number == c.number);
        CHECK(format_address(*address) == c.printed);
    }

    SECTION("every device round-trips 0 and 1234 (hex devices: 0x1234)") {
        for (const auto& spec : all_devices()) {
            for (std::uint32_t n : {0u, 1234u, 0x1234u}) {
                DeviceAddress a{&spec, n};
                auto back = parse_address(format_address(a));
                INFO(format_address(a));
                REQUIRE(back.has_value());
                CHECK(back->spec == &spec);
                CHECK(back->number == n);
            }
        }
    }

    SECTION("bad addresses say what is wrong") {
        std::string error;
        CHECK_FALSE(parse_address("Q100", &error).has_value());
        CHECK(error.find("unknown device") != std::string::npos);
        CHECK_FALSE(parse_address("D1A", &error).has_value());
        CHECK(error.find("decimal") != std::string::npos);
        CHECK_FALSE(parse_address("XG", &error).has_value());
        CHECK(error.find("hexadecimal") != std::string::npos);
        CHECK_FALSE(parse_address("D", &error).has_value());
        CHECK_FALSE(parse_address("", &error).has_value());
        CHECK_FALSE(parse_address("D-1", &error).has_value());
        CHECK_FALSE(parse_address("D 1", &error).has_value());
    }
}
