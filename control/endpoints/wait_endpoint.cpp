// GET /api/devices/{address}/wait?equals=5&timeout_ms=2000 (also not_equals,
// greater, less, changes; as=bits|words|dwords). See control/endpoints/wait_endpoint.hpp.
#include "control/endpoints/device_names.hpp"
#include "control/endpoints/wait_endpoint.hpp"

#include <chrono>

#include "control/endpoints/device_view.hpp"
#include "control/observers/device_waits.hpp"

namespace slmp::control {

namespace asio = boost::asio;
using nlohmann::json;

namespace {

constexpr std::uint64_t kDefaultTimeoutMs = 10000;
constexpr std::uint64_t kMaxTimeoutMs = 600000;

struct Condition {
    enum class Kind : std::uint8_t { Equals, NotEquals, Greater, Less, Changes } kind;
    std::uint32_t operand = 0;   // Changes: the value when the wait began
    std::string text;            // "equals 5"

    bool holds(std::uint32_t value) const {
        switch (kind) {
            case Kind::Equals: return value == operand;
            case Kind::NotEquals: return value != operand;
            case Kind::Greater: return value > operand;
            case Kind::Less: return value < operand;
            case Kind::Changes: return value != operand;
        }
        return false;
    }
};

Condition parse_condition(const WaitTarget& target, const ApiRequest& request) {
    static const std::pair<const char*, Condition::Kind> kinds[] = {
        {"equals", Condition::Kind::Equals},   {"not_equals", Condition::Kind::NotEquals},
        {"greater", Condition::Kind::Greater}, {"less", Condition::Kind::Less},
        {"changes", Condition::Kind::Changes}};
    std::optional<Condition> found;
    for (const auto& [name, kind] : kinds) {
        const auto* value = request.param(name);
        if (!value) continue;
        if (found) bad("give one condition: " + found->text.substr(0, found->text.find(' ')) + " and " + name +
                       " were both given; wait twice for two conditions");
        if (kind == Condition::Kind::Changes) {
            if (!value->empty() && *value != "true" && *value != "1")
                bad("changes takes no value (write ?changes or ?changes=true)");
            found = Condition{kind, target.read(), "changes"};
        } else {
            if (value->empty()) bad(std::string(name) + " needs a value, e.g. ?" + name + "=5");
            found = Condition{kind, target.parse(*value), std::string(name) + " " + *value};
        }
    }
    if (!found) bad("say what to wait for: equals=N, not_equals=N, greater=N, less=N or changes (and timeout_ms=N)");
    return *found;
}

std::chrono::milliseconds timeout_of(const ApiRequest& request) {
    const auto* text = request.param("timeout_ms");
    if (!text) return std::chrono::milliseconds(kDefaultTimeoutMs);
    std::uint64_t ms = 0;
    bool digits = !text->empty() && text->size() <= 9;
    for (char c : *text) digits = digits && c >= '0' && c <= '9';
    if (digits) ms = std::stoull(*text);
    if (!digits || ms > kMaxTimeoutMs)
        bad("timeout_ms=" + *text + " is not a number of milliseconds from 0 to " + std::to_string(kMaxTimeoutMs));
    return std::chrono::milliseconds(ms);
}

json answer(const WaitTarget& target, const Condition& condition, std::uint32_t value,
            std::chrono::steady_clock::time_point began) {
    json out = target.fields;
    out["value"] = value;
    out["condition"] = condition.text;
    out["waited_ms"] =
        std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - began).count() / 1000.0;
    return out;
}

// The deferred half: the connection's coroutine awaits this while every other
// connection is served. Parameters by value: the frame owns them.
asio::awaitable<Reply> wait_until(Api& api, WaitTarget target, Condition condition, std::chrono::milliseconds timeout,
                                  std::chrono::steady_clock::time_point began) {
    auto executor = co_await asio::this_coro::executor;
    DeviceWaits::Waiter waiter(executor, [&] { return condition.holds(target.read()); });
    waiter.timer.expires_after(timeout);
    api.waits.add(&waiter);
    struct Leave {
        DeviceWaits& waits;
        DeviceWaits::Waiter* waiter;
        ~Leave() { waits.remove(waiter); }
    } leave{api.waits, &waiter};
    boost::system::error_code ec;
    co_await waiter.timer.async_wait(asio::redirect_error(asio::use_awaitable, ec));
    auto value = target.read();
    if (waiter.met || condition.holds(value)) co_return json_reply(answer(target, condition, value, began));
    auto body = answer(target, condition, value, began);
    body["error"] = target.name + " did not meet '" + condition.text + "' within " + std::to_string(timeout.count()) +
                    " ms; its last value is " + std::to_string(value) + " (raise timeout_ms, or check what should write it)";
    body["timeout_ms"] = timeout.count();
    co_return json_reply(body, Status::request_timeout);
}

Reply device_wait(Api& api, const ApiRequest& request) {
    auto named = parse_station_device(api.station, request.captures.at(0));
    auto start = named.start;
    View view = named.view.value_or(default_view(*start.spec));
    if (const auto* as = request.param("as")) {
        auto parsed = parse_view(*as);
        if (!parsed || *parsed == View::String) bad("as=" + *as + " cannot be waited on; use bits, words or dwords");
        view = *parsed;
    }
    auto run = make_run(api.station.cpu(), start, view, 1);
    WaitTarget target;
    target.name = devicemodel::format_address(start, run.numbering);
    target.fields = {{"device", target.name}, {"as", to_string(view)}};
    target.read = [&api, run] { return read_run(api.station.cpu().memory(), run)["values"][0].get<std::uint32_t>(); };
    target.parse = [view](const std::string& text) {
        auto number = json::parse(text, nullptr, false);
        if (number.is_discarded() || !(number.is_number_integer() || number.is_boolean()))
            bad("'" + text + "' is not a number; give an integer such as 5, -1 or, for bits, 0/1");
        return parse_values(json::array({number}), view).at(0);
    };
    return wait_reply(api, std::move(target), request);
}

}  // namespace

Reply wait_reply(Api& api, WaitTarget target, const ApiRequest& request) {
    auto began = std::chrono::steady_clock::now();
    auto condition = parse_condition(target, request);
    auto timeout = timeout_of(request);
    auto value = target.read();
    if (condition.kind != Condition::Kind::Changes && condition.holds(value))
        return json_reply(answer(target, condition, value, began));
    Reply reply;
    reply.deferred = [&api, target = std::move(target), condition, timeout, began] {
        return wait_until(api, target, condition, timeout, began);
    };
    return reply;
}

void add_wait_endpoints(Router& router, Api& api) {
    auto parameters = kWaitParameters;
    parameters.push_back("as");
    router.add(Verb::get, "/api/devices/{address}/wait", parameters,
               [&api](const ApiRequest& request) { return device_wait(api, request); });
}

}  // namespace slmp::control
