// JSON the parser itself refuses beyond syntax: a number too large for a
// double is nlohmann's out_of_range (406), not a parse_error. Found by
// tests/fuzz/fuzz_config; the loaders promise a ConfigError naming the file.
#include "support/fixtures.hpp"

#include "scenarios/loader.hpp"

using namespace slmp;

TEST_CASE("a number overflowing a double is a ConfigError naming the file", "[config]") {
    for (const std::string text : {"1E400", R"({"max_request_bytes": 1e999})", R"({"ports": [{"port": -1E400}]})"}) {
        CAPTURE(text);
        CHECK_THROWS_WITH(config::parse_server_config(text, "test.json"), Catch::Contains("test.json: not valid JSON"));
        CHECK_THROWS_AS(config::parse_profile(text, "p.json"), config::ConfigError);
        CHECK_THROWS_AS(scenarios::parse_scenario(text, "s.json"), config::ConfigError);
    }
}
