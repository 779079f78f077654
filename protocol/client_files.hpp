// Client-side builders and decoders for the file commands 1810-182A
// (SLMP Reference Manual §5.8). Like the other client builders they write through
// build_request() and a FieldWriter, so the CLI (slmp file ...) and the tests
// send exactly what the server decodes. `iqr` picks subcommand 0040 (UTF-16
// paths, length-prefixed password) over 0000 (8.3 names, 4-character password).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/client.hpp"

namespace slmp::protocol::client {

struct FileTarget {
    bool iqr = true;
    std::uint16_t drive = 4;
    std::string name;        // 0040: a path from the root ("LOG\\A.CSV"); 0000: an 8.3 name
    std::string password;    // empty: none
    bool l_password = false; // Q/L form as subcommand 0004: the L CPUs' 32-character password slot
};

std::vector<std::uint8_t> file_list(const FrameOptions& o, bool iqr, std::uint16_t drive, std::uint32_t start,
                                    std::uint16_t count, const std::string& dir = {});
std::vector<std::uint8_t> file_search(const FrameOptions& o, const FileTarget& t);
std::vector<std::uint8_t> file_new(const FrameOptions& o, const FileTarget& t, std::uint32_t size);
std::vector<std::uint8_t> file_delete(const FrameOptions& o, const FileTarget& t);
std::vector<std::uint8_t> file_copy(const FrameOptions& o, const FileTarget& to, const FileTarget& from);
std::vector<std::uint8_t> file_state(const FrameOptions& o, const FileTarget& t, std::uint16_t attribute);
std::vector<std::uint8_t> file_date(const FrameOptions& o, const FileTarget& t, std::uint16_t date, std::uint16_t time);
std::vector<std::uint8_t> file_open(const FrameOptions& o, const FileTarget& t, bool for_write);
std::vector<std::uint8_t> file_read(const FrameOptions& o, std::uint16_t pointer, std::uint32_t offset,
                                    std::uint16_t count);
std::vector<std::uint8_t> file_write(const FrameOptions& o, std::uint16_t pointer, std::uint32_t offset,
                                     std::span<const std::uint8_t> data);
std::vector<std::uint8_t> file_close(const FrameOptions& o, std::uint16_t pointer, std::uint16_t type);

struct FileListEntry {
    std::string name;          // 0000: "NAME.EXT" rebuilt from the 8+3 record
    std::uint16_t attribute = 0, time = 0, date = 0;
    std::uint32_t size = 0;
};
struct FileListPage {
    std::uint16_t count = 0;        // FFFFH: the end (0040)
    std::uint32_t last_number = 0;  // 0040 only
    std::vector<FileListEntry> entries;
};
std::optional<FileListPage> parse_file_list(const Response& r, bool iqr);
// 1811 file No. / 1827 pointer No.
std::optional<std::uint32_t> parse_file_number(const Response& r, bool iqr);
std::optional<std::uint16_t> parse_file_pointer(const Response& r);
// 1828: the bytes read.
std::optional<std::vector<std::uint8_t>> parse_file_read(const Response& r);

}  // namespace slmp::protocol::client
