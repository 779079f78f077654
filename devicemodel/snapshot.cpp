#include "devicemodel/snapshot.hpp"

#include <cstring>
#include <optional>

namespace slmp::devicemodel {
namespace {

constexpr char kMagic[8] = {'S', 'L', 'M', 'P', 'S', 'N', 'A', 'P'};
constexpr std::uint32_t kVersion = 1;

std::uint64_t fnv1a(std::span<const std::uint8_t> bytes) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (auto b : bytes) {
        h ^= b;
        h *= 0x100000001b3ull;
    }
    return h;
}

// The label area (DeviceMemory::label_area_words) travels as one more area
// entry under a name no device has: files without it (older versions) restore
// with the label area left as it is, and an older version reading a newer file
// skips it with a warning, so the format version stays 1.
constexpr std::string_view kLabelArea = "LABEL";

bool saved(Area area, SnapshotContents contents) {
    if (area == Area::R) return false;   // R lives in ZR
    return contents == SnapshotContents::WithSystem || (area != Area::SM && area != Area::SD);
}

class Writer {
public:
    void u8(std::uint8_t v) { out.push_back(v); }
    void u32(std::uint32_t v) {
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void u64(std::uint64_t v) {
        for (int i = 0; i < 8; ++i) out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    void name(std::string_view s) {
        u8(static_cast<std::uint8_t>(s.size()));
        out.insert(out.end(), s.begin(), s.end());
    }
    std::vector<std::uint8_t> out;
};

class Reader {
public:
    explicit Reader(std::span<const std::uint8_t> in) : in_(in) {}
    std::optional<std::uint32_t> u32() {
        if (in_.size() - pos_ < 4) return std::nullopt;
        std::uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= std::uint32_t{in_[pos_ + i]} << (8 * i);
        pos_ += 4;
        return v;
    }
    std::optional<std::uint8_t> u8() {
        if (pos_ >= in_.size()) return std::nullopt;
        return in_[pos_++];
    }
    std::optional<std::string> name() {
        auto n = u8();
        if (!n || in_.size() - pos_ < *n) return std::nullopt;
        std::string s(in_.begin() + static_cast<std::ptrdiff_t>(pos_), in_.begin() + static_cast<std::ptrdiff_t>(pos_ + *n));
        pos_ += *n;
        return s;
    }
    bool done() const { return pos_ == in_.size(); }

private:
    std::span<const std::uint8_t> in_;
    std::size_t pos_ = 0;
};

// How many values from `from` are zero: 64 at a time with memcmp (vectorised)
// while it can, as most of a station's memory is.
std::size_t zeros_from(std::span<const std::uint32_t> values, std::size_t from) {
    static constexpr std::uint32_t kZeroBlock[64] = {};
    std::size_t i = from;
    while (i + 64 <= values.size() && std::memcmp(values.data() + i, kZeroBlock, sizeof kZeroBlock) == 0) i += 64;
    while (i < values.size() && values[i] == 0) ++i;
    return i - from;
}

// Zero runs and literal runs: device memory is mostly zeros.
void write_values(Writer& w, std::span<const std::uint32_t> values) {
    std::size_t i = 0;
    while (i < values.size()) {
        std::size_t zeros = zeros_from(values, i);
        std::size_t literals = 0;
        while (i + zeros + literals < values.size() && values[i + zeros + literals] != 0) ++literals;
        w.u32(static_cast<std::uint32_t>(zeros));
        w.u32(static_cast<std::uint32_t>(literals));
        for (std::size_t k = 0; k < literals; ++k) w.u32(values[i + zeros + k]);
        i += zeros + literals;
    }
}

std::optional<std::vector<std::uint32_t>> read_values(Reader& r, std::uint32_t size) {
    std::vector<std::uint32_t> values;
    values.reserve(size);
    while (values.size() < size) {
        auto zeros = r.u32();
        auto literals = r.u32();
        if (!zeros || !literals || std::uint64_t{*zeros} + *literals > size - values.size()) return std::nullopt;
        values.insert(values.end(), *zeros, 0);
        for (std::uint32_t k = 0; k < *literals; ++k) {
            auto v = r.u32();
            if (!v) return std::nullopt;
            values.push_back(*v);
        }
    }
    return values;
}

struct SavedPart {
    const DeviceSpec* spec;
    std::vector<std::uint32_t> values;
};
struct SavedArea {
    Area area;
    std::uint32_t size;
    std::vector<SavedPart> parts;
};

}  // namespace

std::vector<std::uint8_t> encode_snapshot(const DeviceMemory& memory, std::string_view profile_name,
                                          SnapshotContents contents) {
    Writer w;
    w.out.insert(w.out.end(), std::begin(kMagic), std::end(kMagic));
    w.u32(kVersion);
    w.name(profile_name);
    std::vector<Area> areas;
    for (std::size_t i = 0; i < static_cast<std::size_t>(Area::Count); ++i)
        if (saved(static_cast<Area>(i), contents)) areas.push_back(static_cast<Area>(i));
    const bool labels = memory.label_area_words() > 0;
    w.u32(static_cast<std::uint32_t>(areas.size() + (labels ? 1 : 0)));
    for (auto area : areas) {
        auto size = area == Area::ZR ? std::max(memory.size(Area::ZR), memory.size(Area::R)) : memory.size(area);
        auto parts = stored_parts(area);
        w.name(area_name(area));
        w.u32(size);
        w.u8(static_cast<std::uint8_t>(parts.size()));
        for (const auto* part : parts) {
            w.u8(static_cast<std::uint8_t>(part->part));
            // One buffer a thread, reused: a fresh vector per area would cost
            // its pages again for every station of a plant (docs/plants.md).
            thread_local std::vector<std::uint32_t> buffer;
            if (buffer.size() < size) buffer.resize(size);
            std::span<std::uint32_t> values(buffer.data(), size);
            memory.read_part(*part, values);
            write_values(w, values);
        }
    }
    if (labels) {
        w.name(kLabelArea);
        w.u32(memory.label_area_words());
        w.u8(1);
        w.u8(static_cast<std::uint8_t>(Part::Plain));
        std::vector<std::uint32_t> values(memory.label_area_words());
        for (std::uint32_t n = 0; n < values.size(); ++n) values[n] = memory.label_word(n);
        write_values(w, values);
    }
    w.u64(fnv1a(w.out));
    return std::move(w.out);
}

RestoreResult restore_snapshot(std::span<const std::uint8_t> bytes, DeviceMemory& memory, std::string_view profile_name,
                               const LatchMap& latch, RestoreScope scope) {
    RestoreResult result;
    auto fail = [&](std::string why) {
        result.error = std::move(why);
        return result;
    };
    if (bytes.size() < sizeof kMagic + 12 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        return fail("not a slmp-sim snapshot (bad magic)");
    std::uint64_t stored = 0;
    for (int i = 0; i < 8; ++i) stored |= std::uint64_t{bytes[bytes.size() - 8 + static_cast<std::size_t>(i)]} << (8 * i);
    auto body = bytes.first(bytes.size() - 8);
    if (fnv1a(body) != stored) return fail("checksum mismatch (the file is damaged)");

    Reader r(body.subspan(sizeof kMagic));
    auto version = r.u32();
    if (!version || *version != kVersion) return fail("unsupported snapshot version");
    auto profile = r.name();
    if (!profile) return fail("truncated header");
    if (*profile != profile_name)
        return fail("it was saved by profile " + *profile + ", not " + std::string(profile_name));
    auto count = r.u32();
    if (!count) return fail("truncated header");

    // Decode everything before touching memory: a bad file changes nothing.
    std::vector<SavedArea> areas;
    std::optional<std::vector<std::uint32_t>> label_area;
    for (std::uint32_t a = 0; a < *count; ++a) {
        auto name = r.name();
        auto size = r.u32();
        auto parts = r.u8();
        if (!name || !size || !parts) return fail("truncated area header");
        auto area = area_by_name(*name);
        SavedArea saved_area{area.value_or(Area::Count), *size, {}};
        for (std::uint8_t p = 0; p < *parts; ++p) {
            auto part = r.u8();
            if (!part) return fail("truncated part header");
            auto values = read_values(r, *size);
            if (!values) return fail("truncated values of " + *name);
            const DeviceSpec* spec = nullptr;
            if (area)
                for (const auto* s : stored_parts(*area))
                    if (static_cast<std::uint8_t>(s->part) == *part) spec = s;
            if (spec) saved_area.parts.push_back({spec, std::move(*values)});
            else if (*name == kLabelArea) label_area = std::move(*values);
        }
        if (*name == kLabelArea) continue;
        if (!area) result.warnings.push_back("device area " + *name + " is unknown to this version; skipped");
        else areas.push_back(std::move(saved_area));
    }
    if (!r.done()) return fail("unexpected bytes after the last area");

    for (const auto& a : areas) {
        auto size = a.area == Area::ZR ? std::max(memory.size(Area::ZR), memory.size(Area::R)) : memory.size(a.area);
        if (size != a.size)
            result.warnings.push_back(std::string(area_name(a.area)) + " was saved with " + std::to_string(a.size) +
                                      " points and is now " + std::to_string(size) + "; the common part was restored");
        auto n_max = std::min(size, a.size);
        for (const auto& part : a.parts) {
            if (scope == RestoreScope::All) {
                memory.write_part(*part.spec, std::span(part.values).first(n_max));
                continue;
            }
            for (std::uint32_t n = 0; n < n_max; ++n)
                if (latch.latched(a.area, n)) memory.set_value(*part.spec, n, part.values[n]);
        }
    }
    // Labels are not latched (a VAR_GLOBAL label starts at 0 after a power
    // cycle), so only a full restore brings the label area back.
    if (label_area && scope == RestoreScope::All) {
        if (label_area->size() != memory.label_area_words())
            result.warnings.push_back("the label area was saved with " + std::to_string(label_area->size()) +
                                      " words and is now " + std::to_string(memory.label_area_words()) +
                                      " (labels were added or removed); the common part was restored");
        auto n_max = std::min<std::size_t>(label_area->size(), memory.label_area_words());
        for (std::uint32_t n = 0; n < n_max; ++n) memory.set_label_word(n, static_cast<std::uint16_t>((*label_area)[n]));
    }
    result.ok = true;
    return result;
}

}  // namespace slmp::devicemodel
