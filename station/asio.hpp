// Boost.Asio, with the one include Boost 1.74 forgets: its awaitable.hpp uses
// std::exchange without <utility>. Include this instead of <boost/asio.hpp>.
#pragma once

#include <exception>
#include <optional>
#include <type_traits>
#include <utility>

#include <boost/asio.hpp>

namespace slmp::station {

// A station's home: a strand of the process's io_context. Everything that
// touches a station (its listeners, scan cycle, scenarios, HTTP routes and the
// serving of every request) runs on it, so the station needs no lock while
// the process's threads share its connections' reads and writes
// (docs/plants.md, "Threads").
using Home = boost::asio::strand<boost::asio::io_context::executor_type>;

namespace detail {
template <class Result> struct OnHomeSignature { using type = void(std::exception_ptr, Result); };
template <> struct OnHomeSignature<void> { using type = void(std::exception_ptr); };
}  // namespace detail

// `co_await on_home(home, fn)`: runs fn() on the station's strand and resumes
// the caller on its own executor with fn's result (or exception). fn runs at
// once when the strand is free; the caller resumes as a continuation of it,
// so its next steps (a socket write) do not hold the station's strand.
template <class F>
auto on_home(Home home, F fn) {
    using Result = std::invoke_result_t<F>;
    return boost::asio::async_initiate<const boost::asio::use_awaitable_t<>&, typename detail::OnHomeSignature<Result>::type>(
        [](auto handler, Home home, F fn) {
            boost::asio::dispatch(home, [handler = std::move(handler), fn = std::move(fn)]() mutable {
                auto back = boost::asio::get_associated_executor(handler);
                std::exception_ptr error;
                if constexpr (std::is_void_v<Result>) {
                    try {
                        fn();
                    } catch (...) {
                        error = std::current_exception();
                    }
                    boost::asio::defer(back, [handler = std::move(handler), error]() mutable { std::move(handler)(error); });
                } else {
                    std::optional<Result> result;
                    try {
                        result.emplace(fn());
                    } catch (...) {
                        error = std::current_exception();
                    }
                    boost::asio::defer(back, [handler = std::move(handler), error, result = std::move(result)]() mutable {
                        std::move(handler)(error, result ? std::move(*result) : Result{});
                    });
                }
            });
        },
        boost::asio::use_awaitable, std::move(home), std::move(fn));
}

}  // namespace slmp::station
