// slmp type (0101 Read Type Name) and slmp selftest (0619 Self Test loopback).
#include "protocol/client_commands.hpp"
#include "tools/slmp/arguments.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {

namespace client = protocol::client;

void run_type(Invocation& in) {
    if (!in.options.args.empty()) throw UsageError("type takes no arguments");
    auto response = in.client.exchange(client::read_type_name(in.client.frame()));
    auto type = client::decode_type_name(response);
    if (!type) throw ConnectionError("the Read Type Name answer is not 16 characters and a model code");
    auto code = word_hex(type->model_code, 4);
    in.output.result(Json{{"model", type->model}, {"model_code", code}},
                     Table{{"model", "model code"}, {{type->model, code}}});
}

// The manual asks for 1–960 characters of 0-9/A-F; anything printable is sent
// as given, so a PLC's answer to other characters can be seen too.
void run_selftest(Invocation& in) {
    const auto& args = in.options.args;
    if (args.size() > 1) throw UsageError("selftest takes at most one DATA argument");
    std::string data = args.empty() ? "0123456789ABCDEF" : args[0];
    if (data.empty() || data.size() > 960) throw UsageError("selftest DATA must be 1..960 characters");
    for (unsigned char c : data)
        if (c < 0x20 || c > 0x7E) throw UsageError("selftest DATA must be printable ASCII (the manual asks for 0-9, A-F)");
    auto response = in.client.exchange(client::self_test(in.client.frame(), data));
    auto echoed = client::decode_self_test(response);
    if (!echoed) throw ConnectionError("the Self Test answer's count does not match its data");
    if (*echoed != data) throw ConnectionError("the PLC echoed '" + *echoed + "' instead of '" + data + "'");
    in.output.result(Json{{"sent", data}, {"received", *echoed}, {"match", true}},
                     "loopback OK: " + std::to_string(data.size()) + " byte(s) echoed");
}

}  // namespace slmp::cli
