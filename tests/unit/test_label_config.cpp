// Label declarations (docs/labels.md): the issue's minimal form, GX Works3
// type names and IEC aliases, array forms, the CSV import of a sample list,
// and every declaration mistake with its exact message.
#include "support/labels.hpp"

#include "config/config_parts.hpp"

using namespace slmp;
using namespace slmp::test;

namespace {

std::string declare_error(const std::string& json, const std::string& profile = "R08CPU") {
    try {
        cpu_with_labels(json, profile);
    } catch (const config::ConfigError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace

TEST_CASE("the issue's minimal form: LabelW on D9000, DDD[20] in the label area, Hidden not external", "[labels][config]") {
    auto cpu = cpu_with_labels(R"J({"labels": [{"name": "LabelW", "type": "Word [Signed]", "device": "D9000"},
                                               {"name": "DDD", "type": "Word [Signed]", "dims": [20]},
                                               {"name": "Hidden", "type": "Bit", "external": false}]})J");
    const auto& labels = cpu.labels().labels();
    REQUIRE(labels.size() == 3);
    CHECK(devicemodel::format_address(*labels[0].device) == "D9000");
    CHECK(devicemodel::format_label_type(labels[1].type, labels[1].dims) == "Word [Signed](0..19)");
    CHECK_FALSE(labels[2].external);
    CHECK(cpu.memory().label_area_words() == 21);   // DDD 20 words + Hidden 1
    CHECK(kBinary3E.exchange(cpu, random_label_read_req({"Hidden"})) == kBinary3E.expect(error(0x40C0, 0x041C, 0)));
}

TEST_CASE("type names: GX Works3 and IEC aliases map to the same type", "[labels][config]") {
    struct Alias {
        const char* gx;
        const char* iec;
    };
    for (auto [gx, iec] : {Alias{"Bit", "BOOL"}, Alias{"Word [Signed]", "INT"},
                           Alias{"Word [Unsigned]/Bit String [16-bit]", "UINT"},
                           Alias{"Word [Unsigned]/Bit String [16-bit]", "WORD"}, Alias{"Double Word [Signed]", "DINT"},
                           Alias{"Double Word [Unsigned]/Bit String [32-bit]", "UDINT"},
                           Alias{"Double Word [Unsigned]/Bit String [32-bit]", "DWORD"},
                           Alias{"FLOAT [Single Precision]", "REAL"}, Alias{"FLOAT [Double Precision]", "LREAL"},
                           Alias{"Time", "TIME"}, Alias{"String(32)", "STRING[32]"},
                           Alias{"String [Unicode](32)", "WSTRING[32]"}, Alias{"Timer", "TIMER"},
                           Alias{"Long Retentive Timer", "LRETENTIVETIMER"}}) {
        CAPTURE(gx, iec);
        std::string error;
        auto a = devicemodel::parse_label_type(gx, {}, &error);
        auto b = devicemodel::parse_label_type(iec, {}, &error);
        REQUIRE(a);
        REQUIRE(b);
        CHECK(devicemodel::format_label_type(a->type) == gx);
        CHECK(devicemodel::format_label_type(b->type) == gx);
    }
    std::string error;
    auto arr = devicemodel::parse_label_type("Word [Signed](0..1,0..19)", {}, &error);
    REQUIRE(arr);
    CHECK(arr->dims == std::vector<std::uint32_t>{2, 20});
    auto str = devicemodel::parse_label_type("String(16)(0..3)", {}, &error);
    REQUIRE(str);
    CHECK(str->type.chars == 16);
    CHECK(str->dims == std::vector<std::uint32_t>{4});
}

TEST_CASE("declaration mistakes stop start-up with the file, the pointer and the fix", "[labels][config]") {
    const auto d_size = std::to_string(make_cpu().memory().size(devicemodel::Area::D));
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "WORDX"}]})J") ==
          "test.json: /labels/0/type: unknown data type 'WORDX'; use a GX Works3 type (Bit, Word [Signed], Word "
          "[Unsigned]/Bit String [16-bit], Double Word [Signed], Double Word [Unsigned]/Bit String [32-bit], FLOAT "
          "[Single Precision], FLOAT [Double Precision], Time, String(32), String [Unicode](32), Timer, Counter, "
          "Retentive Timer, Long Timer, Long Counter, Long Retentive Timer), an IEC name (BOOL, INT, UINT, WORD, DINT, "
          "UDINT, DWORD, REAL, LREAL, TIME, STRING[32], WSTRING[32]) or a structure declared before it");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "DINT", "dims": [10], "device": "D100"},
                                        {"name": "B", "type": "INT", "device": "D119"}]})J") ==
          "test.json: /labels/1/device: label 'B' on D119 overlaps label 'A' on D100; assign devices that do not overlap");
    CHECK(declare_error(R"J({"labels": [{"name": "Big", "type": "INT(0..19999)", "device": "D0"}]})J") ==
          "test.json: /labels/0/device: label 'Big' needs 20000 device(s) from D0, past the D size of " + d_size +
              "; assign a lower device number or raise device_sizes");
    CHECK(declare_error(R"J({"labels": [{"name": "1abc", "type": "INT"}]})J") ==
          "test.json: /labels/0: bad label name: a name cannot start with a digit; rename the label");
    CHECK(declare_error(R"J({"labels": [{"name": "D100", "type": "INT"}]})J") ==
          "test.json: /labels/0: bad label name: 'D100' is a device name; rename the label");
    CHECK(declare_error(R"J({"labels": [{"name": "A.b", "type": "INT"}]})J") ==
          "test.json: /labels/0: bad label name: a name may hold only letters, digits and '_' (no '.', '[', ',', '%' "
          "or spaces); rename the label");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "INT"}, {"name": "A", "type": "Bit"}]})J") ==
          "test.json: /labels/1: label 'A' is declared twice; rename or remove one");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "Bit", "device": "D0"}]})J") ==
          "test.json: /labels/0/device: a Bit label needs a bit device, not D0; assign it to a bit device such as M, "
          "X, Y, L or B");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "INT", "device": "M0"}]})J") ==
          "test.json: /labels/0/device: a Word [Signed] label needs a word device, not M0; assign it to a word device "
          "such as D, W, R or ZR");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "Timer", "device": "C3"}]})J") ==
          "test.json: /labels/0/device: a Timer label needs a T device, not CN3; assign it to e.g. TN0");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "INT(1..19)"}]})J") ==
          "test.json: /labels/0/type: array range '1..19' does not start at 0; write an array as (0..n), (0..n,0..m) "
          "or (0..n,0..m,0..k) and a string as String(n), n 1 to 255");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "INT(0..1)", "dims": [2]}]})J") ==
          "test.json: /labels/0/type: the type 'INT(0..1)' is an array and \"dims\" is given too; give the array "
          "once: in the type or in \"dims\"");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "INT", "dims": [2, 2, 2, 2]}]})J") ==
          "test.json: /labels/0/dims: an array has 1 to 3 dimensions; write e.g. [20] or [2, 20]");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "INT", "dims": [70000]}]})J") ==
          "test.json: /labels/0/dims/0: value 70000 is larger than 65536; use a smaller number");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "INT", "devic": "D0"}]})J") ==
          "test.json: /labels/0/devic: unknown key; use one of: name, type, device, dims, external, comment");
    CHECK(declare_error(R"J({"labels": [{"name": "A", "type": "INT", "device": "Q5"}]})J") ==
          "test.json: /labels/0/device: " +
              [] {
                  std::string e;
                  devicemodel::parse_address("Q5", &e);
                  return e;
              }() +
              "; write a device such as D1000, M100, ZR0 (T5 for a Timer label)");
    CHECK(declare_error(R"J({"structures": [{"name": "In", "members": [{"name": "x", "type": "INT"}]},
                                            {"name": "Out", "members": [{"name": "i", "type": "In"}]}],
                            "labels": [{"name": "A", "type": "Out", "device": "D0"}]})J") ==
          "test.json: /labels/0/device: structure 'Out' has member 'i' of a structure or timer type, and such a label "
          "cannot be assigned to a device (docs/labels.md, \"Assigned to a device\"); remove \"device\" to place the label in "
          "the label area");
    CHECK_THAT(declare_error(R"J({"structures": [{"name": "Out", "members": [{"name": "i", "type": "Later"}]},
                                            {"name": "Later", "members": [{"name": "x", "type": "INT"}]}]})J"),
               Catch::StartsWith("test.json: /structures/0/members/0/type: unknown data type 'Later'; use a GX Works3 type"));
    CHECK(declare_error(R"J({"structures": [{"name": "S", "members": [{"name": "x", "type": "INT"}, {"name": "x", "type": "INT"}]}]})J") ==
          "test.json: /structures/0: member 'x' is declared twice; rename one");
}

TEST_CASE("CSV import: a GX Works3 global label list", "[labels][config][csv]") {
    auto labels = config::load_labels_file(SLMP_SOURCE_DIR "/tests/data/labels/global_labels.csv");
    REQUIRE(labels.labels.size() == 6);   // MAXLEN (VAR_GLOBAL_CONSTANT) is skipped, the empty row too
    auto cpu = make_cpu();
    config::declare_labels(cpu, labels);
    const auto& l = cpu.labels();
    REQUIRE(l.find("LabelW"));
    CHECK(devicemodel::format_address(*l.find("LabelW")->device) == "D9000");
    CHECK(devicemodel::format_label_type(l.find("DDD")->type, l.find("DDD")->dims) == "Word [Signed](0..19)");
    CHECK(devicemodel::format_address(*l.find("Flags")->device) == "M200");
    CHECK(l.find("Speed")->external);
    CHECK_FALSE(l.find("Hidden")->external);
    CHECK_FALSE(l.find("Name1")->external);   // empty cell: off, as in GX Works3
    CHECK_FALSE(l.find("MAXLEN"));
    CHECK(kAscii3E.exchange(cpu, random_label_write_req({{"Flags[3]", 2, word(1)}})) == kAscii3E.expect(ok()));
    CHECK(cpu.memory().bit(*devicemodel::find_by_symbol("M"), 203));

    CHECK_THROWS_WITH(config::parse_labels_csv("Label Name,Data Type,Class\nA,INT,VAR_LOCAL\n", "x.csv"),
                      "x.csv: line 2, column Class: unknown class 'VAR_LOCAL'; use VAR_GLOBAL, VAR_GLOBAL_RETAIN or "
                      "VAR_GLOBAL_CONSTANT");
    CHECK_THROWS_WITH(config::parse_labels_csv("Name,Type\nA,INT\n", "x.csv"),
                      "x.csv: no header row with \"Label Name\" and \"Data Type\"; export the list from GX Works3's "
                      "global label editor (or write that header line first)");
    auto bad = config::parse_labels_csv("Label Name,Data Type,Assign (Device/Label)\nA,INT,M0\n", "x.csv");
    auto cpu2 = make_cpu();
    CHECK_THROWS_WITH(config::declare_labels(cpu2, bad),
                      "x.csv: line 2, column Assign (Device/Label): a Word [Signed] label needs a word device, not M0; "
                      "assign it to a word device such as D, W, R or ZR");
}
