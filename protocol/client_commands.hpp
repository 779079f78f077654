// Client-side builders and decoders for the commands beyond batch read/write:
// random read/write (0403/1402), remote control (1001–1006), remote password
// (1630/1631), Read Type Name (0101), Self Test (0619), and the error
// information block of an error response. Like client.hpp, every request goes
// through build_request() and a FieldWriter, so binary and ASCII are written once
// and the tests, slmp-bench and the slmp CLI send exactly the same bytes.
// Layouts: SLMP Reference Manual §5.2,
//          SLMP Reference Manual ch. 5, §5.6, §5.7, §5.9.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "protocol/client.hpp"

namespace slmp::protocol::client {

// --- Random read / write -------------------------------------------------------

// 0403, subcommand 0000 (Q form) or 0002 (iQ-R form): word-access devices first,
// then double-word-access devices. The response holds one word per word device,
// then one double word per double-word device.
std::vector<std::uint8_t> read_random(const FrameOptions& options, std::span<const devicemodel::DeviceAddress> words,
                                      std::span<const devicemodel::DeviceAddress> dwords,
                                      DeviceForm form = DeviceForm::Q);

struct WordWrite {
    devicemodel::DeviceAddress device;
    std::uint16_t value = 0;
};
struct DwordWrite {
    devicemodel::DeviceAddress device;
    std::uint32_t value = 0;
};
struct BitWrite {
    devicemodel::DeviceAddress device;
    bool on = false;
};

// 1402, subcommand 0000/0002: word and double-word writes in one request.
std::vector<std::uint8_t> write_random_words(const FrameOptions& options, std::span<const WordWrite> words,
                                             std::span<const DwordWrite> dwords, DeviceForm form = DeviceForm::Q);
// 1402, subcommand 0001/0003: set/reset is one byte ("00"/"01") in the Q form and
// a word ("0000"/"0001") in the iQ-R form.
std::vector<std::uint8_t> write_random_bits(const FrameOptions& options, std::span<const BitWrite> bits,
                                            DeviceForm form = DeviceForm::Q);

// --- Remote control ------------------------------------------------------------

// Mode of 1001/1003: 0001 runs/pauses only when no other client holds a remote
// STOP/PAUSE; 0003 forces it.
enum class RemoteMode : std::uint16_t { Normal = 0x0001, Force = 0x0003 };
// Clear mode of 1001: which devices are initialised before RUN.
enum class ClearMode : std::uint8_t { None = 0x00, NonLatch = 0x01, All = 0x02 };

std::vector<std::uint8_t> remote_run(const FrameOptions& options, RemoteMode mode, ClearMode clear);
std::vector<std::uint8_t> remote_stop(const FrameOptions& options);
std::vector<std::uint8_t> remote_pause(const FrameOptions& options, RemoteMode mode);
std::vector<std::uint8_t> remote_latch_clear(const FrameOptions& options);
std::vector<std::uint8_t> remote_reset(const FrameOptions& options);

// --- Remote password -----------------------------------------------------------

// 1630 Unlock / 1631 Lock: length word, then the password as raw characters in
// both codecs.
std::vector<std::uint8_t> unlock(const FrameOptions& options, std::string_view password);
std::vector<std::uint8_t> lock(const FrameOptions& options, std::string_view password);

// --- Read Type Name, Self Test -------------------------------------------------

std::vector<std::uint8_t> read_type_name(const FrameOptions& options);
// 0619: loopback data count, then the data as raw characters.
std::vector<std::uint8_t> self_test(const FrameOptions& options, std::string_view data);

struct TypeName {
    std::string model;          // trailing spaces removed
    std::uint16_t model_code = 0;
};
std::optional<TypeName> decode_type_name(const Response& response);
// The echoed loopback data, or nullopt when the count and the data disagree.
std::optional<std::string> decode_self_test(const Response& response);

// --- Error responses -----------------------------------------------------------

// The 9-byte error information after a non-zero end code: the responding
// station's route, then the command and subcommand of the failed request.
struct ErrorInfo {
    Route route;
    std::uint16_t command = 0;
    std::uint16_t subcommand = 0;
};
std::optional<ErrorInfo> decode_error_info(const Response& response);

}  // namespace slmp::protocol::client
