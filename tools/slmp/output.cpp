#include "tools/slmp/output.hpp"

#include <algorithm>

namespace slmp::cli {

void Output::print_row(const std::vector<std::string>& cells, const std::vector<std::size_t>& widths) {
    std::string line;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        if (i) line += "  ";
        line += cells[i];
        if (i + 1 < cells.size() && i < widths.size() && cells[i].size() < widths[i])
            line.append(widths[i] - cells[i].size(), ' ');
    }
    out_ << line << '\n';
}

void Output::result(const Json& json, const Table& table) {
    if (json_) {
        out_ << json.dump() << '\n';
        return;
    }
    std::vector<std::size_t> widths(table.headers.size(), 0);
    for (std::size_t i = 0; i < widths.size(); ++i) widths[i] = table.headers[i].size();
    for (const auto& row : table.rows)
        for (std::size_t i = 0; i < row.size() && i < widths.size(); ++i) widths[i] = std::max(widths[i], row[i].size());
    if (!table.headers.empty()) print_row(table.headers, widths);
    for (const auto& row : table.rows) print_row(row, widths);
    out_.flush();
}

void Output::result(const Json& json, const std::string& message) {
    if (json_) out_ << json.dump() << '\n';
    else out_ << message << '\n';
    out_.flush();
}

void Output::stream_header(const std::vector<std::string>& headers) {
    stream_widths_.clear();
    for (const auto& h : headers) stream_widths_.push_back(std::max<std::size_t>(h.size(), 6));
    if (!json_) print_row(headers, stream_widths_);
    out_.flush();
}

void Output::stream_row(const Json& json, const std::vector<std::string>& cells) {
    if (json_) out_ << json.dump() << '\n';
    else print_row(cells, stream_widths_);
    out_.flush();   // a monitor is watched live, and often piped
}

void Output::error_json(const Json& error) {
    if (json_) out_ << Json{{"error", error}}.dump() << '\n';
    out_.flush();
}

}  // namespace slmp::cli
