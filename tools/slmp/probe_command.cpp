// slmp probe: runs the Prober (probe.hpp) against the target and writes the
// profile; progress on stderr, the summary table (or --json) on stdout.
#include <fstream>
#include <iostream>

#include "config/config.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"
#include "tools/slmp/probe.hpp"

namespace slmp::cli {

void run_probe(Invocation& in) {
    const auto& o = in.options;
    if (o.out.empty()) throw UsageError("probe needs --out FILE: where to write the probed profile");
    if (!o.args.empty()) throw UsageError("probe takes no arguments (got '" + o.args.front() + "')");
    ProbeSettings settings;
    settings.target = o.target;
    settings.frame = o.frame;
    settings.silence = o.silence.value_or(o.target.timeout);
    if (!o.allow_writes.empty()) settings.scratch = parse_scratch_ranges(o.allow_writes, o.frame.numbering);
    std::unique_ptr<WireRecorder> recorder;
    if (!o.record.empty()) recorder = std::make_unique<WireRecorder>(o.record, "probe of " + o.target.host);

    auto started = Clock::now();
    Prober prober(settings, recorder.get(), std::cerr);
    auto profile = prober.run();
    auto seconds = std::chrono::duration<double>(Clock::now() - started).count();

    const auto& base = prober.base();
    nlohmann::ordered_json file{
        {"name", "probed-" + o.target.host + "-" + std::to_string(o.target.port)},
        {"description", "probed by slmp probe from " + o.target.host + ":" + std::to_string(o.target.port) +
                            "; what the probe could not find is " + base + "'s (docs/twin.md)"},
        {"extends", base}};
    for (const auto& [key, value] : profile.items()) file[key] = value;
    std::ofstream out(o.out);
    if (!out) throw UsageError("--out '" + o.out + "': cannot write the file; check the directory");
    out << file.dump(2) << '\n';
    out.close();
    // The file must be a profile slmp-sim loads as it is.
    try {
        config::load_profile(o.out);
    } catch (const std::exception& e) {
        throw ConnectionError(std::string("the probed profile does not load: ") + e.what() +
                              " (a probe bug: please report it with --record)");
    }

    Table table;
    table.headers = {"fact", "value", "how", "found"};
    Json facts = Json::array();
    for (const auto& f : prober.facts()) {
        table.rows.push_back({f.name, f.value, f.how, f.found ? "yes" : "no: base's"});
        facts.push_back({{"fact", f.name}, {"value", f.value}, {"how", f.how}, {"found", f.found}});
    }
    Json result{{"profile", o.out}, {"extends", base}, {"requests", prober.requests()}, {"seconds", seconds},
                {"facts", facts}};
    in.output.result(result, table);
    std::cerr << "probe: " << prober.requests() << " requests in " << seconds << " s; profile written to " << o.out
              << " (slmp-sim --profile " << o.out << ")\n";
}

}  // namespace slmp::cli
