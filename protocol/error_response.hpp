// An error response: the end code, then the error information — the
// responding station's route and the failed request's command and
// subcommand (SLMP Reference Manual ch. 4; real-CPU measurements).
// Used by the engine and by scenario faults that force an end code, so both
// send the same bytes.
#pragma once

#include <cstdint>
#include <vector>

#include "protocol/end_code.hpp"
#include "protocol/frame.hpp"

namespace slmp::protocol {

std::vector<std::uint8_t> encode_error_response(const FrameHeader& request, std::uint16_t command,
                                                std::uint16_t subcommand, EndCode code);

}  // namespace slmp::protocol
