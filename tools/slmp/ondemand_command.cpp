// slmp ondemand --wait [--count N] [--timeout 60s]
// Listens for Ondemand (2101) pushes the station sends unasked (docs/timing.md)
// and prints each: the time and its words. Over UDP the station only knows a
// client that has sent it something, so a Read Type Name (0101) goes first.
#include <ctime>

#include "devicemodel/hex.hpp"
#include "protocol/client.hpp"
#include "protocol/client_commands.hpp"
#include "protocol/ondemand.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {

void run_ondemand(Invocation& in) {
    if (!in.options.wait) throw UsageError("ondemand needs --wait: the CPU sends, the client listens (slmp ondemand --wait)");
    if (!in.options.args.empty()) throw UsageError("ondemand takes no arguments; give --count N to wait for N pushes");
    if (in.client.link().datagram()) in.client.exchange(protocol::client::read_type_name(in.client.frame()));
    const unsigned long pushes = in.options.count.value_or(1);
    in.output.stream_header({"push", "words"});
    for (unsigned long n = 1; n <= pushes; ++n) {
        auto frame = in.client.next_push(Clock::now() + in.options.target.timeout);
        auto reader = frame.reader();
        const auto command = reader.u16("command");
        const auto subcommand = reader.u16("subcommand");
        if (!reader.ok() || command != protocol::kOndemandCommand || subcommand != 0)
            throw ConnectionError("a frame that is no Ondemand push arrived (command " + devicemodel::hex4(command) + ")");
        const auto count = (frame.data.size() - (frame.header.codec == protocol::Codec::Ascii ? 8 : 4)) /
                           (frame.header.codec == protocol::Codec::Ascii ? 4 : 2);
        auto words = reader.words(count, "send data");
        Json values = Json::array();
        std::string cells;
        for (auto w : words) {
            values.push_back(w);
            cells += (cells.empty() ? "" : " ") + std::to_string(w);
        }
        in.output.stream_row(Json{{"push", n}, {"command", "2101"}, {"words", values}}, {std::to_string(n), cells});
    }
}

}  // namespace slmp::cli
