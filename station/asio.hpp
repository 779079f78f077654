// Boost.Asio, with the one include Boost 1.74 forgets: boost/asio/awaitable.hpp uses
// std::exchange without <utility>. Include this instead of <boost/asio.hpp>.
#pragma once

#include <chrono>
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

// A socket, timer and coroutine bound to such a strand (a station's home, or a
// connection's own). Their executor type is the strand itself, not Asio's
// polymorphic any_io_executor: wrapping a strand in one costs a heap
// allocation each time Asio copies it (about 8 per served request).
using Strand = Home;
using StrandSocket = boost::asio::basic_stream_socket<boost::asio::ip::tcp, Strand>;
using StrandDatagramSocket = boost::asio::basic_datagram_socket<boost::asio::ip::udp, Strand>;
using StrandTimer = boost::asio::basic_waitable_timer<std::chrono::steady_clock,
                                                      boost::asio::wait_traits<std::chrono::steady_clock>, Strand>;
template <class T = void>
using StrandTask = boost::asio::awaitable<T, Strand>;
inline constexpr boost::asio::use_awaitable_t<Strand> use_strand;

namespace detail {
template <class Result> struct OnHomeSignature { using type = void(std::exception_ptr, Result); };
template <> struct OnHomeSignature<void> { using type = void(std::exception_ptr); };
}  // namespace detail

// `co_await on_home(home, fn)`: runs fn() on the station's strand and resumes
// the caller on its own executor with fn's result (or exception). fn runs at
// once when the strand is free; the caller resumes as a continuation of it,
// so its next steps (a socket write) do not hold the station's strand.
// `token` is use_awaitable for an any_io_executor coroutine, use_strand for a StrandTask.
template <class F, class Token = const boost::asio::use_awaitable_t<>&>
auto on_home(Home home, F fn, Token&& token = boost::asio::use_awaitable) {
    using Result = std::invoke_result_t<F>;
    return boost::asio::async_initiate<Token, typename detail::OnHomeSignature<Result>::type>(
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
        std::forward<Token>(token), std::move(home), std::move(fn));
}

}  // namespace slmp::station
