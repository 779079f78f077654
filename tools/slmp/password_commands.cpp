// slmp lock|unlock PASSWORD: Remote Password Lock 1631 / Unlock 1630.
// The CPU keeps the lock state per connection, and each slmp run is a new
// connection; to reach a locked PLC use the global --password, which unlocks
// on the same connection before the command.
#include "protocol/client_commands.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"
#include "tools/slmp/password.hpp"

namespace slmp::cli {
namespace {

namespace client = protocol::client;

const std::string& password_argument(const Invocation& in) {
    if (in.options.args.size() != 1)
        throw UsageError(in.options.command + " needs exactly one PASSWORD, e.g. slmp " + in.options.command + " abcd1234");
    check_password(in.options.args[0]);
    return in.options.args[0];
}

}  // namespace

void run_lock(Invocation& in) {
    in.client.exchange(client::lock(in.client.frame(), password_argument(in)));
    in.output.result(Json{{"command", "lock"}, {"ok", true}}, "remote password lock: OK");
}

void run_unlock(Invocation& in) {
    in.client.exchange(client::unlock(in.client.frame(), password_argument(in)));
    in.output.result(Json{{"command", "unlock"}, {"ok", true}}, "remote password unlock: OK");
}

}  // namespace slmp::cli
