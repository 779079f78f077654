#include "devicemodel/snapshot.hpp"

#include <algorithm>
#include <cstring>
#include <optional>

#include "devicemodel/byte_reader.hpp"

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

// How many values from `from` are zero: 64 at a time with memcmp (vectorised)
// while it can, as most of a station's memory is.
std::size_t zeros_from(std::span<const std::uint32_t> values, std::size_t from) {
    static constexpr std::uint32_t kZeroBlock[64] = {};
    std::size_t i = from;
    while (i + 64 <= values.size() && std::memcmp(values.data() + i, kZeroBlock, sizeof kZeroBlock) == 0) i += 64;
    while (i < values.size() && values[i] == 0) ++i;
    return i - from;
}

// Zero runs and literal runs, as the file holds them: each run is the count of
// zeros before it, then its non-zero values. Fed in ascending order and in
// pieces, so a part is read only where its pages were ever touched and the
// untouched rest is a count (DeviceMemory::possibly_nonzero).
class RunEncoder {
public:
    explicit RunEncoder(ByteWriter& w) : w_(w) {}
    void zeros(std::size_t n) {
        if (n == 0) return;
        if (literals_ > 0) close_literals();
        zeros_ += n;
    }
    void values(std::span<const std::uint32_t> values) {
        for (std::size_t i = 0; i < values.size();) {
            const auto z = zeros_from(values, i);
            zeros(z);
            for (i += z; i < values.size() && values[i] != 0; ++i) literal(values[i]);
        }
    }
    void finish() {
        if (literals_ > 0) close_literals();
        else if (zeros_ > 0) {
            w_.u32(static_cast<std::uint32_t>(zeros_));
            w_.u32(0);
        }
        zeros_ = 0;
    }

private:
    void literal(std::uint32_t v) {
        if (literals_ == 0) {
            w_.u32(static_cast<std::uint32_t>(zeros_));
            count_at_ = w_.out.size();
            w_.u32(0);   // the count, set when the run ends
        }
        ++literals_;
        w_.u32(v);
    }
    void close_literals() {
        w_.u32_at(count_at_, literals_);
        literals_ = 0;
        zeros_ = 0;
    }

    ByteWriter& w_;
    std::size_t zeros_ = 0;
    std::uint32_t literals_ = 0;
    std::size_t count_at_ = 0;
};

// One part of the memory, devices [0, size): only the devices that may be
// non-zero are read, in pieces of a thread's reused buffer (a buffer of the
// whole part would cost its pages again for every station of a plant).
void encode_part(ByteWriter& w, const DeviceMemory& memory, const DeviceSpec& part, std::uint32_t size,
                 const std::vector<ByteRange>& touched_pages) {
    thread_local std::vector<std::uint32_t> buffer(4096);
    RunEncoder runs(w);
    std::uint32_t at = 0;
    for (const auto& r : memory.possibly_nonzero(part, touched_pages)) {
        const auto end = std::min(r.end, size);
        if (r.first >= end) continue;
        runs.zeros(r.first - at);
        for (at = r.first; at < end;) {
            const auto n = std::min<std::size_t>(buffer.size(), end - at);
            std::span<std::uint32_t> piece(buffer.data(), n);
            memory.read_part(part, at, piece);
            runs.values(piece);
            at += static_cast<std::uint32_t>(n);
        }
    }
    runs.zeros(size - at);
    runs.finish();
}

// A part as the file holds it: its literal runs (ascending); every other
// device is 0. Decoding to this, not to a vector of the whole part, keeps a
// restore's memory to what the file holds.
struct SparseValues {
    struct Run {
        std::uint32_t first;
        std::uint32_t count;
        std::size_t at;   // in values
    };
    std::vector<Run> runs;
    std::vector<std::uint32_t> values;
};

std::optional<SparseValues> read_values(ByteReader& r, std::uint32_t size) {
    SparseValues out;
    std::uint32_t position = 0;
    while (position < size) {
        auto zeros = r.u32();
        auto literals = r.u32();
        if (!zeros || !literals || std::uint64_t{*zeros} + *literals > size - position) return std::nullopt;
        if (*zeros == 0 && *literals == 0) return std::nullopt;   // would never end
        position += *zeros;
        if (*literals > 0) out.runs.push_back({position, *literals, out.values.size()});
        for (std::uint32_t k = 0; k < *literals; ++k) {
            auto v = r.u32();
            if (!v) return std::nullopt;
            out.values.push_back(*v);
        }
        position += *literals;
    }
    return out;
}

// Devices [0, n_max) where the memory or the file may hold a non-zero value,
// ascending, in pieces: put(first, values) with the file's values of a piece
// (zeros where the file has none). Everywhere else both are 0 already, so a
// restore neither reads nor writes an untouched page.
template <class Put>
void for_each_saved_piece(const DeviceMemory& memory, const DeviceSpec& spec, const SparseValues& saved,
                          std::uint32_t n_max, Put&& put) {
    static constexpr std::uint32_t kZeros[1024] = {};
    std::vector<ByteRange> live, in_file;
    for (const auto& r : memory.possibly_nonzero(spec)) live.push_back({r.first, r.end});
    for (const auto& run : saved.runs) in_file.push_back({run.first, std::size_t{run.first} + run.count});
    std::size_t k = 0;
    for (const auto& segment : merge_ranges(live, in_file)) {
        auto at = static_cast<std::uint32_t>(std::min<std::size_t>(segment.begin, n_max));
        const auto end = static_cast<std::uint32_t>(std::min<std::size_t>(segment.end, n_max));
        while (at < end) {
            while (k < saved.runs.size() && saved.runs[k].first + saved.runs[k].count <= at) ++k;
            if (k < saved.runs.size() && saved.runs[k].first <= at) {
                const auto& run = saved.runs[k];
                const auto n = std::min(end, run.first + run.count) - at;
                put(at, std::span(saved.values).subspan(run.at + (at - run.first), n));
                at += n;
            } else {
                const auto next = k < saved.runs.size() ? std::min(end, saved.runs[k].first) : end;
                const auto n = std::min<std::uint32_t>(next - at, std::size(kZeros));
                put(at, std::span<const std::uint32_t>(kZeros, n));
                at += n;
            }
        }
    }
}

struct SavedPart {
    const DeviceSpec* spec;
    SparseValues values;
};
struct SavedArea {
    Area area;
    std::uint32_t size;
    std::vector<SavedPart> parts;
};

}  // namespace

std::vector<std::uint8_t> encode_snapshot(const DeviceMemory& memory, std::string_view profile_name,
                                          SnapshotContents contents) {
    ByteWriter w;
    w.out.insert(w.out.end(), std::begin(kMagic), std::end(kMagic));
    w.u32(kVersion);
    w.name(profile_name);
    std::vector<Area> areas;
    for (std::size_t i = 0; i < static_cast<std::size_t>(Area::Count); ++i)
        if (saved(static_cast<Area>(i), contents)) areas.push_back(static_cast<Area>(i));
    const bool labels = memory.label_area_words() > 0;
    const auto touched_pages = memory.touched_pages();
    w.u32(static_cast<std::uint32_t>(areas.size() + (labels ? 1 : 0)));
    for (auto area : areas) {
        auto size = area == Area::ZR ? std::max(memory.size(Area::ZR), memory.size(Area::R)) : memory.size(area);
        auto parts = stored_parts(area);
        w.name(area_name(area));
        w.u32(size);
        w.u8(static_cast<std::uint8_t>(parts.size()));
        for (const auto* part : parts) {
            w.u8(static_cast<std::uint8_t>(part->part));
            encode_part(w, memory, *part, size, touched_pages);
        }
    }
    if (labels) {
        w.name(kLabelArea);
        w.u32(memory.label_area_words());
        w.u8(1);
        w.u8(static_cast<std::uint8_t>(Part::Plain));
        std::vector<std::uint32_t> values(memory.label_area_words());
        for (std::uint32_t n = 0; n < values.size(); ++n) values[n] = memory.label_word(n);
        RunEncoder runs(w);
        runs.values(values);
        runs.finish();
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
    auto stored = *ByteReader(bytes.last(8)).u64();
    auto body = bytes.first(bytes.size() - 8);
    if (fnv1a(body) != stored) return fail("checksum mismatch (the file is damaged)");

    ByteReader r(body.subspan(sizeof kMagic));
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
    std::optional<SparseValues> label_area;
    std::uint32_t label_area_size = 0;
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
            else if (*name == kLabelArea) {
                label_area = std::move(*values);
                label_area_size = *size;
            }
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
            for_each_saved_piece(memory, *part.spec, part.values, n_max,
                                 [&](std::uint32_t first, std::span<const std::uint32_t> values) {
                if (scope == RestoreScope::All) return memory.write_part(*part.spec, first, values);
                for (std::uint32_t i = 0; i < values.size(); ++i)
                    if (latch.latched(a.area, first + i)) memory.set_value(*part.spec, first + i, values[i]);
            });
        }
    }
    // Labels are not latched (a VAR_GLOBAL label starts at 0 after a power
    // cycle), so only a full restore brings the label area back.
    if (label_area && scope == RestoreScope::All) {
        if (label_area_size != memory.label_area_words())
            result.warnings.push_back("the label area was saved with " + std::to_string(label_area_size) +
                                      " words and is now " + std::to_string(memory.label_area_words()) +
                                      " (labels were added or removed); the common part was restored");
        const auto n_max = std::min(label_area_size, memory.label_area_words());
        std::vector<std::uint32_t> words(n_max);   // the label area is small: words of the common part
        for (const auto& run : label_area->runs)
            for (std::uint32_t i = 0; i < run.count && run.first + i < n_max; ++i) words[run.first + i] = label_area->values[run.at + i];
        for (std::uint32_t n = 0; n < n_max; ++n) memory.set_label_word(n, static_cast<std::uint16_t>(words[n]));
    }
    result.ok = true;
    return result;
}

}  // namespace slmp::devicemodel
