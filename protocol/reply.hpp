// Builds the Outcome of one decoded request: a normal response, an error
// response with the error information, a refusal as the port's profile says
// (end code, close, silence), or nothing.
#pragma once

#include <span>
#include <string>

#include "protocol/engine.hpp"
#include "protocol/fields.hpp"

namespace slmp::protocol {

class Reply {
public:
    explicit Reply(const Request& request);

    // Response data after the end code 0000.
    Outcome ok(std::span<const std::uint8_t> data);
    // End code, then the error information: the responding station's route and
    // the request's command and subcommand (SLMP Reference Manual ch. 4; real-CPU measurements).
    Outcome error(EndCode code, std::string note);
    // What the profile says for a request its port does not serve.
    Outcome refuse(const Refusal& refusal, std::string note);
    // No response: Silent, Close or Restart.
    Outcome drop(Outcome::Action action, std::string note);

private:
    void extended_echo(FieldWriter& w) const;

    const FrameHeader& header_;
    Outcome outcome_;
};

}  // namespace slmp::protocol
