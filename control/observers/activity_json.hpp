// Connections and request summaries as JSON, shared by GET /api/connections
// and the /api/events stream so both show the same fields.
#pragma once

#include <nlohmann/json.hpp>

#include "devicemodel/device_table.hpp"
#include "station/activity.hpp"

namespace slmp::control {

// {"id", "peer", "transport", "port", "opened", "requests"}
nlohmann::json connection_json(const station::Connection& connection);

// {"time", "connection", "transport", "peer", "command", "subcommand", "name",
//  "device", "points", "unit", "end_code", "reaction", "latency_us",
//  "bytes_in", "bytes_out", "note"} — docs/api.md, "request" events.
// `numbering`: the station CPU's (FX5: X/Y head devices in octal).
nlohmann::json request_json(const station::RequestRecord& record, devicemodel::Numbering numbering);

// A protocol face's request in the same shape: "protocol" the face's name,
// "command" its text ("RD", "24"), "subcommand" null, "end_code" the response
// code or RSLT, and the bytes as hex ("request", "response").
nlohmann::json frontend_request_json(const station::FrontEndRecord& record);

// One request of differential mode and how the upstream's and the twin's
// answers differ, as GET /api/compare lists it and "compare" events carry it:
// scenarios/difference_json.hpp's fields with "number", "time", "connection",
// "peer", "command", "subcommand" (docs/api.md, "Compare").
nlohmann::json compared_json(const station::ComparedRequest& compared);

}  // namespace slmp::control
