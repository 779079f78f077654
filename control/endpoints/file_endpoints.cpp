// The CPU's file drives over HTTP (docs/api.md, docs/files.md):
//   GET    /api/drives                           the drives: number, kind, capacity, used, flags, folder
//   GET    /api/drives/{drive}/files?path=DIR    a folder's entries (file No., name, size, date, attribute)
//   GET    /api/drives/{drive}/file?path=FILE    download (application/octet-stream)
//   PUT    /api/drives/{drive}/file?path=FILE    upload the body (replaces the file; refused while open)
//   GET    /api/drives/locks                     open files and their owners
//   DELETE /api/drives/locks/{pointer}           release one lock (as close type 2 would, for one file)
// Names go through the same checks as SLMP 0040 paths ("\" or "/" between names).
#include <charconv>

#include "control/endpoints/api.hpp"
#include "devicemodel/drives.hpp"
#include "protocol/lock_owner.hpp"

namespace slmp::control {

using devicemodel::FileFault;
using nlohmann::json;

namespace {

[[noreturn]] void fail(FileFault fault, const std::string& what) {
    auto status = fault == FileFault::NotFound || fault == FileFault::NoDrive ? Status::not_found
                  : fault == FileFault::Locked || fault == FileFault::Exists  ? Status::conflict
                  : fault == FileFault::NoCapacity                             ? Status::payload_too_large
                                                                               : Status::bad_request;
    throw ApiError{status, what + ": " + std::string(devicemodel::describe(fault))};
}

std::uint16_t drive_of(Api& api, const std::string& text) {
    unsigned number = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), number);
    if (ec != std::errc{} || end != text.data() + text.size() || number > 0xFFFF ||
        !api.station.cpu().drives().exists(static_cast<std::uint16_t>(number)))
        throw ApiError{Status::not_found, "no drive '" + text + "' on this CPU; GET /api/drives lists them"};
    return static_cast<std::uint16_t>(number);
}

std::string path_of(const ApiRequest& request, bool required) {
    const auto* path = request.param("path");
    if (!path || path->empty()) {
        if (required) throw ApiError{Status::bad_request, "give the file as ?path=NAME (folders joined with / or \\)"};
        return {};
    }
    std::string out = *path;
    for (auto& c : out)
        if (c == '/') c = '\\';
    return out;
}

Reply list_drives(Api& api) {
    auto list = json::array();
    for (const auto& d : api.station.cpu().drives().drives()) {
        json item{{"drive", d.spec.number}, {"kind", devicemodel::drive_kind_name(d.spec.kind)}};
        if (d.spec.alias_of) {
            item["alias_of"] = *d.spec.alias_of;
        } else {
            item.update({{"capacity", d.spec.capacity}, {"used", d.used}, {"present", d.spec.present},
                         {"write_protect", d.spec.write_protect}, {"location", d.location}});
        }
        list.push_back(std::move(item));
    }
    return json_reply(json{{"drives", std::move(list)}});
}

std::string dos_text(std::uint16_t date, std::uint16_t time) {
    char text[32];
    std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d", (date >> 9) + 1980, (date >> 5) & 0xF,
                  date & 0x1F, time >> 11, (time >> 5) & 0x3F, (time & 0x1F) * 2);
    return text;
}

Reply list_files(Api& api, const ApiRequest& request) {
    auto drive = drive_of(api, request.captures.at(0));
    auto dir = path_of(request, false);
    devicemodel::Listing listing;
    if (auto fault = api.station.cpu().drives().host_list(drive, dir, listing); fault != FileFault::None)
        fail(fault, "drive " + std::to_string(drive) + " folder '" + dir + "'");
    auto entries = json::array();
    for (const auto& e : listing.entries)
        entries.push_back({{"number", e.number}, {"name", e.name}, {"directory", e.directory}, {"size", e.size},
                           {"attribute", e.attribute}, {"read_only", (e.attribute & 0x01) != 0},
                           {"date", dos_text(e.dos_date, e.dos_time)}});
    return json_reply(json{{"drive", drive}, {"path", dir}, {"entries", std::move(entries)}});
}

Reply download(Api& api, const ApiRequest& request) {
    auto drive = drive_of(api, request.captures.at(0));
    auto path = path_of(request, true);
    std::vector<std::uint8_t> bytes;
    if (auto fault = api.station.cpu().drives().host_read({drive, path}, bytes); fault != FileFault::None)
        fail(fault, "drive " + std::to_string(drive) + " file '" + path + "'");
    Reply reply;
    reply.content_type = "application/octet-stream";
    reply.body.assign(bytes.begin(), bytes.end());
    return reply;
}

Reply upload(Api& api, const ApiRequest& request) {
    auto drive = drive_of(api, request.captures.at(0));
    auto path = path_of(request, true);
    std::vector<std::uint8_t> bytes(request.body.begin(), request.body.end());
    if (auto fault = api.station.cpu().drives().host_write({drive, path}, bytes); fault != FileFault::None)
        fail(fault, "drive " + std::to_string(drive) + " file '" + path + "'");
    return json_reply(json{{"drive", drive}, {"path", path}, {"size", bytes.size()}});
}

json lock_list(Api& api) {
    auto list = json::array();
    for (const auto& f : api.station.cpu().drives().open_files()) {
        std::string path;
        for (const auto& name : f.path) path += (path.empty() ? "" : "\\") + name;
        json item{{"pointer", f.pointer}, {"drive", f.drive}, {"path", path},
                  {"mode", f.mode == devicemodel::OpenMode::Write ? "write" : "read"}, {"connection", f.owner}};
        // A UDP owner is a peer, not a connection: name it (docs/files.md).
        if (auto peer = protocol::udp_owner_text(f.owner)) item["peer"] = *peer;
        list.push_back(std::move(item));
    }
    return json{{"locks", std::move(list)}};
}

Reply release(Api& api, const ApiRequest& request) {
    const auto& text = request.captures.at(0);
    unsigned pointer = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), pointer);
    if (ec != std::errc{} || end != text.data() + text.size() || pointer > 0xFFFF ||
        !api.station.cpu().drives().release(static_cast<std::uint16_t>(pointer)))
        throw ApiError{Status::not_found, "no open file with pointer No. '" + text + "'; GET /api/drives/locks lists them"};
    return json_reply(lock_list(api));
}

}  // namespace

void add_file_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/drives", {}, [&api](const ApiRequest&) { return list_drives(api); });
    router.add(Verb::get, "/api/drives/locks", {}, [&api](const ApiRequest&) { return json_reply(lock_list(api)); });
    router.add(Verb::delete_, "/api/drives/locks/{pointer}", {},
               [&api](const ApiRequest& request) { return release(api, request); });
    router.add(Verb::get, "/api/drives/{drive}/files", {"path"},
               [&api](const ApiRequest& request) { return list_files(api, request); });
    router.add(Verb::get, "/api/drives/{drive}/file", {"path"},
               [&api](const ApiRequest& request) { return download(api, request); });
    router.add(Verb::put, "/api/drives/{drive}/file", {"path"},
               [&api](const ApiRequest& request) { return upload(api, request); });
}

}  // namespace slmp::control
