// Device memory: native values (bits as bytes, 16-bit words, 32-bit long values)
// in one store per area, sized from the profile. Byte order and nibble packing
// exist only in the codec; here a word is a uint16_t.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_table.hpp"
#include "devicemodel/zero_page_arena.hpp"

namespace slmp::devicemodel {

// Told about every change to a DeviceMemory that has it attached (the HTTP
// API's change stream): a write that stores the value already there is not
// reported. Calls come per device; the observer coalesces them into runs.
// Detached (null) costs one branch per write.
class WriteObserver {
public:
    virtual void written(const DeviceSpec& spec, std::uint32_t first, std::uint32_t count) = 0;
    // A word of the label area changed (labels not assigned to a device).
    virtual void label_area_written(std::uint32_t index) { (void)index; }

protected:
    ~WriteObserver() = default;
};

// Devices [first, end) of one part.
struct DeviceRange {
    std::uint32_t first = 0;
    std::uint32_t end = 0;
};

class DeviceMemory {
public:
    // `slack_words` extra words are kept behind R/ZR so that iQ-R's start-only
    // range check can read and write past the configured end without touching
    // another area (real-CPU measurements: ZR163839 ×64 succeeds).
    explicit DeviceMemory(const DeviceSizes& sizes, std::uint32_t slack_words = 1024);
    // A copy holds the same values and costs RAM only for the pages that hold
    // something (zero_page_arena.hpp); the observer pointer is copied too.
    DeviceMemory(const DeviceMemory& other);
    DeviceMemory& operator=(const DeviceMemory& other);
    DeviceMemory(DeviceMemory&&) noexcept = default;
    DeviceMemory& operator=(DeviceMemory&&) noexcept = default;

    // Number of devices configured for an area (R counts its own size though it
    // shares ZR's storage).
    std::uint32_t size(Area area) const { return sizes_[static_cast<std::size_t>(area)]; }

    // Bit-unit access; `spec` must be a bit device (plain, contact or coil).
    bool bit(const DeviceSpec& spec, std::uint32_t number) const;
    void set_bit(const DeviceSpec& spec, std::uint32_t number, bool on);

    // Word-unit access, the view that 0401/1401 word units give:
    //  bit device   -> word i holds devices start+16i .. start+16i+15 (bit 0 lowest);
    //  word device  -> word i is device start+i;
    //  double word  -> words_per_device() words per device: value low, value high
    //                  (LTN/LSTN then a status word b0 coil b1 contact, and a system word).
    void read_words(const DeviceSpec& spec, std::uint32_t start, std::span<std::uint16_t> out) const;
    void write_words(const DeviceSpec& spec, std::uint32_t start, std::span<const std::uint16_t> in);

    // Single values by device number, for configuration and special registers.
    std::uint32_t value(const DeviceSpec& spec, std::uint32_t number) const;
    void set_value(const DeviceSpec& spec, std::uint32_t number, std::uint32_t value);

    // Bulk forms of value()/set_value() over devices [0, n) of one part (bits,
    // coils, contacts, values), for snapshots: an R08CPU restores in a few ms
    // instead of a million calls. write_part tells the observer of each change.
    void read_part(const DeviceSpec& spec, std::span<std::uint32_t> out) const { read_part(spec, 0, out); }
    void write_part(const DeviceSpec& spec, std::span<const std::uint32_t> values) { write_part(spec, 0, values); }
    // The same from device `first` on (devices past the store read 0, writes there are dropped).
    void read_part(const DeviceSpec& spec, std::uint32_t first, std::span<std::uint32_t> out) const;
    void write_part(const DeviceSpec& spec, std::uint32_t first, std::span<const std::uint32_t> values);

    // The devices of one part (bits, coils, contacts, values) that may hold a
    // non-zero value, ascending and disjoint; every other device reads 0.
    // Known from which pages of the store were ever touched, without reading
    // them (zero_page_arena.hpp), so snapshots, restores and clears of an idle
    // CPU neither read nor dirty its memory. Covers the whole store (for ZR
    // the slack behind it too).
    std::vector<DeviceRange> possibly_nonzero(const DeviceSpec& spec) const;
    // The same from touched_pages(), read once for many parts: a snapshot asks
    // for every part, and one question per part was most of a plant's start.
    std::vector<DeviceRange> possibly_nonzero(const DeviceSpec& spec, const std::vector<ByteRange>& touched_pages) const;
    std::vector<ByteRange> touched_pages() const { return arena_.touched(); }

    // Whether devices [start, start + count) exist (count in devices, not words).
    bool contains(Area area, std::uint64_t start, std::uint64_t count) const;

    void set_write_observer(WriteObserver* observer) { observer_ = observer; }

    // Raw planes for the program engine (program/execution.cpp), which fetches
    // them once per scan and indexes them itself: bit_plane holds the bits of a
    // bit area and the contacts of a timer/counter area, coil_plane the coils,
    // value_plane word, double-word and current values (R: ZR's store). Empty
    // where the area has no such plane. A writer through these tells the
    // observer itself: notify() when observed().
    std::span<std::uint8_t> bit_plane(Area area) { return store(area).bits; }
    std::span<std::uint8_t> coil_plane(Area area) { return store(area).coils; }
    std::span<std::uint32_t> value_plane(Area area) { return store(area).values; }
    std::span<const std::uint8_t> bit_plane(Area area) const { return store(area).bits; }
    std::span<const std::uint8_t> coil_plane(Area area) const { return store(area).coils; }
    std::span<const std::uint32_t> value_plane(Area area) const { return store(area).values; }
    bool observed() const { return observer_ != nullptr; }
    void notify(const DeviceSpec& spec, std::uint32_t first, std::uint32_t count) {
        if (observer_) observer_->written(spec, first, count);
    }

    // The label area: words the CPU owns for global labels that are not
    // assigned to a device (devicemodel/labels.hpp lays them out). It lives
    // here, beside the devices, so that snapshots and persistence save and
    // restore labels with the rest of memory. Not reachable by any device code.
    std::uint32_t label_area_words() const { return static_cast<std::uint32_t>(label_area_.size()); }
    void resize_label_area(std::uint32_t words) { label_area_.resize(words, 0); }
    std::uint16_t label_word(std::uint32_t index) const { return index < label_area_.size() ? label_area_[index] : 0; }
    void set_label_word(std::uint32_t index, std::uint16_t value) {
        if (index >= label_area_.size() || label_area_[index] == value) return;
        label_area_[index] = value;
        if (observer_) observer_->label_area_written(index);
    }

    // Same sizes and every stored value the same; the observer is not compared.
    // A copy and this make a cheap before/after snapshot (fuzz_http checks that
    // a refused request wrote nothing).
    // Compares only the pages touched in either (zero_page_arena.hpp).
    bool operator==(const DeviceMemory& other) const;

private:
    std::vector<DeviceRange> nonzero_in_pages(const DeviceSpec& spec, const std::vector<ByteRange>* touched_pages) const;
    // Device memory only costs RAM where it is used (docs/plants.md, "Memory"):
    // every store is a slice of one ZeroPageArena, whose pages stay the
    // kernel's zero page until written, whatever the heap's state.
    struct Store {
        std::span<std::uint8_t> bits;      // plain bit areas; contacts of T/C areas
        std::span<std::uint8_t> coils;     // T/C areas only
        std::span<std::uint32_t> values;   // word areas (low 16 bits), LZ, T/C current values
    };
    Store& store(Area area);
    const Store& store(Area area) const;
    static Area storage_area(Area area) { return area == Area::R ? Area::ZR : area; }

    DeviceSizes sizes_;
    ZeroPageArena arena_;
    std::vector<Store> stores_;   // slices of arena_
    std::vector<std::uint16_t> label_area_;
    WriteObserver* observer_ = nullptr;
};

}  // namespace slmp::devicemodel
