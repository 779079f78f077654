// slmp label read|write: global labels through 041C/041A and 141B/141A.
//   slmp label read LabelW Tank1.Level      041C, one point each
//   slmp label read DDD[0]:20                041A, 20 elements from DDD[0]
//   slmp label write LabelW 5                141B
//   slmp label write DDD[0] 1 2 3            141A, consecutive elements
// The CLI does not know the project's types: it asks first (041C of the
// label, whose answer carries the data type ID and length), then encodes the
// values for that type, as a client that browses a CPU's labels would.
#include <vector>

#include "devicemodel/label_values.hpp"
#include "protocol/client_labels.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {
namespace {

namespace client = protocol::client;
using devicemodel::BasicType;

std::string type_name(std::uint8_t id) {
    if (id < 1 || id > 10) return "type " + std::to_string(id);
    devicemodel::LabelType t{devicemodel::LabelType::Kind::Basic, static_cast<BasicType>(id)};
    auto name = devicemodel::format_label_type(t);
    // Strings print their capacity from the answer, not a declaration.
    return id == 9 ? "String" : id == 10 ? "String [Unicode]" : name;
}

// 041C of one label: its type ID and data length.
client::LabelData probe(Invocation& in, const std::string& name) {
    auto response = in.client.exchange(client::label_read_random(in.client.frame(), std::vector<std::string>{name}));
    auto data = client::decode_label_read(response, false);
    if (!data || data->size() != 1) throw ConnectionError("the 041C answer for " + name + " does not match the request");
    return (*data)[0];
}

void label_read(Invocation& in, const std::vector<std::string>& items) {
    if (items.empty()) throw UsageError("label read needs names, e.g. slmp label read LabelW DDD[0]:20");
    Json values = Json::array();
    Table table{{"label", "type", "value"}, {}};
    for (const auto& item : items) {
        auto colon = item.rfind(':');
        auto name = colon == std::string::npos ? item : item.substr(0, colon);
        std::uint32_t count = 1;
        if (colon != std::string::npos) {
            auto text = item.substr(colon + 1);
            if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos || text.size() > 5 ||
                std::stoul(text) == 0)
                throw UsageError("'" + item + "': write NAME:COUNT with COUNT 1 to 65535, e.g. DDD[0]:20");
            count = static_cast<std::uint32_t>(std::stoul(text));
        }
        auto first = probe(in, name);
        auto type = static_cast<BasicType>(first.type_id);
        std::vector<std::vector<std::uint16_t>> elements = first.elements;
        if (count > 1) {
            const bool bits = type == BasicType::Bit;
            const auto length = bits ? count : count * first.length;
            if (length > 0xFFFF) throw UsageError("'" + item + "': too many elements for one request");
            std::vector<client::ArrayRead> reads = {{name, bits, static_cast<std::uint16_t>(length)}};
            auto response = in.client.exchange(client::array_label_read(in.client.frame(), reads));
            auto data = client::decode_label_read(response, true);
            if (!data || data->size() != 1) throw ConnectionError("the 041A answer does not match the request");
            elements = (*data)[0].elements;
            // A string array answers as one run: split it by the element length.
            if ((type == BasicType::String || type == BasicType::WString) && !elements.empty()) {
                auto run = elements[0];
                elements.clear();
                for (std::size_t at = 0; at + first.length / 2 <= run.size(); at += first.length / 2)
                    elements.emplace_back(run.begin() + static_cast<std::ptrdiff_t>(at),
                                          run.begin() + static_cast<std::ptrdiff_t>(at + first.length / 2));
            }
        }
        for (std::size_t i = 0; i < elements.size(); ++i) {
            auto scalar = devicemodel::decode_label_scalar(type, elements[i]);
            auto shown = i == 0 ? name : name + "+" + std::to_string(i);
            Json v = scalar.kind == devicemodel::LabelScalar::Kind::Int     ? Json(scalar.integer)
                     : scalar.kind == devicemodel::LabelScalar::Kind::Float ? Json(scalar.real)
                                                                             : Json(scalar.text);
            values.push_back({{"label", shown}, {"type", type_name(first.type_id)}, {"value", v}});
            table.rows.push_back({shown, type_name(first.type_id), devicemodel::format_label_scalar(scalar)});
        }
    }
    in.output.result(Json{{"values", values}}, table);
}

void label_write(Invocation& in, const std::vector<std::string>& args) {
    if (args.size() < 2) throw UsageError("label write needs a name and values, e.g. slmp label write LabelW 5");
    const auto& name = args[0];
    auto first = probe(in, name);
    auto type = static_cast<BasicType>(first.type_id);
    std::vector<std::vector<std::uint16_t>> elements;
    for (std::size_t i = 1; i < args.size(); ++i) {
        std::string error;
        auto scalar = devicemodel::parse_label_scalar(type, args[i], &error);
        auto words = scalar ? devicemodel::encode_label_scalar(type, first.length / 2u, *scalar, &error) : std::nullopt;
        if (!words) throw UsageError("'" + args[i] + "' for " + name + " (" + type_name(first.type_id) + "): " + error);
        elements.push_back(std::move(*words));
    }
    if (elements.size() == 1) {
        std::vector<client::LabelWrite> writes = {{name, {type, elements[0]}}};
        in.client.exchange(client::label_write_random(in.client.frame(), writes));
    } else {
        std::vector<client::ArrayWrite> writes = {{name, type, elements}};
        in.client.exchange(client::array_label_write(in.client.frame(), writes));
    }
    in.output.result(Json{{"label", name}, {"written", elements.size()}},
                     "wrote " + std::to_string(elements.size()) + " element(s) of " + name);
}

}  // namespace

void run_label(Invocation& in) {
    const auto& args = in.options.args;
    if (args.empty() || (args[0] != "read" && args[0] != "write"))
        throw UsageError("label needs read or write, e.g. slmp label read DDD[0]:20 or slmp label write LabelW 5");
    std::vector<std::string> rest(args.begin() + 1, args.end());
    if (args[0] == "read") label_read(in, rest);
    else label_write(in, rest);
}

}  // namespace slmp::cli
