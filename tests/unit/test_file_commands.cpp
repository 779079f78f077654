// File control 1810-182A: every canonical vector of the SLMP Reference Manual §5.8,
// byte-exact in binary and ASCII, 3E and 4E, plus the refusals (family,
// names that would leave the drive, locks, protection, capacity, Q/L RUN).
// End codes are the choices in docs/end-codes.md.
#include "devicemodel/drives.hpp"
#include "support/fixtures.hpp"
#include "support/scenario_fixtures.hpp"

using namespace slmp;
using namespace slmp::test;
using devicemodel::FileFault;
using devicemodel::FileRef;
using devicemodel::NameForm;

namespace {

const std::vector<Wire> kWires{kBinary3E, kBinary4E, kAscii3E, kAscii4E};

// The Q/L built-in ports serve 3E only (their profiles: 4E gets no answer), so
// their vectors travel in the 3E frame of the same code.
const Wire& ql(const Wire& w) {
    if (w.kind == FrameKind::E3) return w;
    return w.ascii() ? kAscii3E : kBinary3E;
}

// "LINE.CSV" in the 0040 dialect (§3.3).
const Payload kLineCsv{"08 00 4C 00 49 00 4E 00 45 00 2E 00 43 00 53 00 56 00", "0008004C0049004E0045002E004300530056"};
const Payload kAtoZ{"1A 00 41 42 43 44 45 46 47 48 49 4A 4B 4C 4D 4E 4F 50 51 52 53 54 55 56 57 58 59 5A",
                    "001AABCDEFGHIJKLMNOPQRSTUVWXYZ"};
const std::string kAZ = "ABCDEFGHIJKLMNOPQRSTUVWXYZ";

std::string spaces_bin(int n) {
    std::string s;
    for (int i = 0; i < n; ++i) s += " 20";
    return s;
}

Payload p(std::string binary, std::string ascii) { return {std::move(binary), std::move(ascii)}; }

std::int64_t when(std::uint16_t date, std::uint16_t time) { return *devicemodel::from_dos(date, time); }

void stop(devicemodel::Cpu& cpu) { cpu.runtime().set_switch(cpu.memory(), devicemodel::RunSwitch::Stop); }

// A file of `size` bytes with content, attribute and date as a fixture.
void file(devicemodel::Cpu& cpu, std::uint16_t drive, const std::string& path, std::size_t size, NameForm form,
          std::uint8_t attribute = 0x20, std::optional<std::int64_t> mtime = std::nullopt) {
    auto& drives = cpu.drives();
    REQUIRE(drives.create({drive, path}, form, size) == FileFault::None);
    std::vector<std::uint8_t> content(size);
    for (std::size_t i = 0; i < size; ++i) content[i] = static_cast<std::uint8_t>(i * 7 + 1);
    REQUIRE(drives.host_write({drive, path}, content) == FileFault::None);
    if (attribute != 0x20) REQUIRE(drives.set_attribute({drive, path}, form, attribute) == FileFault::None);
    if (mtime) REQUIRE(drives.set_date({drive, path}, form, *mtime) == FileFault::None);
}

struct Client {
    protocol::Session session{};
    explicit Client(std::uint64_t id) { session.id = id; }
    std::string exchange(devicemodel::Cpu& cpu, const Wire& w, const Payload& payload) {
        return w.show(engine_for(cpu).process(w.request(payload), DataCodePolicy::Auto, session));
    }
};

Payload err(std::uint16_t code, std::uint16_t command, std::uint16_t sub) {
    return error(code, command, sub, Route{0x00, 0xFF, 0x03FF, 0x00});
}

}  // namespace

TEST_CASE("1810/0000 Read Directory: Example 1 (QCPU, drive 0)", "[files][spec]") {
    for (const auto& w : kWires) {
        auto cpu = make_cpu("Q06UDVCPU");
        file(cpu, 0, "ABCDEFGH.QPG", 1024, NameForm::Short83, 0x01, when(0x3C81, 0xA65D));
        auto req = p("10 18 00 00 30 30 30 30 00 00 01 00 03 00 00 00", "1810000000000000000100030000");
        // One file on the drive: the count is 1 (the manual's 2nd and 3rd entries are not printed).
        auto entry = p("41 42 43 44 45 46 47 48 51 50 47 01 00 00 00 00 00 00 00 00 00 00 5D A6 81 3C 00 00 00 04 00 00",
                       "ABCDEFGHQPG0001000000000000000000A65D3C81000000000400");
        INFO(w.name());
        CHECK(ql(w).exchange(cpu, req) == ql(w).expect(ok(word(0x0001) + entry)));
        // The next window (start 4) is past the end: count 0, the client stops (§4.7).
        CHECK(ql(w).exchange(cpu, p("10 18 00 00 30 30 30 30 00 00 04 00 03 00 00 00", "1810000000000000000400030000")) ==
              ql(w).expect(ok(word(0x0000))));
    }
}

TEST_CASE("1810/0040 Read Directory: Example 2 (RCPU, SUBDIR, CN response)", "[files][spec]") {
    for (const auto& w : kWires) {
        auto cpu = make_cpu("R08CPU");
        auto& drives = cpu.drives();
        REQUIRE(drives.host_make_directory({4, "SUBDIR"}) == FileFault::None);
        // Slots 3 and 4 deleted: LINE.CSV is file No. 5, as in the CN example.
        file(cpu, 4, "SUBDIR\\A.CSV", 2, NameForm::Long);
        file(cpu, 4, "SUBDIR\\B.CSV", 2, NameForm::Long);
        file(cpu, 4, "SUBDIR\\LINE.CSV", 1024, NameForm::Long, 0x01, when(0x4791, 0x71FA));
        REQUIRE(drives.remove({4, "SUBDIR\\A.CSV"}, NameForm::Long) == FileFault::None);
        REQUIRE(drives.remove({4, "SUBDIR\\B.CSV"}, NameForm::Long) == FileFault::None);
        REQUIRE(drives.set_date({4, "SUBDIR"}, NameForm::Long, when(0x4791, 0x71E7)) == FileFault::None);
        auto req = p("10 18 40 00 30 30 30 30 04 00 01 00 00 00 03 00 06 00 53 00 55 00 42 00 44 00 49 00 52 00",
                     "18100040000000040000000100030006005300550042004400490052");
        auto response = p("03 00 05 00 00 00 "
                          "01 00 2E 00 30 00 00 00 00 00 00 00 00 00 00 E7 71 91 47 00 00 00 00 00 00 "
                          "02 00 2E 00 2E 00 30 00 00 00 00 00 00 00 00 00 00 E7 71 91 47 00 00 00 00 00 00 "
                          "08 00 4C 00 49 00 4E 00 45 00 2E 00 43 00 53 00 56 00 01 00 00 00 00 00 00 00 00 00 00 FA 71 "
                          "91 47 00 00 00 04 00 00",
                          "000300000005"
                          "0001002E003000000000000000000071E74791000000000000"
                          "0002002E002E003000000000000000000071E74791000000000000"
                          "0008004C0049004E0045002E004300530056000100000000000000000071FA4791000000000400");
        INFO(w.name());
        CHECK(w.exchange(cpu, req) == w.expect(ok(response)));
        // Next start = last file No. + 1 = 6: the end, count FFFFH (§4.7).
        auto next = p("10 18 40 00 30 30 30 30 04 00 06 00 00 00 03 00 06 00 53 00 55 00 42 00 44 00 49 00 52 00",
                      "18100040000000040000000600030006005300550042004400490052");
        CHECK(w.exchange(cpu, next) == w.expect(ok(p("FF FF 05 00 00 00", "FFFF00000005"))));
    }
}

TEST_CASE("1811 Search: Examples 1 (0000) and 2 (0040), file No. 6", "[files][spec]") {
    for (const auto& w : kWires) {
        auto q = make_cpu("Q06UDVCPU");
        for (int i = 1; i <= 5; ++i) file(q, 0, "F" + std::to_string(i) + ".CSV", 4, NameForm::Short83);
        file(q, 0, "ABC.QPG", 4, NameForm::Short83);
        auto req = p("11 18 00 00 20 20 20 20 00 00 00 00 07 00 41 42 43 2E 51 50 47", "18110000    000000000007ABC.QPG");
        INFO(w.name());
        CHECK(ql(w).exchange(q, req) == ql(w).expect(ok(word(0x0006))));

        auto r = make_cpu("R08CPU");
        for (int i = 1; i <= 5; ++i) file(r, 4, "F" + std::to_string(i) + ".CSV", 4, NameForm::Long);
        file(r, 4, "LINE.CSV", 4, NameForm::Long);
        auto req2 = p("11 18 40 00 00 00 00 00 04 00 00 00 08 00 4C 00 49 00 4E 00 45 00 2E 00 43 00 53 00 56 00",
                      "181100400000000400000008004C0049004E0045002E004300530056");
        CHECK(w.exchange(r, req2) == w.expect(ok(p("06 00 00 00", "00000006"))));
    }
}

TEST_CASE("1820 New File: Example 1 as printed (16384 bytes) and Example 2 (7168 bytes, inferred)", "[files][spec]") {
    for (const auto& w : kWires) {
        INFO(w.name());
        auto q = make_cpu("Q06UDVCPU");
        auto req = p("20 18 00 00 20 20 20 20 00 00 00 40 00 00 07 00 41 42 43 2E 43 53 56", "18200000    0000000040000007ABC.CSV");
        CHECK(ql(w).exchange(q, req) == ql(w).expect(ok()));
        std::vector<std::uint8_t> content;
        REQUIRE(q.drives().host_read({0, "ABC.CSV"}, content) == FileFault::None);
        CHECK(content == std::vector<std::uint8_t>(16384, 0));   // reserved and zero-filled
        CHECK(ql(w).exchange(q, req) == ql(w).expect(err(0x4028, 0x1820, 0x0000)));   // the name is taken

        auto r = make_cpu("R08CPU");
        auto req2 = p("20 18 40 00 00 00 00 00 04 00 00 1C 00 00 " + kLineCsv.binary, "182000400000000400001C00" + kLineCsv.ascii);
        CHECK(w.exchange(r, req2) == w.expect(ok()));
        REQUIRE(r.drives().host_read({4, "LINE.CSV"}, content) == FileFault::None);
        CHECK(content.size() == 7168);
    }
}

TEST_CASE("1822 Delete File: Examples 1 (password 1234) and 2 (password A-Z)", "[files][spec]") {
    for (const auto& w : kWires) {
        INFO(w.name());
        auto q = make_cpu("Q06UDVCPU");
        stop(q);   // a program file: STOP first (§5)
        file(q, 0, "ABC.QPG", 4, NameForm::Short83);
        q.drives().set_password(0, "ABC.QPG", "1234");
        auto req = p("22 18 00 00 31 32 33 34 00 00 07 00 41 42 43 2E 51 50 47", "18220000123400000007ABC.QPG");
        auto wrong = p("22 18 00 00 31 32 33 35 00 00 07 00 41 42 43 2E 51 50 47", "18220000123500000007ABC.QPG");
        CHECK(ql(w).exchange(q, wrong) == ql(w).expect(err(0x4026, 0x1822, 0x0000)));
        CHECK(ql(w).exchange(q, req) == ql(w).expect(ok()));
        std::uint32_t number = 0;
        CHECK(q.drives().find({0, "ABC.QPG"}, NameForm::Short83, number) == FileFault::NotFound);
        CHECK(ql(w).exchange(q, req) == ql(w).expect(err(0x4022, 0x1822, 0x0000)));

        auto r = make_cpu("R08CPU");
        file(r, 4, "LINE.CSV", 4, NameForm::Long);
        r.drives().set_password(4, "LINE.CSV", kAZ);
        auto req2 = p("22 18 40 00 " + kAtoZ.binary + " 04 00 " + kLineCsv.binary, "18220040" + kAtoZ.ascii + "0004" + kLineCsv.ascii);
        CHECK(w.exchange(r, req2) == w.expect(ok()));
    }
}

TEST_CASE("1824 Copy File: Examples 1 (drive 0 to 0) and 2 (drive 2 to 4)", "[files][spec]") {
    for (const auto& w : kWires) {
        INFO(w.name());
        auto q = make_cpu("Q06UDVCPU");
        stop(q);
        file(q, 0, "ABC.QPG", 64, NameForm::Short83, 0x20, when(0x3C81, 0xA65D));
        q.drives().set_password(0, "ABC.QPG", "1234");
        auto req = p("24 18 00 00 00 00 00 00 00 00 00 00 31 32 33 34 00 00 07 00 43 42 41 2E 51 50 47 31 32 33 34 00 00 07 "
                     "00 41 42 43 2E 51 50 47",
                     "182400000000000000000000123400000007CBA.QPG123400000007ABC.QPG");
        CHECK(ql(w).exchange(q, req) == ql(w).expect(ok()));
        std::vector<std::uint8_t> a, b;
        REQUIRE(q.drives().host_read({0, "ABC.QPG"}, a) == FileFault::None);
        REQUIRE(q.drives().host_read({0, "CBA.QPG"}, b) == FileFault::None);
        CHECK(a == b);
        CHECK(ql(w).exchange(q, req) == ql(w).expect(err(0x4028, 0x1824, 0x0000)));   // no overwrite

        auto r = make_cpu("R08CPU");
        file(r, 2, "LINE.CSV", 3000, NameForm::Long);
        r.drives().set_password(2, "LINE.CSV", kAZ);
        auto req2 = p("24 18 40 00 00 00 00 00 00 00 00 00 " + kAtoZ.binary + " 04 00 " + kLineCsv.binary + " " + kAtoZ.binary +
                          " 02 00 " + kLineCsv.binary,
                      "182400400000000000000000" + kAtoZ.ascii + "0004" + kLineCsv.ascii + kAtoZ.ascii + "0002" + kLineCsv.ascii);
        CHECK(w.exchange(r, req2) == w.expect(ok()));
        REQUIRE(r.drives().host_read({2, "LINE.CSV"}, a) == FileFault::None);
        REQUIRE(r.drives().host_read({4, "LINE.CSV"}, b) == FileFault::None);
        CHECK(a == b);
    }
}

TEST_CASE("1825 Change File State and 1826 Change File Date: Examples 1 and 2", "[files][spec]") {
    for (const auto& w : kWires) {
        INFO(w.name());
        auto q = make_cpu("Q06UDVCPU");
        stop(q);
        file(q, 0, "ABC.QPG", 4, NameForm::Short83);
        q.drives().set_password(0, "ABC.QPG", "1234");
        CHECK(ql(w).exchange(q, p("25 18 00 00 31 32 33 34 00 00 01 00 07 00 41 42 43 2E 51 50 47", "182500001234000000010007ABC.QPG")) ==
              ql(w).expect(ok()));
        CHECK(ql(w).exchange(q, p("26 18 00 00 00 00 00 00 00 00 81 3C 5D A6 07 00 41 42 43 2E 51 50 47",
                              "18260000000000003C81A65D0007ABC.QPG")) == ql(w).expect(ok()));
        devicemodel::Listing listing;
        REQUIRE(q.drives().list(0, "", NameForm::Short83, 1, 1, listing) == FileFault::None);
        REQUIRE(listing.entries.size() == 1);
        CHECK(listing.entries[0].attribute == 0x01);
        CHECK(listing.entries[0].dos_date == 0x3C81);
        CHECK(listing.entries[0].dos_time == 0xA65D);

        auto r = make_cpu("R08CPU");
        file(r, 4, "LINE.CSV", 4, NameForm::Long);
        r.drives().set_password(4, "LINE.CSV", kAZ);
        CHECK(w.exchange(r, p("25 18 40 00 " + kAtoZ.binary + " 04 00 01 00 " + kLineCsv.binary,
                              "18250040" + kAtoZ.ascii + "00040001" + kLineCsv.ascii)) == w.expect(ok()));
        CHECK(w.exchange(r, p("26 18 40 00 00 00 00 00 04 00 81 3C 5D A6 " + kLineCsv.binary,
                              "18260040000000043C81A65D" + kLineCsv.ascii)) == w.expect(ok()));
        // A bad date (month 0) is refused.
        CHECK(w.exchange(r, p("26 18 40 00 00 00 00 00 04 00 01 3C 5D A6 " + kLineCsv.binary,
                              "18260040000000043C01A65D" + kLineCsv.ascii)) == w.expect(err(0xC05C, 0x1826, 0x0040)));
    }
}

TEST_CASE("1827 Open, 1828 Read, 1829 Write, 182A Close: the examples (pointer 0, 1 KB)", "[files][spec]") {
    for (const auto& w : kWires) {
        INFO(w.name());
        auto q = make_cpu("Q06UDVCPU");
        stop(q);
        file(q, 0, "ABC.QPG", 1024, NameForm::Short83);
        q.drives().set_password(0, "ABC.QPG", "1234");
        Client c(1);
        CHECK(c.exchange(q, ql(w), p("27 18 00 00 31 32 33 34 00 01 00 00 07 00 41 42 43 2E 51 50 47", "182700001234010000000007ABC.QPG")) ==
              ql(w).expect(ok(word(0x0000))));
        // 1829: 1024 bytes at offset 0.
        std::string data_bin, data_asc;
        for (int i = 0; i < 1024; ++i) {
            data_bin += (i ? " " : "") + hexn(static_cast<std::uint8_t>(255 - i), 2);
            data_asc += hexn(static_cast<std::uint8_t>(255 - i), 2);
        }
        CHECK(c.exchange(q, ql(w), p("29 18 00 00 00 00 00 00 00 00 00 04 " + data_bin, "182900000000000000000400" + data_asc)) ==
              ql(w).expect(ok(word(0x0400))));
        CHECK(c.exchange(q, ql(w), p("28 18 00 00 00 00 00 00 00 00 00 04", "182800000000000000000400")) ==
              ql(w).expect(ok(word(0x0400) + p(data_bin, data_asc))));
        CHECK(c.exchange(q, ql(w), p("2A 18 00 00 00 00 02 00", "182A000000000002")) == ql(w).expect(ok()));
        CHECK(q.drives().open_files().empty());

        auto r = make_cpu("R08CPU");
        file(r, 4, "LINE.CSV", 4, NameForm::Long);
        r.drives().set_password(4, "LINE.CSV", kAZ);
        CHECK(c.exchange(r, w, p("27 18 40 00 " + kAtoZ.binary + " 00 01 04 00 " + kLineCsv.binary,
                                 "18270040" + kAtoZ.ascii + "01000004" + kLineCsv.ascii)) == w.expect(ok(word(0x0000))));

        auto l = make_cpu("L02CPU");
        stop(l);
        file(l, 0, "MAIN.QPG", 8, NameForm::Short83);
        l.drives().set_password(0, "MAIN.QPG", "AbCd1234");
        std::string pad(24, ' ');
        auto pad_bin = spaces_bin(24);
        CHECK(c.exchange(l, ql(w), p("27 18 04 00 41 62 43 64 31 32 33 34" + pad_bin + " 00 01 00 00 08 00 4D 41 49 4E 2E 51 50 47",
                                 "18270004AbCd1234" + pad + "010000000008MAIN.QPG")) == ql(w).expect(ok(word(0x0000))));
        // *5: with 0000 an LCPU reaches only files without a password.
        CHECK(c.exchange(l, ql(w), p("27 18 00 00 41 62 43 64 00 00 00 00 08 00 4D 41 49 4E 2E 51 50 47", "18270000AbCd000000000008MAIN.QPG")) ==
              ql(w).expect(err(0x4026, 0x1827, 0x0000)));
    }
}

TEST_CASE("file commands: each family speaks its own subcommands (§2.2)", "[files]") {
    const auto& w = kBinary3E;
    auto q = make_cpu("Q06UDVCPU");
    auto r = make_cpu("R08CPU");
    auto fx = make_cpu("FX5U-32MR");
    auto list_q = p("10 18 00 00 30 30 30 30 00 00 01 00 03 00 00 00", "");
    auto list_r = p("10 18 40 00 30 30 30 30 04 00 01 00 00 00 03 00 00 00", "");
    CHECK(w.exchange(q, list_r) == w.expect(err(0xC059, 0x1810, 0x0040)));
    CHECK(w.exchange(r, list_q) == w.expect(err(0xC059, 0x1810, 0x0000)));
    CHECK(w.exchange(r, list_r) == w.expect(ok(p("FF FF 00 00 00 00", ""))));   // an empty root: the end at once
    CHECK(w.exchange(fx, list_q) == w.expect(err(port_of(fx).not_supported_code, 0x1810, 0x0000)));
    // 0004 is for LCPU only (*4).
    CHECK(w.exchange(q, p("22 18 04 00" + spaces_bin(32) + " 00 00 01 00 41", "")) == w.expect(err(0xC059, 0x1822, 0x0004)));
    // iQ-R has no drive 0; drive 1 is drive 3.
    CHECK(w.exchange(r, p("10 18 40 00 30 30 30 30 00 00 01 00 00 00 03 00 00 00", "")) == w.expect(err(0x4021, 0x1810, 0x0040)));
    file(r, 3, "X.BIN", 2, NameForm::Long);
    CHECK(w.exchange(r, p("11 18 40 00 00 00 00 00 01 00 00 00 05 00 58 00 2E 00 42 00 49 00 4E 00", "")) ==
          w.expect(ok(p("01 00 00 00", ""))));
}

TEST_CASE("file names that would leave the drive are refused and create nothing", "[files]") {
    auto r = make_cpu("R08CPU");
    REQUIRE(r.drives().host_make_directory({4, "SUB"}) == FileFault::None);
    for (std::string bad : {"..\\X.CSV", "SUB\\..\\..\\X.CSV", "\\..\\X.CSV", "C:\\X.CSV", "SUB/../X.CSV", "CON",
                            "nul.txt", "SUB\\\\X.CSV", "A*B.CSV", ".", "X.CSV."}) {
        INFO(bad);
        CHECK(r.drives().create({4, bad}, NameForm::Long, 4) == FileFault::BadName);
    }
    for (std::string bad : {"ABCDEFGHI.CSV", "A.CSVX", "A.B.C", "..", "COM1.TXT"}) {
        INFO(bad);
        CHECK(r.drives().create({2, bad}, NameForm::Short83, 4) == FileFault::BadName);
    }
    devicemodel::Listing listing;
    REQUIRE(r.drives().host_list(4, "", listing) == FileFault::None);
    CHECK(listing.entries.size() == 1);   // SUB only
    // Over the wire: 1820 with "..\A" answers 4024.
    const auto& w = kBinary3E;
    CHECK(w.exchange(r, p("20 18 40 00 00 00 00 00 04 00 04 00 00 00 04 00 2E 00 2E 00 5C 00 41 00", "")) ==
          w.expect(err(0x4024, 0x1820, 0x0040)));
}

TEST_CASE("file locks: one writer, shared readers, owners, close types (§8.3)", "[files]") {
    auto r = make_cpu("R08CPU");
    file(r, 4, "LINE.CSV", 8, NameForm::Long);
    const auto& w = kBinary3E;
    Client a(1), b(2);
    auto open_read = p("27 18 40 00 00 00 00 00 04 00 " + kLineCsv.binary, "");
    auto open_write = p("27 18 40 00 00 00 00 01 04 00 " + kLineCsv.binary, "");
    auto remove = p("22 18 40 00 00 00 04 00 " + kLineCsv.binary, "");
    CHECK(a.exchange(r, w, open_read) == w.expect(ok(word(0))));
    CHECK(b.exchange(r, w, open_read) == w.expect(ok(word(1))));    // readers share
    CHECK(b.exchange(r, w, open_write) == w.expect(err(0x4025, 0x1827, 0x0040)));
    CHECK(b.exchange(r, w, remove) == w.expect(err(0x4025, 0x1822, 0x0040)));
    // b reads on a's pointer: refused; b closes a's pointer with type 0: refused.
    CHECK(b.exchange(r, w, p("28 18 00 00 00 00 00 00 00 00 02 00", "")) == w.expect(err(0x4025, 0x1828, 0x0000)));
    CHECK(b.exchange(r, w, p("2A 18 00 00 00 00 00 00", "")) == w.expect(err(0x4025, 0x182A, 0x0000)));
    CHECK(b.exchange(r, w, p("2A 18 00 00 00 00 01 00", "")) == w.expect(ok()));   // all of b's
    CHECK(r.drives().open_files().size() == 1);
    CHECK(a.exchange(r, w, p("2A 18 00 00 00 00 00 00", "")) == w.expect(ok()));
    CHECK(a.exchange(r, w, open_write) == w.expect(ok(word(0))));
    CHECK(b.exchange(r, w, open_read) == w.expect(err(0x4025, 0x1827, 0x0040)));
    // 1829 past the reserved size, odd offset, more than 1920 bytes, unknown pointer.
    CHECK(a.exchange(r, w, p("29 18 00 00 00 00 06 00 00 00 04 00 01 02 03 04", "")) == w.expect(err(0x4027, 0x1829, 0x0000)));
    CHECK(a.exchange(r, w, p("29 18 00 00 00 00 01 00 00 00 02 00 01 02", "")) == w.expect(err(0xC05C, 0x1829, 0x0000)));
    CHECK(a.exchange(r, w, p("29 18 00 00 00 00 00 00 00 00 81 07", "")) == w.expect(err(0xCEE1, 0x1829, 0x0000)));
    CHECK(a.exchange(r, w, p("28 18 00 00 05 00 00 00 00 00 02 00", "")) == w.expect(err(0xC059, 0x1828, 0x0000)));
    // Close type 2 releases another client's lock; so does a Remote RESET.
    CHECK(b.exchange(r, w, p("2A 18 00 00 00 00 02 00", "")) == w.expect(ok()));
    CHECK(r.drives().open_files().empty());
    CHECK(a.exchange(r, w, open_write) == w.expect(ok(word(0))));
    auto config = r.runtime().config();
    config.remote_reset_enabled = true;
    config.run_switch = devicemodel::RunSwitch::Stop;
    r.runtime().configure(config, r.memory());
    auto reset = engine_for(r).process(w.request(p("06 10 00 00 01 00", "")), DataCodePolicy::Auto, a.session);
    CHECK(reset.action == Outcome::Action::Restart);
    CHECK(r.drives().open_files().empty());
}

TEST_CASE("file protection: write-protect, system protect, capacity, read-only, Q/L RUN", "[files]") {
    const auto& w = kBinary3E;
    auto r = make_cpu("R08CPU");
    file(r, 2, "LINE.CSV", 8, NameForm::Long);
    r.drives().set_write_protect(2, true);
    CHECK(w.exchange(r, p("22 18 40 00 00 00 02 00 " + kLineCsv.binary, "")) == w.expect(err(0x4050, 0x1822, 0x0040)));
    r.drives().set_write_protect(2, false);
    // System protect blocks the §5 list before the handler (the profile's 4004... code).
    auto protect = make_cpu("R08CPU");
    auto config = protect.runtime().config();
    config.system_protect = true;
    protect.runtime().configure(config, protect.memory());
    file(protect, 4, "LINE.CSV", 8, NameForm::Long);
    auto del = p("22 18 40 00 00 00 04 00 " + kLineCsv.binary, "");
    CHECK(w.exchange(protect, del) == w.expect(err(0x4004, 0x1822, 0x0040)));
    CHECK(w.exchange(protect, p("11 18 40 00 00 00 00 00 04 00 00 00 " + kLineCsv.binary, "")) == w.expect(ok(p("01 00 00 00", ""))));
    // Capacity: drive 3 holds 512 KiB.
    CHECK(w.exchange(r, p("20 18 40 00 00 00 00 00 03 00 01 00 08 00 " + kLineCsv.binary, "")) ==
          w.expect(err(0x4029, 0x1820, 0x0040)));
    // Read-only: no write-open, no delete.
    CHECK(w.exchange(r, p("25 18 40 00 00 00 02 00 01 00 " + kLineCsv.binary, "")) == w.expect(ok()));
    CHECK(w.exchange(r, p("27 18 40 00 00 00 00 01 02 00 " + kLineCsv.binary, "")) == w.expect(err(0x4052, 0x1827, 0x0040)));
    CHECK(w.exchange(r, p("22 18 40 00 00 00 02 00 " + kLineCsv.binary, "")) == w.expect(err(0x4052, 0x1822, 0x0040)));
    // Q/L in RUN: programs and parameters are not deleted, drive-0 programs not re-dated.
    auto q = make_cpu("Q06UDVCPU");
    REQUIRE(q.runtime().state() == devicemodel::RunState::Run);
    file(q, 0, "MAIN.QPG", 8, NameForm::Short83);
    CHECK(ql(w).exchange(q, p("22 18 00 00 20 20 20 20 00 00 08 00 4D 41 49 4E 2E 51 50 47", "")) ==
          ql(w).expect(err(0x4013, 0x1822, 0x0000)));
    CHECK(ql(w).exchange(q, p("26 18 00 00 00 00 00 00 00 00 81 3C 5D A6 08 00 4D 41 49 4E 2E 51 50 47", "")) ==
          ql(w).expect(err(0x4013, 0x1826, 0x0000)));
    // 1820 refuses the project-data extensions on Q/L (§4.2): create under another name, then copy.
    CHECK(ql(w).exchange(q, p("20 18 00 00 20 20 20 20 00 00 10 00 00 00 07 00 41 42 43 2E 51 50 47", "")) ==
          ql(w).expect(err(0x4024, 0x1820, 0x0000)));
}

TEST_CASE("the outcome names the file a request carried, for the call monitor and recordings", "[files]") {
    for (const auto& w : kWires) {
        INFO(w.name());
        auto r = make_cpu("R08CPU");
        file(r, 4, "LINE.CSV", 4, NameForm::Long);
        auto search = p("11 18 40 00 00 00 00 00 04 00 00 00 08 00 4C 00 49 00 4E 00 45 00 2E 00 43 00 53 00 56 00",
                        "181100400000000400000008004C0049004E0045002E004300530056");
        CHECK(run(r, w.request(search)).named == "4:LINE.CSV");
    }
}

TEST_CASE("a scenario trigger takes the SD card out at t = 5 s and moves its LOCK switch", "[files][scenario]") {
    ScenarioRig rig(R"({"triggers": [
        {"when": {"at_ms": 5000}, "do": [{"drive": {"number": 2, "present": false}}]},
        {"when": {"at_ms": 6000}, "do": [{"drive": {"number": 2, "present": true, "write_protect": true}}]}]})");
    const FileRef log{2, "LOG.CSV"};
    REQUIRE(rig.cpu.drives().create(log, NameForm::Long, 4) == FileFault::None);
    rig.scan(0);
    rig.scan(4990);
    const std::vector<std::uint8_t> data{1, 2, 3, 4};
    CHECK(rig.cpu.drives().host_write(log, data) == FileFault::None);
    rig.scan(5000);
    CHECK(rig.cpu.drives().create({2, "B.CSV"}, NameForm::Long, 4) == FileFault::NoDrive);   // no card
    rig.scan(6000);
    CHECK(rig.cpu.drives().create({2, "B.CSV"}, NameForm::Long, 4) == FileFault::WriteProtected);
    CHECK_THROWS_WITH(ScenarioRig(R"({"triggers": [{"when": {"at_ms": 0}, "do": [{"drive": {"number": 0, "present": false}}]}]})"),
                      "test.json: /triggers/0/do/0/drive/number: R08CPU has no drive 0; name one of its drives (GET "
                      "/api/drives lists them)");
}
