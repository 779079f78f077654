#include "protocol/reply.hpp"

#include "devicemodel/hex.hpp"
#include "protocol/error_response.hpp"
#include "protocol/frame_1e.hpp"
#include "protocol/message.hpp"

namespace slmp::protocol {

Reply::Reply(const Request& request) : header_(request.header) {
    outcome_.consumed = request.size;
    outcome_.command = request.command;
    outcome_.subcommand = request.subcommand;
}

Outcome Reply::ok(std::span<const std::uint8_t> data) {
    outcome_.action = Outcome::Action::Respond;
    if (header_.kind == FrameKind::E1) {
        outcome_.response = encode_response_1e(header_, data);
        return std::move(outcome_);
    }
    if (header_.kind != FrameKind::Ext) {   // the end code 0000 as the codec writes it, then the data
        static constexpr std::uint8_t kOkBinary[] = {0x00, 0x00}, kOkAscii[] = {'0', '0', '0', '0'};
        const auto ok = header_.codec == Codec::Binary ? std::span<const std::uint8_t>(kOkBinary)
                                                       : std::span<const std::uint8_t>(kOkAscii);
        outcome_.response = encode_frame(Direction::Response, header_, ok, data);
        return std::move(outcome_);
    }
    FieldWriter head(header_.codec);   // the end code and the extended frame's echo
    head.u16(raw(EndCode::Ok));
    extended_echo(head);
    outcome_.response = encode_frame(Direction::Response, header_, head.bytes(), data);
    return std::move(outcome_);
}

Outcome Reply::error(EndCode code, std::string note) {
    outcome_.end_code = code;
    outcome_.note = devicemodel::hex4(raw(code)) + " (" + std::string(describe(code)) + "): " + note;
    outcome_.action = Outcome::Action::Respond;
    outcome_.response = encode_error_response(header_, outcome_.command, outcome_.subcommand, code);
    return std::move(outcome_);
}

// The station-number-extended frame's response data start with the request's
// command and subcommand, fixed 00 and the 5-byte system area (§3.2.5).
void Reply::extended_echo(FieldWriter& w) const {
    w.u16(outcome_.command);
    w.u16(outcome_.subcommand);
    w.u8(0x00);
    for (int i = 0; i < 5; ++i) w.u8(0x00);
}

Outcome Reply::refuse(const Refusal& refusal, std::string note) {
    switch (refusal.kind) {
        case Refusal::Kind::EndCode: return error(end_code(refusal.end_code), std::move(note));
        case Refusal::Kind::Close: return drop(Outcome::Action::Close, std::move(note) + "; closing the connection");
        case Refusal::Kind::Silence:
        case Refusal::Kind::Serve: break;
    }
    return drop(Outcome::Action::Silent, std::move(note) + "; not answered");
}

Outcome Reply::drop(Outcome::Action action, std::string note) {
    outcome_.action = action;
    outcome_.note = std::move(note);
    return std::move(outcome_);
}

}  // namespace slmp::protocol
