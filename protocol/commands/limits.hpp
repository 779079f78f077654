// Point and block limits shared by the random, monitor and block commands
// (SLMP Reference Manual §5.2; real-CPU measurements). A port
// enforces them while it reads the request, so the decoders check them.
#pragma once

#include <cstdint>

#include "protocol/command_table.hpp"

namespace slmp::protocol::commands {

// The limit for the request's subcommand family.
inline std::uint64_t form_max(const CommandSpec& spec, const FormLimit& limit) {
    return spec.form == DeviceForm::Q ? limit.q : limit.iqr;
}

// With the Q form's extended subcommands (0080/0081) every point or block
// counts twice (the manual's *1 notes).
inline std::uint64_t weight(const CommandSpec& spec) { return spec.extended() && spec.form == DeviceForm::Q ? 2 : 1; }

// Whether a weighted count is outside 1..limit.
inline bool over(const DecodeContext& d, const FormLimit& limit, std::uint64_t count) {
    return count == 0 || count * weight(d.spec) > form_max(d.spec, limit);
}

// The end code for an exceeded limit (QJ71E71-100 answers extended requests with 4080).
inline EndCode over_limit_code(const DecodeContext& d, const FormLimit& limit) {
    if (d.spec.extended() && d.port.extended_over_limit_code != 0) return end_code(d.port.extended_over_limit_code);
    return end_code(limit.end_code);
}

// Decoders record the first problem for the handler and go on reading the
// fields they still can, so the scenario hook sees every device a request names.
inline void fail(DecodeContext& d, EndCode code, bool after_checks = false) {
    if (d.out.error != EndCode::Ok) return;
    d.out.error = code;
    d.out.error_after_checks = after_checks;
}
inline void fail_field(DecodeContext& d, bool after_checks = false) {
    if (d.out.error != EndCode::Ok) return;
    fail(d, d.in.error(), after_checks);
    d.out.error_field = d.in.error_field();
}

// One device in the layout the row's subcommand selects (plain or 008x), or
// the 1E layout for a 1E request.
inline DeviceField read_device(DecodeContext& d, std::string_view what) {
    if (d.a_compatible) return d.in.device_1e(what);
    return d.spec.extended() ? d.in.extended_device(d.spec.form, what) : d.in.device(d.spec.form, what);
}

}  // namespace slmp::protocol::commands
