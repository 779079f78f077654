// Bytes -> the program loader (program/source.hpp): read_source, then the
// program written back with write_csv and write_text and read again, and
// read_comments. LoadError is the documented refusal; anything else escaping,
// or a round trip that changes the lines, is a finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include "program/source.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

using namespace slmp::program;

// Kind, mnemonic, operands, statement and note of every line.
std::vector<std::string> lines_of(const Source& source) {
    std::vector<std::string> out;
    for (const auto& line : source.lines) {
        std::string text = std::to_string(static_cast<int>(line.kind)) + "|" + line.mnemonic + "|" + line.statement;
        for (const auto& operand : line.operands) text += "|" + operand;
        out.push_back(std::move(text));
    }
    return out;
}

// A row the writer lengthened (doubled quotes, seven quoted fields) may pass
// the loader's row limit; every other refusal of our own output is a finding.
bool only_row_length(const LoadError& e) {
    for (const auto& problem : e.problems) {
        if (problem.find("bytes long; the limit is") == std::string::npos) return false;
    }
    return true;
}

void round_trip_csv(const Source& source) {
    auto bytes = write_csv(source);
    FUZZ_CHECK(bytes.starts_with("\xFF\xFE") && bytes.ends_with(std::string("\r\0\n\0", 4)),
               "write_csv wrote no BOM or no final CR LF");
    try {
        auto again = read_source(bytes, "again.csv");
        FUZZ_CHECK(again.format == Format::GxWorksCsv, "write_csv's output was not read as a CSV list");
        FUZZ_CHECK(lines_of(again) == lines_of(source), "write_csv -> read_source changed the lines");
        for (std::size_t k = 0; k < source.lines.size(); ++k) {
            if (source.lines[k].step) FUZZ_CHECK(again.lines[k].step == source.lines[k].step, "a step number changed");
        }
    } catch (const LoadError& e) {
        FUZZ_CHECK(only_row_length(e), "read_source refused write_csv's output: %s", e.what());
    }
}

void round_trip_text(const Source& source) {
    auto text = write_text(source);
    try {
        auto again = read_source(text, "again.il");
        FUZZ_CHECK(again.format == Format::Text, "write_text's output was read as a CSV list");
        if (source.format == Format::Text) {
            FUZZ_CHECK(lines_of(again) == lines_of(source), "write_text -> read_source changed the lines");
        }
    } catch (const LoadError& e) {
        // CSV cells may hold what the text form cannot (a ';' in a mnemonic,
        // an unclosed '"'); a text program's own lines must come back.
        FUZZ_CHECK(source.format != Format::Text, "read_source refused write_text's output: %s", e.what());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        auto source = read_source(bytes, "fuzz.csv");
        round_trip_csv(source);
        round_trip_text(source);
    } catch (const LoadError&) {
        // The documented way to refuse input.
    } catch (const std::exception& e) {
        FUZZ_CHECK(false, "the program loader let a non-LoadError escape: %s", e.what());
    }
    try {
        auto comments = read_comments(bytes, "fuzz-comments.csv");
        for (const auto& c : comments) FUZZ_CHECK(!c.device.empty() && !c.comment.empty(), "an empty comment entry");
    } catch (const LoadError&) {
    } catch (const std::exception& e) {
        FUZZ_CHECK(false, "read_comments let a non-LoadError escape: %s", e.what());
    }
    return 0;
}
