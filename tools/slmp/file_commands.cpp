// slmp file ls|get|put|rm: the CPU's file drives through 1810-182A, so the CLI
// manages files on a real PLC as on the simulator (docs/files.md, docs/cli.md).
//   slmp file ls [DRIVE:[PATH]]          1810 paging (default 4:)
//   slmp file get DRIVE:PATH [LOCAL]     1827 read, 1828 in 1920-byte pieces, 182A
//   slmp file put LOCAL DRIVE:PATH       1820, 1827 write, 1829 pieces, 182A
//   slmp file rm DRIVE:PATH              1822
// --file-password P fills the commands' file password field (1811/1820 carry
// it on Q/L only; 1810 has none): 4 characters space-padded in 0000, a length
// and 6-32 characters in 0040.
// The dialect is found by asking: 0040 (iQ-R) first, 0000 (Q/L) when the CPU
// answers C059, as a tool facing an unknown CPU would.
#include <fstream>
#include <iterator>
#include <vector>

#include "protocol/client_files.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {
namespace {

namespace client = protocol::client;
constexpr std::size_t kPiece = 1920;
constexpr std::size_t kQlPassword = 4, kIqrPasswordMin = 6, kIqrPasswordMax = 32;   // SLMP Reference Manual §5.8

bool fits(const std::string& password, bool iqr) {
    if (password.empty()) return true;
    return iqr ? password.size() >= kIqrPasswordMin && password.size() <= kIqrPasswordMax : password.size() <= kQlPassword;
}

// "4:LOGS\A.CSV" -> drive 4, path "LOGS\A.CSV"; "/" is taken as "\".
client::FileTarget target(const std::string& text, bool need_name, const std::string& password = {}) {
    auto colon = text.find(':');
    if (colon == std::string::npos || colon == 0 || text.find_first_not_of("0123456789") < colon)
        throw UsageError("'" + text + "': write DRIVE:PATH, e.g. 4:LOGS\\A.CSV");
    client::FileTarget t;
    t.password = password;
    t.drive = static_cast<std::uint16_t>(std::stoi(text.substr(0, colon)));
    t.name = text.substr(colon + 1);
    for (auto& c : t.name)
        if (c == '/') c = '\\';
    if (need_name && t.name.empty()) throw UsageError("'" + text + "': name a file after the drive, e.g. 4:A.CSV");
    return t;
}

// Runs `request(iqr)` in the iQ-R dialect, falling back to Q/L on C059. A
// password only one dialect can carry picks that dialect; one neither can
// carry is refused before anything is sent.
template <typename Build>
client::Response ask(Invocation& in, client::FileTarget& t, Build build) {
    if (!fits(t.password, true) && !fits(t.password, false))
        throw UsageError("--file-password: a file password has up to 4 characters (Q/L) or 6-32 (iQ-R), not " +
                         std::to_string(t.password.size()));
    if (fits(t.password, true)) {
        try {
            t.iqr = true;
            return in.client.exchange(build(t));
        } catch (const EndCodeError& e) {
            if (e.end_code != 0xC059 || !fits(t.password, false)) throw;
        }
    }
    t.iqr = false;
    return in.client.exchange(build(t));
}

std::string dos_date(std::uint16_t d, std::uint16_t t) {
    char text[32];
    std::snprintf(text, sizeof text, "%04d-%02d-%02d %02d:%02d:%02d", (d >> 9) + 1980, (d >> 5) & 0xF, d & 0x1F, t >> 11,
                  (t >> 5) & 0x3F, (t & 0x1F) * 2);
    return text;
}

void file_ls(Invocation& in, const std::vector<std::string>& args) {
    auto t = target(args.empty() ? "4:" : args[0], false);
    Json entries = Json::array();
    Table table{{"name", "size", "date", "attribute"}, {}};
    std::uint32_t start = 1;
    for (int page = 0; page < 10000; ++page) {
        auto response = ask(in, t, [&](const client::FileTarget& x) {
            return client::file_list(in.client.frame(), x.iqr, x.drive, start, 36, x.name);
        });
        auto listing = client::parse_file_list(response, t.iqr);
        if (!listing) throw ConnectionError("the 1810 answer does not parse");
        if (t.iqr && listing->count == 0xFFFF) break;
        for (const auto& e : listing->entries) {
            entries.push_back({{"name", e.name}, {"size", e.size}, {"date", dos_date(e.date, e.time)},
                               {"attribute", e.attribute}, {"directory", (e.attribute & 0x10) != 0}});
            table.rows.push_back({e.name, std::to_string(e.size), dos_date(e.date, e.time),
                                  (e.attribute & 0x10) ? "dir" : (e.attribute & 0x01) ? "read-only" : ""});
        }
        if (!t.iqr && listing->count < 36) break;
        start = t.iqr ? listing->last_number + 1 : start + 36;
    }
    in.output.result(Json{{"drive", t.drive}, {"path", t.name}, {"entries", entries}}, table);
}

void file_get(Invocation& in, const std::vector<std::string>& args) {
    if (args.empty()) throw UsageError("file get needs DRIVE:PATH [LOCAL], e.g. slmp file get 4:A.CSV a.csv");
    auto t = target(args[0], true, in.options.file_password);
    auto local = args.size() > 1 ? args[1] : t.name.substr(t.name.rfind('\\') + 1);
    auto opened = ask(in, t, [&](const client::FileTarget& x) { return client::file_open(in.client.frame(), x, false); });
    auto pointer = client::parse_file_pointer(opened);
    if (!pointer) throw ConnectionError("the 1827 answer does not parse");
    std::vector<std::uint8_t> content;
    for (std::uint32_t offset = 0;; offset += kPiece) {
        auto piece = client::parse_file_read(in.client.exchange(client::file_read(in.client.frame(), *pointer, offset, kPiece)));
        if (!piece) throw ConnectionError("the 1828 answer does not parse");
        content.insert(content.end(), piece->begin(), piece->end());
        if (piece->size() < kPiece) break;
    }
    in.client.exchange(client::file_close(in.client.frame(), *pointer, 0));
    std::ofstream out(local, std::ios::binary);
    out.write(reinterpret_cast<const char*>(content.data()), static_cast<std::streamsize>(content.size()));
    if (!out) throw UsageError("cannot write " + local);
    in.output.result(Json{{"file", args[0]}, {"local", local}, {"bytes", content.size()}},
                     "read " + std::to_string(content.size()) + " byte(s) into " + local);
}

void file_put(Invocation& in, const std::vector<std::string>& args) {
    if (args.size() != 2) throw UsageError("file put needs LOCAL DRIVE:PATH, e.g. slmp file put a.csv 4:A.CSV");
    std::ifstream file(args[0], std::ios::binary);
    if (!file) throw UsageError("cannot read " + args[0]);
    std::vector<std::uint8_t> content((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    auto t = target(args[1], true, in.options.file_password);
    ask(in, t, [&](const client::FileTarget& x) {
        return client::file_new(in.client.frame(), x, static_cast<std::uint32_t>(content.size()));
    });
    auto pointer = client::parse_file_pointer(in.client.exchange(client::file_open(in.client.frame(), t, true)));
    if (!pointer) throw ConnectionError("the 1827 answer does not parse");
    for (std::size_t offset = 0; offset < content.size(); offset += kPiece) {
        auto n = std::min(kPiece, content.size() - offset);
        in.client.exchange(client::file_write(in.client.frame(), *pointer, static_cast<std::uint32_t>(offset),
                                              std::span(content).subspan(offset, n)));
    }
    in.client.exchange(client::file_close(in.client.frame(), *pointer, 0));
    in.output.result(Json{{"file", args[1]}, {"bytes", content.size()}},
                     "wrote " + std::to_string(content.size()) + " byte(s) to " + args[1]);
}

void file_rm(Invocation& in, const std::vector<std::string>& args) {
    if (args.size() != 1) throw UsageError("file rm needs DRIVE:PATH, e.g. slmp file rm 4:A.CSV");
    auto t = target(args[0], true, in.options.file_password);
    ask(in, t, [&](const client::FileTarget& x) { return client::file_delete(in.client.frame(), x); });
    in.output.result(Json{{"file", args[0]}, {"deleted", true}}, "deleted " + args[0]);
}

}  // namespace

void run_file(Invocation& in) {
    const auto& args = in.options.args;
    if (args.empty()) throw UsageError("file needs ls, get, put or rm, e.g. slmp file ls 4:");
    std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "ls") return file_ls(in, rest);
    if (args[0] == "get") return file_get(in, rest);
    if (args[0] == "put") return file_put(in, rest);
    if (args[0] == "rm") return file_rm(in, rest);
    throw UsageError("file needs ls, get, put or rm, not '" + args[0] + "'");
}

}  // namespace slmp::cli
