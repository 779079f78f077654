// Ondemand 2101 (docs/timing.md): the station reads the devices now and sends
// their words, unasked, to the clients the action names, in each client's own
// frame shape (protocol/ondemand.hpp).
#include <spdlog/spdlog.h>

#include "protocol/ondemand.hpp"
#include "station/station.hpp"

namespace slmp::station {

namespace {

bool wanted(const PushTarget& t, const std::string& to) {
    if (to == "all") return true;
    if (to == "tcp") return t.peer.transport == Transport::Tcp;
    if (to == "udp") return t.peer.transport == Transport::Udp;
    return t.peer.transport == Transport::Tcp && std::to_string(t.session) == to;
}

}  // namespace

std::vector<Station::Pushed> Station::ondemand(const scenarios::OndemandAction& action, const std::string& why) {
    const auto& spec = *action.first.spec;
    const auto name = devicemodel::format_address(action.first, cpu_.profile().numbering);
    if (!cpu_.memory().contains(spec.area, action.first.number, action.points))
        throw config::ConfigError("ondemand: " + name + " with " + std::to_string(action.points) + " point(s) runs past the " +
                                  std::string(devicemodel::area_name(spec.area)) + " size of " +
                                  std::to_string(cpu_.memory().size(spec.area)) + "; name devices inside it");
    const auto& to = action.to;
    if (to != "all" && to != "tcp" && to != "udp" && (to.empty() || to.find_first_not_of("0123456789") != std::string::npos))
        throw config::ConfigError("ondemand: unknown target '" + to + "'; use \"all\", \"tcp\", \"udp\" or a TCP connection id");
    const std::size_t words = spec.unit == devicemodel::Unit::Bit ? (action.points + 15) / 16
                                                                  : std::size_t{action.points} * devicemodel::words_per_device(spec);
    if (words > protocol::kOndemandMaxWords)
        throw config::ConfigError("ondemand: " + std::to_string(words) + " words; at most 960 words (1920 bytes) go in one push");
    std::vector<std::uint16_t> data(words);
    cpu_.memory().read_words(spec, action.first.number, data);

    std::vector<Pushed> sent;
    if (!transports_) return sent;
    for (auto& target : transports_->push_targets()) {
        if (!wanted(target, to)) continue;
        auto frame = protocol::encode_ondemand(target.kind, target.codec, data);
        activity_.pushed({target.session, target.peer, frame, why});
        sent.push_back({target.session, target.peer, frame});
        target.send(std::move(frame));
    }
    log_->info("Ondemand 2101 ({}): {} word(s) from {} to {} client(s)", why, words, name, sent.size());
    return sent;
}

}  // namespace slmp::station
