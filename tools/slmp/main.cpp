// slmp: a command-line SLMP client for MELSEC PLCs and slmp-sim. See docs/cli.md.
//
// Exit status: 0 success; 1 the PLC answered an error end code (its meaning is
// printed); 2 usage error; 3 connection failure, timeout or an answer that is
// not a valid response to the request.
#include <algorithm>
#include <iostream>

#include "protocol/end_code.hpp"
#include "tools/slmp/arguments.hpp"
#include "tools/slmp/client.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"
#include "tools/slmp/options.hpp"
#include "tools/slmp/output.hpp"
#include "tools/slmp/password.hpp"
#include "tools/slmp/station_lookup.hpp"

namespace {

using namespace slmp::cli;

const CommandSpec& resolve_command(const Options& options) {
    const auto* spec = find_command(options.command);
    if (!spec) throw UsageError("unknown command '" + options.command + "' (try --help)");
    for (const auto& given : options.given) {
        if (std::find(spec->accepts.begin(), spec->accepts.end(), given) == spec->accepts.end())
            throw UsageError("--" + given + " does not apply to '" + options.command + "'");
    }
    if (options.password) check_password(*options.password);
    return *spec;
}

int fail(Output& output, int code, const std::string& kind, const std::string& message, Json extra = Json::object()) {
    std::cerr << "slmp: " << message << '\n';
    Json error{{"kind", kind}, {"message", message}};
    for (auto& [key, value] : extra.items()) error[key] = value;
    output.error_json(error);
    return code;
}

}  // namespace

int main(int argc, char** argv) {
    int exit_code = kOk;
    auto options = parse_options(argc, argv, exit_code);
    if (!options) return exit_code;
    Output output(std::cout, options->json);
    try {
        const auto& spec = resolve_command(*options);
        if (!options->plant_station.empty())
            look_up_station(options->target, options->frame.numbering, options->plant_station, options->api_port);
        Client client(options->target, options->frame, options->password);
        Invocation invocation{*options, client, output};
        spec.run(invocation);
        return kOk;
    } catch (const UsageError& e) {
        return fail(output, kUsage, "usage", e.what());
    } catch (const EndCodeError& e) {
        Json extra{{"end_code", word_hex(e.end_code, 4)},
                   {"meaning", std::string(slmp::protocol::describe(slmp::protocol::end_code(e.end_code)))}};
        if (e.error_info) {
            extra["command"] = word_hex(e.error_info->command, 4);
            extra["subcommand"] = word_hex(e.error_info->subcommand, 4);
        }
        return fail(output, kEndCode, "end_code", std::string("the PLC answered end code ") + e.what(), extra);
    } catch (const DifferenceError& e) {
        return fail(output, kEndCode, "difference", e.what());
    } catch (const ConnectionError& e) {
        return fail(output, kConnection, "connection", e.what());
    } catch (const std::exception& e) {
        return fail(output, kConnection, "internal", e.what());
    }
}
