// slmp monitor ITEM... [--interval 500ms] [--count N]
// Polls each item with one 0401 Device Read (bit units for bit devices, word
// units for word devices) and prints one row per poll, until Ctrl-C (SIGINT or
// SIGTERM: the current poll finishes, then exit 0) or --count polls. Items are
// devices (D100, M0) or inclusive ranges of one device (D100-D109, X0-X1F).
// Polls start every --interval (a slow answer delays the next poll, it never
// makes two overlap). 0403 Read Random would take one request, but 0401 is the
// one command every CPU and port serves.
#include <csignal>
#include <ctime>
#include <vector>

#include <boost/asio/signal_set.hpp>
#include <boost/asio/steady_timer.hpp>

#include "protocol/client.hpp"
#include "tools/slmp/arguments.hpp"
#include "tools/slmp/commands.hpp"
#include "tools/slmp/errors.hpp"

namespace slmp::cli {
namespace {

namespace client = protocol::client;

struct Item {
    DeviceRange range;
    bool bits;
    std::uint16_t points;      // on the wire: bits, or words
    std::vector<std::string> labels;
};

Item make_item(const std::string& text, devicemodel::Numbering numbering) {
    Item item{parse_range(text, numbering), false, 0, {}};
    item.bits = is_bit_device(item.range.start);
    std::uint64_t points = item.range.points;
    if (!item.bits) points *= devicemodel::words_per_device(*item.range.start.spec);
    if (points > 65535) throw UsageError("'" + text + "' is too long for one read (65535 points at most)");
    item.points = static_cast<std::uint16_t>(points);
    item.labels = value_labels(item.range.start, item.points, item.bits, numbering);
    return item;
}

// Wall-clock time of a poll: local HH:MM:SS.mmm for the table, UTC ISO 8601 for JSON.
struct Stamp {
    std::string local;
    std::string utc;
};

Stamp now_stamp() {
    auto now = std::chrono::system_clock::now();
    auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
    std::time_t t = std::chrono::system_clock::to_time_t(now);
    std::tm local{}, utc{};
    localtime_r(&t, &local);
    gmtime_r(&t, &utc);
    char a[32], b[40];
    std::strftime(a, sizeof a, "%H:%M:%S", &local);
    std::strftime(b, sizeof b, "%Y-%m-%dT%H:%M:%S", &utc);
    char ms_text[8];
    std::snprintf(ms_text, sizeof ms_text, ".%03d", static_cast<int>(ms));
    return {std::string(a) + ms_text, std::string(b) + ms_text + "Z"};
}

}  // namespace

void run_monitor(Invocation& in) {
    const auto& args = in.options.args;
    if (args.empty()) throw UsageError("monitor needs devices, e.g. slmp monitor D100 M0 D200-D209 --interval 500ms");
    std::vector<Item> items;
    std::vector<std::string> headers{"time"};
    for (const auto& text : args) {
        items.push_back(make_item(text, in.client.frame().numbering));
        headers.insert(headers.end(), items.back().labels.begin(), items.back().labels.end());
    }

    auto& io = in.client.link().context();
    bool interrupted = false;
    boost::asio::signal_set signals(io, SIGINT, SIGTERM);
    signals.async_wait([&](const boost::system::error_code& ec, int) {
        if (!ec) interrupted = true;
    });

    in.output.stream_header(headers);
    auto next = Clock::now();
    for (unsigned long poll = 1; !interrupted; ++poll) {
        auto stamp = now_stamp();
        Json values = Json::object();
        std::vector<std::string> cells{stamp.local};
        for (const auto& item : items) {
            const auto& frame = in.client.frame();
            auto request = item.bits ? client::read_bits(frame, item.range.start, item.points, in.options.form)
                                     : client::read_words(frame, item.range.start, item.points, in.options.form);
            auto response = in.client.exchange(request);
            auto reader = response.reader();   // reads from `response`, which must outlive it
            auto data = item.bits ? reader.bits(item.points, "read data") : std::vector<std::uint8_t>{};
            auto words = item.bits ? std::vector<std::uint16_t>{} : reader.words(item.points, "read data");
            if (!reader.finish()) throw ConnectionError("the read data does not match the points requested");
            for (std::size_t i = 0; i < item.points; ++i) {
                unsigned value = item.bits ? data[i] : words[i];
                values[item.labels[i]] = value;
                cells.push_back(std::to_string(value));
            }
        }
        in.output.stream_row(Json{{"time", stamp.utc}, {"poll", poll}, {"values", values}}, cells);
        if (in.options.count && poll >= *in.options.count) break;

        next += in.options.interval;
        boost::asio::steady_timer timer(io, next);
        bool ticked = false;
        timer.async_wait([&](const boost::system::error_code&) { ticked = true; });
        io.restart();
        while (!ticked && !interrupted) io.run_one();
        timer.cancel();
        while (!ticked) io.run_one();
        if (Clock::now() > next + in.options.interval) next = Clock::now();   // fell behind: do not burst
    }
    signals.cancel();
}

}  // namespace slmp::cli
