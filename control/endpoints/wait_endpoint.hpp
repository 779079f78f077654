// Waiting for a value (docs/api.md, "Waiting for a value"): the query of a
// wait (equals, not_equals, greater, less or changes, and timeout_ms), and the
// deferred answer: 200 as soon as the condition holds, 408 with the last value
// when timeout_ms runs out. The device endpoint is one user
// (GET /api/devices/{address}/wait); anything else that reads one value can
// offer the same wait by building a WaitTarget — e.g. a label endpoint,
// GET /api/labels/{name}/wait, with a target that reads the label.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "control/endpoints/api.hpp"

namespace slmp::control {

struct WaitTarget {
    std::string name;                       // "D100", a label's name: for the answer and messages
    nlohmann::json fields;                  // extra keys of the answer ({"device": "D100", "as": "words"})
    std::function<std::uint32_t()> read;    // the value now, as GET shows it
    // A query value ("5", "-1", "true") as a raw value comparable with read();
    // throws ApiError (400) naming the accepted range.
    std::function<std::uint32_t(const std::string& text)> parse;
};

// The query parameters every wait takes (besides the target's own, e.g. "as").
inline const std::vector<std::string> kWaitParameters = {"equals", "not_equals", "greater", "less", "changes",
                                                          "timeout_ms"};

// Checks the query (400 naming the fix) and answers now when the condition
// already holds, else returns a deferred reply that the HTTP server awaits.
Reply wait_reply(Api& api, WaitTarget target, const ApiRequest& request);

}  // namespace slmp::control
