// JSON text -> the server configuration loader, the plant loader (stations,
// templates, placeholders: config/plant_config.hpp) (and what the server then does
// with the result: profile, sizes, initial values, hardware, runtime
// parameters) and -> the profile parser. config/config.hpp promises that every
// mistake is a config::ConfigError; anything else escaping is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "config/plant_config.hpp"
#include "devicemodel/cpu.hpp"
#include "tests/fuzz/fuzz_check.hpp"

namespace {

using namespace slmp;

// A profile named by path would make the fuzzer read arbitrary files
// (/dev/zero never ends); only built-in names are followed.
bool builtin(const std::string& name) { return name.find('/') == std::string::npos && !name.ends_with(".json"); }

void use(const config::ServerConfig& c) {
    if (!builtin(c.profile)) return;
    devicemodel::Cpu cpu(config::resolve_profile(c).cpu);
    config::apply_initial_values(cpu, c);
    config::attach_hardware(cpu, c);
    cpu.runtime().configure(config::checked_runtime_config(c.cpu, cpu.profile()), cpu.memory());
    for (const auto& other : c.cpus) {
        if (!builtin(other.profile)) continue;
        devicemodel::Cpu more(config::resolve_profile(other).cpu);
        config::apply_initial_values(more, other.devices);
    }
}

template <class F>
void expect_config_errors_only(const char* what, F&& f) {
    try {
        f();
    } catch (const config::ConfigError&) {
        // The documented way to refuse input.
    } catch (const std::exception& e) {
        FUZZ_CHECK(false, "%s let a non-ConfigError escape: %s", what, e.what());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    expect_config_errors_only("parse_server_config", [&] { use(config::parse_server_config(text, "fuzz.json")); });
    expect_config_errors_only("parse_plant_config", [&] {
        auto plant = config::parse_plant_config(text, "fuzz.json", "");
        for (std::size_t k = 0; k < plant.stations.size() && k < 4; ++k) use(plant.stations[k].server);
    });
    expect_config_errors_only("parse_profile", [&] {
        auto profile = config::parse_profile(text, "fuzz-profile.json");
        devicemodel::Cpu cpu(profile.cpu);
    });
    return 0;
}
