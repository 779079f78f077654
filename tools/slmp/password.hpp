// The remote password as the CLI accepts it (lock, unlock, --password).
#pragma once

#include <string>

#include "tools/slmp/errors.hpp"

namespace slmp::cli {

// Q/L CPUs use exactly 4 characters and iQ-R CPUs 6–32; the CLI does not know
// which CPU it talks to, so it takes 1–32 printable ASCII characters and lets
// the PLC judge the rest.
inline void check_password(const std::string& password) {
    if (password.empty() || password.size() > 32)
        throw UsageError("a remote password has 1..32 characters (Q/L: 4, iQ-R: 6..32)");
    for (unsigned char c : password)
        if (c < 0x21 || c > 0x7E) throw UsageError("a remote password is printable ASCII without spaces");
}

}  // namespace slmp::cli
