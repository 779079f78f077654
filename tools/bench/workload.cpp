#include "tools/bench/workload.hpp"

#include <numeric>
#include <stdexcept>

#include "devicemodel/device_table.hpp"
#include "protocol/client.hpp"

namespace slmp::bench {

namespace client = protocol::client;
using devicemodel::DeviceAddress;

namespace {

DeviceAddress address(const std::string& text, devicemodel::Numbering numbering) {
    std::string error;
    auto parsed = devicemodel::parse_address(text, numbering, &error);
    if (!parsed) throw std::invalid_argument("bad device '" + text + "': " + error);
    return *parsed;
}

struct Recipe {
    enum class Kind { ReadWords, WriteWords, ReadBits } kind;
    std::uint16_t points;
    const char* default_device;
};

Recipe recipe(const std::string& name) {
    if (name == "read1") return {Recipe::Kind::ReadWords, 1, "D0"};
    if (name == "read960") return {Recipe::Kind::ReadWords, 960, "D0"};
    if (name == "write1") return {Recipe::Kind::WriteWords, 1, "D0"};
    if (name == "write960") return {Recipe::Kind::WriteWords, 960, "D0"};
    if (name == "readbits") return {Recipe::Kind::ReadBits, 64, "M0"};
    throw std::invalid_argument("unknown --mix operation '" + name +
                                "' (known: read1, read960, write1, write960, readbits)");
}

// Bytes a good response carries after its end code (SLMP Reference Manual §5.2: words are 2 bytes
// or 4 hex characters; bits one nibble or one character a point).
std::size_t response_data(const Recipe& r, protocol::Codec codec) {
    bool ascii = codec == protocol::Codec::Ascii;
    switch (r.kind) {
    case Recipe::Kind::ReadWords: return r.points * (ascii ? 4u : 2u);
    case Recipe::Kind::ReadBits: return ascii ? r.points : (r.points + 1u) / 2u;
    case Recipe::Kind::WriteWords: return 0;
    }
    return 0;
}

std::vector<std::uint8_t> encode(const Recipe& r, const client::FrameOptions& frame, const DeviceAddress& start) {
    switch (r.kind) {
    case Recipe::Kind::ReadWords: return client::read_words(frame, start, r.points);
    case Recipe::Kind::ReadBits: return client::read_bits(frame, start, r.points);
    case Recipe::Kind::WriteWords: {
        std::vector<std::uint16_t> values(r.points);
        std::iota(values.begin(), values.end(), std::uint16_t{1});
        return client::write_words(frame, start, values);
    }
    }
    return {};
}

}  // namespace

Workload make_workload(const Options& options) {
    Workload w;
    w.kind = options.e4 ? protocol::FrameKind::E4 : protocol::FrameKind::E3;
    w.codec = options.ascii ? protocol::Codec::Ascii : protocol::Codec::Binary;
    unsigned slots = options.e4 ? options.depth : 1;
    const devicemodel::Numbering numbering{options.octal_xy ? devicemodel::Radix::Oct : devicemodel::Radix::Hex};
    for (const auto& name : options.mix) {
        Recipe r = recipe(name);
        DeviceAddress start = address(options.device.empty() ? r.default_device : options.device, numbering);
        Operation op{name, {}, response_data(r, w.codec)};
        for (unsigned slot = 0; slot < slots; ++slot) {
            client::FrameOptions frame;
            frame.kind = w.kind;
            frame.codec = w.codec;
            frame.serial = static_cast<std::uint16_t>(slot);
            frame.numbering = numbering;
            op.requests.push_back(encode(r, frame, start));
        }
        w.operations.push_back(std::move(op));
    }
    return w;
}

}  // namespace slmp::bench
