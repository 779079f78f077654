// Text handling shared by the program loader (source_*.cpp) and the device
// comment loader (device_comments.cpp): the file's bytes decoded to checked
// UTF-8 rows, the quoted-field record of a GX Works list, operands split on
// blanks outside string constants, and the list of problems a load reports
// (docs/program.md "Files"). Internal to program/.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slmp::program::load_text {

inline constexpr std::size_t max_file_bytes = 10u * 1024 * 1024;   // "10 MiB" in messages
// A row of a real list is well under 200 bytes; the bound keeps a hostile
// file's one-row megabyte statement out of messages, exports and the API.
inline constexpr std::size_t max_row_bytes = 4096;
// Beyond this many, a message would be read by nobody: the rest is counted.
inline constexpr std::size_t max_reported_problems = 100;

// Every problem of one load, one line each; thrown together as LoadError.
class Problems {
public:
    explicit Problems(std::string file) : file_(std::move(file)) {}
    const std::string& file() const { return file_; }
    // "file: <text>"
    void add(const std::string& text);
    bool empty() const { return count_ == 0; }
    // Throws LoadError with every problem added, if any.
    void throw_if_any() const;

private:
    std::string file_;
    std::vector<std::string> lines_;
    std::size_t count_ = 0;
};

struct DecodedFile {
    std::string text;          // UTF-8 without BOM
    bool utf16 = false;        // the file began with FF FE
};

// The file's bytes as UTF-8: size limit, BOM, UTF-16LE decoding, NUL bytes
// (a binary file) and invalid UTF-8/UTF-16 are refused with a LoadError
// naming the file and what it is.
DecodedFile decode_file(std::string_view bytes, const std::string& file);

// The rows of decoded text one at a time, split on LF with a CR before the
// LF removed (CR LF and LF files alike); a final empty piece after the last
// line end is not a row. One at a time because a 10 MiB file of line ends
// would be millions of rows at once.
class RowCursor {
public:
    explicit RowCursor(std::string_view text) : rest_(text) {}
    // The next row, or nullopt at the end of the text.
    std::optional<std::string_view> next();
    // The 1-based number of the row next() returned last.
    std::size_t number() const { return number_; }

private:
    std::string_view rest_;
    std::size_t number_ = 0;
};

// Why a row cannot be read as text, if it cannot: too long, or a control
// character other than TAB (C0, DEL, C1). "" when the row is fine.
std::string row_problem(std::string_view row);

// One record of a GX Works list or a comment file: fields separated by
// `separator`, a field in double quotes may hold the separator and doubled
// quotes. A record that is a single field holding TABs is the re-quoted
// variant (a comma-CSV tool re-saved the TAB file) and is parsed again as a
// TAB record. nullopt: a quote opened and never closed.
std::optional<std::vector<std::string>> split_record(std::string_view row, char separator);

// The fields of a record up to its last non-blank one: spreadsheets leave
// empty fields at the end of short rows.
std::size_t used_fields(const std::vector<std::string>& fields);

// "1 field", "8 fields".
std::string fields_count(std::size_t n);

// Blanks (space, TAB) at both ends removed.
std::string_view trimmed(std::string_view s);

// Operands separated by blanks outside "…" string constants (with "" for a
// quote); a string constant keeps its quotes as written. nullopt: a string
// constant never closed.
std::optional<std::vector<std::string>> split_operands(std::string_view text);

// The first `;` or `//` outside a string constant, or npos.
std::size_t comment_start(std::string_view line);

// "P10" or "p10:": a pointer label (P and decimal digits, optional colon).
bool is_pointer_label(std::string_view token);

// Case-insensitive ASCII equality ("end" is END).
bool same_mnemonic(std::string_view a, std::string_view b);

// A decimal step number ("17"); nullopt when not one or beyond 32 bits.
std::optional<std::uint32_t> parse_step(std::string_view text);

// For messages: at most 40 characters of what the user wrote, quoted.
std::string quoted_excerpt(std::string_view s);

}  // namespace slmp::program::load_text
