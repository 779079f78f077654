// read_source: which of the two forms a file is, by content, never by name
// (docs/program.md "Files").
#include "program/load_text.hpp"
#include "program/source.hpp"
#include "program/source_builder.hpp"

namespace slmp::program {

namespace {

// The separator of a GX Works list, judged by its column-name row (row 3),
// or 0 when row 3 has not 7 TAB- or comma-separated fields.
char list_separator(std::string_view text) {
    load_text::RowCursor rows(text);
    std::optional<std::string_view> third;
    for (int k = 0; k < 3; ++k) third = rows.next();
    if (!third) return 0;
    for (char separator : {'\t', ','}) {
        auto fields = load_text::split_record(*third, separator);
        if (fields && fields->size() == 7) return separator;
    }
    return 0;
}

}  // namespace

Source read_source(std::string_view bytes, std::string file) {
    auto decoded = load_text::decode_file(bytes, file);
    Source source;
    source.file = file;
    load_text::Problems problems(std::move(file));
    char separator = list_separator(decoded.text);
    // The UTF-16 BOM is GX Works' own mark: such a file is a list even when
    // its third row is damaged, and the list reader says what is wrong.
    if (decoded.utf16 || separator != 0) {
        source.format = Format::GxWorksCsv;
        read_gx_works_rows(decoded.text, separator != 0 ? separator : '\t', source, problems);
    } else {
        source.format = Format::Text;
        read_text_rows(decoded.text, source, problems);
    }
    problems.throw_if_any();
    return source;
}

}  // namespace slmp::program
