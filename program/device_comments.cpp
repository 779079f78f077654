// Device comment files (cpu.program.comments; docs/program.md "Device
// comments"): GX Works2's UTF-16LE TAB file (a title row, then
// "Device Name"/"Comment", then one device a row) and GX Converter's
// device,label,comment CSV after its column-name line; UTF-8 too.
#include <algorithm>

#include "program/load_text.hpp"
#include "program/source.hpp"

namespace slmp::program {

namespace {

// GX Converter's TEXT layout gives a device 16 characters.
constexpr std::size_t max_device_chars = 16;

bool plausible_device(std::string_view device) {
    // Letters and digits, "." for a bit of a word (D0.F), "\" for a module
    // access device (U3E0\G10).
    return !device.empty() && device.size() <= max_device_chars &&
           std::all_of(device.begin(), device.end(), [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '.' || c == '\\';
           });
}

}  // namespace

std::vector<DeviceComment> read_comments(std::string_view bytes, std::string file) {
    auto decoded = load_text::decode_file(bytes, file);
    load_text::Problems problems(file);
    // GX Converter's TEXT files must not hold a TAB, so one means the TAB layout.
    const char separator = decoded.text.find('\t') != std::string::npos ? '\t' : ',';
    std::vector<DeviceComment> comments;
    std::size_t header_columns = 0;   // 0 until the column-name row is passed
    load_text::RowCursor rows(decoded.text);
    while (auto record = rows.next()) {
        const std::string where = "row " + std::to_string(rows.number()) + ": ";
        if (auto why = load_text::row_problem(*record); !why.empty()) {
            problems.add(where + why);
            continue;
        }
        auto fields = load_text::split_record(*record, separator);
        if (!fields) {
            problems.add(where + "a quote opens a field and is never closed");
            continue;
        }
        auto used = load_text::used_fields(*fields);
        if (used == 0) continue;
        if (header_columns == 0) {
            // The title row has one field; the column names are the first
            // row with more ("Device Name", "Comment" or device, label, comment).
            if (used >= 2) header_columns = used;
            continue;
        }
        auto device = load_text::trimmed((*fields)[0]);
        // device,label,comment: the comment, or the label when there is none.
        std::string_view comment = fields->size() >= 2 ? load_text::trimmed((*fields)[1]) : std::string_view();
        if (header_columns == 3 && fields->size() >= 3 && !load_text::trimmed((*fields)[2]).empty()) {
            comment = load_text::trimmed((*fields)[2]);
        }
        if (device.empty()) {
            problems.add(where + "the comment " + load_text::quoted_excerpt(comment) + " names no device");
            continue;
        }
        if (!plausible_device(device)) {
            problems.add(where + load_text::quoted_excerpt(device) +
                         " is no device name (letters, digits, '.' or '\\', at most 16 characters)");
            continue;
        }
        if (comment.empty()) continue;   // GX Converter omits such devices; a blank one says nothing
        comments.push_back({std::string(device), std::string(comment)});
    }
    problems.throw_if_any();
    return comments;
}

}  // namespace slmp::program
