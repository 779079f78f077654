// One compared request as JSON (difference_json.hpp).
#include "scenarios/difference_json.hpp"

#include "devicemodel/hex.hpp"
#include "scenarios/recording.hpp"

namespace slmp::scenarios {

using nlohmann::json;
using protocol::differential::Observed;

json observed_json(const Observed& observed) {
    const bool answer = observed.kind == Observed::Kind::Answer;
    json time = nullptr;
    if (observed.time) time = static_cast<double>(observed.time->count()) / 1000.0;
    return json{{"kind", std::string(protocol::differential::kind_name(observed.kind))},
                {"end_code", answer ? json(devicemodel::hex4(observed.end_code)) : json(nullptr)},
                {"bytes", answer ? json(to_hex(observed.bytes)) : json(nullptr)},
                {"ms", time}};
}

json difference_json(const protocol::differential::Difference& difference, std::span<const std::uint8_t> request,
                     const std::string& a_name, const Observed& a, const std::string& b_name, const Observed& b) {
    return json{{"kind", std::string(protocol::differential::kind_name(difference.kind))},
                {"first_byte", difference.first_byte ? json(*difference.first_byte) : json(nullptr)},
                {"text", difference.text},
                {"request", to_hex(request)},
                {a_name, observed_json(a)},
                {b_name, observed_json(b)}};
}

}  // namespace slmp::scenarios
