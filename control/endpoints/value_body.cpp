#include "control/endpoints/value_body.hpp"

#include <charconv>

#include "control/endpoints/device_view.hpp"

namespace slmp::control {

using nlohmann::json;

std::uint64_t count_param(const ApiRequest& request) {
    const auto* text = request.param("count");
    if (!text) return 1;
    std::uint64_t count = 0;
    auto [ptr, ec] = std::from_chars(text->data(), text->data() + text->size(), count);
    if (ec != std::errc{} || ptr != text->data() + text->size())
        bad("count=" + *text + " is not a number; use 1 to " + std::to_string(kMaxValues));
    return count;
}

json parse_value_body(const std::string& body) {
    auto parsed = json::parse(body, nullptr, false);
    if (parsed.is_discarded())
        bad("the body is not valid JSON; send {\"values\": [1, 2, 3]} or {\"string\": \"text\"}");
    if (!parsed.is_object()) bad("the body must be a JSON object: {\"values\": [...]} or {\"string\": \"...\"}");
    for (const auto& [key, _] : parsed.items())
        if (key != "values" && key != "string")
            bad("unknown key \"" + key + "\" in the body; use \"values\" or \"string\"");
    if (parsed.contains("values") == parsed.contains("string"))
        bad("give either \"values\" or \"string\", not " + std::string(parsed.contains("values") ? "both" : "neither"));
    return parsed;
}

}  // namespace slmp::control
