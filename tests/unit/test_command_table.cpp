// The command table's flags against the specs' tables: the request path asks
// these flags and nothing else, so a wrong flag is a wrong answer on the wire.
// Sources: SLMP Reference Manual §5.6–§5.10 (remote, password, clear error),
// Appendix 3 (commands that cannot reach CPU No.2–4), real-CPU measurements
// (what each port family refuses).
#include "protocol/command_table.hpp"
#include "protocol/engine.hpp"

#include <set>

#include "support/fixtures.hpp"

using namespace slmp;
using namespace slmp::protocol;
using devicemodel::Family;

namespace {

std::set<std::uint16_t> commands_where(bool (CommandSpec::*flag)() const) {
    std::set<std::uint16_t> found;
    for (const auto& row : all_commands())
        if ((row.*flag)()) found.insert(row.command);
    return found;
}

std::set<std::uint16_t> commands_refused_by(Family family) {
    std::set<std::uint16_t> found;
    for (const auto& row : all_commands())
        if (!row.served_by(family)) found.insert(row.command);
    return found;
}

}  // namespace

TEST_CASE("command table: exactly 1630/1631 are served on a connection the remote password locks", "[table]") {
    CHECK(commands_where(&CommandSpec::password_exempt) == std::set<std::uint16_t>{0x1630, 0x1631});
}

TEST_CASE("command table: exactly 1001 1002 1003 1005 1006 1617 are operator (state-changing) commands", "[table]") {
    CHECK(commands_where(&CommandSpec::operator_command) ==
          std::set<std::uint16_t>{0x1001, 0x1002, 0x1003, 0x1005, 0x1006, 0x1617});
}

TEST_CASE("command table: the commands that cannot reach CPU No.2-4 (Appendix 3)", "[table]") {
    CHECK(commands_where(&CommandSpec::control_cpu_only) ==
          std::set<std::uint16_t>{0x0613, 0x0619, 0x0801, 0x0802, 0x1613, 0x1617});
}

TEST_CASE("command table: exactly the file commands 1810-182A name only §3.1.4's file destinations", "[table][files]") {
    CHECK(commands_where(&CommandSpec::file_route) ==
          std::set<std::uint16_t>{0x1810, 0x1811, 0x1820, 0x1822, 0x1824, 0x1825, 0x1826, 0x1827, 0x1828, 0x1829, 0x182A});
    // Every row of a command agrees (the decoder asks any row of an unknown subcommand).
    for (const auto& row : all_commands())
        if (row.command >= 0x1810 && row.command <= 0x182A) CHECK(row.file_route());
    auto destination = [](std::uint16_t io) { return file_route_allowed(Route{0x00, 0xFF, io, 0x00}); };
    for (std::uint16_t io : {0x03FF, 0x03D2, 0x03D3, 0x03E0, 0x03E1, 0x03E2, 0x03E3}) CHECK(destination(io));
    for (std::uint16_t io : {0x03D0, 0x03D1, 0x0000, 0x0004, 0x01FF, 0x03E4}) CHECK_FALSE(destination(io));
}

TEST_CASE("command table: device commands have a decoder, the write ones are flagged as writes", "[table]") {
    CHECK(commands_where(&CommandSpec::device_command) ==
          std::set<std::uint16_t>{0x0401, 0x0403, 0x0406, 0x0801, 0x1401, 0x1402, 0x1406});
    std::set<std::uint16_t> device_writes;
    for (const auto& row : all_commands())
        if (row.device_command() && row.writes()) device_writes.insert(row.command);
    CHECK(device_writes == std::set<std::uint16_t>{0x1401, 0x1402, 0x1406});
    // Everything else that writes memory: buffer memory, and the remote
    // operations that clear devices (RUN with a clear mode, Latch Clear, RESET).
    CHECK(commands_where(&CommandSpec::writes) ==
          std::set<std::uint16_t>{0x1001, 0x1005, 0x1006, 0x1401, 0x1402, 0x1406, 0x141A, 0x141B, 0x1601, 0x1613,
                                  // the file commands system protect blocks (SLMP Reference Manual §5.8)
                                  0x1820, 0x1822, 0x1824, 0x1825, 0x1826, 0x1829});
}

TEST_CASE("command table: the device form and the extended layout follow the subcommand", "[table]") {
    for (const auto& row : all_commands()) {
        INFO(std::hex << row.command << "/" << row.subcommand);
        if (!row.device_command()) {
            // The file commands' dialects (SLMP Reference Manual §5.8): 0000 Q/L, 0004 L, 0040 iQ-R.
            const bool file_command = row.command >= 0x1810 && row.command <= 0x182A;
            CHECK((row.subcommand == 0x0000 || (file_command && (row.subcommand == 0x0004 || row.subcommand == 0x0040))));
            continue;
        }
        const auto form = row.subcommand & 0x0003;
        CHECK(row.extended() == ((row.subcommand & 0x0080) != 0));
        CHECK(row.form == (form >= 2 ? DeviceForm::IQR : DeviceForm::Q));
        CHECK(row.access == (form % 2 == 1 ? Access::Bits : Access::Words));
    }
}

TEST_CASE("command table: which port families refuse which commands (hardware-behaviour.md §4)", "[table]") {   // signposts: allow (the name ctest lists)
    CHECK(commands_refused_by(Family::IQR).empty());
    // Label commands: iQ-R CPUs only (SLMP Reference Manual §5.1).
    const std::set<std::uint16_t> labels{0x041A, 0x041C, 0x141A, 0x141B};
    CHECK(commands_refused_by(Family::QJ71E71) == labels);
    std::set<std::uint16_t> built_in_q_l{0x0101, 0x0406, 0x0613, 0x0619, 0x1406, 0x1613};
    built_in_q_l.insert(labels.begin(), labels.end());
    CHECK(commands_refused_by(Family::QnU) == built_in_q_l);
    CHECK(commands_refused_by(Family::L) == built_in_q_l);
    std::set<std::uint16_t> fx5{0x0613, 0x0801, 0x0802, 0x1613};
    fx5.insert(labels.begin(), labels.end());
    // File control 1810-182A: not in the FX5 port's command list (inferred; the
    // FX5 reaches its SD card by FTP; docs/files.md).
    fx5.insert({0x1810, 0x1811, 0x1820, 0x1822, 0x1824, 0x1825, 0x1826, 0x1827, 0x1828, 0x1829, 0x182A});
    CHECK(commands_refused_by(Family::IQF) == fx5);
}

TEST_CASE("command table: find_command and find_any_row", "[table]") {
    REQUIRE(find_command(0x0401, 0x0082));
    CHECK(find_command(0x0401, 0x0082)->name == "Device Read (word units, iQ-R form, extended)");
    CHECK_FALSE(find_command(0x0403, 0x0001));   // Read Random has no bit units
    REQUIRE(find_any_row(0x0403));
    CHECK(find_any_row(0x0403)->command == 0x0403);
    REQUIRE(find_command(0x041A, 0x0000));
    CHECK(find_command(0x041A, 0x0000)->name == "Array Label Read");
    CHECK_FALSE(find_command(0x041A, 0x0001));   // labels: subcommand 0000 only
    CHECK(find_command(0x141B, 0x0000)->writes());
    CHECK_FALSE(find_any_row(0x0E40));   // between the node commands 0E3A and 0E44: none
}

TEST_CASE("command table: the node commands 0E30-0E53 (JA §3.12-3.14) and the parameter write sequence's rows", "[table][node]") {
    CHECK(commands_where(&CommandSpec::node_command) ==
          std::set<std::uint16_t>{0x0E30, 0x0E31, 0x0E32, 0x0E33, 0x0E34, 0x0E35, 0x0E36, 0x0E3A, 0x0E44, 0x0E45, 0x0E53});
    CHECK(commands_where(&CommandSpec::parameter_write) == std::set<std::uint16_t>{0x0E34, 0x0E35, 0x0E36, 0x0E3A});
}
