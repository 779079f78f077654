// The file drives and file end codes of the profiles ("file_drives",
// "file_end_codes", docs/files.md): every built-in profile has exactly the
// table its family had when it was code, "extends" changes one drive or one
// code and keeps the rest, and the engine answers with the profile's code.
#include "config/config.hpp"
#include "devicemodel/drives.hpp"
#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::DriveKind;
using devicemodel::DriveSpec;
using devicemodel::Family;
using devicemodel::FileFault;

namespace {

// The tables as devicemodel::family_drives gave them before they moved to
// the profiles: the move must not change a byte of behaviour.
std::vector<DriveSpec> was_code(Family family) {
    using enum DriveKind;
    switch (family) {
        case Family::IQR:
            return {{1, DeviceLabelMemory, 0, true, false, 3},
                    {2, SdCard, 8u << 20, true, false, std::nullopt},
                    {3, DeviceLabelMemory, 512u << 10, true, false, std::nullopt},
                    {4, DataMemory, 5u << 20, true, false, std::nullopt}};
        case Family::QnU:
        case Family::L:
        case Family::QJ71E71:
            return {{0, ProgramMemory, 240u << 10, true, false, std::nullopt},
                    {1, SramCard, 1u << 20, false, false, std::nullopt},
                    {2, SdCard, 8u << 20, true, false, std::nullopt},
                    {3, StandardRam, 768u << 10, true, false, std::nullopt},
                    {4, StandardRom, 1u << 20, true, false, std::nullopt}};
        case Family::IQF: return {};
    }
    return {};
}

std::string show(const std::vector<DriveSpec>& drives) {
    std::string out;
    for (const auto& d : drives)
        out += std::to_string(d.number) + ":" + std::string(devicemodel::drive_kind_key(d.kind)) + "/" +
               std::to_string(d.capacity) + (d.present ? "" : "/absent") + (d.write_protect ? "/locked" : "") +
               (d.alias_of ? "/alias" + std::to_string(*d.alias_of) : "") + " ";
    return out;
}

// The codes docs/end-codes.md lists, the same on every family with drives.
const std::pair<FileFault, std::uint16_t> kCodes[] = {
    {FileFault::NoDrive, 0x4021},        {FileFault::BadName, 0x4024},     {FileFault::NotFound, 0x4022},
    {FileFault::Exists, 0x4028},         {FileFault::NotAFile, 0x4024},    {FileFault::NoCapacity, 0x4029},
    {FileFault::WriteProtected, 0x4050}, {FileFault::ReadOnly, 0x4052},    {FileFault::Locked, 0x4025},
    {FileFault::Password, 0x4026},       {FileFault::BadPointer, 0xC059},  {FileFault::NotWriteMode, 0x402C},
    {FileFault::OutOfRange, 0x4027},     {FileFault::TooManyOpen, 0x4008}, {FileFault::HostError, 0x4051},
    {FileFault::RunState, 0x4013},
};

}  // namespace

TEST_CASE("every built-in profile has the drives and file end codes its family had in code", "[profiles][drives]") {
    for (const auto& name : config::builtin_profile_names()) {
        INFO(name);
        auto profile = config::load_profile(name);
        CHECK(show(profile.cpu.drives) == show(was_code(profile.cpu.family)));
        if (profile.cpu.drives.empty()) continue;
        for (const auto& [fault, code] : kCodes) {
            INFO(devicemodel::file_fault_key(fault));
            CHECK(profile.port.file_end_codes[static_cast<std::size_t>(fault)] == code);
        }
    }
}

TEST_CASE("a profile that extends another changes one drive, removes one, and moves one end code", "[profiles][drives]") {
    auto derived = config::parse_profile(R"({"name": "R08-small-sd", "extends": "R08CPU", "description": "test",
        "file_drives": {"2": {"capacity": 1000, "write_protect": true}, "4": null},
        "file_end_codes": {"exists": "4030"}})",
                                         "small.json");
    CHECK(show(derived.cpu.drives) ==
          "1:device_label_memory/0/alias3 2:sd_card/1000/locked 3:device_label_memory/524288 ");
    CHECK(derived.port.file_end_codes[static_cast<std::size_t>(FileFault::Exists)] == 0x4030);
    CHECK(derived.port.file_end_codes[static_cast<std::size_t>(FileFault::NotFound)] == 0x4022);

    // The engine answers with the profile's code: 1820 on a taken name.
    devicemodel::Cpu cpu(derived.cpu);
    REQUIRE(cpu.drives().create({3, "A.BIN"}, devicemodel::NameForm::Long, 4) == FileFault::None);
    protocol::Engine engine(cpu, derived.port);
    protocol::Session session;
    // 1820/0040: fixed 0, drive 3, size 4, "A.BIN".
    auto request = kBinary3E.request(Payload{"20 18 40 00 00 00 00 00 03 00 04 00 00 00 05 00 41 00 2E 00 42 00 49 00 4E 00",
                                             "18200040000000030000000400050041002E00420049004E"});
    CHECK(kBinary3E.show(engine.process(request, DataCodePolicy::Auto, session)) ==
          kBinary3E.expect(error(0x4030, 0x1820, 0x0040)));
    // Drive 4 is gone: 4021, the code for no drive.
    CHECK(cpu.drives().create({4, "A.BIN"}, devicemodel::NameForm::Long, 4) == FileFault::NoDrive);
}

TEST_CASE("file_drives mistakes name the key and the fix", "[profiles][drives]") {
    auto parse = [](const std::string& extra) {
        config::parse_profile(R"({"name": "T", "extends": "R08CPU", "description": "test", )" + extra + "}", "t.json");
    };
    CHECK_THROWS_WITH(parse(R"("file_drives": {"2": {"kind": "floppy"}})"),
                      Catch::Contains("t.json: /file_drives/2/kind: unknown drive kind 'floppy'"));
    CHECK_THROWS_WITH(parse(R"("file_drives": {"x": {"kind": "sd_card", "capacity": 1}})"),
                      Catch::Contains("'x' is not a drive number"));
    CHECK_THROWS_WITH(parse(R"("file_drives": {"3": null})"),
                      Catch::Contains("/file_drives/1/alias_of: drive 3 is not a drive of its own"));
    CHECK_THROWS_WITH(parse(R"("file_end_codes": {"bogus": "4000"})"), Catch::Contains("/file_end_codes/bogus: unknown file end code"));
    // A profile of its own with drives must give every code.
    auto fx = config::load_profile("FX5U-32MR");
    CHECK(fx.cpu.drives.empty());
    CHECK_THROWS_WITH(config::parse_profile(R"({"name": "FX-sd", "extends": "FX5U-32MR", "description": "test",
        "file_drives": {"2": {"kind": "sd_card", "capacity": 1}}})", "fx.json"),
                      Catch::Contains("fx.json: /: a profile with file_drives needs file_end_codes"));
}
