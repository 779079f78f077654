// One compared request as JSON, the one shape GET /api/compare (slmp-sim
// --compare) and slmp-replay --json both write (docs/twin.md, "Compare"):
//   {"kind": "end_code", "first_byte": 9, "text": "end code 0000, 12 bytes vs end code C051, 11 bytes",
//    "request": "500000ff…", "<a>": {"kind": "answer", "end_code": "0000", "bytes": "d00000ff…", "ms": 0.312},
//    "<b>": {"kind": "silence", "end_code": null, "bytes": null, "ms": null}}
// with <a>/<b> "upstream"/"twin" or "recorded"/"now". Bytes are lower-case
// hex as in recordings; "ms" is null where no time was measured.
#pragma once

#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "protocol/differential.hpp"

namespace slmp::scenarios {

nlohmann::json observed_json(const protocol::differential::Observed& observed);

nlohmann::json difference_json(const protocol::differential::Difference& difference, std::span<const std::uint8_t> request,
                               const std::string& a_name, const protocol::differential::Observed& a,
                               const std::string& b_name, const protocol::differential::Observed& b);

// {"close": 0, "silence": 1, "end_code": 0, "bytes": 2, "time": 0}: every kind, counted by `count(kind)`.
template <class Count>
nlohmann::json kinds_json(Count count) {
    nlohmann::json kinds = nlohmann::json::object();
    for (auto kind : protocol::differential::kDifferenceKinds)
        kinds[std::string(protocol::differential::kind_name(kind))] = count(kind);
    return kinds;
}

}  // namespace slmp::scenarios
