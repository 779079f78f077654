// The fields the file commands 1810-182A share (SLMP Reference Manual §5.8),
// read and written once for binary and ASCII through FieldReader/FieldWriter,
// and the end codes a devicemodel::FileFault gets (docs/end-codes.md).
#pragma once

#include <string>

#include "devicemodel/drives.hpp"
#include "protocol/command_table.hpp"

namespace slmp::protocol::commands::files {

// The dialect the subcommand picks: 0000 Q/L (8.3 names, 4-character
// password), 0004 LCPU (32-character password), 0040 iQ-R (UTF-16 paths,
// length + 6-32 character password).
struct Dialect {
    std::uint16_t subcommand = 0;
    devicemodel::NameForm form = devicemodel::NameForm::Short83;
    bool long_form() const { return form == devicemodel::NameForm::Long; }
};

// Whether the target CPU's family speaks this subcommand (§2.2): Q/L and a
// QJ71E71 0000 (0004 on L only), iQ-R 0040; 1828/1829/182A 0000 everywhere.
bool family_accepts(const CommandContext& ctx, bool iqr_form_exists);
Dialect dialect_of(const CommandContext& ctx);

// STR 4 / STR 32 / (HEX4 length + STR n, n = 0 or 6-32). Raw ASCII in both codecs.
std::string password(FieldReader& in, const Dialect& d, EndCode& bad);
// 0000: HEX4 count + STR n (raw bytes); 0040: HEX4 count + U16 n (UTF-16 code units).
std::string file_name(FieldReader& in, const Dialect& d, std::string_view what);
// A 4-character slot that is "0000" in ASCII and 4 bytes (30H or 00H) in
// binary: 1810's ASC0000, 1811/1820's iQ-R password, 1826's fixed field.
bool fixed_zero4(FieldReader& in, std::string_view what);
// File No. / start file No.: HEX4 in 0000, HEX8 in 0040.
std::uint32_t file_number(FieldReader& in, const Dialect& d, std::string_view what);
void put_file_number(FieldWriter& out, const Dialect& d, std::uint32_t number);
// One 1810 directory entry (32-byte FAT record, or its 0040 UTF-16 form).
void put_entry(FieldWriter& out, const Dialect& d, const devicemodel::FileEntry& entry);
std::size_t entry_bytes(const Dialect& d, const devicemodel::FileEntry& entry);   // as binary

// The end code the CPU's profile gives a refused file operation ("file_end_codes").
EndCode end_code_for(const PortProfile& port, devicemodel::FileFault fault);

// Q/L in RUN (§5): what a command may not touch unless the CPU is in STOP.
bool ql_running(const CommandContext& ctx);

}  // namespace slmp::protocol::commands::files
