// POST /api/snapshots {"name": "clean"[, "file": "path"]}, GET /api/snapshots,
// GET/DELETE /api/snapshots/{name}, GET /api/snapshots/{name}/file,
// POST /api/snapshots/{name}/restore [{"drop_connections": true}],
// POST /api/reset [{"drop_connections": true}].
// What a snapshot holds: station/station_snapshot.hpp; docs/api.md, "Snapshots".
#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "control/endpoints/api.hpp"
#include "control/http/timestamp.hpp"
#include "control/observers/event_hub.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

double ms_since(std::chrono::steady_clock::time_point started) {
    return std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - started).count() / 1000.0;
}

// An empty body is {}; anything else must be a JSON object of the given keys.
json body_object(const std::string& text, std::initializer_list<const char*> keys, const std::string& example) {
    if (text.find_first_not_of(" \t\r\n") == std::string::npos) return json::object();
    auto body = json::parse(text, nullptr, false);
    if (body.is_discarded() || !body.is_object()) bad("the body must be a JSON object such as " + example);
    for (const auto& item : body.items()) {
        // Not a structured binding: clang 14 cannot capture one in the lambda.
        const auto& key = item.key();
        if (std::find_if(keys.begin(), keys.end(), [&](const char* k) { return key == k; }) == keys.end())
            bad("unknown key \"" + key + "\" in the body; send " + example);
    }
    return body;
}

bool drop_connections(const json& body) {
    if (!body.contains("drop_connections")) return false;
    if (!body["drop_connections"].is_boolean()) bad("\"drop_connections\" must be true or false");
    return body["drop_connections"].get<bool>();
}

void check_name(const std::string& name) {
    bool ok = !name.empty() && name.size() <= 64;
    for (char c : name) ok = ok && (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.');
    if (!ok) bad("snapshot name '" + name + "': use 1-64 letters, digits, '-', '_' or '.'");
}

json summary(const std::string& name, const station::StationSnapshot& s) {
    json scenarios = json::array();
    for (const auto& group : s.scenarios)
        for (const auto& scenario : group) scenarios.push_back(scenario.name);
    return {{"name", name}, {"taken", iso_time(s.taken)}, {"bytes", s.memory_bytes()}, {"cpus", s.cpus.size()},
            {"scenarios", std::move(scenarios)}};
}

const station::StationSnapshot& find(Api& api, const std::string& name) {
    auto it = api.snapshots.find(name);
    if (it == api.snapshots.end()) {
        std::string names;
        for (const auto& [n, _] : api.snapshots) names += (names.empty() ? "" : ", ") + n;
        throw ApiError{Status::not_found, "no snapshot '" + name + "'; " +
                                              (names.empty() ? std::string("none is saved (POST /api/snapshots {\"name\": \"" + name + "\"})")
                                                             : "the saved ones are " + names)};
    }
    return it->second;
}

// Written whole (temporary file, then rename), as the ready file is.
void write_file(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    auto temp = path + ".tmp";
    {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
        if (!out) bad("cannot write " + temp + "; give \"file\" a path in a writable directory");
    }
    std::error_code ec;
    std::filesystem::rename(temp, path, ec);
    if (ec) bad("cannot rename " + temp + " to " + path + ": " + ec.message());
}

Reply take(Api& api, const ApiRequest& request) {
    auto body = body_object(request.body, {"name", "file"}, "{\"name\": \"clean\"} or {\"name\": \"clean\", \"file\": \"clean.snap\"}");
    if (!body.contains("name") || !body["name"].is_string()) bad("the body needs a \"name\": {\"name\": \"clean\"}");
    auto name = body["name"].get<std::string>();
    check_name(name);
    if (body.contains("file") && !body["file"].is_string()) bad("\"file\" must be a path string");
    api.events.flush_writes("internal");
    auto started = std::chrono::steady_clock::now();
    auto snapshot = api.station.snapshot();
    auto took = ms_since(started);
    if (body.contains("file")) write_file(body["file"].get<std::string>(), station::encode_station_file(snapshot));
    bool replaced = api.snapshots.contains(name);
    auto out = summary(name, snapshot);
    api.snapshots.insert_or_assign(name, std::move(snapshot));
    out["took_ms"] = took;
    out["replaced"] = replaced;
    if (body.contains("file")) out["file"] = body["file"];
    return json_reply(out, Status::created);
}

Reply restore(Api& api, const station::StationSnapshot* snapshot, const std::string& name, const ApiRequest& request) {
    auto body = body_object(request.body, {"drop_connections"}, "{\"drop_connections\": true} (or no body)");
    auto drop = drop_connections(body);
    api.events.flush_writes("internal");
    auto started = std::chrono::steady_clock::now();
    try {
        if (snapshot) api.station.restore(*snapshot, drop);
        else api.station.reset(drop);
    } catch (const config::ConfigError& e) {
        throw ApiError{Status::conflict, e.what()};
    }
    auto took = ms_since(started);
    api.events.flush_writes("api");
    json out{{"took_ms", took}, {"drop_connections", drop}};
    out[snapshot ? "restored" : "reset"] = snapshot ? json(name) : json(true);
    return json_reply(out);
}

Reply file(Api& api, const std::string& name) {
    auto bytes = station::encode_station_file(find(api, name));
    Reply reply;
    reply.content_type = "application/octet-stream";
    reply.body.assign(bytes.begin(), bytes.end());
    reply.headers.emplace_back("Content-Disposition", "attachment; filename=\"" + name + ".snap\"");
    return reply;
}

}  // namespace

void add_snapshot_endpoints(Router& router, Api& api) {
    router.add(Verb::post, "/api/snapshots", {}, [&api](const ApiRequest& request) { return take(api, request); });
    router.add(Verb::get, "/api/snapshots", {}, [&api](const ApiRequest&) {
        json list = json::array();
        for (const auto& [name, s] : api.snapshots) list.push_back(summary(name, s));
        return json_reply(json{{"snapshots", std::move(list)}});
    });
    router.add(Verb::get, "/api/snapshots/{name}", {}, [&api](const ApiRequest& request) {
        const auto& name = request.captures.at(0);
        return json_reply(summary(name, find(api, name)));
    });
    router.add(Verb::get, "/api/snapshots/{name}/file", {},
               [&api](const ApiRequest& request) { return file(api, request.captures.at(0)); });
    router.add(Verb::delete_, "/api/snapshots/{name}", {}, [&api](const ApiRequest& request) {
        const auto& name = request.captures.at(0);
        find(api, name);
        api.snapshots.erase(name);
        return json_reply(json{{"deleted", name}});
    });
    router.add(Verb::post, "/api/snapshots/{name}/restore", {}, [&api](const ApiRequest& request) {
        const auto& name = request.captures.at(0);
        return restore(api, &find(api, name), name, request);
    });
    router.add(Verb::post, "/api/reset", {}, [&api](const ApiRequest& request) { return restore(api, nullptr, "", request); });
}

}  // namespace slmp::control
