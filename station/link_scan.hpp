// The cyclic link devices of a plant's networks (docs/plants.md, "Link
// devices"): a station with a module on a network sends its send ranges of
// LB/LW (J□\B, J□\W) to every other station of that network at the END of
// each of its scans — its link scan — so J1\W100 written at one station is
// seen at the others. A range travels when it changed since the last link
// scan; each receiver's link devices are written on the receiver's strand.
#pragma once

#include <cstdint>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/device_table.hpp"

namespace slmp::station {

class NetworkMap;
class Station;

class LinkScan {
public:
    // `self`'s send ranges (its "networks" entries with a station No.) and
    // the stations of each network, from the plant's network map.
    LinkScan(Station& self, const NetworkMap& map, const std::vector<config::NetworkConfig>& networks);
    bool empty() const { return sends_.empty(); }
    // After each END of `self`'s scan, on its strand.
    void scanned();

private:
    struct Send {
        std::uint16_t network = 0;
        const devicemodel::DeviceSpec* spec = nullptr;   // B or W
        std::uint32_t first = 0;
        std::uint32_t words = 0;                          // B: 16 points a word
        std::vector<Station*> to;
        std::vector<std::uint16_t> last;                  // what the last link scan sent
        bool sent = false;
    };
    Station& self_;
    std::vector<Send> sends_;
};

}  // namespace slmp::station
