#include "station/frontend_state.hpp"

#include <cstring>

#include "config/config_error.hpp"
#include "devicemodel/byte_reader.hpp"
#include "frontends/face.hpp"

namespace slmp::station {

namespace {

constexpr char kMagic[8] = {'S', 'L', 'M', 'P', 'U', 'N', 'T', '1'};

[[noreturn]] void refuse(const std::string& part, std::size_t got, std::size_t want) {
    throw config::ConfigError("the snapshot's '" + part + "' holds " + std::to_string(got) + " bytes and this station's " +
                              std::to_string(want) + "; restore it with the configuration it was taken with");
}

}  // namespace

UnitParts take_units(const Station::FrontEnds& units) {
    UnitParts parts;
    for (const auto* unit : units) unit->save(parts);
    return parts;
}

void give_units(const UnitParts& parts, Station::FrontEnds& units) {
    // Every part first: a refused part changes nothing.
    for (const auto* unit : units) {
        for (const auto& [name, want] : unit->part_sizes()) {
            auto it = parts.find(name);
            if (it == parts.end()) continue;   // taken without that front end: it keeps its state
            if (it->second.size() != want) refuse(name, it->second.size(), want);
        }
        if (auto problem = unit->check(parts); !problem.empty()) throw config::ConfigError(problem);
    }
    for (auto* unit : units) unit->restore(parts);
}

std::vector<std::uint8_t> encode_units(const UnitParts& parts) {
    devicemodel::ByteWriter w;
    w.out.assign(std::begin(kMagic), std::end(kMagic));
    w.u32(static_cast<std::uint32_t>(parts.size()));
    for (const auto& [name, bytes] : parts) {
        w.name(name);
        w.u32(static_cast<std::uint32_t>(bytes.size()));
        w.bytes(bytes);
    }
    return std::move(w.out);
}

UnitParts decode_units(std::span<const std::uint8_t> bytes, const std::string& source) {
    auto fail = [&](const std::string& why) {
        return config::ConfigError(source + ": " + why + "; move the file away to start the front ends afresh");
    };
    devicemodel::ByteReader r(bytes);
    auto need = [&](auto value) {
        if (!value) throw fail("truncated front-end state");
        return *value;
    };
    auto magic = need(r.bytes(sizeof kMagic));
    if (std::memcmp(magic.data(), kMagic, sizeof kMagic) != 0) throw fail("not a slmp-sim front-end state file (bad magic)");
    UnitParts parts;
    for (auto count = need(r.u32()); count > 0; --count) {
        auto name = need(r.name());
        auto part = need(r.bytes(need(r.u32())));
        parts[name].assign(part.begin(), part.end());
    }
    if (!r.done()) throw fail("unexpected bytes after the last part");
    return parts;
}

}  // namespace slmp::station
