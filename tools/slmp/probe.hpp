// slmp probe: what a PLC's SLMP port does, found by asking it, written as a
// slmp-sim profile (docs/twin.md lists every fact, how it is found and what
// cannot be). The Prober runs the steps in order over raw exchanges (wire.hpp)
// and keeps, for each fact, the value, how it was found, and whether it was
// found at all — a fact it cannot find is left to the base profile the
// probed one extends, and the summary says so.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "devicemodel/cpu_profile.hpp"
#include "protocol/client.hpp"
#include "tools/slmp/wire.hpp"

namespace slmp::cli {

// --allow-writes D9000-D9999,M9000-M9999: scratch ranges the probe may write
// (and restores): one word range, optionally one bit range.
struct ScratchRanges {
    std::optional<devicemodel::DeviceAddress> words;
    std::uint32_t word_count = 0;
    std::optional<devicemodel::DeviceAddress> bits;
    std::uint32_t bit_count = 0;
};
ScratchRanges parse_scratch_ranges(const std::string& text, devicemodel::Numbering numbering);

struct Fact {
    std::string name;    // "batch_words", "device_sizes.D"
    std::string value;   // "960, over it C051"
    std::string how;     // "bisection of 0401 D0 xN (11 requests)"
    bool found = true;   // false: not found; the base profile's value stands
};

struct ProbeSettings {
    Target target;
    protocol::client::FrameOptions frame;   // the route; codec and kind are the probe's to vary
    std::chrono::milliseconds silence{1000};
    ScratchRanges scratch;
    unsigned max_connections = 64;           // stop counting connections here
};

class Prober {
public:
    Prober(const ProbeSettings& settings, WireRecorder* recorder, std::ostream& progress);

    // Runs every step; the profile JSON (with "extends" of the family's base).
    nlohmann::ordered_json run();
    const std::vector<Fact>& facts() const { return facts_; }
    std::size_t requests() const { return wire_.sent() + other_wires_sent_; }
    const std::string& base() const { return base_; }   // the built-in profile the probed one extends

private:
    Observed ask(const std::vector<std::uint8_t>& request);
    Observed ask_in(protocol::Codec codec, protocol::FrameKind kind, std::uint16_t command, std::uint16_t subcommand,
                    const std::function<void(protocol::FieldWriter&)>& body);
    protocol::client::FrameOptions frame(protocol::Codec codec, protocol::FrameKind kind) const;
    void fact(std::string name, std::string value, std::string how, bool found = true);
    void progress(const std::string& line);

    void identity();
    void frames();
    void subcommand_forms();
    void family();
    void end_codes();
    void sizes();
    void limits();
    void commands();
    void pipeline();
    void connections();
    void timing();
    void writes();

    // The largest n in [1, cap] that `request(n)` serves (end code 0), by
    // doubling then bisection; nullopt when n = 1 is not served. `over` gets
    // the end code of max + 1 (nullopt when the cap was served).
    struct Limit {
        std::uint32_t max = 0;
        std::optional<Observed> over;
        unsigned requests = 0;
    };
    std::optional<Limit> bisect(std::uint32_t cap, const std::function<std::vector<std::uint8_t>(std::uint32_t)>& request);
    std::optional<std::uint32_t> area_size(const devicemodel::DeviceSpec& spec, protocol::DeviceForm form, unsigned& asked);

    ProbeSettings settings_;
    WireRecorder* recorder_;
    std::ostream& progress_;
    Wire wire_;
    std::size_t other_wires_sent_ = 0;   // by the connections counted
    std::uint16_t serial_ = 0;
    std::vector<Fact> facts_;
    nlohmann::ordered_json profile_ = nlohmann::ordered_json::object();
    // What the steps learn and later steps use.
    protocol::Codec codec_ = protocol::Codec::Binary;   // a data code the port answers
    bool ascii_ = false, binary_ = false, e4_ = false, iqr_ = false, extended_ = false;
    bool type_answered_ = false, monitor_served_ = false, l_only_subcommand_ = false;
    devicemodel::Family family_ = devicemodel::Family::IQR;
    std::string base_;
    devicemodel::CpuProfile base_cpu_;
    std::uint16_t not_supported_ = 0xC059;
    std::uint32_t d_size_ = 0;
};

}  // namespace slmp::cli
