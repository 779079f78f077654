// The one error type of the configuration: its message names the file, the key
// (as a JSON pointer) or the option, and the fix. Include this header alone
// where only the error is caught or thrown; config/config.hpp has the rest.
#pragma once

#include <stdexcept>

namespace slmp::config {

struct ConfigError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace slmp::config
