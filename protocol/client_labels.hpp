// Client-side builders and decoders for the label commands: Array Label
// Read/Write 041A/141A and Label Read/Write Random 041C/141B. Like the other
// client builders they write through build_request() and a FieldWriter, so
// the CLI and the tests send what the server decodes.
// Layouts: SLMP Reference Manual §5.3.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "devicemodel/label_types.hpp"
#include "protocol/client.hpp"

namespace slmp::protocol::client {

// 041C: read one point of each label.
std::vector<std::uint8_t> label_read_random(const FrameOptions& options, std::span<const std::string> names,
                                            std::span<const std::string> abbreviations = {});

// One value to write: its type decides how it travels (label_values.hpp).
struct LabelValue {
    devicemodel::BasicType type = devicemodel::BasicType::Word;
    std::vector<std::uint16_t> words;   // low word first; a bit is one word 0/1
};
struct LabelWrite {
    std::string name;
    LabelValue value;
};
// 141B: write data length = 2 × words.
std::vector<std::uint8_t> label_write_random(const FrameOptions& options, std::span<const LabelWrite> writes,
                                             std::span<const std::string> abbreviations = {});

struct ArrayRead {
    std::string name;          // the first element, e.g. "DDD[0]"
    bool bits = false;         // unit spec 0 (a bit label) or 1
    std::uint16_t length = 0;  // bits when `bits`, bytes otherwise
};
std::vector<std::uint8_t> array_label_read(const FrameOptions& options, std::span<const ArrayRead> reads,
                                           std::span<const std::string> abbreviations = {});

struct ArrayWrite {
    std::string name;
    devicemodel::BasicType type = devicemodel::BasicType::Word;
    std::vector<std::vector<std::uint16_t>> elements;   // each element's words (a bit: one word 0/1)
};
// 141A: bit labels travel with unit 0 (elements packed 16 a word), others with unit 1.
std::vector<std::uint8_t> array_label_write(const FrameOptions& options, std::span<const ArrayWrite> writes,
                                            std::span<const std::string> abbreviations = {});

// One entry of a 041A or 041C response: the type ID, the unit spec (041A) or
// spare (041C), the length, and the values, one element a vector.
struct LabelData {
    std::uint8_t type_id = 0;
    std::uint8_t unit = 0;
    std::uint16_t length = 0;
    std::vector<std::vector<std::uint16_t>> elements;
};
// `array`: a 041A response (the length counts bits under unit 0); 041C otherwise.
std::optional<std::vector<LabelData>> decode_label_read(const Response& response, bool array);

}  // namespace slmp::protocol::client
