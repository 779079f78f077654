// GET /api/buffer/{module}/{address}?count=N&as=words|dwords|string
// PUT /api/buffer/{module}/{address}?as=...  with {"values": [...]} or {"string": "..."}
// Buffer memory, the same stores SLMP reaches: U3\G100 (an intelligent
// module, also Extend Unit 0601/1601), U3E0\G10 and U3E0\HG10 (the CPU buffer
// of CPU No.1, also 0601/1601 module 03E0; U3E1-U3E3 for CPU No.2-4) and
// "station" (Memory Read/Write 0613/1613: the CPU buffer unless the profile
// gives the port its own). Same views and body as /api/devices; docs/api.md.
#include <cctype>
#include <charconv>

#include "control/endpoints/api.hpp"
#include "control/endpoints/device_view.hpp"
#include "control/endpoints/value_body.hpp"
#include "control/observers/event_hub.hpp"

namespace slmp::control {

using devicemodel::Area;
using devicemodel::DeviceMemory;
using nlohmann::json;

namespace {

std::string hex(unsigned value) {
    char text[8];
    auto [end, _] = std::to_chars(text, text + sizeof text, value, 16);
    std::string out(text, end);
    for (auto& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return out;
}

// One buffer memory the API can reach.
struct Buffer {
    std::string name;          // "U3", "U3E0", "station"
    DeviceMemory* memory;
    std::string owner;         // for messages: "module U3 (Q62DA)"
    std::string enlarge;       // how to make it larger
    bool high_speed = false;   // HG (the CPU buffer's fixed-cycle area) exists
};

std::vector<Buffer> buffers(Api& api) {
    std::vector<Buffer> list;
    auto& cpu = api.station.cpu();
    for (const auto& [io, module] : cpu.modules())
        list.push_back({"U" + hex(io), &module->memory, "module U" + hex(io) + " (" + module->model + ")",
                        "raise buffer_words of that module in the configuration's \"modules\"", false});
    const auto& cpus = api.station.engine().cpus();
    for (std::size_t i = 0; i < cpus.size(); ++i)
        if (cpus[i])
            list.push_back({"U3E" + std::to_string(i), &cpus[i]->memory(),
                            "the CPU buffer of CPU No." + std::to_string(i + 1) + " (" + cpus[i]->profile().name + ")",
                            "raise device_sizes.G (or HG) in the configuration", true});
    list.push_back({"station", &cpu.station_buffer(), "the own-station buffer memory (0613/1613)",
                    cpu.profile().station_buffer_words > 0 ? "use a profile with a larger station_buffer_words"
                                                           : "raise device_sizes.G in the configuration",
                    false});
    return list;
}

std::string names(const std::vector<Buffer>& list) {
    std::string text;
    for (const auto& b : list) text += (text.empty() ? "" : ", ") + b.name;
    return text;
}

Buffer find_buffer(Api& api, const std::string& text) {
    auto list = buffers(api);
    std::string wanted;
    for (char c : text) wanted += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    // "U03" and "u3" name the same module as "U3".
    if (wanted.size() > 1 && wanted[0] == 'U') {
        unsigned number = 0;
        auto [ptr, ec] = std::from_chars(wanted.data() + 1, wanted.data() + wanted.size(), number, 16);
        if (ec == std::errc{} && ptr == wanted.data() + wanted.size()) wanted = "U" + hex(number);
    }
    for (auto& b : list) {
        std::string name;
        for (char c : b.name) name += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        if (name == wanted) return b;
    }
    throw ApiError{Status::not_found, "no buffer memory '" + text + "'; the configured ones are " + names(list) +
                                          " (add an intelligent module under \"modules\" in the configuration)"};
}

devicemodel::DeviceAddress parse_buffer_address(const Buffer& buffer, const std::string& text) {
    std::string error;
    auto address = devicemodel::parse_address(text, &error);
    if (!address || (address->spec->area != Area::G && address->spec->area != Area::HG))
        bad("'" + text + "' is not a buffer memory address; write G100" +
            std::string(buffer.high_speed ? " or HG100" : ""));
    if (address->spec->area == Area::HG && !buffer.high_speed)
        bad("HG is the CPU buffer's fixed-cycle area; " + buffer.name + " has only G (use U3E0 for HG)");
    return *address;
}

View view_of(const ApiRequest& request) {
    const auto* as = request.param("as");
    if (!as) return View::Words;
    auto view = parse_view(*as);
    if (!view || *view == View::Bits) bad("as=" + *as + " is not a buffer memory view; use words, dwords or string");
    return *view;
}

json shown(const Buffer& buffer, const DeviceRun& run) {
    auto out = read_run(*buffer.memory, run);
    out["module"] = buffer.name;
    return out;
}

Reply get_buffer(Api& api, const ApiRequest& request) {
    auto buffer = find_buffer(api, request.captures.at(0));
    auto start = parse_buffer_address(buffer, request.captures.at(1));
    auto run = make_run(*buffer.memory, {buffer.owner, buffer.enlarge}, start, view_of(request), count_param(request));
    return json_reply(shown(buffer, run));
}

Reply put_buffer(Api& api, const ApiRequest& request) {
    auto buffer = find_buffer(api, request.captures.at(0));
    auto start = parse_buffer_address(buffer, request.captures.at(1));
    auto body = parse_value_body(request.body);
    std::vector<std::uint32_t> values;
    auto view = body.contains("string") ? View::String : view_of(request);
    if (view == View::String) {
        if (!body.contains("string") || !body["string"].is_string()) bad("as=string takes {\"string\": \"...\"}");
        auto words = pack_string(body["string"].get<std::string>());
        values.assign(words.begin(), words.end());
    } else {
        values = parse_values(body["values"], view);
    }
    // Every check is done before the first write: a rejected request changes nothing.
    auto run = make_run(*buffer.memory, {buffer.owner, buffer.enlarge}, start, view, values.size());
    api.events.flush_writes("internal");
    write_run(*buffer.memory, run, values);
    api.events.flush_writes("api");
    return json_reply(shown(buffer, run));
}

Reply list_buffers(Api& api) {
    auto list = json::array();
    for (const auto& b : buffers(api)) {
        json item{{"module", b.name}, {"owner", b.owner}, {"G", b.memory->size(Area::G)}};
        if (b.high_speed) item["HG"] = b.memory->size(Area::HG);
        list.push_back(std::move(item));
    }
    return json_reply(json{{"buffers", std::move(list)}});
}

}  // namespace

void add_buffer_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/buffer", {}, [&api](const ApiRequest&) { return list_buffers(api); });
    router.add(Verb::get, "/api/buffer/{module}/{address}", {"count", "as"},
               [&api](const ApiRequest& request) { return get_buffer(api, request); });
    router.add(Verb::put, "/api/buffer/{module}/{address}", {"as"},
               [&api](const ApiRequest& request) { return put_buffer(api, request); });
}

}  // namespace slmp::control
