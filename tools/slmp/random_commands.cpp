// slmp random read|write: 0403 Read Random and 1402 Write Random.
//   slmp random read D0 TN0 M100 --dword D1500 --dword Y160
//        word access for the plain items (a bit device gives 16 bits), double-word
//        access for each --dword item (a bit device gives 32 bits);
//   slmp random write D0=1 M100=0x00FF --dword D1500=305419896
//   slmp random write --bits M50=0 Y2F=1
// The item counts are one-byte fields, so at most 255 of each; the PLC's own
// limits (96/192 points, weighted 1402 limits) come back as its end code.
#include <vector>

#include "protocol/client_commands.hpp"
#include "tools/slmp/arguments.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {
namespace {

namespace client = protocol::client;
using devicemodel::DeviceAddress;
using devicemodel::format_address;

void check_count(std::size_t count, const char* what) {
    if (count > 255) throw UsageError(std::string("at most 255 ") + what + " in one request (the count is one byte)");
}

void random_read(Invocation& in, const std::vector<std::string>& items) {
    const auto numbering = in.client.frame().numbering;
    if (in.options.bits) throw UsageError("random read takes no --bits: it reads words and double words");
    std::vector<DeviceAddress> words, dwords;
    for (const auto& item : items) words.push_back(parse_device(item, numbering));
    for (const auto& item : in.options.dwords) dwords.push_back(parse_device(item, numbering));
    if (words.empty() && dwords.empty())
        throw UsageError("random read needs devices, e.g. slmp random read D0 M100 --dword D200");
    check_count(words.size(), "word devices");
    check_count(dwords.size(), "double-word devices");

    auto response = in.client.exchange(client::read_random(in.client.frame(), words, dwords, in.options.form));
    auto reader = response.reader();
    Json values = Json::array();
    Table table{{"device", "access", "value", "hex"}, {}};
    for (const auto& d : words) {
        auto v = reader.u16("word data");
        values.push_back({{"device", format_address(d, numbering)}, {"access", "word"}, {"value", v}});
        table.rows.push_back({format_address(d, numbering), "word", std::to_string(v), word_hex(v, 4)});
    }
    for (const auto& d : dwords) {
        auto v = reader.u32("double-word data");
        values.push_back({{"device", format_address(d, numbering)}, {"access", "dword"}, {"value", v}});
        table.rows.push_back({format_address(d, numbering), "dword", std::to_string(v), word_hex(v, 8)});
    }
    if (!reader.finish()) throw ConnectionError("the random read data does not match the devices requested");
    in.output.result(Json{{"values", values}}, table);
}

void random_write(Invocation& in, const std::vector<std::string>& items) {
    const auto numbering = in.client.frame().numbering;
    Json written = Json::array();
    auto note = [&](const DeviceAddress& device, const char* access, std::uint32_t value) {
        written.push_back({{"device", format_address(device, numbering)}, {"access", access}, {"value", value}});
    };
    std::vector<std::uint8_t> request;
    if (in.options.bits) {
        if (!in.options.dwords.empty()) throw UsageError("--bits and --dword do not mix: 1402 writes bits or words");
        std::vector<client::BitWrite> bits;
        for (const auto& item : items) {
            auto a = parse_assignment(item);
            auto device = parse_device(a.device, numbering);
            if (!is_bit_device(device)) throw UsageError(a.device + " is a word device; --bits writes bit devices");
            bits.push_back({device, parse_bit(a.value)});
            note(device, "bit", bits.back().on ? 1 : 0);
        }
        if (bits.empty()) throw UsageError("random write --bits needs DEVICE=0|1 items, e.g. M50=0 Y2F=1");
        check_count(bits.size(), "bits");
        request = client::write_random_bits(in.client.frame(), bits, in.options.form);
    } else {
        std::vector<client::WordWrite> words;
        std::vector<client::DwordWrite> dwords;
        for (const auto& item : items) {
            auto a = parse_assignment(item);
            words.push_back({parse_device(a.device, numbering), parse_word(a.value)});
            note(words.back().device, "word", words.back().value);
        }
        for (const auto& item : in.options.dwords) {
            auto a = parse_assignment(item);
            dwords.push_back({parse_device(a.device, numbering), parse_dword(a.value)});
            note(dwords.back().device, "dword", dwords.back().value);
        }
        if (words.empty() && dwords.empty())
            throw UsageError("random write needs DEVICE=VALUE items, e.g. slmp random write D0=1 --dword D200=70000");
        check_count(words.size(), "word devices");
        check_count(dwords.size(), "double-word devices");
        request = client::write_random_words(in.client.frame(), words, dwords, in.options.form);
    }
    in.client.exchange(request);
    in.output.result(Json{{"written", written}}, "wrote " + std::to_string(written.size()) + " device(s)");
}

}  // namespace

void run_random(Invocation& in) {
    const auto& args = in.options.args;
    if (args.empty() || (args[0] != "read" && args[0] != "write"))
        throw UsageError("random needs read or write, e.g. slmp random read D0 M100 --dword D200");
    std::vector<std::string> items(args.begin() + 1, args.end());
    if (args[0] == "read") random_read(in, items);
    else random_write(in, items);
}

}  // namespace slmp::cli
