// Differential mode's report (comparison.hpp; docs/twin.md, "Compare").
#include "station/comparison.hpp"

#include "devicemodel/hex.hpp"

namespace slmp::station {

using protocol::differential::DifferenceKind;

protocol::differential::Difference Comparison::add(ComparedRequest compared) {
    compared.number = ++compared_;
    compared.difference = protocol::differential::classify(compared.upstream, compared.twin, slack_);
    const auto& d = compared.difference;
    ++by_kind_[static_cast<std::size_t>(d.kind)];
    if (d.same()) return d;
    // One line a difference, the upstream's side first: "upstream vs twin".
    log_.warn("compare: #{} {}/{} from {}: {}: upstream vs twin: {}; request {}", compared.number,
              devicemodel::hex4(compared.command), devicemodel::hex4(compared.subcommand), compared.peer.text(),
              protocol::differential::kind_name(d.kind), d.text, devicemodel::bytes_to_hex(compared.request));
    auto difference = d;
    kept_.push_back(std::move(compared));
    if (kept_.size() > kKept) kept_.pop_front();
    return difference;
}

std::uint64_t Comparison::different() const {
    std::uint64_t sum = 0;
    for (auto kind : protocol::differential::kDifferenceKinds) sum += count(kind);
    return sum;
}

void Comparison::clear() {
    compared_ = 0;
    by_kind_ = {};
    kept_.clear();
}

}  // namespace slmp::station
