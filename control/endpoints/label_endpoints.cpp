// GET /api/labels                      every global label: type, device, external access
// GET /api/labels/{name}?count=N       N elements from the named one ("DDD[0]", "Tank1.Level")
// PUT /api/labels/{name}               {"values": [...]} or {"string": "..."}
// GET /api/labels/{name}/wait?equals=N  the wait of control/endpoints/wait_endpoint.hpp on one element
// Names resolve like SLMP label names (devicemodel/labels.hpp), but the API is
// the simulator's own: labels without "Access from External Device" are
// reachable here. docs/api.md, "Labels".
#include "control/endpoints/api.hpp"
#include "control/endpoints/value_body.hpp"
#include "control/endpoints/wait_endpoint.hpp"
#include "control/observers/event_hub.hpp"
#include "devicemodel/label_values.hpp"
#include "devicemodel/labels.hpp"

namespace slmp::control {

using nlohmann::json;
using devicemodel::LabelScalar;

namespace {

json label_json(const devicemodel::Label& l, devicemodel::Numbering numbering) {
    return {{"name", l.name},
            {"type", devicemodel::format_label_type(l.type, l.dims)},
            {"device", l.device ? json(devicemodel::format_address(*l.device, numbering)) : json(nullptr)},
            {"external", l.external},
            {"words", l.words}};
}

Reply list_labels(Api& api) {
    const auto& table = api.station.cpu().labels();
    json labels = json::array(), structures = json::array();
    for (const auto& l : table.labels()) labels.push_back(label_json(l, api.station.cpu().profile().numbering));
    for (const auto& s : table.structures()) {
        json members = json::array();
        for (const auto& m : s.members)
            members.push_back({{"name", m.name}, {"type", devicemodel::format_label_type(m.type, m.dims)}, {"offset", m.offset}});
        structures.push_back({{"name", s.name}, {"words", s.words}, {"members", members}});
    }
    return json_reply({{"labels", labels}, {"structures", structures}});
}

devicemodel::LabelRef resolve(Api& api, const std::string& name) {
    devicemodel::LabelFault fault{};
    auto ref = api.station.cpu().labels().resolve(name, {}, fault, /*external_only=*/false);
    if (!ref) throw ApiError{Status::not_found, "label '" + name + "': " + std::string(devicemodel::describe(fault)) +
                                                    "; GET /api/labels lists the labels"};
    return *ref;
}

json scalar_json(const LabelScalar& s) {
    switch (s.kind) {
        case LabelScalar::Kind::Int: return s.integer;
        case LabelScalar::Kind::Float: return s.real;
        case LabelScalar::Kind::Text: return s.text;
    }
    return nullptr;
}

Reply read_reply(Api& api, const std::string& name, const devicemodel::LabelRef& ref, std::uint64_t count) {
    json values = json::array();
    for (std::uint32_t i = 0; i < count; ++i)
        values.push_back(scalar_json(devicemodel::decode_label_scalar(ref.basic, devicemodel::read_element(api.station.cpu().memory(), ref, i))));
    devicemodel::LabelType type{devicemodel::LabelType::Kind::Basic, ref.basic, ref.chars};
    return json_reply({{"name", name}, {"type", devicemodel::format_label_type(type)}, {"values", values}});
}

void check_count(const devicemodel::LabelRef& ref, std::uint64_t count, const std::string& name) {
    if (count == 0 || count > ref.elements)
        bad("count=" + std::to_string(count) + " for '" + name + "': use 1 to " + std::to_string(ref.elements) +
            " (the elements from it to the end of its array)");
}

Reply get_label(Api& api, const ApiRequest& request) {
    const auto& name = request.captures.at(0);
    auto ref = resolve(api, name);
    auto count = count_param(request);
    check_count(ref, count, name);
    return read_reply(api, name, ref, count);
}

LabelScalar scalar_of(const json& v) {
    LabelScalar s;
    if (v.is_string()) {
        s.kind = LabelScalar::Kind::Text;
        s.text = v.get<std::string>();
    } else if (v.is_boolean()) {
        s.integer = v.get<bool>() ? 1 : 0;
    } else if (v.is_number_integer()) {
        s.integer = v.get<std::int64_t>();
    } else if (v.is_number()) {
        s.kind = LabelScalar::Kind::Float;
        s.real = v.get<double>();
    } else {
        bad("values must be numbers, true/false or strings, not " + v.dump());
    }
    return s;
}

Reply put_label(Api& api, const ApiRequest& request) {
    const auto& name = request.captures.at(0);
    auto ref = resolve(api, name);
    auto body = parse_value_body(request.body);
    std::vector<json> values;
    if (body.contains("string")) values.push_back(body["string"]);
    else if (body["values"].is_array()) values.assign(body["values"].begin(), body["values"].end());
    else bad("\"values\" must be a JSON array");
    check_count(ref, values.size(), name);
    // Every value is checked before the first write: a rejected request changes nothing.
    std::vector<std::vector<std::uint16_t>> encoded;
    for (std::size_t i = 0; i < values.size(); ++i) {
        std::string error;
        auto words = devicemodel::encode_label_scalar(ref.basic, devicemodel::basic_words(ref.basic, ref.chars),
                                                      scalar_of(values[i]), &error);
        if (!words) bad("values[" + std::to_string(i) + "]: " + error);
        encoded.push_back(std::move(*words));
    }
    auto& memory = api.station.cpu().memory();
    api.events.flush_writes("internal");
    for (std::uint32_t i = 0; i < encoded.size(); ++i) devicemodel::write_element(memory, ref, i, encoded[i]);
    api.events.flush_writes("api");
    return read_reply(api, name, ref, encoded.size());
}

// A wait on one element of a bit, integer or TIME label. Values are compared
// as their 32-bit two's-complement patterns, so equals=-1 matches a Word
// [Signed] of -1; greater/less compare those patterns unsigned, as for devices.
Reply label_wait(Api& api, const ApiRequest& request) {
    const auto& name = request.captures.at(0);
    auto ref = resolve(api, name);
    auto probe = devicemodel::decode_label_scalar(ref.basic, devicemodel::read_element(api.station.cpu().memory(), ref, 0));
    if (probe.kind != LabelScalar::Kind::Int)
        bad("label '" + name + "' holds " + (probe.kind == LabelScalar::Kind::Float ? "a FLOAT" : "a string") +
            ", which cannot be waited on; wait on a bit, integer or TIME label");
    devicemodel::LabelType type{devicemodel::LabelType::Kind::Basic, ref.basic, ref.chars};
    WaitTarget target;
    target.name = name;
    target.fields = {{"label", name}, {"type", devicemodel::format_label_type(type)}};
    target.read = [&api, ref] {
        auto words = devicemodel::read_element(api.station.cpu().memory(), ref, 0);
        return static_cast<std::uint32_t>(devicemodel::decode_label_scalar(ref.basic, words).integer);
    };
    target.parse = [name](const std::string& text) {
        auto number = json::parse(text, nullptr, false);
        if (number.is_discarded() || !(number.is_number_integer() || number.is_boolean()))
            bad("'" + text + "' is not a number; give an integer such as 5, -1 or, for bits, 0/1");
        return static_cast<std::uint32_t>(number.is_boolean() ? (number.get<bool>() ? 1 : 0) : number.get<std::int64_t>());
    };
    return wait_reply(api, std::move(target), request);
}

}  // namespace

void add_label_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/labels/{name}/wait", kWaitParameters,
               [&api](const ApiRequest& request) { return label_wait(api, request); });
    router.add(Verb::get, "/api/labels", {}, [&api](const ApiRequest&) { return list_labels(api); });
    router.add(Verb::get, "/api/labels/{name}", {"count"},
               [&api](const ApiRequest& request) { return get_label(api, request); });
    router.add(Verb::put, "/api/labels/{name}", {},
               [&api](const ApiRequest& request) { return put_label(api, request); });
}

}  // namespace slmp::control
