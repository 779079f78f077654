// Boost.Asio, with the one include Boost 1.74 forgets: its awaitable.hpp uses
// std::exchange without <utility>. Include this instead of <boost/asio.hpp>.
#pragma once

#include <utility>

#include <boost/asio.hpp>
