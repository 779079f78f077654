// --plant-station NAME: the SLMP address of a plant's station, asked of the
// simulator's HTTP API (GET /api/stations/NAME on --api-port), so scripts
// name stations instead of keeping a port list (docs/plants.md).
#pragma once

#include <cstdint>
#include <string>

#include "devicemodel/device_table.hpp"
#include "tools/slmp/client.hpp"

namespace slmp::cli {

// Sets target.port (the station's first TCP port, or UDP with --udp), when
// the station listens on one address target.host, and for an iQ-F station
// octal X/Y numbering. Throws UsageError naming the station and the fix when
// the API cannot say.
void look_up_station(Target& target, devicemodel::Numbering& numbering, const std::string& name,
                     std::uint16_t api_port);

}  // namespace slmp::cli
