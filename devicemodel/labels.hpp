// Global labels of a CPU: declarations laid out on device memory, name
// resolution ("Tank1.Level", "Recipe[3].Speed", "A[1,2]", "T1.N", "%1.led[2]")
// and element access. A label either is assigned to a device (its data is that
// device's data: writing the label and reading D1000 agree) or lives in the
// label area of DeviceMemory, which snapshots save with the devices.
// Knows no wire protocol; the SLMP commands are protocol/commands/labels.cpp.
// Source: SLMP Reference Manual §5.3.
//
// Layout in a word store (the label area, or a word device such as D):
//   basic types: basic_words() words, 32/64-bit values low word first;
//   a lone Bit: bit 0 of a word; bit arrays: 16 elements a word from bit 0;
//   String(n): bytes from the low byte of the first word, NUL-terminated;
//   Timer/Counter/Retentive Timer: [N][status b0 = S, b1 = C];
//   Long types: [N low][N high][status][spare];
//   structures: members in declaration order, each at its own word offset.
// Assigned to a device: Bit labels (and bit arrays) take one bit device an
// element; timer-family labels take one device of their family (T, ST, C, LT,
// LST, LC) an element, S/C/N being its contact, coil and current value.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devicemodel/device_memory.hpp"
#include "devicemodel/device_table.hpp"
#include "devicemodel/label_types.hpp"

namespace slmp::devicemodel {

struct LabelDecl {
    std::string name;
    LabelType type;
    std::vector<std::uint32_t> dims;
    bool external = true;                  // "Access from External Device" (slmp-sim: on unless declared off)
    std::optional<DeviceAddress> device;   // assigned device, or allocated in the label area
};

struct Label : LabelDecl {
    std::uint32_t area_offset = 0;         // word offset in the label area (no device)
    std::uint32_t words = 0;               // storage_words(type, dims)
};

// A declaration mistake: what is wrong and how to fix it (config/ adds the file and key).
struct LabelProblem {
    std::string problem;
    std::string fix;
};

// Where one element lives.
struct LabelCell {
    enum class Kind : std::uint8_t {
        Words,       // words from `at` in the label area (spec null) or a word device
        BitInWord,   // bit number `at` (word × 16 + bit) of the label area or a word device
        Bit,         // bit device `spec` number `at` (M100, TS5, ...)
        Value,       // current value of timer device `spec` number `at` (16 or 32 bits)
    };
    Kind kind = Kind::Words;
    const DeviceSpec* spec = nullptr;
    std::uint64_t at = 0;
};

// Why a name does not resolve. Every one of them is "this label cannot be
// reached by that name" to a client (protocol/commands/labels.cpp: 40C0).
enum class LabelFault : std::uint8_t {
    None,
    NotFound,         // no global label of that name, or no such member
    NotExternal,      // "Access from External Device" is off
    BadName,          // syntax, forbidden form (§2.3), wrong number of indexes
    IndexOutOfRange,  // an element index past the array's declared size
    NotALeaf,         // names a structure or timer, not a member of basic type
};
std::string_view describe(LabelFault fault);

// A name resolved to one element of basic type.
struct LabelRef {
    const Label* label = nullptr;
    BasicType basic = BasicType::Word;
    std::uint16_t chars = 0;
    bool timer_member = false;        // S/C/N of a timer-family label (041A/141A refuse these)
    unsigned array_dims = 0;          // dimensions of the array the element belongs to (0: not an array)
    std::uint32_t elements = 1;       // this element and the ones after it, to the end of its array
    LabelCell first;                  // the named element
    std::uint32_t stride = 0;         // words from one element to the next (Words cells)
};

class LabelTable {
public:
    // Structures must be added before the labels and structures that use them.
    std::optional<LabelProblem> add_structure(StructType type);
    const StructType* structure(std::string_view name) const;
    // Checks the name, the type, the device (kind, range against `memory`'s
    // sizes, overlap with other assigned labels).
    std::optional<LabelProblem> add_label(LabelDecl decl, const DeviceMemory& memory);
    // Lays the unassigned labels out in the label area and sizes it.
    std::optional<LabelProblem> allocate(DeviceMemory& memory);

    const std::vector<Label>& labels() const { return labels_; }
    const Label* find(std::string_view name) const;
    bool empty() const { return labels_.empty(); }

    const std::deque<StructType>& structures() const { return structures_; }

    // `name` as a client sends it, after abbreviation: the registered
    // prefixes replace whole units "%1", "%2", ... (§2.3). Fills `fault` on
    // failure. `external_only`: SLMP clients reach only labels with "Access
    // from External Device"; the simulator's own API reaches every label.
    std::optional<LabelRef> resolve(std::string_view name, std::span<const std::string> abbreviations,
                                    LabelFault& fault, bool external_only = true) const;

private:
    std::deque<StructType> structures_;   // stable addresses: LabelType points at them
    std::vector<Label> labels_;
    std::map<std::string, std::size_t, std::less<>> by_name_;
};

// The element `index` places after `ref.first` (0 is the named one).
LabelCell element_cell(const LabelRef& ref, std::uint32_t index);
// One element's data as the wire carries it, in words: a bit is one word 0/1;
// 32/64-bit values low word first; strings two bytes a word, low byte first.
std::vector<std::uint16_t> read_element(const DeviceMemory& memory, const LabelRef& ref, std::uint32_t index);
void write_element(DeviceMemory& memory, const LabelRef& ref, std::uint32_t index, std::span<const std::uint16_t> data);

// A label name as config and CLI accept it: GX Works3's rules (letters,
// digits, '_', not starting with a digit, not a device name). Returns why not.
std::optional<std::string> check_label_name(std::string_view name);

}  // namespace slmp::devicemodel
