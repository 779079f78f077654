#include "frontends/jw51cm/buffers.hpp"

namespace slmp::jw51cm {

namespace {

std::uint16_t u16(std::span<const std::uint8_t> bytes, std::size_t at) {
    return static_cast<std::uint16_t>(bytes[at] | bytes[at + 1] << 8);
}

std::uint16_t memory_u16(const ByteAccess& memory, Place at, std::uint32_t offset) {
    return static_cast<std::uint16_t>(memory.byte(at.file, at.address + offset) |
                                      memory.byte(at.file, at.address + offset + 1) << 8);
}

void set_memory_u16(ByteAccess& memory, Place at, std::uint32_t offset, std::uint32_t value) {
    memory.set_byte(at.file, at.address + offset, static_cast<std::uint8_t>(value));
    memory.set_byte(at.file, at.address + offset + 1, static_cast<std::uint8_t>(value >> 8));
}

bool valid_length_code(std::uint8_t code) {
    return code == 0 || (code & (code - 1)) == 0;   // 00 (64 KB) or one bit: 01, 02, 04, … 80
}

// An info area: 8 bytes inside a file.
bool valid_info(const MemoryMap& map, Place info) { return info.file <= 7 && map.contains(info.file, info.address, 8); }

std::span<const std::uint8_t> block(std::span<const std::uint8_t> parameters, std::uint32_t first, unsigned number) {
    return parameters.subspan(first + 8 * number, 8);
}

}  // namespace

std::string octal(std::uint32_t value, int digits) {
    std::string text;
    for (int i = 0; i < digits || value; ++i, value >>= 3) text.insert(text.begin(), static_cast<char>('0' + (value & 7)));
    return text;
}

bool valid_buffer_layout(const MemoryMap& map, Place start, std::uint32_t bytes) {
    return start.file <= 7 && map.contains(start.file, start.address, bytes);
}

bool valid_ring_layout(const MemoryMap& map, std::uint8_t file, std::uint8_t high, std::uint8_t direction,
                       std::uint8_t length_code) {
    if (file > 7 || high % 4 != 0 || !valid_length_code(length_code)) return false;
    if (direction != kToHost && direction != kToHostAlt && direction != kToPlc) return false;
    RingBuffer ring;
    ring.high = high;
    ring.length_code = length_code;
    return map.contains(file, ring.address(), ring.size());
}

DesignatedBuffer designated_buffer(std::span<const std::uint8_t> parameters, const MemoryMap& map,
                                   const ByteAccess& memory, unsigned number) {
    DesignatedBuffer buffer;
    auto p = block(parameters, kDesignatedParameters, number);
    if (p[7] == kDirect) {
        buffer.dinf = kDinfDirect;
        buffer.start = {p[2], u16(p, 0)};
        buffer.length_field = u16(p, 4);
    } else if (p[7] == kIndirect) {
        buffer.dinf = kDinfIndirect;
        buffer.info = {p[2], u16(p, 0)};
        // The info area itself was checked with the parameters: +0/+1 DA, +2 DF, +4/+5 DL.
        buffer.start = {memory.byte(buffer.info.file, buffer.info.address + 2), memory_u16(memory, buffer.info, 0)};
        buffer.length_field = memory_u16(memory, buffer.info, 4);
    } else {
        return buffer;
    }
    if (!valid_buffer_layout(map, buffer.start, buffer.bytes())) buffer.dinf |= kDinfInvalid;
    return buffer;
}

RingBuffer ring_buffer(std::span<const std::uint8_t> parameters, const MemoryMap& map, const ByteAccess& memory,
                       unsigned number) {
    RingBuffer ring;
    auto p = block(parameters, kRingParameters, number);
    if (p[7] != kDirect && p[7] != kIndirect) return ring;
    ring.info = {p[2], u16(p, 0)};
    ring.wp = memory_u16(memory, ring.info, 0);
    ring.rp = memory_u16(memory, ring.info, 2);
    if (p[7] == kDirect) {
        ring.dinf = kDinfDirect;
        ring.direction = p[3];
        ring.high = p[4];
        ring.file = p[5];
        ring.length_code = p[6];
    } else {
        ring.dinf = kDinfIndirect;
        ring.high = memory.byte(ring.info.file, ring.info.address + 4);
        ring.file = memory.byte(ring.info.file, ring.info.address + 5);
        ring.direction = memory.byte(ring.info.file, ring.info.address + 6);
        ring.length_code = memory.byte(ring.info.file, ring.info.address + 7);
    }
    if (!valid_ring_layout(map, ring.file, ring.high, ring.direction, ring.length_code)) ring.dinf |= kDinfInvalid;
    return ring;
}

std::vector<std::uint8_t> ring_bytes(const RingBuffer& ring, const ByteAccess& memory, std::uint32_t from,
                                     std::uint32_t count) {
    std::vector<std::uint8_t> out;
    out.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) out.push_back(memory.byte(ring.file, ring.address() + (from + i) % ring.size()));
    return out;
}

void put_ring_bytes(const RingBuffer& ring, ByteAccess& memory, std::uint32_t at, std::span<const std::uint8_t> data) {
    for (std::size_t i = 0; i < data.size(); ++i)
        memory.set_byte(ring.file, ring.address() + static_cast<std::uint32_t>((at + i) % ring.size()), data[i]);
}

void set_write_pointer(RingBuffer& ring, ByteAccess& memory, std::uint32_t wp) {
    ring.wp = static_cast<std::uint16_t>(wp % ring.size());
    set_memory_u16(memory, ring.info, 0, ring.wp);
}

void set_read_pointer(RingBuffer& ring, ByteAccess& memory, std::uint32_t rp) {
    ring.rp = static_cast<std::uint16_t>(rp % ring.size());
    set_memory_u16(memory, ring.info, 2, ring.rp);
}

std::string check_parameters(std::span<const std::uint8_t> parameters, const MemoryMap& map) {
    auto at = [](std::uint32_t first, unsigned number, unsigned offset) {
        return "parameter " + octal(first + 8 * number + offset, 4);
    };
    for (unsigned n = 0; n < kDesignatedBuffers; ++n) {
        auto p = block(parameters, kDesignatedParameters, n);
        if (p[7] != kUnused && p[7] != kDirect && p[7] != kIndirect)
            return at(kDesignatedParameters, n, 7) + " (designated buffer " + octal(n, 2) + "'s definition) is not 00, 80 or C0";
        if (p[7] == kDirect) {
            DesignatedBuffer b;
            b.start = {p[2], u16(p, 0)};
            b.length_field = u16(p, 4);
            if (!valid_buffer_layout(map, b.start, b.bytes()))
                return at(kDesignatedParameters, n, 0) + ": designated buffer " + octal(n, 2) + " (file " +
                       std::to_string(p[2]) + ", " + std::to_string(b.bytes()) + " bytes from " + octal(u16(p, 0), 6) +
                       ") is not inside a file; files 1-7 have \"file_bytes\" bytes, file 0 8192";
        }
        if (p[7] == kIndirect && !valid_info(map, {p[2], u16(p, 0)}))
            return at(kDesignatedParameters, n, 0) + ": designated buffer " + octal(n, 2) +
                   "'s info area (8 bytes) is not inside a file";
    }
    for (unsigned n = 0; n < kRingBuffers; ++n) {
        auto p = block(parameters, kRingParameters, n);
        if (p[7] != kUnused && p[7] != kDirect && p[7] != kIndirect)
            return at(kRingParameters, n, 7) + " (ring buffer " + octal(n, 1) + "'s definition) is not 00, 80 or C0";
        if (p[7] == kUnused) continue;
        if (!valid_info(map, {p[2], u16(p, 0)}))
            return at(kRingParameters, n, 0) + ": ring buffer " + octal(n, 1) + "'s info area (8 bytes) is not inside a file";
        if (p[7] == kDirect && !valid_ring_layout(map, p[5], p[4], p[3], p[6]))
            return at(kRingParameters, n, 3) + ": ring buffer " + octal(n, 1) +
                   " needs a direction (+3) 01 or 81, a start high byte (+4) that is a multiple of 04, a file (+5) 0-7, "
                   "a length code (+6) 00, 01, 02, 04, 08, 10, 20, 40 or 80, and to fit inside its file (files 1-7 "
                   "have \"file_bytes\" bytes, file 0 8192)";
    }
    return {};
}

}  // namespace slmp::jw51cm
