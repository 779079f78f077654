// What the station may do to a front end's request once its command is known
// (a scenario fault, station/frontend_call.hpp): let it run, answer it with a
// chosen response code instead (nothing is read or written), or leave it
// unanswered. The front ends call the gate; they know no scenarios.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>

namespace slmp::frontends {

struct Intercept {
    enum class Kind : std::uint8_t { Pass, Answer, Silent } kind = Kind::Pass;
    std::uint8_t code = 0;   // Answer: the host-link response code / JW RSLT
};

// Called with the request's command text ("RD"; JW: the COM in uppercase hex, "24").
using Gate = std::function<Intercept(std::string_view command)>;

}  // namespace slmp::frontends
