// Where results go: a table for people, or JSON (one object per line) for
// scripts. Subcommands build both forms of their result and hand them over;
// only this file decides which one is printed.
#pragma once

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace slmp::cli {

using Json = nlohmann::ordered_json;   // keeps keys in the order written

struct Table {
    std::vector<std::string> headers;
    std::vector<std::vector<std::string>> rows;
};

class Output {
public:
    Output(std::ostream& out, bool json) : out_(out), json_(json) {}
    bool json() const { return json_; }

    void result(const Json& json, const Table& table);
    void result(const Json& json, const std::string& message);

    // A table printed a row at a time (monitor): the header once, then rows
    // aligned to it; in JSON mode each row's JSON is one line.
    void stream_header(const std::vector<std::string>& headers);
    void stream_row(const Json& json, const std::vector<std::string>& cells);

    // A failure, in JSON mode only (the message always goes to stderr too).
    void error_json(const Json& error);

private:
    void print_row(const std::vector<std::string>& cells, const std::vector<std::size_t>& widths);

    std::ostream& out_;
    bool json_;
    std::vector<std::size_t> stream_widths_;
};

}  // namespace slmp::cli
