#include "program/load_text.hpp"

#include <algorithm>
#include <cstdio>
#include <span>

#include "devicemodel/utf16.hpp"
#include "program/source.hpp"

namespace slmp::program::load_text {

void Problems::add(const std::string& text) {
    ++count_;
    if (lines_.size() < max_reported_problems) lines_.push_back(file_ + ": " + text);
}

void Problems::throw_if_any() const {
    if (count_ == 0) return;
    auto lines = lines_;
    if (count_ > lines_.size()) {
        lines.push_back(file_ + ": ... and " + std::to_string(count_ - lines_.size()) + " more problems");
    }
    throw LoadError(std::move(lines));
}

namespace {

[[noreturn]] void refuse(const std::string& file, const std::string& text) { throw LoadError({file + ": " + text}); }

std::string hex_byte(unsigned char b) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "0x%02X", b);
    return buffer;
}

// Offset of the first byte that does not belong to well-formed UTF-8
// (overlong forms, surrogates and code points past U+10FFFF included), or npos.
std::size_t invalid_utf8_at(std::string_view s) {
    std::size_t i = 0;
    while (i < s.size()) {
        auto b = static_cast<unsigned char>(s[i]);
        if (b < 0x80) {
            ++i;
            continue;
        }
        std::size_t n = 0;
        std::uint32_t c = 0, min = 0;
        if ((b & 0xE0) == 0xC0) n = 2, c = b & 0x1F, min = 0x80;
        else if ((b & 0xF0) == 0xE0) n = 3, c = b & 0x0F, min = 0x800;
        else if ((b & 0xF8) == 0xF0) n = 4, c = b & 0x07, min = 0x10000;
        else return i;
        if (i + n > s.size()) return i;
        for (std::size_t k = 1; k < n; ++k) {
            auto t = static_cast<unsigned char>(s[i + k]);
            if ((t & 0xC0) != 0x80) return i;
            c = c << 6 | (t & 0x3F);
        }
        if (c < min || c > 0x10FFFF || (c >= 0xD800 && c < 0xE000)) return i;
        i += n;
    }
    return std::string_view::npos;
}

bool blank(char c) { return c == ' ' || c == '\t'; }

// Past the string constant that starts at s[i] == '"': "" inside is a quote.
// npos when it never closes.
std::size_t past_string_constant(std::string_view s, std::size_t i) {
    for (++i; i < s.size(); ++i) {
        if (s[i] != '"') continue;
        if (i + 1 < s.size() && s[i + 1] == '"') {
            ++i;
            continue;
        }
        return i + 1;
    }
    return std::string_view::npos;
}

}  // namespace

DecodedFile decode_file(std::string_view bytes, const std::string& file) {
    if (bytes.size() > max_file_bytes) {
        refuse(file, "is " + std::to_string(bytes.size()) + " bytes; the limit is 10 MiB (" +
                         std::to_string(max_file_bytes) + " bytes)");
    }
    if (bytes.starts_with("\xFE\xFF")) refuse(file, "is UTF-16 big-endian; save it as UTF-16LE (Unicode) or UTF-8");
    if (bytes.starts_with("\xFF\xFE")) {
        auto body = bytes.substr(2);
        if (body.size() % 2 != 0) refuse(file, "is not valid UTF-16LE: an odd number of bytes (" + std::to_string(bytes.size()) + ")");
        std::vector<std::uint16_t> units(body.size() / 2);
        for (std::size_t k = 0; k < units.size(); ++k) {
            units[k] = static_cast<std::uint16_t>(static_cast<unsigned char>(body[2 * k]) |
                                                  static_cast<unsigned char>(body[2 * k + 1]) << 8);
        }
        // utf16_to_utf8 would turn a lone surrogate into U+FFFD; a program file
        // with one is damaged, and saying so beats loading a guess.
        for (std::size_t k = 0; k < units.size(); ++k) {
            bool high = units[k] >= 0xD800 && units[k] < 0xDC00;
            bool low = units[k] >= 0xDC00 && units[k] < 0xE000;
            if (high && k + 1 < units.size() && units[k + 1] >= 0xDC00 && units[k + 1] < 0xE000) {
                ++k;
            } else if (high || low) {
                refuse(file, "is not valid UTF-16LE: an unpaired surrogate at byte offset " + std::to_string(2 + 2 * k));
            }
        }
        return {devicemodel::utf16_to_utf8(std::span<const std::uint16_t>(units)), true};
    }
    if (bytes.starts_with("\xEF\xBB\xBF")) bytes.remove_prefix(3);
    if (auto nul = bytes.find('\0'); nul != std::string_view::npos) {
        refuse(file, "is a binary file (a NUL byte at offset " + std::to_string(nul) +
                         "), not a program or comment list; a UTF-16 file needs its byte order mark FF FE");
    }
    if (auto bad = invalid_utf8_at(bytes); bad != std::string_view::npos) {
        refuse(file, "is not UTF-8 (byte " + hex_byte(static_cast<unsigned char>(bytes[bad])) + " at offset " +
                         std::to_string(bad) + "); save it as UTF-16LE (Unicode) or UTF-8");
    }
    return {std::string(bytes), false};
}

std::optional<std::string_view> RowCursor::next() {
    if (rest_.empty()) return std::nullopt;
    auto end = rest_.find('\n');
    auto row = rest_.substr(0, end);
    rest_.remove_prefix(end == std::string_view::npos ? rest_.size() : end + 1);
    if (row.ends_with('\r')) row.remove_suffix(1);
    ++number_;
    return row;
}

std::string row_problem(std::string_view row) {
    if (row.size() > max_row_bytes) {
        return "is " + std::to_string(row.size()) + " bytes long; the limit is " + std::to_string(max_row_bytes) + " bytes";
    }
    for (std::size_t i = 0; i < row.size(); ++i) {
        auto b = static_cast<unsigned char>(row[i]);
        std::uint32_t c = 0;
        if ((b < 0x20 && b != '\t') || b == 0x7F) c = b;
        // C1 controls (U+0080-U+009F) are C2 80 - C2 9F in UTF-8.
        if (b == 0xC2 && i + 1 < row.size() && static_cast<unsigned char>(row[i + 1]) < 0xA0) {
            c = static_cast<unsigned char>(row[i + 1]);
        }
        if (c != 0 || b == 0) {
            char code[8];
            std::snprintf(code, sizeof code, "U+%04X", static_cast<unsigned>(c));
            return std::string("holds the control character ") + code + "; only printable text and TAB may appear";
        }
    }
    return "";
}

std::optional<std::vector<std::string>> split_record(std::string_view row, char separator) {
    std::vector<std::string> fields;
    std::size_t i = 0;
    while (true) {
        std::string field;
        std::size_t start = i;
        while (start < row.size() && row[start] == ' ') ++start;
        if (start < row.size() && row[start] == '"') {
            i = start + 1;
            bool closed = false;
            while (i < row.size()) {
                if (row[i] == '"') {
                    if (i + 1 < row.size() && row[i + 1] == '"') {
                        field += '"';
                        i += 2;
                        continue;
                    }
                    closed = true;
                    ++i;
                    break;
                }
                field += row[i++];
            }
            if (!closed) return std::nullopt;
            // Hand-edited files: text between the closing quote and the
            // separator is kept rather than refused.
            while (i < row.size() && row[i] != separator) field += row[i++];
        } else {
            while (i < row.size() && row[i] != separator) field += row[i++];
        }
        fields.push_back(std::move(field));
        if (i >= row.size()) break;
        ++i;   // the separator
    }
    if (fields.size() == 1 && fields.front().find('\t') != std::string::npos) {
        auto inner = fields.front();
        auto again = split_record(inner, '\t');
        // A field that merely holds a TAB but is no record stays as it was.
        if (again && again->size() > 1) return again;
    }
    return fields;
}

std::size_t used_fields(const std::vector<std::string>& fields) {
    std::size_t n = fields.size();
    while (n > 0 && trimmed(fields[n - 1]).empty()) --n;
    return n;
}

std::string fields_count(std::size_t n) { return std::to_string(n) + (n == 1 ? " field" : " fields"); }

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && blank(s.back())) s.remove_suffix(1);
    return s;
}

std::optional<std::vector<std::string>> split_operands(std::string_view text) {
    std::vector<std::string> operands;
    std::size_t i = 0;
    while (true) {
        while (i < text.size() && blank(text[i])) ++i;
        if (i >= text.size()) break;
        std::size_t start = i;
        while (i < text.size() && !blank(text[i])) {
            if (text[i] == '"') {
                i = past_string_constant(text, i);
                if (i == std::string_view::npos) return std::nullopt;
            } else {
                ++i;
            }
        }
        operands.emplace_back(text.substr(start, i - start));
    }
    return operands;
}

std::size_t comment_start(std::string_view line) {
    for (std::size_t i = 0; i < line.size();) {
        if (line[i] == '"') {
            i = past_string_constant(line, i);
            if (i == std::string_view::npos) return std::string_view::npos;
        } else if (line[i] == ';' || line.substr(i).starts_with("//")) {
            return i;
        } else {
            ++i;
        }
    }
    return std::string_view::npos;
}

bool is_pointer_label(std::string_view token) {
    if (token.ends_with(':')) token.remove_suffix(1);
    if (token.size() < 2 || (token[0] != 'P' && token[0] != 'p')) return false;
    return std::all_of(token.begin() + 1, token.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool same_mnemonic(std::string_view a, std::string_view b) {
    auto upper = [](char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; };
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [&](char x, char y) { return upper(x) == upper(y); });
}

std::optional<std::uint32_t> parse_step(std::string_view text) {
    if (text.empty() || text.size() > 10) return std::nullopt;
    std::uint64_t value = 0;
    for (char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + static_cast<std::uint64_t>(c - '0');
    }
    if (value > 0xFFFFFFFFu) return std::nullopt;
    return static_cast<std::uint32_t>(value);
}

std::string quoted_excerpt(std::string_view s) {
    constexpr std::size_t limit = 40;
    if (s.size() <= limit) return "'" + std::string(s) + "'";
    std::size_t cut = limit;
    // Never end inside a UTF-8 sequence.
    while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;
    return "'" + std::string(s.substr(0, cut)) + "...'";
}

}  // namespace slmp::program::load_text
