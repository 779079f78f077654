// A Ladder Motion controller's host-link port (Ladder Motion host-link manual, docs/hostlink.md):
// bytes in, one response record out (or silence). One object per station;
// transports call handle() with the bytes a connection received and their
// connection's LinkState, the way SLMP transports call Station::handle().
// Knows no sockets and no SLMP: it reads and writes the station's CPU through
// the memory map (frontends/hostlink/memory_map.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "devicemodel/cpu.hpp"
#include "frontends/gate.hpp"
#include "frontends/hostlink/memory_map.hpp"
#include "frontends/hostlink/record.hpp"

namespace slmp::hostlink {

struct Options {
    MemoryMap map;
    std::string refused_code = "01";     // §6.11: "01" or "15" for the OMRON commands Ladder Motion refuses
    std::string fcs_error_code = "01";   // §8: Ladder Motion's 01; an OMRON PLC answers 13
    std::size_t environment_bytes = 8192;   // RE/WE image (inferred size)
    std::size_t object_bytes = 65536;       // RP/WP intermediate object (inferred size)
    std::uint16_t version = 0x0231;         // R& item 9, "vvrr" (the manual's example)
};

// One entry of a QQMR list (§6.9).
struct QqEntry {
    Area area;
    std::uint32_t channel = 0;
    int bit = -1;   // -1: the whole channel ("CH")
};

// A connection's own state: its QQMR list (§11.2: one list per connection).
struct LinkState {
    std::optional<std::vector<QqEntry>> composite;
};

class HostLink {
public:
    HostLink(devicemodel::Cpu& cpu, Options options);

    struct Result {
        Cut::Kind kind = Cut::Kind::NeedMore;
        std::size_t consumed = 0;
        std::string response;   // empty: nothing to send (silence, garbage, need more)
        std::string command;    // the record's command, for logs ("" when none)
        std::string code;       // the response code answered ("00", "01", "IC"; "" for silence)
    };
    // Cuts the first record from `stream` and answers it. `gate` (a scenario
    // fault, frontends/gate.hpp) is asked once a known command's record is valid.
    Result handle(std::span<const std::uint8_t> stream, LinkState& link, const frontends::Gate& gate = {});
    // The answer to one record (`@` … CR, without a wrapper): a response record,
    // or empty for silence (XZ, `**`, another station, a record without `*`).
    // `result`, when given, gets the command and the response code.
    std::string answer(std::string_view record, LinkState& link, Result* result = nullptr,
                       const frontends::Gate& gate = {});

    const Options& options() const { return options_; }
    devicemodel::Cpu& cpu() { return cpu_; }
    std::vector<std::uint8_t>& environment() { return environment_; }
    std::vector<std::uint8_t>& object() { return object_; }
    const std::vector<std::uint8_t>& environment() const { return environment_; }
    const std::vector<std::uint8_t>& object() const { return object_; }

private:
    devicemodel::Cpu& cpu_;
    Options options_;
    std::vector<std::uint8_t> environment_;   // RE/WE: an opaque image, not persisted
    std::vector<std::uint8_t> object_;        // RP/WP: an opaque image, not persisted
};

}  // namespace slmp::hostlink
