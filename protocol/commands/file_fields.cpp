#include "protocol/commands/file_fields.hpp"

#include <algorithm>
#include <cctype>

#include "devicemodel/utf16.hpp"

namespace slmp::protocol::commands::files {

using devicemodel::Family;
using devicemodel::FileFault;

namespace {

bool ql_family(Family f) { return f == Family::QnU || f == Family::L || f == Family::QJ71E71; }

// The 8.3 record's name and extension, space-padded, upper-case (§6.1).
std::pair<std::string, std::string> short_parts(const std::string& name) {
    auto dot = name.rfind('.');
    std::string base = dot == std::string::npos ? name : name.substr(0, dot);
    std::string ext = dot == std::string::npos ? std::string() : name.substr(dot + 1);
    for (auto* part : {&base, &ext})
        for (auto& c : *part) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    base.resize(8, ' ');
    ext.resize(3, ' ');
    return {base, ext};
}

void put_text(FieldWriter& out, const std::string& text) {
    out.raw(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
}

}  // namespace

bool family_accepts(const CommandContext& ctx, bool iqr_form_exists) {
    const auto family = ctx.cpu.profile().family;
    const auto sub = ctx.spec.subcommand;
    // A CPU whose profile lists no drives (FX5) has no file commands at all.
    if (ctx.cpu.profile().drives.empty()) return false;
    if (!iqr_form_exists) return sub == 0x0000;
    if (family == Family::IQR) return sub == 0x0040;
    if (sub == 0x0004) return family == Family::L;   // *4: 0004 cannot reach a QCPU
    return ql_family(family) && sub == 0x0000;
}

Dialect dialect_of(const CommandContext& ctx) {
    Dialect d;
    d.subcommand = ctx.spec.subcommand;
    d.form = d.subcommand == 0x0040 ? devicemodel::NameForm::Long : devicemodel::NameForm::Short83;
    return d;
}

std::string password(FieldReader& in, const Dialect& d, EndCode& bad) {
    std::size_t length = d.subcommand == 0x0004 ? 32 : 4;
    if (d.long_form()) {
        length = in.u16("password length");
        // 0 (no password) or 6-32 characters (§3.1).
        if (in.ok() && length != 0 && (length < 6 || length > 32)) bad = EndCode::BadRequestContent;
        if (length > 32) return {};
    }
    auto bytes = in.raw(length, "password");
    return std::string(bytes.begin(), bytes.end());
}

std::string file_name(FieldReader& in, const Dialect& d, std::string_view what) {
    auto count = in.u16(what);
    if (!in.ok()) return {};
    if (!d.long_form()) {
        auto bytes = in.raw(count, what);
        return std::string(bytes.begin(), bytes.end());
    }
    std::vector<std::uint16_t> units;
    for (std::uint16_t i = 0; i < count && in.ok(); ++i) units.push_back(in.u16(what));
    return devicemodel::utf16_to_utf8(units);
}

bool fixed_zero4(FieldReader& in, std::string_view what) {
    auto bytes = in.raw(4, what);
    return std::all_of(bytes.begin(), bytes.end(), [](std::uint8_t b) { return b == '0' || b == 0x00; });
}

std::uint32_t file_number(FieldReader& in, const Dialect& d, std::string_view what) {
    return d.long_form() ? in.u32(what) : in.u16(what);
}

void put_file_number(FieldWriter& out, const Dialect& d, std::uint32_t number) {
    if (d.long_form())
        out.u32(number);
    else
        out.u16(static_cast<std::uint16_t>(number));
}

void put_entry(FieldWriter& out, const Dialect& d, const devicemodel::FileEntry& entry) {
    if (d.long_form()) {
        auto units = devicemodel::utf8_to_utf16(entry.name);
        out.u16(static_cast<std::uint16_t>(units.size()));
        for (auto unit : units) out.u16(unit);
    } else {
        auto [base, ext] = short_parts(entry.name);
        put_text(out, base);
        put_text(out, entry.directory && entry.name.find('.') == std::string::npos ? "   " : ext);
    }
    out.u16(entry.attribute);
    for (int i = 0; i < 7; ++i) out.u8(0);   // reserved data 1: 7 bytes / 14 characters (§10.1)
    out.u16(0);                              // reserved data 2
    out.u16(entry.dos_time);
    out.u16(entry.dos_date);
    out.u16(0);                              // reserved data 3
    out.u32(static_cast<std::uint32_t>(entry.size));
}

std::size_t entry_bytes(const Dialect& d, const devicemodel::FileEntry& entry) {
    return d.long_form() ? 23 + 2 * devicemodel::utf8_to_utf16(entry.name).size() : 32;
}

// Neither manual lists file end codes (§7); these are the MELSEC CPU codes
// for the conditions, chosen and explained in docs/end-codes.md.
EndCode end_code_for(const PortProfile& port, FileFault fault) {
    if (fault == FileFault::None) return EndCode::Ok;
    return end_code(port.file_end_codes[static_cast<std::size_t>(fault)]);
}

bool ql_running(const CommandContext& ctx) {
    return ql_family(ctx.cpu.profile().family) && ctx.cpu.runtime().state() != devicemodel::RunState::Stop;
}

}  // namespace slmp::protocol::commands::files
