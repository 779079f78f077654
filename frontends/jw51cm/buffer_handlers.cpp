// The JW-51CM's buffer commands (JW-51CM manual §8, §9; docs/jw51cm.md):
// designated buffers 28/38/68/78 and ring buffers 29/39/69/79. Every field,
// definition and pointer is checked before the first write: a refused request
// changes nothing.
#include <algorithm>

#include "frontends/jw51cm/buffers.hpp"
#include "frontends/jw51cm/command_table.hpp"

namespace slmp::jw51cm {

namespace {

constexpr std::uint8_t kTag = 0x01;   // §8, §9: TAG is always 01
constexpr std::uint8_t kRead = 0x01, kReadConfirmed = 0x81, kConfirm = 0x82, kConfirmAndAgain = 0x83;

std::uint16_t u16(std::span<const std::uint8_t> text, std::size_t at) {
    return static_cast<std::uint16_t>(text[at] | text[at + 1] << 8);
}

void put16(std::vector<std::uint8_t>& out, std::uint32_t value) {
    out.push_back(static_cast<std::uint8_t>(value));
    out.push_back(static_cast<std::uint8_t>(value >> 8));
}

void echo(Context& c, std::size_t bytes) {
    c.out.insert(c.out.end(), c.text.begin(), c.text.begin() + static_cast<std::ptrdiff_t>(bytes));
}

ByteAccess bytes(Context& c) { return ByteAccess(c.link.cpu().memory(), c.link.map()); }

DesignatedBuffer designated(Context& c, unsigned number) {
    return designated_buffer(c.link.options().parameters, c.link.map(), bytes(c), number);
}

RingBuffer ring(Context& c, unsigned number) {
    return ring_buffer(c.link.options().parameters, c.link.map(), bytes(c), number);
}

// 28/38: DB TAG IP L. The manual limits IP as well as L to 1024 (§8), and L 0
// reads nothing a host could want: 01 (chosen, as 24's L 0).
struct Window {
    DesignatedBuffer buffer;
    std::uint32_t offset, length;
};
Rslt window(Context& c, Window& w) {
    auto number = c.text[0];
    w.offset = u16(c.text, 2);
    w.length = u16(c.text, 4);
    if (number >= kDesignatedBuffers || c.text[1] != kTag || w.offset > kMaxData || w.length == 0 || w.length > kMaxData)
        return Rslt::Format;
    w.buffer = designated(c, number);
    if (!w.buffer.defined()) return Rslt::BufferUndefined;
    if (!w.buffer.valid()) return Rslt::BufferInvalid;
    if (w.offset + w.length > w.buffer.bytes()) return Rslt::BufferLength;
    return Rslt::Ok;
}

// 29/39: RB FUN TAG LC, the ring defined, valid, of the command's direction
// (another direction: 40, chosen — for this command there is no such ring) and
// its pointers inside it.
Rslt ring_request(Context& c, RingBuffer& r, bool to_host) {
    auto number = c.text[0], fun = c.text[1];
    if (number >= kRingBuffers || c.text[2] != kTag || u16(c.text, 3) > kMaxData ||
        (fun != kRead && fun != kReadConfirmed && fun != kConfirm && fun != kConfirmAndAgain))
        return Rslt::Format;
    r = ring(c, number);
    if (!r.defined()) return Rslt::RingUndefined;
    if (!r.valid()) return Rslt::RingInvalid;
    if (r.to_host() != to_host) return Rslt::RingUndefined;
    if (!r.pointers_inside()) return Rslt::RingPointers;
    return Rslt::Ok;
}

}  // namespace

Rslt buffer_read(Context& c) {
    Window w{};
    if (auto rslt = window(c, w); rslt != Rslt::Ok) return rslt;
    echo(c, 6);
    auto access = bytes(c);
    for (std::uint32_t i = 0; i < w.length; ++i)
        c.out.push_back(access.byte(w.buffer.start.file, w.buffer.start.address + w.offset + i));
    return Rslt::Ok;
}

Rslt buffer_write(Context& c) {
    Window w{};
    if (auto rslt = window(c, w); rslt != Rslt::Ok) return rslt;
    auto access = bytes(c);
    for (std::uint32_t i = 0; i < w.length; ++i)
        access.set_byte(w.buffer.start.file, w.buffer.start.address + w.offset + i, c.text[6 + i]);
    echo(c, 6);
    return Rslt::Ok;
}

// 68: DB TAG DINF ISEG IADR BSEG BADR LB, the stored values even when invalid;
// an undefined buffer answers DB, TAG and zeros.
Rslt buffer_info_read(Context& c) {
    auto number = c.text[0];
    if (number >= kDesignatedBuffers) return Rslt::Format;
    auto b = designated(c, number);
    c.out.push_back(number);
    c.out.push_back(kTag);
    c.out.push_back(b.dinf);
    if (!b.defined()) {
        c.out.insert(c.out.end(), 8, 0x00);
        return Rslt::Ok;
    }
    c.out.push_back(b.info.file);
    put16(c.out, b.info.address);
    c.out.push_back(b.start.file);
    put16(c.out, b.start.address);
    put16(c.out, b.length_field);
    return Rslt::Ok;
}

// 78: an indirect buffer's DF, DA, DL into its info area. DINF must match the
// definition: a direct buffer cannot be changed (48), nor the kind of definition.
Rslt buffer_info_write(Context& c) {
    auto number = c.text[0], dinf = c.text[2];
    Place start{c.text[3], u16(c.text, 4)};
    std::uint16_t length = u16(c.text, 6);
    if (number >= kDesignatedBuffers || c.text[1] != kTag || (dinf != kDinfDirect && dinf != kDinfIndirect) ||
        !valid_buffer_layout(c.link.map(), start, length == 0 ? 0x10000u : length))
        return Rslt::Format;
    auto b = designated(c, number);
    if ((b.dinf & ~kDinfInvalid) != kDinfIndirect || dinf != kDinfIndirect) return Rslt::BufferUndefined;
    auto access = bytes(c);
    access.set_byte(b.info.file, b.info.address, static_cast<std::uint8_t>(start.address));
    access.set_byte(b.info.file, b.info.address + 1, static_cast<std::uint8_t>(start.address >> 8));
    access.set_byte(b.info.file, b.info.address + 2, start.file);
    access.set_byte(b.info.file, b.info.address + 4, static_cast<std::uint8_t>(length));
    access.set_byte(b.info.file, b.info.address + 5, static_cast<std::uint8_t>(length >> 8));
    c.out.push_back(number);
    return Rslt::Ok;
}

// 29: RB TAG RP LR MORE DATA. FUN 01 moves RP at once; 81 waits for the host's
// confirm (82, or 83 that also reads again, confirm type). A confirm moves RP by
// the last unconfirmed read only when RP is still where that read began, so a
// repeated confirm (its answer lost) skips nothing (inferred, §19.4).
Rslt ring_read(Context& c) {
    RingBuffer r;
    if (auto rslt = ring_request(c, r, true); rslt != Rslt::Ok) return rslt;
    auto number = c.text[0], fun = c.text[1];
    auto access = bytes(c);
    auto& pending = c.link.ring_confirms[number];
    if (fun == kConfirm || fun == kConfirmAndAgain) {
        if (pending.open && pending.from == r.rp && pending.length <= r.unread())
            set_read_pointer(r, access, r.rp + pending.length);
        pending.open = false;
    }
    std::uint32_t length = 0;
    std::vector<std::uint8_t> data;
    if (fun != kConfirm) {
        auto wanted = u16(c.text, 3);
        length = std::min<std::uint32_t>(r.unread(), wanted == 0 ? kMaxData : wanted);
        data = ring_bytes(r, access, r.rp, length);
    }
    c.out.push_back(number);
    c.out.push_back(kTag);
    put16(c.out, r.rp);
    put16(c.out, length);
    c.out.push_back(r.unread() > length ? 0x01 : 0x00);   // MORE: unread data beyond this answer
    c.out.insert(c.out.end(), data.begin(), data.end());
    if (fun == kRead) {
        set_read_pointer(r, access, r.rp + length);
        pending.open = false;
    } else if (fun != kConfirm) {
        pending = {true, r.rp, static_cast<std::uint16_t>(length)};
    }
    return Rslt::Ok;
}

// 39: RB TAG WP(before) LR LE(free after). FUN 01 moves WP at once; 81 puts the
// data at WP and moves WP on the confirm (82, or 83 that also writes again);
// a repeated confirm moves nothing (inferred, §19.4). 82's LC and data are not used.
Rslt ring_write(Context& c) {
    RingBuffer r;
    if (auto rslt = ring_request(c, r, false); rslt != Rslt::Ok) return rslt;
    auto number = c.text[0], fun = c.text[1];
    auto length = u16(c.text, 3);
    auto data = c.text.subspan(5, length);
    if (fun != kConfirm) {
        // What the confirm would free up counts: 83's write lands after it.
        auto pending = c.link.ring_confirms[number];
        auto free = r.free();
        if (fun == kConfirmAndAgain && pending.open && pending.from == r.wp && pending.length <= free) free -= pending.length;
        if (length > r.size()) return Rslt::RingTooLarge;
        if (length > free) return Rslt::RingFull;
    }
    auto access = bytes(c);
    auto& pending = c.link.ring_confirms[number];
    if (fun == kConfirm || fun == kConfirmAndAgain) {
        if (pending.open && pending.from == r.wp && pending.length <= r.free())
            set_write_pointer(r, access, r.wp + pending.length);
        pending.open = false;
    }
    std::uint32_t written = fun == kConfirm ? 0 : length;
    auto free_after = r.free() - written;
    put_ring_bytes(r, access, r.wp, data.first(written));
    c.out.push_back(number);
    c.out.push_back(kTag);
    put16(c.out, r.wp);
    put16(c.out, written);
    put16(c.out, free_after);
    if (fun == kRead) {
        set_write_pointer(r, access, r.wp + written);
        pending.open = false;
    } else if (fun != kConfirm) {
        pending = {true, r.wp, static_cast<std::uint16_t>(written)};
    }
    return Rslt::Ok;
}

// 69: RB TAG DINF ISEG IADR BSEG BADR WP RP DIR LB. DIR in 69's own code: 80
// PLC -> host (stored 01), 81 host -> PLC; an invalid one as stored.
Rslt ring_info_read(Context& c) {
    auto number = c.text[0];
    if (number >= kRingBuffers) return Rslt::Format;
    auto r = ring(c, number);
    c.out.push_back(number);
    c.out.push_back(kTag);
    c.out.push_back(r.dinf);
    if (!r.defined()) {
        c.out.insert(c.out.end(), 13, 0x00);
        return Rslt::Ok;
    }
    c.out.push_back(r.info.file);
    put16(c.out, r.info.address);
    c.out.push_back(r.file);
    put16(c.out, r.address());
    put16(c.out, r.wp);
    put16(c.out, r.rp);
    c.out.push_back(r.direction == kToHost ? kToHostAlt : r.direction);
    put16(c.out, static_cast<std::uint32_t>(r.length_code) << 8);
    return Rslt::Ok;
}

// 79: WP and RP; for an indirect ring also BSEG, BADR, DIR, LB into its info
// area (a direct ring's are the parameters', and the command's are ignored).
// Undefined or DINF not the ring's own kind: 48, as the manual says for 79.
Rslt ring_info_write(Context& c) {
    auto number = c.text[0], dinf = c.text[2];
    if (number >= kRingBuffers || c.text[1] != kTag || (dinf != kDinfDirect && dinf != kDinfIndirect))
        return Rslt::Format;
    auto r = ring(c, number);
    if ((r.dinf & ~kDinfInvalid) != dinf) return Rslt::BufferUndefined;
    std::uint16_t wp = u16(c.text, 6), rp = u16(c.text, 8);
    if (dinf == kDinfIndirect) {
        std::uint8_t file = c.text[3], direction = c.text[10];
        std::uint16_t address = u16(c.text, 4), length = u16(c.text, 11);
        if ((address & 0xFF) != 0 || (length & 0xFF) != 0 ||
            !valid_ring_layout(c.link.map(), file, static_cast<std::uint8_t>(address >> 8), direction,
                               static_cast<std::uint8_t>(length >> 8)))
            return Rslt::Format;
        r.file = file;
        r.high = static_cast<std::uint8_t>(address >> 8);
        r.direction = direction == kToHostAlt ? kToHost : direction;   // the info area's code (§9 [4])
        r.length_code = static_cast<std::uint8_t>(length >> 8);
    }
    if (wp >= r.size() || rp >= r.size()) return Rslt::Format;
    auto access = bytes(c);
    if (dinf == kDinfIndirect) {
        access.set_byte(r.info.file, r.info.address + 4, r.high);
        access.set_byte(r.info.file, r.info.address + 5, r.file);
        access.set_byte(r.info.file, r.info.address + 6, r.direction);
        access.set_byte(r.info.file, r.info.address + 7, r.length_code);
    }
    set_write_pointer(r, access, wp);
    set_read_pointer(r, access, rp);
    c.link.ring_confirms[number].open = false;   // the pointers are the host's now
    c.out.push_back(number);
    return Rslt::Ok;
}

}  // namespace slmp::jw51cm
