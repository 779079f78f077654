// The completion handler for co_spawn: an exception that ends a coroutine is
// logged with what stopped, never dropped: no bare `detached` (docs/architecture.md, "Errors are values").
// `on_error`, when given, runs after the log line (a session then finishes
// itself instead of leaking its connection).
#pragma once

#include <exception>
#include <functional>
#include <string>

#include <spdlog/spdlog.h>

namespace slmp::station {

inline auto log_exception(std::string what, std::function<void()> on_error = {}) {
    return [what = std::move(what), on_error = std::move(on_error)](std::exception_ptr e) {
        if (!e) return;
        try {
            std::rethrow_exception(e);
        } catch (const std::exception& ex) {
            spdlog::error("{}: {}", what, ex.what());
            if (on_error) on_error();
        }
    };
}

}  // namespace slmp::station
