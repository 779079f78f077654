// The completion handler for co_spawn: an exception that ends a coroutine is
// logged with what stopped, never dropped (STYLE.md §6.20: no bare `detached`).
#pragma once

#include <exception>
#include <string>

#include <spdlog/spdlog.h>

namespace slmp::server {

inline auto log_exception(std::string what) {
    return [what = std::move(what)](std::exception_ptr e) {
        if (!e) return;
        try {
            std::rethrow_exception(e);
        } catch (const std::exception& ex) {
            spdlog::error("{}: {}", what, ex.what());
        }
    };
}

}  // namespace slmp::server
