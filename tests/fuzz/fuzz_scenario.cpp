// JSON text -> the scenario loader (scenarios/loader.hpp), alone and checked
// together with a shipped example. Its documented error is config::ConfigError;
// anything else escaping is a finding.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>
#include <vector>

#include "config/config_error.hpp"
#include "scenarios/loader.hpp"
#include "tests/fuzz/fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        auto scenario = slmp::scenarios::parse_scenario(text, "fuzz.json");
        slmp::scenarios::check_together({scenario});
        slmp::scenarios::check_together({scenario, scenario});   // duplicate ids must be a ConfigError
    } catch (const slmp::config::ConfigError&) {
        // The documented way to refuse input.
    } catch (const std::exception& e) {
        FUZZ_CHECK(false, "the scenario loader let a non-ConfigError escape: %s", e.what());
    }
    return 0;
}
