#include "station/link_scan.hpp"

#include <memory>

#include "station/network_map.hpp"
#include "station/station.hpp"

namespace slmp::station {

LinkScan::LinkScan(Station& self, const NetworkMap& map, const std::vector<config::NetworkConfig>& networks) : self_(self) {
    for (const auto& n : networks) {
        if (n.station == 0) continue;
        std::vector<Station*> to;
        auto members = map.networks().find(n.number);
        if (members != map.networks().end())
            for (const auto& m : members->second)
                if (m.station != &self) to.push_back(m.station);
        if (to.empty()) continue;
        for (const auto& range : n.send) {
            Send s;
            s.network = n.number;
            s.spec = range.spec;
            s.first = range.first;
            s.words = range.spec->unit == devicemodel::Unit::Bit ? range.count / 16 : range.count;
            s.to = to;
            sends_.push_back(std::move(s));
        }
    }
}

void LinkScan::scanned() {
    for (auto& s : sends_) {
        const auto* memory = self_.cpu().network(s.network);
        if (!memory) continue;
        std::vector<std::uint16_t> now(s.words);
        memory->read_words(*s.spec, s.first, now);
        if (s.sent && now == s.last) continue;
        s.last = now;
        s.sent = true;
        auto words = std::make_shared<const std::vector<std::uint16_t>>(std::move(now));
        for (auto* to : s.to)
            boost::asio::post(to->home(), [to, network = s.network, spec = s.spec, first = s.first, words] {
                if (auto* link = to->cpu().network(network)) link->write_words(*spec, first, *words);
            });
    }
}

}  // namespace slmp::station
