// File drives over TCP against the real binary (SLMP Reference Manual §5.8): a folder
// served with --drive, read in 1920-byte pieces, create/write/close and find
// it in the folder byte-identical, copy, change state and date, delete,
// directory paging over 100 files in both dialects, locks across two
// connections, names that would leave the folder, capacity, write-protect.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <random>

#include "frames.hpp"
#include "http_client.hpp"
#include "link.hpp"
#include "protocol/client_files.hpp"
#include "sim_process.hpp"

using namespace slmp::test;
namespace client = slmp::protocol::client;
namespace fs = std::filesystem;

namespace {

const std::vector<Wire> kWires = {
    {FrameKind::E3, Codec::Binary, 0},
    {FrameKind::E3, Codec::Ascii, 0},
    {FrameKind::E4, Codec::Binary, 0x0102},
    {FrameKind::E4, Codec::Ascii, 0xFEDC},
};

Bytes pattern(std::size_t n, unsigned seed) {
    Bytes out(n);
    for (std::size_t i = 0; i < n; ++i) out[i] = static_cast<std::uint8_t>((i * 131 + seed * 17 + (i >> 7)) & 0xFF);
    return out;
}

void put(const fs::path& file, const Bytes& content) {
    std::ofstream(file, std::ios::binary).write(reinterpret_cast<const char*>(content.data()),
                                                static_cast<std::streamsize>(content.size()));
}

Bytes slurp(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// One exchange, parsed: the end code and the response data.
client::Response ask(Link& link, const Bytes& request) {
    auto frame = link.exchange(request);
    auto parsed = client::parse_response(frame);
    REQUIRE(parsed);
    return *parsed;
}

std::uint16_t code(Link& link, const Bytes& request) { return ask(link, request).end_code; }

// §4.1: 1827 (read) -> 1828 x n in 1920-byte pieces -> 182A.
Bytes read_whole(Link& link, const Wire& w, const client::FileTarget& t, std::size_t size) {
    auto opened = ask(link, client::file_open(w.options(), t, false));
    REQUIRE(opened.end_code == 0);
    auto pointer = *client::parse_file_pointer(opened);
    Bytes out;
    for (std::size_t offset = 0; offset < size; offset += 1920) {
        auto r = ask(link, client::file_read(w.options(), pointer, static_cast<std::uint32_t>(offset), 1920));
        REQUIRE(r.end_code == 0);
        auto piece = *client::parse_file_read(r);
        CHECK(piece.size() == std::min<std::size_t>(1920, size - offset));
        out.insert(out.end(), piece.begin(), piece.end());
    }
    CHECK(code(link, client::file_close(w.options(), pointer, 0)) == 0);
    return out;
}

// §4.2: 1820 -> 1827 (write) -> 1829 x n -> 182A.
void write_new(Link& link, const Wire& w, const client::FileTarget& t, const Bytes& content) {
    REQUIRE(code(link, client::file_new(w.options(), t, static_cast<std::uint32_t>(content.size()))) == 0);
    auto opened = ask(link, client::file_open(w.options(), t, true));
    REQUIRE(opened.end_code == 0);
    auto pointer = *client::parse_file_pointer(opened);
    for (std::size_t offset = 0; offset < content.size(); offset += 1920) {
        auto n = std::min<std::size_t>(1920, content.size() - offset);
        auto r = ask(link, client::file_write(w.options(), pointer, static_cast<std::uint32_t>(offset),
                                              std::span(content).subspan(offset, n)));
        REQUIRE(r.end_code == 0);
    }
    CHECK(code(link, client::file_close(w.options(), pointer, 0)) == 0);
}

// §4.7 paging: 0000 by start + count until fewer come back; 0040 by last No. + 1 until FFFFH.
std::vector<std::string> list_all(Link& link, const Wire& w, bool iqr, std::uint16_t drive, const std::string& dir = {}) {
    std::vector<std::string> names;
    std::uint32_t start = 1;
    for (int page = 0; page < 100; ++page) {
        auto r = ask(link, client::file_list(w.options(), iqr, drive, start, 36, dir));
        REQUIRE(r.end_code == 0);
        auto listing = client::parse_file_list(r, iqr);
        REQUIRE(listing);
        if (iqr && listing->count == 0xFFFF) return names;
        for (const auto& e : listing->entries) names.push_back(e.name);
        if (!iqr && listing->count < 36) return names;
        start = iqr ? listing->last_number + 1 : start + 36;
    }
    FAIL("listing did not end");
    return names;
}

}  // namespace

TEST_CASE("files: a --drive folder read, written, copied, re-dated and deleted over TCP", "[files][tcp]") {
    TempDir data;
    auto folder = data.path() / "plc-data";
    fs::create_directories(folder);
    auto existing = pattern(5000, 1);
    put(folder / "RECIPE.BIN", existing);
    SimProcess sim(with_args({"--profile", "R08CPU", "--drive", "4=" + folder.string()}));
    for (const auto& w : kWires) {
        INFO(w.name());
        TcpLink link(sim.tcp_port());
        // A file dropped into the folder is on the drive with its size.
        auto r = ask(link, client::file_list(w.options(), true, 4, 1, 36));
        REQUIRE(r.end_code == 0);
        auto listing = *client::parse_file_list(r, true);
        bool seen = false;
        for (const auto& e : listing.entries)
            if (e.name == "RECIPE.BIN") seen = e.size == 5000 && e.attribute == 0x20;
        CHECK(seen);
        CHECK(read_whole(link, w, {true, 4, "RECIPE.BIN", ""}, 5000) == existing);

        // Create, write, close: the host folder holds the same bytes.
        auto content = pattern(4000, w.serial + (w.codec == Codec::Ascii ? 7 : 3));
        client::FileTarget fresh{true, 4, "NEW.BIN", ""};
        write_new(link, w, fresh, content);
        CHECK(slurp(folder / "NEW.BIN") == content);

        // Copy (rename by copy), attribute, date, delete.
        client::FileTarget copy{true, 4, "COPY.BIN", ""};
        CHECK(code(link, client::file_copy(w.options(), copy, fresh)) == 0);
        CHECK(slurp(folder / "COPY.BIN") == content);
        CHECK(code(link, client::file_state(w.options(), copy, 0x0001)) == 0);
        CHECK(code(link, client::file_date(w.options(), copy, 0x3C81, 0xA65D)) == 0);
        auto after = *client::parse_file_list(ask(link, client::file_list(w.options(), true, 4, 1, 36)), true);
        bool dated = false;
        for (const auto& e : after.entries)
            if (e.name == "COPY.BIN") dated = e.attribute == 0x01 && e.date == 0x3C81 && e.time == 0xA65D;
        CHECK(dated);
        CHECK(code(link, client::file_delete(w.options(), copy)) == 0x4052);   // read-only
        CHECK(code(link, client::file_state(w.options(), copy, 0x0020)) == 0);
        CHECK(code(link, client::file_delete(w.options(), copy)) == 0);
        CHECK(code(link, client::file_delete(w.options(), fresh)) == 0);
        CHECK_FALSE(fs::exists(folder / "COPY.BIN"));
        CHECK_FALSE(fs::exists(folder / "NEW.BIN"));
        CHECK(code(link, client::file_delete(w.options(), fresh)) == 0x4022);
    }
}

TEST_CASE("files: directory paging over 100 files in both dialects", "[files][tcp]") {
    TempDir data;
    auto folder = data.path() / "d";
    fs::create_directories(folder / "LOGS");
    for (int i = 0; i < 100; ++i) {
        char name[16];
        std::snprintf(name, sizeof name, "F%03d.CSV", i);
        put(folder / name, pattern(10, static_cast<unsigned>(i)));
        put(folder / "LOGS" / name, pattern(4, static_cast<unsigned>(i)));
    }
    std::vector<std::string> expected;
    for (int i = 0; i < 100; ++i) {
        char name[16];
        std::snprintf(name, sizeof name, "F%03d.CSV", i);
        expected.push_back(name);
    }
    SimProcess iqr(with_args({"--profile", "R08CPU", "--drive", "2=" + folder.string()}));
    SimProcess ql(with_args({"--profile", "Q06UDVCPU", "--drive", "2=" + folder.string()}));
    for (const auto& w : kWires) {
        INFO(w.name());
        TcpLink a(iqr.tcp_port());
        auto root = list_all(a, w, true, 2);
        REQUIRE(root.size() == 101);
        CHECK(root.front() == "F000.CSV");
        CHECK(root.back() == "LOGS");
        auto sub = list_all(a, w, true, 2, "LOGS");
        REQUIRE(sub.size() == 102);
        CHECK(sub[0] == ".");
        CHECK(sub[1] == "..");
        CHECK(std::vector<std::string>(sub.begin() + 2, sub.end()) == expected);

        if (w.kind != FrameKind::E3) continue;   // the Q built-in port serves 3E only (its profile)
        TcpLink b(ql.tcp_port());
        auto names = list_all(b, w, false, 2);
        REQUIRE(names.size() == 101);
        CHECK(std::vector<std::string>(names.begin(), names.begin() + 100) == expected);
        CHECK(names.back() == "LOGS");
        // 1811: the file No. of F050.CSV is its slot, 51.
        auto found = ask(b, client::file_search(w.options(), {false, 2, "F050.CSV", ""}));
        REQUIRE(found.end_code == 0);
        CHECK(*client::parse_file_number(found, false) == 51);
    }
}

TEST_CASE("files: locks hold across connections and survive a disconnect", "[files][tcp][no-proxy]") {
    TempDir data;
    auto folder = data.path() / "d";
    fs::create_directories(folder);
    put(folder / "A.BIN", pattern(64, 2));
    SimProcess sim(with_args({"--profile", "R08CPU", "--drive", "4=" + folder.string()}));
    const Wire w{FrameKind::E3, Codec::Binary, 0};
    client::FileTarget a_bin{true, 4, "A.BIN", ""};
    std::uint16_t pointer = 0;
    {
        TcpLink first(sim.tcp_port());
        auto opened = ask(first, client::file_open(w.options(), a_bin, true));
        REQUIRE(opened.end_code == 0);
        pointer = *client::parse_file_pointer(opened);
        TcpLink second(sim.tcp_port());
        CHECK(code(second, client::file_open(w.options(), a_bin, false)) == 0x4025);
        CHECK(code(second, client::file_delete(w.options(), a_bin)) == 0x4025);
        CHECK(code(second, client::file_write(w.options(), pointer, 0, pattern(4, 9))) == 0x4025);
        CHECK(code(second, client::file_close(w.options(), pointer, 0)) == 0x4025);
    }
    // The writer went away; its lock stays until close type 2 (§8.1).
    TcpLink third(sim.tcp_port());
    CHECK(code(third, client::file_delete(w.options(), a_bin)) == 0x4025);
    CHECK(code(third, client::file_close(w.options(), 0, 2)) == 0);
    CHECK(code(third, client::file_delete(w.options(), a_bin)) == 0);
    CHECK_FALSE(fs::exists(folder / "A.BIN"));
}

TEST_CASE("files: names that would leave the folder are refused and nothing is created outside", "[files][tcp]") {
    TempDir data;
    auto folder = data.path() / "drive";
    fs::create_directories(folder / "SUB");
    put(data.path() / "SECRET.TXT", text("outside"));
    fs::create_symlink(data.path() / "SECRET.TXT", folder / "LINK.TXT");
    fs::create_directory_symlink(data.path(), folder / "UP");
    SimProcess sim(with_args({"--profile", "R08CPU", "--drive", "4=" + folder.string()}));
    const Wire w{FrameKind::E3, Codec::Ascii, 0};
    TcpLink link(sim.tcp_port());
    auto before = std::distance(fs::directory_iterator(data.path()), fs::directory_iterator());
    for (std::string bad : {"..\\ESC.BIN", "SUB\\..\\..\\ESC.BIN", "\\..\\ESC.BIN", "C:\\ESC.BIN", "../ESC.BIN",
                            "NUL", "SUB\\\\ESC.BIN", "ESC.BIN\\.."}) {
        INFO(bad);
        CHECK(code(link, client::file_new(w.options(), {true, 4, bad, ""}, 16)) == 0x4024);
    }
    // Links are not followed: not listed, not opened, not a way into a folder.
    CHECK(code(link, client::file_open(w.options(), {true, 4, "LINK.TXT", ""}, false)) == 0x4022);
    CHECK(code(link, client::file_new(w.options(), {true, 4, "UP\\ESC.BIN", ""}, 16)) == 0x4022);
    auto names = list_all(link, w, true, 4);
    CHECK(names == std::vector<std::string>{"SUB"});
    CHECK(std::distance(fs::directory_iterator(data.path()), fs::directory_iterator()) == before);
    CHECK_FALSE(fs::exists(data.path() / "ESC.BIN"));
}

TEST_CASE("files: capacity, write-protect and the state directory", "[files][tcp]") {
    TempDir data;
    auto folder = data.path() / "sd";
    fs::create_directories(folder);
    auto state = data.path() / "state";
    SimOptions options;
    options.args = {"--profile", "R08CPU", "--state-dir", state.string()};
    options.config_json = R"({"drives": {"2": {"dir": ")" + folder.string() +
                          R"(", "capacity": 10000, "write_protect": true}, "4": {"capacity": 8000}}})";
    SimProcess sim(options);
    const Wire w{FrameKind::E3, Codec::Binary, 0};
    TcpLink link(sim.tcp_port());
    CHECK(code(link, client::file_new(w.options(), {true, 2, "A.BIN", ""}, 100)) == 0x4050);
    CHECK(code(link, client::file_new(w.options(), {true, 4, "BIG.BIN", ""}, 9000)) == 0x4029);
    CHECK(code(link, client::file_new(w.options(), {true, 4, "A.BIN", ""}, 6000)) == 0);
    CHECK(code(link, client::file_new(w.options(), {true, 4, "B.BIN", ""}, 2001)) == 0x4029);
    // Drive 4 without a folder lives in <state-dir>/drives/4.
    CHECK(fs::file_size(state / "drives" / "4" / "A.BIN") == 6000);
}

TEST_CASE("files: kill -9 during a stream of 1829 writes leaves every file whole", "[files][tcp][crash]") {
    // Each 1829 writes the whole 1920-byte file with one value; after a kill the
    // file holds one value throughout, at least the last acknowledged and at
    // most the last sent (the last write is in flight when the kill lands).
    TempDir data;
    auto folder = data.path() / "d";
    fs::create_directories(folder);
    put(folder / "LOG.BIN", Bytes(1920, 0));
    const Wire w{FrameKind::E3, Codec::Binary, 0};
    client::FileTarget log{true, 4, "LOG.BIN", ""};
    std::mt19937 random(12);   // fixed seed: the same kill moments every run
    std::uint8_t last_sent = 0, last_acknowledged = 0;
    for (int round = 0; round < 12; ++round) {
        INFO("round " << round);
        SimProcess sim(with_args({"--profile", "R08CPU", "--drive", "4=" + folder.string()}));
        TcpLink link(sim.tcp_port());
        auto content = slurp(folder / "LOG.BIN");
        REQUIRE(content.size() == 1920);
        CHECK(std::all_of(content.begin(), content.end(), [&](std::uint8_t b) { return b == content[0]; }));
        CHECK(content[0] >= last_acknowledged);
        CHECK(content[0] <= last_sent);
        last_acknowledged = content[0];
        CHECK(list_all(link, w, true, 4) == std::vector<std::string>{"LOG.BIN"});   // no temporary file shows
        auto opened = ask(link, client::file_open(w.options(), log, true));
        REQUIRE(opened.end_code == 0);
        auto pointer = *client::parse_file_pointer(opened);
        const int writes = std::uniform_int_distribution<int>(5, 15)(random);
        for (int i = 0; i < writes; ++i) {
            ++last_sent;
            REQUIRE(code(link, client::file_write(w.options(), pointer, 0, Bytes(1920, last_sent))) == 0);
            last_acknowledged = last_sent;
        }
        ++last_sent;
        link.client().send(client::file_write(w.options(), pointer, 0, Bytes(1920, last_sent)));   // in flight
        sim.stop(SIGKILL);
    }
}

TEST_CASE("files: the HTTP API lists drives and folders, moves files and releases locks", "[files][http]") {
    TempDir data;
    auto folder = data.path() / "d";
    fs::create_directories(folder / "LOGS");
    SimProcess sim(with_args({"--profile", "R08CPU", "--drive", "4=" + folder.string()}));
    auto port = sim.http_port();
    auto drives = http_get(port, "/api/drives").json()["drives"];
    REQUIRE(drives.size() == 4);
    CHECK(drives[0]["drive"] == 1);
    CHECK(drives[0]["alias_of"] == 3);
    CHECK(drives[3]["drive"] == 4);
    CHECK(drives[3]["location"] == folder.string());
    CHECK(drives[1]["location"] == "memory");

    std::string body = "a,b\n1,2\n";
    body += std::string(1, '\0') + "\xff";
    auto put_reply = http_put(port, "/api/drives/4/file?path=LOGS/A.CSV", body);
    REQUIRE(put_reply.status == 200);
    CHECK(slurp(folder / "LOGS" / "A.CSV") == Bytes(body.begin(), body.end()));
    auto entries = http_get(port, "/api/drives/4/files?path=LOGS").json()["entries"];
    REQUIRE(entries.size() == 3);
    CHECK(entries[2]["name"] == "A.CSV");
    CHECK(entries[2]["number"] == 3);
    CHECK(entries[2]["size"] == body.size());
    auto got = http_get(port, "/api/drives/4/file?path=LOGS%5CA.CSV");
    CHECK(got.status == 200);
    CHECK(got.body == body);
    CHECK(http_get(port, "/api/drives/4/file?path=../x").status == 400);
    CHECK(http_get(port, "/api/drives/4/file?path=NONE.CSV").status == 404);
    CHECK(http_get(port, "/api/drives/0/files").status == 404);

    // A lock taken over SLMP shows, blocks an upload, and goes with DELETE.
    const Wire w{FrameKind::E3, Codec::Binary, 0};
    TcpLink link(sim.tcp_port());
    REQUIRE(code(link, client::file_open(w.options(), {true, 4, "LOGS\\A.CSV", ""}, true)) == 0);
    auto locks = http_get(port, "/api/drives/locks").json()["locks"];
    REQUIRE(locks.size() == 1);
    CHECK(locks[0]["path"] == "LOGS\\A.CSV");
    CHECK(locks[0]["mode"] == "write");
    CHECK(http_put(port, "/api/drives/4/file?path=LOGS/A.CSV", "x").status == 409);
    CHECK(http(port, "DELETE", "/api/drives/locks/0").status == 200);
    CHECK(http_get(port, "/api/drives/locks").json()["locks"].empty());
    CHECK(http(port, "DELETE", "/api/drives/locks/0").status == 404);
    auto metrics = http_get(port, "/metrics").body;
    CHECK(metrics.find("slmp_file_drive_used_bytes{drive=\"4\"} " + std::to_string(body.size())) != std::string::npos);
    CHECK(metrics.find("slmp_open_files 0") != std::string::npos);
}
