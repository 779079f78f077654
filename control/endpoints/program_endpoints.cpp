// GET/PUT/DELETE /api/program, GET /api/program/source?format=csv|text,
// POST /api/program/reload: the CPU's PLC program (station/cpu_program.hpp;
// docs/program.md, docs/api.md "Program"). A program is written and removed
// in STOP only, as GX Works' "Write to PLC" needs.
#include <fmt/format.h>

#include "control/endpoints/api.hpp"
#include "devicemodel/device_parts.hpp"
#include "program/operand_device.hpp"
#include "station/cpu_program.hpp"

namespace slmp::control {

using nlohmann::json;

namespace {

station::CpuProgram& slot(Api& api) {
    auto* program = api.station.program();
    if (!program) fail(Status::conflict, "this station runs no scan cycle, so it runs no program");
    return *program;
}

double microseconds(std::chrono::nanoseconds ns) { return static_cast<double>(ns.count()) / 1000.0; }

json program_json(Api& api) {
    auto& program = slot(api);
    const auto& runtime = api.station.cpu().runtime();
    json out{{"state", program.loaded() ? "loaded" : "none"}, {"cpu_state", run_state_name(runtime.state())}};
    const auto& comments = program.comments();
    json comment_list = json::array();
    for (const auto& c : comments) comment_list.push_back({{"device", c.device}, {"comment", c.comment}});
    out["comments"] = comment_list;
    if (!program.loaded()) return out;
    const auto& source = program::source_of(*program.program());
    const auto& s = program.statistics();
    out["load"] = program.load_number();
    out["file"] = source.file;
    out["name"] = source.name;
    out["plc_info"] = source.plc_info;
    out["format"] = source.format == program::Format::GxWorksCsv ? "csv" : "text";
    out["steps"] = program::step_count(*program.program());
    out["warnings"] = program.warnings();
    out["scans"] = s.scans;
    out["operation_errors"] = s.operation_errors;
    out["executed_last"] = s.executed_last;
    const auto modelled = program.execution()->modelled_times();
    out["modelled_us"] = {{"last", microseconds(modelled.last)},
                          {"min", microseconds(modelled.min)},
                          {"max", microseconds(modelled.max)}};
    out["host_us_last"] = microseconds(s.host_last);
    if (const auto& error = program.execution()->last_error())
        out["last_error"] = {{"code", fmt::format("{:04X}", error->code)},
                             {"step", error->step_index},
                             {"row", error->row},
                             {"mnemonic", error->mnemonic},
                             {"message", error->message}};
    else
        out["last_error"] = nullptr;
    return out;
}

json lines_json(const program::Source& source) {
    json lines = json::array();
    for (const auto& line : source.lines) {
        json l{{"row", line.row}};
        if (line.step) l["step"] = *line.step;
        switch (line.kind) {
            case program::SourceLine::Kind::Instruction:
                l["kind"] = "instruction";
                l["mnemonic"] = line.mnemonic;
                l["operands"] = line.operands;
                break;
            case program::SourceLine::Kind::Pointer:
                l["kind"] = "pointer";
                l["mnemonic"] = line.mnemonic;
                break;
            case program::SourceLine::Kind::Statement:
                l["kind"] = "statement";
                l["statement"] = line.statement;
                break;
        }
        if (!line.note.empty()) l["note"] = line.note;
        lines.push_back(std::move(l));
    }
    return lines;
}

// The live state of one operand as written in the program ("X0", "T0",
// "D100", "D0.F"): {"on": 0|1} for what a contact or coil shows, {"value": n}
// for a word (signed, as the engineering tool's monitor shows it), both for a
// timer or counter (its contact and current value). Constants, digit
// designations and indexed operands have no single device: null.
json operand_state(const devicemodel::DeviceMemory& memory, devicemodel::Numbering numbering, const std::string& text) {
    using devicemodel::Part;
    const auto device = program::operand_device(text, numbering);
    if (!device || device->number >= memory.size(device->area)) return nullptr;
    if (!device->spec) {   // "T0": the timer's or counter's contact and current value
        const auto* contact = devicemodel::find_by_part(device->area, Part::Contact);
        const auto* value = devicemodel::find_by_part(device->area, Part::Value);
        if (!contact || !value) return nullptr;
        return {{"on", memory.value(*contact, device->number)}, {"value", memory.value(*value, device->number)}};
    }
    const auto raw = memory.value(*device->spec, device->number);
    if (device->bit >= 0) return {{"on", (raw >> device->bit) & 1u}};
    switch (device->spec->unit) {
        case devicemodel::Unit::Bit: return {{"on", raw}};
        case devicemodel::Unit::Word: return {{"value", static_cast<std::int16_t>(raw)}};
        case devicemodel::Unit::DoubleWord: break;
    }
    return {{"value", static_cast<std::int32_t>(raw)}};
}

// GET /api/program/monitor: what the program page polls — the scan count and
// times, the last error's row, and the live state of every device operand.
json monitor_json(Api& api) {
    auto out = program_json(api);
    out.erase("comments");
    out.erase("warnings");
    auto& program = slot(api);
    json devices = json::object();
    if (program.loaded()) {
        const auto& memory = api.station.cpu().memory();
        const auto numbering = api.station.cpu().profile().numbering;
        for (const auto& line : program::source_of(*program.program()).lines)
            for (const auto& operand : line.operands)
                if (!devices.contains(operand)) devices[operand] = operand_state(memory, numbering, operand);
    }
    out["devices"] = std::move(devices);
    return out;
}

Reply load_problems(const program::LoadError& e) {
    return json_reply({{"error", e.problems.empty() ? std::string(e.what()) : e.problems.front()}, {"problems", e.problems}},
                      Status::unprocessable_entity);
}

// The change itself throws std::logic_error when the CPU is not in STOP.
template <typename Change>
Reply change(Api& api, Change&& operation) {
    try {
        operation(slot(api));
    } catch (const program::LoadError& e) {
        return load_problems(e);
    } catch (const std::logic_error& e) {
        fail(Status::conflict, std::string(e.what()) + "; stop the CPU first (PUT /api/state {\"switch\": \"STOP\"} or "
                                                       "Remote STOP 1002)");
    }
    return json_reply(program_json(api));
}

Reply source(Api& api, const ApiRequest& request) {
    auto& program = slot(api);
    if (!program.loaded()) fail(Status::not_found, "no program is loaded; PUT one to /api/program or start with --program");
    const auto* format = request.param("format");
    const auto& src = program::source_of(*program.program());
    Reply reply;
    if (!format || *format == "text") {
        reply.content_type = "text/plain; charset=utf-8";
        reply.body = program::write_text(src);
    } else if (*format == "csv") {
        // GX Works' own encoding (UTF-16LE with BOM), so the file reads back into it.
        reply.content_type = "text/csv; charset=utf-16le";
        reply.body = program::write_csv(src);
        reply.headers.emplace_back("Content-Disposition", "attachment; filename=\"" + src.name + ".csv\"");
    } else {
        fail(Status::bad_request, "format=" + *format + " is unknown; use format=csv (GX Works list) or format=text");
    }
    return reply;
}

}  // namespace

void add_program_endpoints(Router& router, Api& api) {
    router.add(Verb::get, "/api/program", {"lines"}, [&api](const ApiRequest& request) {
        auto out = program_json(api);
        if (request.param("lines") && slot(api).loaded()) out["lines"] = lines_json(program::source_of(*slot(api).program()));
        return json_reply(out);
    });
    router.add(Verb::get, "/api/program/monitor", {}, [&api](const ApiRequest&) { return json_reply(monitor_json(api)); });
    router.add(Verb::get, "/api/program/source", {"format"}, [&api](const ApiRequest& r) { return source(api, r); });
    router.add(Verb::put, "/api/program", {"file"}, [&api](const ApiRequest& request) {
        const auto* file = request.param("file");
        if (request.body.empty()) fail(Status::bad_request, "the body is empty; send the program file's bytes (curl --data-binary @line1.csv)");
        return change(api, [&](station::CpuProgram& p) { p.replace(request.body, file ? *file : std::string("program")); });
    });
    router.add(Verb::delete_, "/api/program", {}, [&api](const ApiRequest&) {
        return change(api, [](station::CpuProgram& p) { p.unload(); });
    });
    router.add(Verb::post, "/api/program/reload", {}, [&api](const ApiRequest&) {
        if (slot(api).config().file.empty())
            fail(Status::conflict, "no program file is configured; give cpu.program.file or --program, or PUT the program");
        return change(api, [](station::CpuProgram& p) { p.reload(); });
    });
}

}  // namespace slmp::control
