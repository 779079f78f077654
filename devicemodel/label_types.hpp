// Global label data types: the basic types with their SLMP data type IDs, the
// timer/counter family (structures with members S, C, N), user-defined
// structures, and their names as GX Works3 writes them (with the IEC short
// names as aliases). Sizes are in 16-bit words of the store a label lives in.
// Source: SLMP Reference Manual §5.3.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slmp::devicemodel {

// The value is the data type ID that 041A/041C answer (§2.4).
enum class BasicType : std::uint8_t {
    Bit = 1,
    UWord = 2,     // Word [Unsigned]/Bit String [16-bit]
    UDWord = 3,    // Double Word [Unsigned]/Bit String [32-bit]
    Word = 4,      // Word [Signed]
    DWord = 5,     // Double Word [Signed]
    Real = 6,      // FLOAT [Single Precision]
    LReal = 7,     // FLOAT [Double Precision]
    Time = 8,      // signed 32-bit milliseconds
    String = 9,    // String(n): n bytes + NUL, padded to a whole word
    WString = 10,  // String [Unicode](n): n UTF-16 units + NUL unit
};

enum class TimerKind : std::uint8_t { Timer, Counter, RetentiveTimer, LongTimer, LongCounter, LongRetentiveTimer };

// Long timer/counter types keep a 32-bit current value (§2.3).
constexpr bool is_long(TimerKind k) {
    return k == TimerKind::LongTimer || k == TimerKind::LongCounter || k == TimerKind::LongRetentiveTimer;
}

struct StructType;

struct LabelType {
    enum class Kind : std::uint8_t { Basic, Timer, Struct };
    Kind kind = Kind::Basic;
    BasicType basic = BasicType::Word;
    std::uint16_t chars = 0;                 // String/WString: the defined number of characters
    TimerKind timer = TimerKind::Timer;
    const StructType* structure = nullptr;   // Kind::Struct
};

struct Member {
    std::string name;
    LabelType type;
    std::vector<std::uint32_t> dims;   // array sizes (lower bound 0), empty for a scalar
    std::uint32_t offset = 0;          // words from the start of the structure (laid out by LabelTable)
};

struct StructType {
    std::string name;
    std::vector<Member> members;
    std::uint32_t words = 0;           // size of one value of this structure
};

// Words one value of a basic type occupies. A lone Bit takes a word (bit 0);
// bit arrays pack 16 bits a word (storage_words).
std::uint32_t basic_words(BasicType type, std::uint16_t chars);
// The data length one value has on the wire, in bytes (§2.2, §2.10): 2 for a bit.
std::uint32_t data_bytes(BasicType type, std::uint16_t chars);
// Words one element of `type` occupies (a timer: value and a status word;
// long timers: two value words, status, a spare word, like LTN).
std::uint32_t element_words(const LabelType& type);
std::uint32_t element_count(const std::vector<std::uint32_t>& dims);
// Words `type` with `dims` occupies in a word store.
std::uint32_t storage_words(const LabelType& type, const std::vector<std::uint32_t>& dims);

struct ParsedType {
    LabelType type;
    std::vector<std::uint32_t> dims;
};
// "Word [Signed]", "INT", "String(32)", "STRING[32]", "Timer", "Word [Signed](0..19)",
// "Bit(0..1,0..19)", or a structure name that `find_structure` knows. Type
// names are matched without regard to case. On failure returns nullopt and
// says why in `error`.
std::optional<ParsedType> parse_label_type(std::string_view text,
                                           const std::function<const StructType*(std::string_view)>& find_structure,
                                           std::string* error);
// The GX Works3 name: "Word [Signed]", "String(32)", "Word [Signed](0..19)".
std::string format_label_type(const LabelType& type, const std::vector<std::uint32_t>& dims = {});
std::string_view timer_kind_name(TimerKind kind);

}  // namespace slmp::devicemodel
