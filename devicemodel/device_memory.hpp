// Device memory: native values (bits as bytes, 16-bit words, 32-bit long values)
// in one store per area, sized from the profile. Byte order and nibble packing
// exist only in the codec; here a word is a uint16_t.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <new>
#include <span>
#include <utility>
#include <vector>

#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/device_table.hpp"

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

class DeviceMemory {
public:
    // `slack_words` extra words are kept behind R/ZR so that iQ-R's start-only
    // range check can read and write past the configured end without touching
    // another area (hardware-behaviour.md §6: ZR163839 ×64 succeeds).
    explicit DeviceMemory(const DeviceSizes& sizes, std::uint32_t slack_words = 1024);

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
    void read_part(const DeviceSpec& spec, std::span<std::uint32_t> out) const;
    void write_part(const DeviceSpec& spec, std::span<const std::uint32_t> values);

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
    bool operator==(const DeviceMemory& other) const {
        return sizes_ == other.sizes_ && stores_ == other.stores_ && label_area_ == other.label_area_;
    }

private:
    // Device memory only costs RAM where it is used (docs/plants.md, "Memory"):
    // stores come from calloc, whose large blocks are fresh zero pages the
    // kernel maps on first write, and resize() default-initialises (writes
    // nothing) instead of writing zeros over every page.
    template <class T>
    struct ZeroPages {
        using value_type = T;
        ZeroPages() = default;
        template <class U>
        ZeroPages(const ZeroPages<U>&) {}
        T* allocate(std::size_t n) {
            if (auto* p = static_cast<T*>(std::calloc(n, sizeof(T)))) return p;
            throw std::bad_alloc();
        }
        void deallocate(T* p, std::size_t) { std::free(p); }
        template <class U>
        void construct(U* p) { ::new (static_cast<void*>(p)) U; }
        template <class U, class... Args>
        void construct(U* p, Args&&... args) { ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...); }
        template <class U>
        bool operator==(const ZeroPages<U>&) const { return true; }
    };
    template <class T>
    using Pages = std::vector<T, ZeroPages<T>>;

    struct Store {
        Pages<std::uint8_t> bits;      // plain bit areas; contacts of T/C areas
        Pages<std::uint8_t> coils;     // T/C areas only
        Pages<std::uint32_t> values;   // word areas (low 16 bits), LZ, T/C current values
        bool operator==(const Store&) const = default;
    };
    Store& store(Area area);
    const Store& store(Area area) const;
    static Area storage_area(Area area) { return area == Area::R ? Area::ZR : area; }

    DeviceSizes sizes_;
    std::vector<Store> stores_;
    std::vector<std::uint16_t> label_area_;
    WriteObserver* observer_ = nullptr;
};

}  // namespace slmp::devicemodel
