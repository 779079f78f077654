#include "protocol/client_files.hpp"

#include "devicemodel/utf16.hpp"

namespace slmp::protocol::client {
namespace {

std::uint16_t sub(bool iqr) { return iqr ? 0x0040 : 0x0000; }
// 0004: the L CPUs' form of 1822/1824/1825/1827 with a 32-character password slot.
std::uint16_t sub(const FileTarget& t) { return t.iqr ? 0x0040 : t.l_password ? 0x0004 : 0x0000; }

void raw_text(FieldWriter& w, const std::string& s) {
    w.raw(std::span(reinterpret_cast<const std::uint8_t*>(s.data()), s.size()));
}

void name(FieldWriter& w, bool iqr, const std::string& n) {
    if (!iqr) {
        w.u16(static_cast<std::uint16_t>(n.size()));
        raw_text(w, n);
        return;
    }
    auto units = devicemodel::utf8_to_utf16(n);
    w.u16(static_cast<std::uint16_t>(units.size()));
    for (auto u : units) w.u16(u);
}

// 0000: 4 characters, space-padded; 0040: length + characters (§3.1).
void password(FieldWriter& w, bool iqr, const std::string& pw, bool l_password = false) {
    if (!iqr) {
        auto padded = pw;
        padded.resize(l_password ? 32 : 4, ' ');
        raw_text(w, padded);
        return;
    }
    w.u16(static_cast<std::uint16_t>(pw.size()));
    raw_text(w, pw);
}

// 1811/1820: the Q/L password slot, or iQ-R's "fixed 0" (ASCII 0000, binary 4 zero bytes).
void zero4_or_password(FieldWriter& w, bool iqr, const std::string& pw) {
    if (!iqr) return password(w, false, pw);
    w.u16(0);
    if (w.codec() == Codec::Binary) w.u16(0);
}

void zero4(FieldWriter& w) {
    w.u16(0);
    if (w.codec() == Codec::Binary) w.u16(0);
}

}  // namespace

std::vector<std::uint8_t> file_list(const FrameOptions& o, bool iqr, std::uint16_t drive, std::uint32_t start,
                                    std::uint16_t count, const std::string& dir) {
    return build_request(o, 0x1810, sub(iqr), [&](FieldWriter& w) {
        raw_text(w, "0000");   // ASCII "0000" in both codes
        w.u16(drive);
        if (iqr)
            w.u32(start);
        else
            w.u16(static_cast<std::uint16_t>(start));
        w.u16(count);
        if (iqr)
            name(w, true, dir);
        else
            w.u16(0);
    });
}

std::vector<std::uint8_t> file_search(const FrameOptions& o, const FileTarget& t) {
    return build_request(o, 0x1811, sub(t.iqr), [&](FieldWriter& w) {
        zero4_or_password(w, t.iqr, t.password);
        w.u16(t.drive);
        w.u16(0);
        name(w, t.iqr, t.name);
    });
}

std::vector<std::uint8_t> file_new(const FrameOptions& o, const FileTarget& t, std::uint32_t size) {
    return build_request(o, 0x1820, sub(t.iqr), [&](FieldWriter& w) {
        zero4_or_password(w, t.iqr, t.password);
        w.u16(t.drive);
        w.u32(size);
        name(w, t.iqr, t.name);
    });
}

std::vector<std::uint8_t> file_delete(const FrameOptions& o, const FileTarget& t) {
    return build_request(o, 0x1822, sub(t), [&](FieldWriter& w) {
        password(w, t.iqr, t.password, t.l_password);
        w.u16(t.drive);
        name(w, t.iqr, t.name);
    });
}

std::vector<std::uint8_t> file_copy(const FrameOptions& o, const FileTarget& to, const FileTarget& from) {
    return build_request(o, 0x1824, sub(to), [&](FieldWriter& w) {
        w.u64(0);
        for (const auto* t : {&to, &from}) {
            password(w, to.iqr, t->password, to.l_password);
            w.u16(t->drive);
            name(w, to.iqr, t->name);
        }
    });
}

std::vector<std::uint8_t> file_state(const FrameOptions& o, const FileTarget& t, std::uint16_t attribute) {
    return build_request(o, 0x1825, sub(t), [&](FieldWriter& w) {
        password(w, t.iqr, t.password, t.l_password);
        w.u16(t.drive);
        w.u16(attribute);
        name(w, t.iqr, t.name);
    });
}

std::vector<std::uint8_t> file_date(const FrameOptions& o, const FileTarget& t, std::uint16_t date, std::uint16_t time) {
    return build_request(o, 0x1826, sub(t.iqr), [&](FieldWriter& w) {
        zero4(w);
        w.u16(t.drive);
        w.u16(date);
        w.u16(time);
        name(w, t.iqr, t.name);
    });
}

std::vector<std::uint8_t> file_open(const FrameOptions& o, const FileTarget& t, bool for_write) {
    return build_request(o, 0x1827, sub(t), [&](FieldWriter& w) {
        password(w, t.iqr, t.password, t.l_password);
        w.u16(for_write ? 0x0100 : 0x0000);
        w.u16(t.drive);
        name(w, t.iqr, t.name);
    });
}

std::vector<std::uint8_t> file_read(const FrameOptions& o, std::uint16_t pointer, std::uint32_t offset,
                                    std::uint16_t count) {
    return build_request(o, 0x1828, 0x0000, [&](FieldWriter& w) {
        w.u16(pointer);
        w.u32(offset);
        w.u16(count);
    });
}

std::vector<std::uint8_t> file_write(const FrameOptions& o, std::uint16_t pointer, std::uint32_t offset,
                                     std::span<const std::uint8_t> data) {
    return build_request(o, 0x1829, 0x0000, [&](FieldWriter& w) {
        w.u16(pointer);
        w.u32(offset);
        w.u16(static_cast<std::uint16_t>(data.size()));
        for (auto b : data) w.u8(b);
    });
}

std::vector<std::uint8_t> file_close(const FrameOptions& o, std::uint16_t pointer, std::uint16_t type) {
    return build_request(o, 0x182A, 0x0000, [&](FieldWriter& w) {
        w.u16(pointer);
        w.u16(type);
    });
}

std::optional<FileListPage> parse_file_list(const Response& r, bool iqr) {
    auto in = r.reader();
    FileListPage page;
    page.count = in.u16("count");
    if (iqr) page.last_number = in.u32("last file No.");
    if (page.count == 0xFFFF) return in.ok() ? std::optional(page) : std::nullopt;
    for (std::uint16_t i = 0; i < page.count && in.ok(); ++i) {
        FileListEntry e;
        if (iqr) {
            auto n = in.u16("name count");
            std::vector<std::uint16_t> units;
            for (std::uint16_t k = 0; k < n && in.ok(); ++k) units.push_back(in.u16("name"));
            e.name = devicemodel::utf16_to_utf8(units);
        } else {
            auto base = in.raw(8, "name");
            auto ext = in.raw(3, "extension");
            std::string b(base.begin(), base.end()), x(ext.begin(), ext.end());
            b.erase(b.find_last_not_of(' ') + 1);
            x.erase(x.find_last_not_of(' ') == std::string::npos ? 0 : x.find_last_not_of(' ') + 1);
            e.name = x.empty() ? b : b + "." + x;
        }
        e.attribute = in.u16("attribute");
        for (int k = 0; k < 7; ++k) in.u8("reserved 1");
        in.u16("reserved 2");
        e.time = in.u16("time");
        e.date = in.u16("date");
        in.u16("reserved 3");
        e.size = in.u32("size");
        page.entries.push_back(std::move(e));
    }
    if (!in.finish()) return std::nullopt;
    return page;
}

std::optional<std::uint32_t> parse_file_number(const Response& r, bool iqr) {
    auto in = r.reader();
    std::uint32_t n = iqr ? in.u32("file No.") : in.u16("file No.");
    if (!in.finish()) return std::nullopt;
    return n;
}

std::optional<std::uint16_t> parse_file_pointer(const Response& r) {
    auto in = r.reader();
    auto n = in.u16("file pointer No.");
    if (!in.finish()) return std::nullopt;
    return n;
}

std::optional<std::vector<std::uint8_t>> parse_file_read(const Response& r) {
    auto in = r.reader();
    auto n = in.u16("read byte count");
    std::vector<std::uint8_t> out;
    for (std::uint16_t i = 0; i < n && in.ok(); ++i) out.push_back(in.u8("read data"));
    if (!in.finish()) return std::nullopt;
    return out;
}

}  // namespace slmp::protocol::client
