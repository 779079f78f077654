// slmp diff: the same generated requests (protocol/differential.hpp) to two
// servers — the target and --against — and every difference listed. Each
// frame kind and data code on a connection of its own; a variant the first
// request of which both servers leave unanswered is skipped (a 3E-only port:
// every 4E request would only wait for the silence).
#include <iostream>

#include "config/config.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"
#include "tools/slmp/wire.hpp"

namespace slmp::cli {

using protocol::Codec;
using protocol::FrameKind;
namespace differential = protocol::differential;

namespace {

Target parse_against(const std::string& text, const Target& like) {
    auto colon = text.rfind(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == text.size())
        throw UsageError("--against '" + text + "' must be HOST:PORT, e.g. 127.0.0.1:5001");
    Target target = like;
    target.host = text.substr(0, colon);
    try {
        auto port = std::stoul(text.substr(colon + 1));
        if (port == 0 || port > 65535) throw std::out_of_range("port");
        target.port = static_cast<std::uint16_t>(port);
    } catch (const std::exception&) {
        throw UsageError("--against '" + text + "': the port must be 1..65535");
    }
    return target;
}

}  // namespace

void run_diff(Invocation& in) {
    const auto& o = in.options;
    if (o.against.empty()) throw UsageError("diff needs --against HOST:PORT: the server to compare with");
    if (o.profile.empty())
        throw UsageError("diff needs --profile NAME|FILE: the profile whose limits and sizes the requests test "
                         "(the original's, so that a twin which differs shows it)");
    auto profile = config::load_profile(o.profile);
    auto other = parse_against(o.against, o.target);
    auto silence = o.silence.value_or(o.target.timeout);
    std::unique_ptr<WireRecorder> recorder;
    if (!o.record.empty()) recorder = std::make_unique<WireRecorder>(o.record, "diff against " + o.against);

    Table table;
    table.headers = {"frame", "request", "kind", "difference"};
    Json differences = Json::array();
    std::size_t sent = 0, skipped = 0;
    for (auto kind : {FrameKind::E3, FrameKind::E4}) {
        for (auto codec : {Codec::Binary, Codec::Ascii}) {
            auto frame = o.frame;
            frame.kind = kind;
            frame.codec = codec;
            frame.numbering = profile.cpu.numbering;
            const std::string variant = std::string(kind == FrameKind::E3 ? "3E" : "4E") +
                                        (codec == Codec::Binary ? " binary" : " ASCII");
            auto samples = differential::generate(profile.port, profile.cpu, frame);
            Wire a(o.target, silence, recorder.get()), b(other, silence, recorder.get());
            for (std::size_t i = 0; i < samples.size(); ++i) {
                auto first = a.exchange(samples[i].bytes);
                auto second = b.exchange(samples[i].bytes);
                ++sent;
                // The kinds slmp-sim --compare and slmp-replay name too (docs/twin.md, "Compare").
                if (auto d = differential::classify(first, second); !d.same()) {
                    const std::string kind(differential::kind_name(d.kind));
                    table.rows.push_back({variant, samples[i].label, kind, d.text});
                    differences.push_back({{"frame", variant}, {"request", samples[i].label}, {"kind", kind},
                                           {"difference", d.text}});
                }
                if (i == 0 && first.kind == differential::Observed::Kind::Silence &&
                    second.kind == differential::Observed::Kind::Silence) {
                    skipped += samples.size() - 1;
                    std::cerr << "diff: " << variant << ": no answer from either server; its other "
                              << samples.size() - 1 << " requests skipped\n";
                    break;
                }
            }
            a.close("variant done");
            b.close("variant done");
        }
    }
    std::cerr << "diff: " << sent << " requests sent to both, " << skipped << " skipped, " << differences.size()
              << " difference(s)\n";
    Json result{{"sent", sent}, {"skipped", skipped}, {"differences", differences}};
    if (differences.empty()) in.output.result(result, "no differences in " + std::to_string(sent) + " requests");
    else in.output.result(result, table);
    if (!differences.empty())
        throw DifferenceError(std::to_string(differences.size()) + " difference(s) between the servers");
}

}  // namespace slmp::cli
