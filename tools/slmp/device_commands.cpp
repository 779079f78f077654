// slmp read / slmp write: 0401 and 1401 in word units, or bit units with --bits.
#include <vector>

#include "protocol/client.hpp"
#include "tools/slmp/arguments.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {

namespace client = protocol::client;

void run_read(Invocation& in) {
    const auto& args = in.options.args;
    const auto numbering = in.client.frame().numbering;
    if (args.empty() || args.size() > 2) throw UsageError("read needs DEVICE [POINTS], e.g. slmp read D100 10");
    auto start = parse_device(args[0], numbering);
    std::uint16_t points = args.size() == 2 ? parse_points(args[1]) : 1;
    const bool bits = in.options.bits;
    if (bits && !is_bit_device(start))
        throw UsageError(args[0] + " is a word device; --bits reads bit devices (X, Y, M, B, ...)");

    const auto& frame = in.client.frame();
    auto request = bits ? client::read_bits(frame, start, points, in.options.form)
                        : client::read_words(frame, start, points, in.options.form);
    auto response = in.client.exchange(request);
    auto reader = response.reader();
    auto labels = value_labels(start, points, bits, numbering);

    Json values = Json::array();
    Table table;
    if (bits) {
        auto data = reader.bits(points, "read data");
        if (!reader.finish()) throw ConnectionError("the read data does not hold " + std::to_string(points) + " bits");
        table.headers = {"device", "value"};
        for (std::size_t i = 0; i < points; ++i) {
            values.push_back(data[i]);
            table.rows.push_back({labels[i], std::to_string(data[i])});
        }
    } else {
        auto data = reader.words(points, "read data");
        if (!reader.finish()) throw ConnectionError("the read data does not hold " + std::to_string(points) + " words");
        table.headers = {"device", "value", "signed", "hex"};
        for (std::size_t i = 0; i < points; ++i) {
            values.push_back(data[i]);
            table.rows.push_back({labels[i], std::to_string(data[i]), std::to_string(static_cast<std::int16_t>(data[i])),
                                  word_hex(data[i], 4)});
        }
    }
    Json json{{"device", devicemodel::format_address(start, numbering)},
              {"unit", bits ? "bit" : "word"},
              {"points", points},
              {"devices", labels},
              {"values", values}};
    in.output.result(json, table);
}

void run_write(Invocation& in) {
    const auto& args = in.options.args;
    const auto numbering = in.client.frame().numbering;
    if (args.size() < 2) throw UsageError("write needs DEVICE VALUE..., e.g. slmp write D100 1 2 3");
    if (args.size() - 1 > 65535) throw UsageError("write takes at most 65535 values");
    auto start = parse_device(args[0], numbering);
    const bool bits = in.options.bits;
    if (bits && !is_bit_device(start))
        throw UsageError(args[0] + " is a word device; --bits writes bit devices (X, Y, M, B, ...)");

    std::vector<std::uint8_t> bit_values;
    std::vector<std::uint16_t> word_values;
    for (std::size_t i = 1; i < args.size(); ++i) {
        if (bits) bit_values.push_back(parse_bit(args[i]) ? 1 : 0);
        else word_values.push_back(parse_word(args[i]));
    }
    const auto& frame = in.client.frame();
    auto request = bits ? client::write_bits(frame, start, bit_values, in.options.form)
                        : client::write_words(frame, start, word_values, in.options.form);
    in.client.exchange(request);

    auto points = args.size() - 1;
    auto labels = value_labels(start, points, bits, numbering);
    Json json{{"device", devicemodel::format_address(start, numbering)}, {"unit", bits ? "bit" : "word"}, {"points", points},
              {"written", true}};
    std::string range = labels.front() + (points > 1 ? "-" + labels.back() : "");
    in.output.result(json, "wrote " + std::to_string(points) + (bits ? " bit(s) " : " word(s) ") + range);
}

}  // namespace slmp::cli
