// How the slmp CLI fails, and the exit status each failure gives (docs/cli.md):
//   0 success, 1 the PLC answered an error end code, 2 usage error,
//   3 connection failure, timeout or a response that is not a valid answer.
#pragma once

#include <stdexcept>
#include <string>

#include "protocol/client_commands.hpp"

namespace slmp::cli {

enum ExitCode : int { kOk = 0, kEndCode = 1, kUsage = 2, kConnection = 3 };

// Bad command line: unknown subcommand, bad address, value out of range, ...
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Could not connect, no answer in time, connection closed, or bytes that are not
// the answer to our request.
struct ConnectionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// slmp diff: the two servers answered differently (exit status 1, as an end code).
struct DifferenceError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// The PLC answered with a non-zero end code.
struct EndCodeError : std::runtime_error {
    EndCodeError(std::uint16_t code, std::optional<protocol::client::ErrorInfo> info, const std::string& message)
        : std::runtime_error(message), end_code(code), error_info(info) {}
    std::uint16_t end_code;
    std::optional<protocol::client::ErrorInfo> error_info;
};

}  // namespace slmp::cli
