// slmp run|stop|pause|reset|latch-clear: Remote Control 1001/1002/1003/1006/1005.
// Success answers carry no data. Remote RESET is the exception: a real CPU that
// resets sends no answer at all and drops TCP, so silence counts as success
// (an error end code still fails with exit code 1).
#include "protocol/client_commands.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {
namespace {

namespace client = protocol::client;

void no_arguments(const Invocation& in) {
    if (!in.options.args.empty())
        throw UsageError(in.options.command + " takes no arguments (got '" + in.options.args.front() + "')");
}

client::RemoteMode mode(const Invocation& in) {
    return in.options.force ? client::RemoteMode::Force : client::RemoteMode::Normal;
}

// Checks that no arguments were given, sends what `build` makes from the frame
// options, and reports success.
template <class Build>
void remote(Invocation& in, const char* what, Json json, Build build) {
    no_arguments(in);
    in.client.exchange(build(in.client.frame()));
    json["ok"] = true;
    in.output.result(json, std::string(what) + ": OK");
}

}  // namespace

void run_remote_run(Invocation& in) {
    const auto& clear = in.options.clear;
    client::ClearMode clear_mode;
    if (clear == "none") clear_mode = client::ClearMode::None;
    else if (clear == "nonlatch") clear_mode = client::ClearMode::NonLatch;
    else if (clear == "all") clear_mode = client::ClearMode::All;
    else throw UsageError("--clear '" + clear + "' must be none, nonlatch or all");
    remote(in, "remote RUN", Json{{"command", "run"}, {"force", in.options.force}, {"clear", clear}},
           [&](const client::FrameOptions& f) { return client::remote_run(f, mode(in), clear_mode); });
}

void run_remote_stop(Invocation& in) { remote(in, "remote STOP", Json{{"command", "stop"}}, client::remote_stop); }

void run_remote_pause(Invocation& in) {
    remote(in, "remote PAUSE", Json{{"command", "pause"}, {"force", in.options.force}},
           [&](const client::FrameOptions& f) { return client::remote_pause(f, mode(in)); });
}

void run_remote_latch_clear(Invocation& in) {
    remote(in, "remote latch clear", Json{{"command", "latch-clear"}}, client::remote_latch_clear);
}

void run_remote_reset(Invocation& in) {
    no_arguments(in);
    auto answer = in.client.exchange_allow_silence(client::remote_reset(in.client.frame()));
    Json json{{"command", "reset"}, {"ok", true}, {"answered", answer.has_value()}};
    in.output.result(json, answer ? "remote RESET: OK (answered 0000)"
                                  : "remote RESET: sent; no answer, as a real CPU gives when it resets");
}

}  // namespace slmp::cli
