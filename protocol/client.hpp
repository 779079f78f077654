// The client side of the protocol: build requests, split and decode responses.
// Used by the tests, slmp-bench and the slmp CLI; it shares the codec with the
// server so both speak exactly the same bytes.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "devicemodel/device_table.hpp"
#include "protocol/fields.hpp"
#include "protocol/frame.hpp"

namespace slmp::protocol::client {

struct FrameOptions {
    FrameKind kind = FrameKind::E3;
    Codec codec = Codec::Binary;
    std::uint16_t serial = 0;          // 4E only
    Route route{};
    std::uint16_t monitoring_timer = 0x0010;   // units of 250 ms
    devicemodel::Numbering numbering;   // the target CPU's: FX5 writes X/Y in octal in ASCII frames
};

// A request: header, monitoring timer, command, subcommand, then whatever `body` writes.
std::vector<std::uint8_t> build_request(const FrameOptions& options, std::uint16_t command, std::uint16_t subcommand,
                                        const std::function<void(FieldWriter&)>& body = {});

// Convenience builders for the batch commands. `form` picks 0000/0001 (Q) or 0002/0003 (iQ-R).
std::vector<std::uint8_t> read_words(const FrameOptions& options, const devicemodel::DeviceAddress& start,
                                     std::uint16_t points, DeviceForm form = DeviceForm::Q);
std::vector<std::uint8_t> read_bits(const FrameOptions& options, const devicemodel::DeviceAddress& start,
                                    std::uint16_t points, DeviceForm form = DeviceForm::Q);
std::vector<std::uint8_t> write_words(const FrameOptions& options, const devicemodel::DeviceAddress& start,
                                      std::span<const std::uint16_t> values, DeviceForm form = DeviceForm::Q);
std::vector<std::uint8_t> write_bits(const FrameOptions& options, const devicemodel::DeviceAddress& start,
                                     std::span<const std::uint8_t> values, DeviceForm form = DeviceForm::Q);

struct Response {
    FrameHeader header;
    std::uint16_t end_code = 0;
    std::vector<std::uint8_t> data;   // after the end code, still in the frame's codec
    std::size_t size = 0;             // bytes the frame took

    // A reader over `data`, for decoding read results in either codec.
    FieldReader reader() const { return FieldReader(header.codec, data); }
};

// Parses one response at the start of `bytes`; nullopt while it is incomplete
// or when the bytes are not a response frame (`garbage` is then set).
std::optional<Response> parse_response(std::span<const std::uint8_t> bytes, bool* garbage = nullptr);

}  // namespace slmp::protocol::client
