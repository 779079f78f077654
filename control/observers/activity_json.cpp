#include "control/observers/activity_json.hpp"

#include "control/http/timestamp.hpp"
#include "control/observers/request_summary.hpp"
#include "devicemodel/hex.hpp"
#include "scenarios/difference_json.hpp"
#include "scenarios/recording.hpp"
#include "station/comparison.hpp"

namespace slmp::control {

nlohmann::json compared_json(const station::ComparedRequest& c) {
    auto entry = scenarios::difference_json(c.difference, c.request, "upstream", c.upstream, "twin", c.twin);
    entry["number"] = c.number;
    entry["time"] = iso_time(c.at);
    entry["connection"] = c.connection;
    entry["peer"] = c.peer.text();
    entry["command"] = devicemodel::hex4(c.command);
    entry["subcommand"] = devicemodel::hex4(c.subcommand);
    return entry;
}

using nlohmann::json;
using protocol::Outcome;

namespace {

std::string_view reaction(Outcome::Action action) {
    switch (action) {
        case Outcome::Action::Respond: return "answered";
        case Outcome::Action::Close: return "closed";
        case Outcome::Action::Restart: return "restarted";
        case Outcome::Action::Silent:
        case Outcome::Action::NeedMore: break;
    }
    return "none";
}

}  // namespace

json connection_json(const station::Connection& connection) {
    return json{{"id", connection.id},
                {"peer", connection.peer.text()},
                {"transport", protocol::to_string(connection.peer.transport)},
                {"port", connection.peer.local_port},
                {"opened", iso_time(connection.opened)},
                {"requests", connection.requests}};
}

json request_json(const station::RequestRecord& record, devicemodel::Numbering numbering) {
    const auto& outcome = record.outcome;
    // A frame rejected before its command was read (garbage, a refused 4E
    // header, an oversized length) has command and subcommand 0.
    bool decoded = outcome.command != 0 || outcome.subcommand != 0;
    json out{{"time", iso_time(std::chrono::system_clock::now())},
             {"protocol", "slmp"},
             {"connection", record.connection},
             {"transport", protocol::to_string(record.peer.transport)},
             {"peer", record.peer.text()},
             {"command", decoded ? json(devicemodel::hex4(outcome.command)) : json(nullptr)},
             {"subcommand", decoded ? json(devicemodel::hex4(outcome.subcommand)) : json(nullptr)},
             {"name", decoded ? json(std::string(command_name(outcome.command, outcome.subcommand))) : json(nullptr)},
             {"end_code", outcome.action == Outcome::Action::Respond ? json(devicemodel::hex4(static_cast<std::uint16_t>(outcome.end_code)))
                                                                    : json(nullptr)},
             {"reaction", reaction(outcome.action)},
             {"latency_us", std::chrono::duration<double, std::micro>(record.latency).count()},
             {"bytes_in", record.frame.size()},
             {"bytes_out", outcome.response.size()},
             {"note", outcome.note}};
    if (!outcome.named.empty()) out["named"] = outcome.named;   // label names (the devices column of a label request)
    // The access route it named when not the own station's 00/FF/03FF/00: a
    // request a module's port passed on through the plant's networks, or one
    // refused for its route (docs/plants.md, "Networks and routes").
    if (const auto& route = record.request.header.route; decoded && !(route == protocol::Route{}))
        out["route"] = {{"network", devicemodel::hex2(route.network)},
                        {"station", devicemodel::hex2(route.station)},
                        {"module_io", devicemodel::hex4(route.module_io)},
                        {"multidrop", devicemodel::hex2(route.multidrop)}};
    if (auto devices = decoded ? request_devices(record.request, numbering) : std::nullopt) {
        out["device"] = devices->device;
        out["points"] = devices->points;
        out["unit"] = devices->unit;
    }
    return out;
}

json frontend_request_json(const station::FrontEndRecord& record) {
    std::string note;
    for (const auto& f : record.faults) note += (note.empty() ? "scenario fault '" : ", '") + f + "'";
    if (!note.empty()) note += record.closed ? ": connection closed" : record.code.empty() ? ": not answered" : "";
    return json{{"time", iso_time(std::chrono::system_clock::now())},
                {"protocol", record.protocol},
                {"connection", record.connection},
                {"transport", protocol::to_string(record.peer.transport)},
                {"peer", record.peer.text()},
                {"command", record.command.empty() ? json(nullptr) : json(record.command)},
                {"subcommand", nullptr},
                {"name", record.name.empty() ? json(nullptr) : json(record.name)},
                {"end_code", record.code.empty() ? json(nullptr) : json(record.code)},
                {"reaction", record.closed ? "closed" : record.code.empty() && record.response.empty() ? "none" : "answered"},
                {"latency_us", std::chrono::duration<double, std::micro>(record.latency).count()},
                {"bytes_in", record.request.size()},
                {"bytes_out", record.response.size()},
                {"request", scenarios::to_hex(record.request)},
                {"response", scenarios::to_hex(record.response)},
                {"note", note}};
}

}  // namespace slmp::control
