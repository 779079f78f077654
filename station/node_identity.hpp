// What a station reports as an SLMP-compatible device before any IP Address
// Set (0E31) changes it: derived from its configuration, so a plant's stations
// differ and a restart reports the same (docs/nodes.md, "Identity").
#pragma once

#include "config/config.hpp"
#include "devicemodel/cpu_profile.hpp"
#include "devicemodel/node.hpp"

namespace slmp::station {

// Host name: the station's name, "slmp-sim" for an unnamed single station.
// MAC: 02:00 (locally administered, unicast) and the 32-bit FNV-1a hash of
// "<host name>:<first port>", high octet first. IP: the bind address when it
// is one IPv4 address, else 127.0.0.1; mask 255.255.255.0, no gateway.
// Model code: the profile's; vendor code 0000, version 0001 (inferred).
devicemodel::NodeIdentity node_identity(const config::ServerConfig& config, const devicemodel::CpuProfile& profile);

}  // namespace slmp::station
