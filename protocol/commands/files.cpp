// File control 1810-182A (SLMP Reference Manual §5.8): each command written once,
// its fields through file_fields.hpp, its effect in devicemodel::DriveSet.
// Check order: the family's subcommand (the port's "not supported" code, C059),
// every field and the length (C061/C050), field values (C05C, CEE1/CEE2),
// the Q/L RUN rules (4013), the password (4026), then the drive's own checks.
// System protect (and online change off in RUN) refuse the rows flagged
// kWrites before the handler runs (protocol/execute.cpp) — the §5 list
// 1820/1822/1824/1825/1826/1829. End codes: docs/end-codes.md, docs/files.md.
#include "devicemodel/drives.hpp"
#include "protocol/commands/file_fields.hpp"
#include "protocol/commands/handlers.hpp"

namespace slmp::protocol::commands {

using namespace files;
using devicemodel::DriveSet;
using devicemodel::FileFault;
using devicemodel::FileRef;
using devicemodel::OpenMode;

namespace {

constexpr std::uint16_t kMaxTransfer = 1920;   // 1828/1829 bytes a request (§3.9)
constexpr std::uint16_t kMaxListCount = 36;    // 1810 entries a request (§6.1)

EndCode not_served(const CommandContext& ctx) { return end_code(ctx.port.not_supported_code); }

// The common prologue of 1822/1824/1825/1827: password, checked after the
// whole request is read; L with 0000 only reaches files without one (*5).
EndCode password_check(CommandContext& ctx, const Dialect& d, const FileRef& file, const std::string& given) {
    auto& drives = ctx.cpu.drives();
    if (d.subcommand == 0x0000 && ctx.cpu.profile().family == devicemodel::Family::L && drives.has_password(file, d.form))
        return end_code_for(ctx.port, FileFault::Password);
    return end_code_for(ctx.port, drives.check_password(file, d.form, given));
}

// Q/L RUN (§5): parameter files anywhere and programs on drive 0 are frozen.
bool frozen_in_run(CommandContext& ctx, const FileRef& file) {
    if (!ql_running(ctx)) return false;
    return DriveSet::parameter_file(file.path) || (file.drive == 0 && DriveSet::program_file(file.path));
}

// What the call monitor and recordings show of the request (Outcome::named):
// "2:LOGS/A.CSV", the copy's destination first as the request has it.
void note_file(CommandContext& ctx, const FileRef& file) {
    ctx.named += (ctx.named.empty() ? "" : ", ") + std::to_string(file.drive) + ":" + file.path;
}

}  // namespace

// 1810 Read Directory/File.
EndCode file_list(CommandContext& ctx) {
    if (!family_accepts(ctx, true)) return not_served(ctx);
    auto d = dialect_of(ctx);
    auto& in = ctx.in;
    bool fixed = fixed_zero4(in, "fixed 0000");
    FileRef dir{in.u16("drive No."), {}};
    auto start = file_number(in, d, "start file No.");
    auto count = in.u16("file request count");
    if (d.long_form())
        dir.path = file_name(in, d, "directory path");
    else if (in.u16("fixed 0000") != 0)
        fixed = false;
    note_file(ctx, dir);
    if (!in.finish()) return in.error();
    if (!fixed || start == 0 || count == 0 || count > kMaxListCount) return EndCode::BadRequestContent;
    devicemodel::Listing listing;
    if (auto fault = ctx.cpu.drives().list(dir.drive, dir.path, d.form, start, count, listing); fault != FileFault::None)
        return end_code_for(ctx.port, fault);
    if (listing.past_end && d.long_form()) {
        ctx.out.u16(0xFFFF);   // §4.7: the end of the folder
        ctx.out.u32(listing.last_number);
        return EndCode::Ok;
    }
    ctx.out.u16(static_cast<std::uint16_t>(listing.entries.size()));
    if (d.long_form()) ctx.out.u32(listing.last_number);
    for (const auto& entry : listing.entries) put_entry(ctx.out, d, entry);
    return EndCode::Ok;
}

// 1811 Search Directory/File: the file No.
EndCode file_search(CommandContext& ctx) {
    if (!family_accepts(ctx, true)) return not_served(ctx);
    auto d = dialect_of(ctx);
    auto& in = ctx.in;
    auto pw = in.raw(4, "password");   // Q/L: the password; iQ-R: "fixed to 0"
    std::string given(pw.begin(), pw.end());
    FileRef file{in.u16("drive No."), {}};
    auto fixed = in.u16("fixed 0000");
    file.path = file_name(in, d, "file name");
    note_file(ctx, file);
    if (!in.finish()) return in.error();
    if (fixed != 0) return EndCode::BadRequestContent;
    if (d.long_form() && given.find_first_not_of(std::string("0\0", 2)) != std::string::npos)
        return EndCode::BadRequestContent;
    if (!d.long_form())
        if (auto code = end_code_for(ctx.port, ctx.cpu.drives().check_password(file, d.form, given)); code != EndCode::Ok) return code;
    std::uint32_t number = 0;
    if (auto fault = ctx.cpu.drives().find(file, d.form, number); fault != FileFault::None) return end_code_for(ctx.port, fault);
    put_file_number(ctx.out, d, number);
    return EndCode::Ok;
}

// 1820 New File: the size reserved, zero-filled.
EndCode file_new(CommandContext& ctx) {
    if (!family_accepts(ctx, true)) return not_served(ctx);
    auto d = dialect_of(ctx);
    auto& in = ctx.in;
    auto pw = in.raw(4, "password");
    std::string given(pw.begin(), pw.end());
    FileRef file{in.u16("drive No."), {}};
    auto size = in.u32("file size");
    file.path = file_name(in, d, "file name");
    note_file(ctx, file);
    if (!in.finish()) return in.error();
    if (d.long_form() && given.find_first_not_of(std::string("0\0", 2)) != std::string::npos)
        return EndCode::BadRequestContent;
    // §4.2: project data is created under another extension, then copied (Q/L).
    if (!d.long_form() && DriveSet::project_data(file.path)) return end_code_for(ctx.port, FileFault::BadName);
    return end_code_for(ctx.port, ctx.cpu.drives().create(file, d.form, size));
}

// 1822 Delete File.
EndCode file_delete(CommandContext& ctx) {
    if (!family_accepts(ctx, true)) return not_served(ctx);
    auto d = dialect_of(ctx);
    auto& in = ctx.in;
    EndCode bad = EndCode::Ok;
    auto given = password(in, d, bad);
    FileRef file{in.u16("drive No."), {}};
    file.path = file_name(in, d, "file name");
    note_file(ctx, file);
    if (!in.finish()) return in.error();
    if (bad != EndCode::Ok) return bad;
    if (ql_running(ctx) && (DriveSet::program_file(file.path) || DriveSet::parameter_file(file.path) ||
                            DriveSet::boot_file(file.path)))
        return end_code_for(ctx.port, FileFault::RunState);
    if (auto code = password_check(ctx, d, file, given); code != EndCode::Ok) return code;
    return end_code_for(ctx.port, ctx.cpu.drives().remove(file, d.form));
}

// 1824 Copy File: destination first, then source.
EndCode file_copy(CommandContext& ctx) {
    if (!family_accepts(ctx, true)) return not_served(ctx);
    auto d = dialect_of(ctx);
    auto& in = ctx.in;
    auto fixed = in.u64("fixed data");
    EndCode bad = EndCode::Ok;
    auto to_password = password(in, d, bad);
    FileRef to{in.u16("destination drive No."), {}};
    to.path = file_name(in, d, "destination file name");
    note_file(ctx, to);
    auto from_password = password(in, d, bad);
    FileRef from{in.u16("source drive No."), {}};
    from.path = file_name(in, d, "source file name");
    note_file(ctx, from);
    if (!in.finish()) return in.error();
    if (bad != EndCode::Ok || fixed != 0) return EndCode::BadRequestContent;
    // iQ-R: drive 0 (program memory) is neither source nor destination (§6.5).
    if (d.long_form() && (to.drive == 0 || from.drive == 0)) return end_code_for(ctx.port, FileFault::NoDrive);
    if (frozen_in_run(ctx, from) || frozen_in_run(ctx, to)) return end_code_for(ctx.port, FileFault::RunState);
    if (auto code = password_check(ctx, d, from, from_password); code != EndCode::Ok) return code;
    if (auto code = password_check(ctx, d, to, to_password); code != EndCode::Ok) return code;
    return end_code_for(ctx.port, ctx.cpu.drives().copy(to, from, d.form));
}

// 1825 Change File State: 01H read-only, 20H read/write.
EndCode file_state(CommandContext& ctx) {
    if (!family_accepts(ctx, true)) return not_served(ctx);
    auto d = dialect_of(ctx);
    auto& in = ctx.in;
    EndCode bad = EndCode::Ok;
    auto given = password(in, d, bad);
    FileRef file{in.u16("drive No."), {}};
    auto attribute = in.u16("attribute");
    file.path = file_name(in, d, "file name");
    note_file(ctx, file);
    if (!in.finish()) return in.error();
    // Other values "may not raise an error" but are system values: refused here (chosen).
    if (bad != EndCode::Ok || (attribute != 0x0001 && attribute != 0x0020)) return EndCode::BadRequestContent;
    if (frozen_in_run(ctx, file)) return end_code_for(ctx.port, FileFault::RunState);
    if (auto code = password_check(ctx, d, file, given); code != EndCode::Ok) return code;
    return end_code_for(ctx.port, ctx.cpu.drives().set_attribute(file, d.form, static_cast<std::uint8_t>(attribute)));
}

// 1826 Change File Date: date before time; no password, no lock.
EndCode file_date(CommandContext& ctx) {
    if (!family_accepts(ctx, true)) return not_served(ctx);
    auto d = dialect_of(ctx);
    auto& in = ctx.in;
    bool fixed = fixed_zero4(in, "fixed 0");
    FileRef file{in.u16("drive No."), {}};
    auto date = in.u16("date");
    auto time = in.u16("time");
    file.path = file_name(in, d, "file name");
    note_file(ctx, file);
    if (!in.finish()) return in.error();
    auto when = devicemodel::from_dos(date, time);
    if (!fixed || !when) return EndCode::BadRequestContent;
    if (frozen_in_run(ctx, file)) return end_code_for(ctx.port, FileFault::RunState);
    return end_code_for(ctx.port, ctx.cpu.drives().set_date(file, d.form, *when));
}

// 1827 Open File: a lock for reading (0000) or writing (0100); the pointer No.
EndCode file_open(CommandContext& ctx) {
    if (!family_accepts(ctx, true)) return not_served(ctx);
    auto d = dialect_of(ctx);
    auto& in = ctx.in;
    EndCode bad = EndCode::Ok;
    auto given = password(in, d, bad);
    auto mode = in.u16("open mode");
    FileRef file{in.u16("drive No."), {}};
    file.path = file_name(in, d, "file name");
    note_file(ctx, file);
    if (!in.finish()) return in.error();
    if (bad != EndCode::Ok || (mode != 0x0000 && mode != 0x0100)) return EndCode::BadRequestContent;
    if (auto code = password_check(ctx, d, file, given); code != EndCode::Ok) return code;
    std::uint16_t pointer = 0;
    auto fault = ctx.cpu.drives().open(file, d.form, mode == 0x0100 ? OpenMode::Write : OpenMode::Read,
                                       ctx.session.lock_owner(), pointer);
    if (fault != FileFault::None) return end_code_for(ctx.port, fault);
    ctx.out.u16(pointer);
    return EndCode::Ok;
}

// 1828 Read File.
EndCode file_read(CommandContext& ctx) {
    if (!family_accepts(ctx, false)) return not_served(ctx);
    auto& in = ctx.in;
    auto pointer = in.u16("file pointer No.");
    auto offset = in.u32("offset address");
    auto count = in.u16("read byte count");
    if (!in.finish()) return in.error();
    if (count > kMaxTransfer) return EndCode::ResponseTooLarge;
    if (offset % 2 != 0) return EndCode::BadRequestContent;
    std::vector<std::uint8_t> data;
    if (auto fault = ctx.cpu.drives().read(pointer, ctx.session.lock_owner(), offset, count, data); fault != FileFault::None)
        return end_code_for(ctx.port, fault);
    ctx.out.u16(static_cast<std::uint16_t>(data.size()));
    for (auto byte : data) ctx.out.u8(byte);   // binary: the bytes; ASCII: two hex digits a byte (§10.12)
    return EndCode::Ok;
}

// 1829 Write File: whole or not at all (devicemodel::FileStore::write).
EndCode file_write(CommandContext& ctx) {
    if (!family_accepts(ctx, false)) return not_served(ctx);
    auto& in = ctx.in;
    auto pointer = in.u16("file pointer No.");
    auto offset = in.u32("offset address");
    auto count = in.u16("write byte count");
    if (in.ok() && count > kMaxTransfer) return EndCode::RequestTooLarge;
    std::vector<std::uint8_t> data;
    data.reserve(count);
    for (std::uint16_t i = 0; i < count && in.ok(); ++i) data.push_back(in.u8("write data"));
    if (!in.finish()) return in.error();
    auto& drives = ctx.cpu.drives();
    const devicemodel::OpenFile* open = nullptr;
    for (const auto& f : drives.open_files())
        if (f.pointer == pointer) open = &f;
    // Drive 0 of a Q/L CPU (program memory) takes offsets in fours, the rest in twos.
    const bool program_memory = open && open->drive == 0 && ctx.cpu.profile().family != devicemodel::Family::IQR;
    if (offset % (program_memory ? 4 : 2) != 0) return EndCode::BadRequestContent;
    if (open && !open->path.empty() && frozen_in_run(ctx, FileRef{open->drive, open->path.back()}))
        return end_code_for(ctx.port, FileFault::RunState);
    if (auto fault = drives.write(pointer, ctx.session.lock_owner(), offset, data); fault != FileFault::None)
        return end_code_for(ctx.port, fault);
    ctx.out.u16(count);
    return EndCode::Ok;
}

// 182A Close File: 0 this pointer, 1 all of this client's, 2 every lock.
EndCode file_close(CommandContext& ctx) {
    if (!family_accepts(ctx, false)) return not_served(ctx);
    auto& in = ctx.in;
    auto pointer = in.u16("file pointer No.");
    auto type = in.u16("close type");
    if (!in.finish()) return in.error();
    if (type > 2) return EndCode::BadRequestContent;
    return end_code_for(ctx.port, ctx.cpu.drives().close(pointer, ctx.session.lock_owner(), type));
}

}  // namespace slmp::protocol::commands
