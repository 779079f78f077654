// A GX Works3 global-label list exported as CSV (docs/labels.md "CSV import").
// Read: the header row naming the columns (found by name, in any order, as
// GX Works3's global label editor shows them), then one label a row:
//   Label Name                    the name
//   Data Type                     "Word [Signed]", "Bit(0..15)", a structure name ...
//   Class                         VAR_GLOBAL / VAR_GLOBAL_RETAIN accepted;
//                                 VAR_GLOBAL_CONSTANT rows are skipped (a constant has no memory)
//   Assign (Device/Label)         a device ("D100") or empty for the label area
//   Access from External Device   "Enable"/"Yes"/"1"/"TRUE"/"○" = on, "Disable"/"No"/"0"/"FALSE"/empty = off
// Ignored: every other column (Initial Value, Constant, English/Comment,
// Remark, ...), lines before the header (GX Works3 writes a title line),
// empty rows. Fields may be quoted ("a,b") or tab-separated (GX Works3's TSV).
// Structures cannot be declared in the CSV: declare them in JSON.
#include <algorithm>
#include <cctype>

#include "config/config.hpp"
#include "config/config_parts.hpp"

namespace slmp::config {
namespace {

std::vector<std::string> split_row(const std::string& line, char separator) {
    std::vector<std::string> out(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        char c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') out.back() += '"', ++i;
            else if (c == '"') quoted = false;
            else out.back() += c;
        } else if (c == '"') {
            quoted = true;
        } else if (c == separator) {
            out.emplace_back();
        } else if (c != '\r') {
            out.back() += c;
        }
    }
    for (auto& f : out) {
        while (!f.empty() && f.back() == ' ') f.pop_back();
        f.erase(0, f.find_first_not_of(' ') == std::string::npos ? f.size() : f.find_first_not_of(' '));
    }
    return out;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

}  // namespace

LabelsConfig parse_labels_csv(const std::string& input, const std::string& source) {
    std::string text = input;
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);   // UTF-8 byte order mark
    const char separator = text.find('\t') != std::string::npos && text.find(',') == std::string::npos ? '\t' : ',';
    LabelsConfig out;
    int name_col = -1, type_col = -1, class_col = -1, assign_col = -1, external_col = -1;
    std::size_t line_no = 0, start = 0;
    while (start < text.size()) {
        auto end = text.find('\n', start);
        auto line = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        start = end == std::string::npos ? text.size() : end + 1;
        ++line_no;
        auto row = split_row(line, separator);
        auto at = [&](int col) { return col >= 0 && static_cast<std::size_t>(col) < row.size() ? row[col] : std::string(); };
        if (name_col < 0) {
            for (std::size_t i = 0; i < row.size(); ++i) {
                auto h = lower(row[i]);
                if (h == "label name") name_col = static_cast<int>(i);
                else if (h == "data type") type_col = static_cast<int>(i);
                else if (h == "class") class_col = static_cast<int>(i);
                else if (h.rfind("assign", 0) == 0) assign_col = static_cast<int>(i);
                else if (h == "access from external device") external_col = static_cast<int>(i);
            }
            if (name_col >= 0 && type_col < 0)
                throw ConfigError(source + ": line " + std::to_string(line_no) +
                                  ": the header has \"Label Name\" but no \"Data Type\" column; export the list "
                                  "from GX Works3's global label editor with its columns");
            continue;
        }
        if (std::all_of(row.begin(), row.end(), [](const std::string& f) { return f.empty(); })) continue;
        const auto where = source + ": line " + std::to_string(line_no);
        auto klass = lower(at(class_col));
        if (klass == "var_global_constant") continue;
        if (!klass.empty() && klass != "var_global" && klass != "var_global_retain")
            throw ConfigError(where + ", column Class: unknown class '" + at(class_col) +
                              "'; use VAR_GLOBAL, VAR_GLOBAL_RETAIN or VAR_GLOBAL_CONSTANT");
        LabelEntry e;
        e.where = where;
        e.type_key = ", column Data Type";
        e.device_key = ", column Assign (Device/Label)";
        e.name = at(name_col);
        e.type = at(type_col);
        e.device = at(assign_col);
        auto ext = lower(at(external_col));
        if (ext == "enable" || ext == "enabled" || ext == "yes" || ext == "1" || ext == "true" || ext == "\xE2\x97\x8B")
            e.external = true;
        else if (ext.empty() || ext == "disable" || ext == "disabled" || ext == "no" || ext == "0" || ext == "false")
            // GX Works3's default is off, and a CSV says what the project has (docs/labels.md).
            e.external = external_col < 0;
        else
            throw ConfigError(where + ", column Access from External Device: '" + at(external_col) +
                              "' is neither on nor off; write Enable or Disable");
        if (e.name.empty()) throw ConfigError(where + ", column Label Name: empty; give every row a name");
        out.labels.push_back(std::move(e));
    }
    if (name_col < 0)
        throw ConfigError(source + ": no header row with \"Label Name\" and \"Data Type\"; export the list from "
                          "GX Works3's global label editor (or write that header line first)");
    return out;
}

}  // namespace slmp::config
