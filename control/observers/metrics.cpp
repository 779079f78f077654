#include "control/observers/metrics.hpp"
#include "station/comparison.hpp"
#include "station/cpu_program.hpp"

#include <cstdio>

#include "devicemodel/drives.hpp"
#include "devicemodel/hex.hpp"
#include "frontends/face.hpp"

namespace slmp::control {

using protocol::Outcome;

namespace {

constexpr std::array<const char*, 2> kTransportNames = {"tcp", "udp"};

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

// Prometheus label values: backslash, quote and newline escaped.
std::string label(std::string_view value) {
    std::string out;
    for (char c : value) {
        if (c == '\\' || c == '"') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out;
}

void header(std::string& out, const char* name, const char* type, const char* help) {
    out += "# HELP ";
    out += name;
    out += ' ';
    out += help;
    out += "\n# TYPE ";
    out += name;
    out += ' ';
    out += type;
    out += '\n';
}

}  // namespace

Metrics::Metrics(station::Station& station) : station_(station) { station_.activity().add_observer(this); }
Metrics::~Metrics() { station_.activity().remove_observer(this); }

void Metrics::on_request(const station::RequestRecord& record) {
    const auto& outcome = record.outcome;
    auto transport = static_cast<std::size_t>(record.peer.transport == protocol::Transport::Udp);
    auto& t = transports_[transport];
    t.bytes_in += record.frame.size();
    t.bytes_out += outcome.response.size();
    // Frames rejected before their command was read carry command 0/0.
    if (outcome.command == 0 && outcome.subcommand == 0) {
        ++t.unparsed;
        return;
    }
    std::uint32_t reaction = outcome.action == Outcome::Action::Respond ? static_cast<std::uint32_t>(outcome.end_code)
                             : outcome.action == Outcome::Action::Close ? kClosed
                                                                        : kNoAnswer;
    ++requests_[RequestKey{static_cast<std::uint8_t>(transport), outcome.command, outcome.subcommand, reaction}];

    double seconds = std::chrono::duration<double>(record.latency).count();
    std::size_t bucket = 0;
    while (bucket < kBuckets.size() && seconds > kBuckets[bucket]) ++bucket;
    ++latency_buckets_[bucket];
    latency_sum_ += seconds;
    ++latency_count_;
    if (record.modelled) {
        double modelled = std::chrono::duration<double>(*record.modelled).count();
        std::size_t b = 0;
        while (b < kBuckets.size() && modelled > kBuckets[b]) ++b;
        ++modelled_buckets_[b];
        modelled_sum_ += modelled;
        ++modelled_count_;
    }
}

void Metrics::on_frontend_request(const station::FrontEndRecord& record) {
    auto transport = static_cast<std::uint8_t>(record.peer.transport == protocol::Transport::Udp);
    auto command = record.command.empty() ? std::string("none") : record.known ? std::string(record.command) : std::string("other");
    // A forced code is any byte; the front ends' own codes are two hex digits or IC.
    auto code = record.closed ? std::string("closed") : record.code.empty() ? std::string("none") : std::string(record.code);
    ++frontend_requests_[FrontEndKey{std::string(record.protocol), transport, std::move(command), std::move(code)}];
}

Metrics::Totals Metrics::totals() const {
    Totals totals;
    for (const auto& [key, count] : requests_) {
        totals.requests += count;
        if (std::get<3>(key) != 0) totals.errors += count;
    }
    for (const auto& [key, count] : frontend_requests_) {
        totals.requests += count;
        if (std::get<3>(key) != "00") totals.errors += count;
    }
    for (const auto& t : transports_) {
        totals.requests += t.unparsed;
        totals.errors += t.unparsed;
    }
    return totals;
}

void Metrics::on_opened(const station::Connection&) { ++accepted_; }
void Metrics::on_closed(const station::Connection&, std::string_view) { ++closed_; }

std::string Metrics::render() const {
    std::string out;
    const auto& profile = station_.cpu().profile();
    header(out, "slmp_info", "gauge", "The simulated CPU (always 1).");
    out += "slmp_info{profile=\"" + label(profile.name) + "\",type_name=\"" + label(profile.type_name) + "\"} 1\n";

    header(out, "slmp_requests_total", "counter",
           "SLMP requests handled, by transport, command, subcommand and end code "
           "(end_code=\"none\": not answered, \"closed\": the connection was closed).");
    for (const auto& [key, count] : requests_) {
        auto [transport, command, subcommand, reaction] = key;
        auto code = reaction == kNoAnswer ? std::string("none") : reaction == kClosed ? std::string("closed") : devicemodel::hex4(reaction);
        out += "slmp_requests_total{transport=\"" + std::string(kTransportNames[transport]) + "\",command=\"" +
               devicemodel::hex4(command) + "\",subcommand=\"" + devicemodel::hex4(subcommand) + "\",end_code=\"" + code + "\"} " +
               std::to_string(count) + "\n";
    }

    std::string faces;   // the protocol faces' names (frontends/face.hpp)
    for (const auto* face : frontends::faces()) faces += (faces.empty() ? "\"" : ", \"") + std::string(face->name()) + "\"";
    header(out, "slmp_frontend_requests_total", "counter",
           ("Requests to the station's other protocols (protocol " + faces + "), by transport, command "
           "(\"other\": not in the front end's table; \"none\": no command could be read) and response code "
           "(host-link code or JW RSLT; \"none\": not answered, \"closed\": a fault closed the connection).")
               .c_str());
    for (const auto& [key, count] : frontend_requests_) {
        const auto& [protocol, transport, command, code] = key;
        out += "slmp_frontend_requests_total{protocol=\"" + protocol + "\",transport=\"" +
               std::string(kTransportNames[transport]) + "\",command=\"" + label(command) + "\",code=\"" + label(code) +
               "\"} " + std::to_string(count) + "\n";
    }

    header(out, "slmp_unparsed_frames_total", "counter",
           "Frames rejected before their command was read: bytes that are no request frame, 4E frames on a "
           "3E-only port, oversized or too short length fields.");
    for (std::size_t i = 0; i < transports_.size(); ++i)
        out += "slmp_unparsed_frames_total{transport=\"" + std::string(kTransportNames[i]) + "\"} " +
               std::to_string(transports_[i].unparsed) + "\n";

    header(out, "slmp_request_duration_seconds", "histogram",
           "Time the simulator spent handling a request: decode, execute, encode (network and queueing not included).");
    std::uint64_t cumulative = 0;
    for (std::size_t i = 0; i < kBuckets.size(); ++i) {
        cumulative += latency_buckets_[i];
        out += "slmp_request_duration_seconds_bucket{le=\"" + number(kBuckets[i]) + "\"} " + std::to_string(cumulative) + "\n";
    }
    cumulative += latency_buckets_.back();
    out += "slmp_request_duration_seconds_bucket{le=\"+Inf\"} " + std::to_string(cumulative) + "\n";
    out += "slmp_request_duration_seconds_sum " + number(latency_sum_) + "\n";
    out += "slmp_request_duration_seconds_count " + std::to_string(latency_count_) + "\n";

    header(out, "slmp_modelled_response_seconds", "histogram",
           "The timing model's response time of each request, in CPU time (timing mode \"model\"; docs/timing.md).");
    cumulative = 0;
    for (std::size_t i = 0; i < kBuckets.size(); ++i) {
        cumulative += modelled_buckets_[i];
        out += "slmp_modelled_response_seconds_bucket{le=\"" + number(kBuckets[i]) + "\"} " + std::to_string(cumulative) + "\n";
    }
    cumulative += modelled_buckets_.back();
    out += "slmp_modelled_response_seconds_bucket{le=\"+Inf\"} " + std::to_string(cumulative) + "\n";
    out += "slmp_modelled_response_seconds_sum " + number(modelled_sum_) + "\n";
    out += "slmp_modelled_response_seconds_count " + std::to_string(modelled_count_) + "\n";

    header(out, "slmp_received_bytes_total", "counter", "Bytes of SLMP request frames received (including skipped garbage).");
    for (std::size_t i = 0; i < transports_.size(); ++i)
        out += "slmp_received_bytes_total{transport=\"" + std::string(kTransportNames[i]) + "\"} " +
               std::to_string(transports_[i].bytes_in) + "\n";
    header(out, "slmp_sent_bytes_total", "counter", "Bytes of SLMP response frames sent.");
    for (std::size_t i = 0; i < transports_.size(); ++i)
        out += "slmp_sent_bytes_total{transport=\"" + std::string(kTransportNames[i]) + "\"} " +
               std::to_string(transports_[i].bytes_out) + "\n";

    header(out, "slmp_open_connections", "gauge", "TCP connections open now.");
    out += "slmp_open_connections " + std::to_string(station_.activity().connections().size()) + "\n";
    header(out, "slmp_connections_accepted_total", "counter", "TCP connections accepted.");
    out += "slmp_connections_accepted_total " + std::to_string(accepted_) + "\n";
    header(out, "slmp_connections_closed_total", "counter", "TCP connections closed (by either side).");
    out += "slmp_connections_closed_total " + std::to_string(closed_) + "\n";

    // File drives (docs/files.md): what 1810-182A act on; the requests themselves
    // are in slmp_requests_total by command and end code.
    header(out, "slmp_file_drive_used_bytes", "gauge", "Bytes of file data on each file drive of CPU No.1.");
    std::string capacity;
    for (const auto& d : station_.cpu().drives().drives()) {
        if (d.spec.alias_of) continue;
        auto drive = "{drive=\"" + std::to_string(d.spec.number) + "\"} ";
        out += "slmp_file_drive_used_bytes" + drive + std::to_string(d.used) + "\n";
        capacity += "slmp_file_drive_capacity_bytes" + drive + std::to_string(d.spec.capacity) + "\n";
    }
    header(out, "slmp_file_drive_capacity_bytes", "gauge", "Capacity of each file drive of CPU No.1.");
    out += capacity;
    header(out, "slmp_open_files", "gauge", "Files open (locked) with 1827 now, on every drive.");
    out += "slmp_open_files " + std::to_string(station_.cpu().drives().open_files().size()) + "\n";

    // The CPU's own view (SD203 and SD520-SD525), so a dashboard needs no SLMP poll.
    header(out, "slmp_cpu_state", "gauge", "Operating state as SD203 shows it: 0 RUN, 2 STOP, 3 PAUSE.");
    out += "slmp_cpu_state " + std::to_string(static_cast<int>(station_.cpu().runtime().state())) + "\n";
    header(out, "slmp_scan_time_seconds", "gauge", "Scan time in RUN: the last scan, and the minimum and maximum since RUN.");
    if (auto scan = station_.cpu().runtime().scan_times()) {
        auto seconds = [](std::chrono::microseconds us) { return number(std::chrono::duration<double>(us).count()); };
        out += "slmp_scan_time_seconds{kind=\"current\"} " + seconds(scan->current) + "\n";
        out += "slmp_scan_time_seconds{kind=\"min\"} " + seconds(scan->min) + "\n";
        out += "slmp_scan_time_seconds{kind=\"max\"} " + seconds(scan->max) + "\n";
    }

    // The PLC program (docs/program.md), read when scraped; absent without one.
    if (const auto* program = station_.program(); program && program->loaded()) {
        const auto& stats = program->statistics();
        const auto modelled = program->execution()->modelled_times();
        header(out, "slmp_program_scans_total", "counter", "Scans the loaded PLC program ran.");
        out += "slmp_program_scans_total " + std::to_string(stats.scans) + "\n";
        header(out, "slmp_program_operation_errors_total", "counter", "Scans of the PLC program that raised an operation error or the watchdog.");
        out += "slmp_program_operation_errors_total " + std::to_string(stats.operation_errors) + "\n";
        header(out, "slmp_program_execution_seconds", "gauge",
               "Modelled execution time of the program's scans (instructions and END processing): the last, the least and the most.");
        auto seconds = [](std::chrono::nanoseconds ns) { return number(std::chrono::duration<double>(ns).count()); };
        out += "slmp_program_execution_seconds{kind=\"last\"} " + seconds(modelled.last) + "\n";
        out += "slmp_program_execution_seconds{kind=\"min\"} " + seconds(modelled.min) + "\n";
        out += "slmp_program_execution_seconds{kind=\"max\"} " + seconds(modelled.max) + "\n";
    }

    // Differential mode (docs/twin.md, "Compare"), read when scraped; absent without it.
    if (const auto* comparison = station_.comparison()) {
        header(out, "slmp_compare_total", "counter",
               "Requests served both by the upstream and by this station (--compare): the same answer, or different.");
        out += "slmp_compare_total{result=\"same\"} " + std::to_string(comparison->same()) + "\n";
        out += "slmp_compare_total{result=\"different\"} " + std::to_string(comparison->different()) + "\n";
        header(out, "slmp_compare_differences_total", "counter",
               "Differences between the upstream's answer and this station's, by kind: close, silence, end_code, "
               "bytes, time (docs/twin.md).");
        for (auto kind : protocol::differential::kDifferenceKinds)
            out += "slmp_compare_differences_total{kind=\"" + std::string(protocol::differential::kind_name(kind)) + "\"} " +
                   std::to_string(comparison->count(kind)) + "\n";
    }

    // Read from the scenarios when scraped: a counter per running fault, gone
    // when its scenario stops (Prometheus treats a reappearing one as a reset).
    header(out, "slmp_faults_fired_total", "counter", "Times each fault of the running scenarios fired.");
    for (const auto& f : station_.scenario().fault_stats())
        out += "slmp_faults_fired_total{scenario=\"" + label(f.scenario) + "\",fault=\"" + label(f.name) + "\",kind=\"" +
               label(f.kind) + "\"} " + std::to_string(f.fired) + "\n";
    return out;
}

}  // namespace slmp::control
