// --plant-station NAME: the SLMP address of a plant's station, asked of the
// simulator's HTTP API (GET /api/stations/NAME on --api-port), so scripts
// name stations instead of keeping a port list (docs/plants.md).
#pragma once

#include <cstdint>
#include <string>

#include "tools/slmp/client.hpp"

namespace slmp::cli {

// Sets target.port (the station's first TCP port, or UDP with --udp) and, when
// the station listens on one address, target.host. Throws UsageError naming
// the station and the fix when the API cannot say.
void look_up_station(Target& target, const std::string& name, std::uint16_t api_port);

}  // namespace slmp::cli
