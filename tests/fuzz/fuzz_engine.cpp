// Bytes -> Engine::process(), as a TCP connection would feed it: one Session,
// frame after frame, until the engine asks for more. Input layout:
//   [0] profile (index into config::builtin_profile_names())
//   [1] bits 0-1 data-code policy (binary/ascii/auto), bit 2 adds CPU No.2,
//       bit 3 also compares a full memory snapshot around the first frame
//   [2..] the byte stream
// Checked: consumed <= input, and > 0 unless NeedMore (or Close); a response
// parses with the client decoder as one whole frame of the request's kind,
// codec and serial carrying the outcome's end code; a rejected request (end
// code not Ok, Silent, Close) leaves device memory alone.
//
// Each device area but SM/SD is capped at 512 points (and the station buffer): a
// fresh CPU with the real sizes costs ~3 ms under ASan (filling ~1 MB of
// instrumented vectors), one with 512 points a few microseconds, and every
// range check still has an end to hit.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "config/config.hpp"
#include "devicemodel/cpu.hpp"
#include "devicemodel/device_table.hpp"
#include "protocol/client.hpp"
#include "protocol/engine.hpp"
#include "tests/fuzz/fuzz_check.hpp"
#include "tests/fuzz/write_watch.hpp"

namespace {

using namespace slmp;
using protocol::Outcome;

using Watch = fuzz::WriteWatch;

// Profiles parse once; a fresh Cpu per input keeps every run reproducible.
const config::Profile& profile(std::size_t index) {
    static const auto names = config::builtin_profile_names();
    static std::map<std::size_t, config::Profile> cache;
    index %= names.size();
    auto it = cache.find(index);
    if (it == cache.end()) {
        auto loaded = config::load_profile(names[index]);
        auto& p = loaded.cpu;
        // SM/SD keep their sizes: the CPU itself writes special registers there.
        for (std::size_t a = 0; a < p.sizes.size(); ++a)
            if (auto area = static_cast<devicemodel::Area>(a); area != devicemodel::Area::SM && area != devicemodel::Area::SD)
                p.sizes[a] = std::min<std::uint32_t>(p.sizes[a], 512);
        p.station_buffer_words = std::min<std::uint32_t>(p.station_buffer_words, 512);
        it = cache.emplace(index, std::move(loaded)).first;
    }
    return it->second;
}

void watch(devicemodel::Cpu& cpu, Watch& w) {
    cpu.memory().set_write_observer(&w);
    cpu.station_buffer().set_write_observer(&w);
}

const char* name(Outcome::Action a) {
    switch (a) {
        case Outcome::Action::NeedMore: return "NeedMore";
        case Outcome::Action::Respond: return "Respond";
        case Outcome::Action::Silent: return "Silent";
        case Outcome::Action::Close: return "Close";
        case Outcome::Action::Restart: return "Restart";
    }
    return "?";
}

void check_response(const Outcome& out, const protocol::FrameHeader& request) {
    // The client parser reads 3E/4E responses; a 1E or 68 00 answer must at least exist.
    if (request.kind != protocol::FrameKind::E3 && request.kind != protocol::FrameKind::E4) {
        FUZZ_CHECK(!out.response.empty(), "empty response to a %s request", protocol::to_string(request.kind).data());
        return;
    }
    bool garbage = false;
    auto parsed = protocol::client::parse_response(out.response, &garbage);
    FUZZ_CHECK(parsed.has_value(), "response does not parse (garbage=%d, %zu bytes) for %04X/%04X", garbage,
               out.response.size(), out.command, out.subcommand);
    FUZZ_CHECK(parsed->size == out.response.size(), "response frame is %zu bytes of %zu", parsed->size,
               out.response.size());
    FUZZ_CHECK(parsed->header.kind == request.kind && parsed->header.codec == request.codec,
               "response kind/codec differ from the request's");
    FUZZ_CHECK(request.kind != protocol::FrameKind::E4 || parsed->header.serial == request.serial,
               "4E response serial %04X for request serial %04X", parsed->header.serial, request.serial);
    FUZZ_CHECK(parsed->end_code == protocol::raw(out.end_code), "response end code %04X, outcome says %04X",
               parsed->end_code, protocol::raw(out.end_code));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 2) return 0;
    const auto policy = static_cast<protocol::DataCodePolicy>(data[1] % 3);
    const auto& chosen = profile(data[0]);
    devicemodel::Cpu cpu(chosen.cpu);
    protocol::Engine engine(cpu, chosen.port);
    std::unique_ptr<devicemodel::Cpu> second;
    if (data[1] & 0x04) {
        second = std::make_unique<devicemodel::Cpu>(chosen.cpu);
        engine.add_cpu(2, *second, chosen.port);
    }
    Watch w;
    watch(cpu, w);
    if (second) watch(*second, w);

    protocol::Session session;
    std::span<const std::uint8_t> rest(data + 2, size - 2);
    // Only inputs that ask for it (byte 1 bit 3) get the compare around their first
    // frame: a copy of CPU No.1's memory before it, compared in the storage itself
    // after it (DeviceMemory::operator==), independent of the observer — a write
    // that bypassed it would also be missing from the HTTP API's change stream.
    const bool compare = (data[1] & 0x08) != 0;
    const auto before = compare ? std::optional<devicemodel::DeviceMemory>(cpu.memory()) : std::nullopt;
    for (bool first = true;; first = false) {
        // The request header as the engine will see it, for comparing the response.
        // With the frame shapes the chosen profile's port serves (1E, 68 00), as the engine scans.
        auto scan = protocol::scan_frame(rest, protocol::Direction::Request, policy, engine.options().max_frame_bytes,
                                         protocol::FrameSet{chosen.port.frame_1e, chosen.port.station_extended_frame});
        w.changed = false;
        auto out = engine.process(rest, policy, session);
        FUZZ_CHECK(out.consumed <= rest.size(), "consumed %zu of %zu", out.consumed, rest.size());
        if (out.action == Outcome::Action::NeedMore) {
            FUZZ_CHECK(out.consumed == 0, "NeedMore consumed %zu", out.consumed);
            break;
        }
        // Close may consume nothing (an oversized length field): the connection
        // ends there, so no byte after it is ever read.
        FUZZ_CHECK(out.consumed > 0 || out.action == Outcome::Action::Close, "%s consumed nothing", name(out.action));
        if (out.action == Outcome::Action::Respond) {
            FUZZ_CHECK(scan.status == protocol::FrameScan::Status::Complete, "a response to an incomplete frame");
            FUZZ_CHECK(out.consumed == scan.size, "consumed %zu of a %zu-byte frame", out.consumed, scan.size);
            check_response(out, scan.header);
        }
        const bool rejected = out.end_code != protocol::EndCode::Ok || out.action == Outcome::Action::Silent ||
                              out.action == Outcome::Action::Close;
        FUZZ_CHECK(!(rejected && w.changed), "%s %04X/%04X end code %04X changed %s (%s)", name(out.action),
                   out.command, out.subcommand, protocol::raw(out.end_code), w.what.c_str(), out.note.c_str());
        if (compare && first && rejected)
            FUZZ_CHECK(cpu.memory() == *before, "%s %04X/%04X end code %04X changed memory unseen by the observer (%s)",
                       name(out.action), out.command, out.subcommand, protocol::raw(out.end_code), out.note.c_str());
        // The connection is gone after these, as it is in the server.
        if (out.action == Outcome::Action::Close || out.action == Outcome::Action::Restart) break;
        rest = rest.subspan(out.consumed);
    }
    return 0;
}
