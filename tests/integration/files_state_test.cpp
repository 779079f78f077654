// File drives against the real binary, the parts beyond one TCP session:
// UDP peers as separate lock owners, file dates from the CPU's clock (frozen
// here, so the expected date is exact), and file Nos., attributes and drive
// switches that outlive a kill -9 in the state directory (docs/files.md).
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "frames.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "protocol/client.hpp"
#include "protocol/client_files.hpp"
#include "sim_process.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
namespace fs = std::filesystem;

namespace {

const Wire kBin{FrameKind::E3, Codec::Binary, 0};

client::Response ask(Link& link, const Bytes& request) {
    auto parsed = client::parse_response(link.exchange(request));
    REQUIRE(parsed);
    return *parsed;
}

std::uint16_t code(Link& link, const Bytes& request) { return ask(link, request).end_code; }

client::FileTarget iqr(std::uint16_t drive, std::string name) { return {true, drive, std::move(name), ""}; }

// The 1810 (0040) entries of a drive's root, every page.
std::vector<client::FileListEntry> listing(Link& link, std::uint16_t drive) {
    std::vector<client::FileListEntry> out;
    std::uint32_t start = 1;
    for (int page = 0; page < 100; ++page) {
        auto r = ask(link, client::file_list(kBin.options(), true, drive, start, 36));
        REQUIRE(r.end_code == 0);
        auto list = client::parse_file_list(r, true);
        REQUIRE(list);
        if (list->count == 0xFFFF) break;
        out.insert(out.end(), list->entries.begin(), list->entries.end());
        start = list->last_number + 1;
    }
    return out;
}

const client::FileListEntry& entry(const std::vector<client::FileListEntry>& entries, const std::string& name) {
    static const client::FileListEntry none;
    for (const auto& e : entries)
        if (e.name == name) return e;
    FAIL_CHECK("no entry " << name);
    return none;
}

std::uint32_t file_number(Link& link, const std::string& name) {
    auto r = ask(link, client::file_search(kBin.options(), iqr(4, name)));
    REQUIRE(r.end_code == 0);
    return *client::parse_file_number(r, true);
}

std::int64_t host_mtime(const fs::path& file) {
    struct ::stat st{};
    REQUIRE(::stat(file.c_str(), &st) == 0);
    return st.st_mtime;
}

}  // namespace

TEST_CASE("files: each UDP peer is its own lock owner", "[files][udp]") {
    TempDir data;
    auto folder = data.path() / "d";
    fs::create_directories(folder);
    std::ofstream(folder / "A.BIN", std::ios::binary) << std::string(16, 'a');
    SimProcess sim(with_args({"--profile", "R08CPU", "--drive", "4=" + folder.string()}));
    UdpLink first(sim.udp_port()), second(sim.udp_port());
    auto opened = ask(first, client::file_open(kBin.options(), iqr(4, "A.BIN"), true));
    REQUIRE(opened.end_code == 0);
    auto pointer = *client::parse_file_pointer(opened);
    const Bytes four{1, 2, 3, 4};

    // Another peer of the same port is another client: the pointer is not its own.
    CHECK(code(second, client::file_write(kBin.options(), pointer, 0, four)) == 0x4025);
    CHECK(code(second, client::file_read(kBin.options(), pointer, 0, 4)) == 0x4025);
    CHECK(code(second, client::file_close(kBin.options(), pointer, 0)) == 0x4025);
    CHECK(code(second, client::file_open(kBin.options(), iqr(4, "A.BIN"), false)) == 0x4025);
    // Close type 1 closes the second peer's files only: the first's lock stays.
    CHECK(code(second, client::file_close(kBin.options(), 0, 1)) == 0);
    auto locks = http_get(sim.http_port(), "/api/drives/locks").json()["locks"];
    REQUIRE(locks.size() == 1);
    CHECK(locks[0]["peer"] == "udp:127.0.0.1:" + std::to_string(first.client().local_port()));

    CHECK(code(first, client::file_write(kBin.options(), pointer, 0, four)) == 0);
    CHECK(code(first, client::file_close(kBin.options(), pointer, 0)) == 0);
    CHECK(http_get(sim.http_port(), "/api/drives/locks").json()["locks"].empty());
    std::ifstream in(folder / "A.BIN", std::ios::binary);
    CHECK(std::string(std::istreambuf_iterator<char>(in), {}) == std::string("\x01\x02\x03\x04", 4) + std::string(12, 'a'));
}

TEST_CASE("files: 1820 and 1829 date files by the CPU's clock, which --clock frozen stops", "[files][clock]") {
    TempDir data;
    auto folder = data.path() / "d";
    fs::create_directories(folder);
    SimProcess sim(with_args({"--profile", "R08CPU", "--clock", "frozen", "--drive", "4=" + folder.string()}));
    TcpLink link(sim.tcp_port());
    REQUIRE(code(link, client::file_new(kBin.options(), iqr(4, "A.BIN"), 4)) == 0);
    const auto created = host_mtime(folder / "A.BIN");

    // One minute of CPU time, all at once: the calendar (SD210-SD215) moves by
    // exactly that, the host's clock by however long the steps took.
    auto stepped = http(sim.http_port(), "POST", "/api/clock/step", R"({"ms": 60000})");
    REQUIRE(stepped.status == 200);
    REQUIRE(code(link, client::file_new(kBin.options(), iqr(4, "B.BIN"), 4)) == 0);
    CHECK(host_mtime(folder / "B.BIN") == created + 60);
    CHECK(host_mtime(folder / "A.BIN") == created);   // untouched

    auto opened = ask(link, client::file_open(kBin.options(), iqr(4, "A.BIN"), true));
    REQUIRE(opened.end_code == 0);
    auto pointer = *client::parse_file_pointer(opened);
    REQUIRE(code(link, client::file_write(kBin.options(), pointer, 0, Bytes{9, 9})) == 0);
    REQUIRE(code(link, client::file_close(kBin.options(), pointer, 0)) == 0);
    CHECK(host_mtime(folder / "A.BIN") == created + 60);

    // The DOS date/time 1810 shows is the calendar the CPU shows.
    auto sd = ask(link, client::read_words(kBin.options(), *slmp::devicemodel::parse_address("SD210"), 6));
    REQUIRE(sd.end_code == 0);
    auto in = sd.reader();
    std::uint16_t year = in.u16("y"), month = in.u16("mo"), day = in.u16("d"), hour = in.u16("h"),
                  minute = in.u16("mi"), second = in.u16("s");
    const auto entries = listing(link, 4);
    for (const auto* name : {"A.BIN", "B.BIN"}) {
        INFO(name);
        const auto& e = entry(entries, name);
        CHECK(e.date == ((year - 1980) << 9 | month << 5 | day));
        CHECK(e.time == (hour << 11 | minute << 5 | second / 2));
    }
}

TEST_CASE("files: file Nos., attributes and drive switches survive a kill -9 in the state directory",
          "[files][state]") {
    TempDir data;
    auto state = data.path() / "state";
    auto scenario = data.path() / "lock.json";
    std::ofstream(scenario) << R"({"triggers": [{"when": {"at_ms": 0}, "do": [{"drive": {"number": 2, "write_protect": true}}]}]})";
    {
        SimProcess sim(with_args({"--profile", "R08CPU", "--clock", "frozen", "--state-dir", state.string(),
                                  "--scenario", scenario.string()}));
        REQUIRE(http(sim.http_port(), "POST", "/api/clock/step", R"({"scans": 1})").status == 200);
        TcpLink link(sim.tcp_port());
        CHECK(code(link, client::file_new(kBin.options(), iqr(2, "X.BIN"), 4)) == 0x4050);   // the LOCK switch moved
        for (const auto* name : {"A.BIN", "B.BIN", "C.BIN"})
            REQUIRE(code(link, client::file_new(kBin.options(), iqr(4, name), 4)) == 0);
        REQUIRE(code(link, client::file_delete(kBin.options(), iqr(4, "B.BIN"))) == 0);   // slot 2: a tombstone
        REQUIRE(code(link, client::file_state(kBin.options(), iqr(4, "A.BIN"), 0x0001)) == 0);
        CHECK(file_number(link, "C.BIN") == 3);
        sim.stop(SIGKILL);   // no clean shutdown: every change was saved when it happened
    }
    {
        SimProcess sim(with_args({"--profile", "R08CPU", "--clock", "frozen", "--state-dir", state.string()}));
        TcpLink link(sim.tcp_port());
        CHECK(file_number(link, "A.BIN") == 1);
        CHECK(file_number(link, "C.BIN") == 3);
        auto entries = listing(link, 4);
        REQUIRE(entries.size() == 2);
        CHECK(entry(entries, "A.BIN").attribute == 0x01);   // as 1825 set it
        CHECK(entry(entries, "C.BIN").attribute == 0x20);
        CHECK(code(link, client::file_delete(kBin.options(), iqr(4, "A.BIN"))) == 0x4052);   // still read-only
        CHECK(code(link, client::file_new(kBin.options(), iqr(2, "X.BIN"), 4)) == 0x4050);   // still locked
        REQUIRE(code(link, client::file_new(kBin.options(), iqr(4, "D.BIN"), 4)) == 0);
        CHECK(file_number(link, "D.BIN") == 2);   // the tombstone's number, the first free slot
        sim.stop(SIGKILL);
    }
    // A configuration that moved a switch since wins over the saved one.
    SimOptions edited;
    edited.args = {"--profile", "R08CPU", "--clock", "frozen", "--state-dir", state.string()};
    edited.config_json = R"({"drives": {"2": {"present": false}}})";
    SimProcess sim(edited);
    TcpLink link(sim.tcp_port());
    CHECK(code(link, client::file_new(kBin.options(), iqr(2, "X.BIN"), 4)) == 0x4021);
    CHECK(file_number(link, "D.BIN") == 2);
}
