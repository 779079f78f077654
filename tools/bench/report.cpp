#include "tools/bench/report.hpp"

#include <cstdio>
#include <string>

#include "devicemodel/hex.hpp"

namespace slmp::bench {

namespace {

std::string format(const char* fmt, double value) {
    char text[64];
    std::snprintf(text, sizeof text, fmt, value);
    return text;
}


double rate(std::uint64_t count, double seconds) { return seconds > 0 ? static_cast<double>(count) / seconds : 0.0; }

std::string describe_setup(const Options& o) {
    std::string mix;
    for (const auto& m : o.mix) mix += (mix.empty() ? "" : ",") + m;
    return std::string(o.ascii ? "ascii" : "binary") + " " + (o.e4 ? "4E" : "3E") + ", " +
           std::to_string(o.connections) + " connection(s) x depth " + std::to_string(o.depth) + ", mix " + mix;
}

void table_row(std::ostream& out, const OperationResult& r, double seconds) {
    char line[256];
    const Latency& l = r.latency;
    std::snprintf(line, sizeof line, "%-10s %10llu %11.1f %8llu %9.1f %9.1f %9.1f %9.1f %9.1f\n", r.name.c_str(),
                  static_cast<unsigned long long>(r.ok), rate(r.ok, seconds),
                  static_cast<unsigned long long>(r.recorder.error_total()), l.p50, l.p90, l.p99, l.p999, l.max);
    out << line;
}

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) c = ' ';
        out += c;
    }
    return out + "\"";
}

void json_operation(std::ostream& out, const OperationResult& r, double seconds) {
    const Latency& l = r.latency;
    out << "{\"requests\":" << r.ok << ",\"requests_per_s\":" << format("%.1f", rate(r.ok, seconds))
        << ",\"errors\":{\"total\":" << r.recorder.error_total();
    for (std::size_t k = 0; k < r.recorder.errors.size(); ++k)
        out << ",\"" << to_string(static_cast<ErrorKind>(k)) << "\":" << r.recorder.errors[k];
    out << "},\"end_codes\":{";
    bool first = true;
    for (auto [code, n] : r.recorder.end_codes) {
        out << (first ? "" : ",") << "\"" << devicemodel::hex4(code) << "\":" << n;
        first = false;
    }
    out << "},\"latency_us\":{\"p50\":" << format("%.1f", l.p50) << ",\"p90\":" << format("%.1f", l.p90)
        << ",\"p99\":" << format("%.1f", l.p99) << ",\"p99_9\":" << format("%.1f", l.p999)
        << ",\"max\":" << format("%.1f", l.max) << ",\"mean\":" << format("%.1f", l.mean) << "}}";
}

// Server CPU per answered request, in microseconds.
double us_per_request(const Results& r) {
    return r.total.ok > 0 ? r.cpu.server_s * 1e6 / static_cast<double>(r.total.ok) : 0.0;
}

double cores(double cpu_s, double wall_s) { return wall_s > 0 ? cpu_s / wall_s : 0.0; }

void table_cpu(std::ostream& out, const Options& options, const Results& r) {
    if (options.server_pid <= 0) return;
    if (!r.cpu.measured) {
        out << "\nserver CPU: not measured (process " << options.server_pid << " ended, or the run did not get past its warm-up)\n";
        return;
    }
    char line[256];
    std::snprintf(line, sizeof line,
                  "\nserver CPU (pid %d): %.2f s in %.2f s (%.2f cores), %.2f us per request; client CPU %.2f s (%.2f cores)\n",
                  static_cast<int>(options.server_pid), r.cpu.server_s, r.cpu.wall_s, cores(r.cpu.server_s, r.cpu.wall_s),
                  us_per_request(r), r.cpu.client_s, cores(r.cpu.client_s, r.cpu.wall_s));
    out << line;
}

void json_cpu(std::ostream& out, const Options& options, const Results& r) {
    if (options.server_pid <= 0) return;
    out << ",\"cpu\":";
    if (!r.cpu.measured) {
        out << "null";
        return;
    }
    out << "{\"server_pid\":" << options.server_pid << ",\"wall_s\":" << format("%.3f", r.cpu.wall_s)
        << ",\"server_s\":" << format("%.3f", r.cpu.server_s)
        << ",\"server_cores\":" << format("%.3f", cores(r.cpu.server_s, r.cpu.wall_s))
        << ",\"server_us_per_request\":" << format("%.3f", us_per_request(r))
        << ",\"client_s\":" << format("%.3f", r.cpu.client_s)
        << ",\"client_cores\":" << format("%.3f", cores(r.cpu.client_s, r.cpu.wall_s)) << "}";
}

}  // namespace

void print_table(std::ostream& out, const Options& options, const Results& results) {
    out << "slmp-bench: " << results.target << ", " << describe_setup(options) << '\n';
    if (!results.fatal.empty()) {
        out << "FAILED: " << results.fatal << '\n';
        if (results.sent == 0) return;
    }
    out << "measured " << format("%.3f", results.seconds) << " s after " << format("%.1f", options.warmup)
        << " s warm-up; " << results.sent << " requests sent\n\n";
    out << "operation    requests       req/s   errors    p50 us    p90 us    p99 us  p99.9 us    max us\n";
    for (const auto& op : results.operations) table_row(out, op, results.seconds);
    if (results.operations.size() > 1) table_row(out, results.total, results.seconds);
    const Recorder& e = results.total.recorder;
    if (e.error_total() > 0) {
        out << "\nerrors:";
        for (std::size_t k = 0; k < e.errors.size(); ++k)
            out << ' ' << to_string(static_cast<ErrorKind>(k)) << ' ' << e.errors[k];
        for (auto [code, n] : e.end_codes) out << "  (end code " << devicemodel::hex4(code) << " x" << n << ")";
        out << '\n';
    }
    table_cpu(out, options, results);
}

void print_json(std::ostream& out, const Options& options, const Results& results) {
    std::string mix;
    for (const auto& m : options.mix) mix += (mix.empty() ? "" : ",") + json_string(m);
    out << "{\"target\":" << json_string(results.target) << ",\"targets\":" << results.targets << ",\"codec\":\"" << (options.ascii ? "ascii" : "binary")
        << "\",\"frame\":\"" << (options.e4 ? "4E" : "3E") << "\",\"connections\":" << options.connections
        << ",\"depth\":" << options.depth << ",\"mix\":[" << mix << "]"
        << ",\"warmup_s\":" << format("%.3f", options.warmup) << ",\"seconds\":" << format("%.3f", results.seconds)
        << ",\"sent\":" << results.sent << ",";
    if (!results.fatal.empty()) out << "\"fatal\":" << json_string(results.fatal) << ",";
    out << "\"total\":";
    json_operation(out, results.total, results.seconds);
    out << ",\"operations\":{";
    for (std::size_t i = 0; i < results.operations.size(); ++i) {
        out << (i ? "," : "") << json_string(results.operations[i].name) << ":";
        json_operation(out, results.operations[i], results.seconds);
    }
    out << "}";
    json_cpu(out, options, results);
    out << "}\n";
}

}  // namespace slmp::bench
