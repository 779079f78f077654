#include "devicemodel/operating_state.hpp"

namespace slmp::devicemodel {

RunState OperatingState::state() const {
    if (error_ && error_->stop) return RunState::Stop;
    if (switch_ == RunSwitch::Stop) return RunState::Stop;
    if (hold_.kind == Hold::Kind::Stop) return RunState::Stop;
    if (hold_.kind == Hold::Kind::Pause) return RunState::Pause;
    return RunState::Run;
}

StopCause OperatingState::cause() const {
    if (error_ && error_->stop) return StopCause::Error;
    if (switch_ == RunSwitch::Stop) return StopCause::Switch;
    if (hold_.kind == Hold::Kind::Stop && hold_.owner == kProgramStop) return StopCause::Instruction;
    return hold_.kind == Hold::Kind::None ? StopCause::Switch : StopCause::Remote;
}

// §5.2: with the switch at STOP the command completes normally and the CPU
// stays in STOP; the hold is released all the same (§15.3, inferred), so the
// CPU runs once the switch goes to RUN.
RemoteRefusal OperatingState::remote_run(ClientId client, bool forced) {
    if (!forced && held_by_other(client)) return RemoteRefusal::HeldByOther;
    if (error_ && error_->stop && switch_ == RunSwitch::Run) return RemoteRefusal::StopError;
    hold_ = {};
    return RemoteRefusal::None;
}

// STOP has no mode field: nobody can refuse it, and the sender becomes the holder.
RemoteRefusal OperatingState::remote_stop(ClientId client) {
    hold_ = {Hold::Kind::Stop, client};
    return RemoteRefusal::None;
}

// §5.4: with the switch at STOP the command completes normally without effect.
RemoteRefusal OperatingState::remote_pause(ClientId client, bool forced) {
    if (!forced && held_by_other(client)) return RemoteRefusal::HeldByOther;
    if (switch_ == RunSwitch::Stop) return RemoteRefusal::None;
    if (error_ && error_->stop) return RemoteRefusal::StopError;
    hold_ = {Hold::Kind::Pause, client};
    return RemoteRefusal::None;
}

// §5.5: STOP first; a remote STOP/PAUSE held by another client blocks it.
RemoteRefusal OperatingState::can_latch_clear(ClientId client) const {
    if (state() != RunState::Stop) return RemoteRefusal::NotInStop;
    if (held_by_other(client)) return RemoteRefusal::HeldByOther;
    return RemoteRefusal::None;
}

// §5.6: only when the parameter allows it, and only in STOP.
RemoteRefusal OperatingState::can_reset(bool reset_enabled) const {
    if (!reset_enabled) return RemoteRefusal::ResetDisabled;
    if (state() != RunState::Stop) return RemoteRefusal::NotInStop;
    return RemoteRefusal::None;
}

// Clear Error resets a continuation error; a stop error needs a reset, as on
// the real CPU (the error is what stopped it).
RemoteRefusal OperatingState::clear_error() {
    if (error_ && error_->stop) return RemoteRefusal::StopError;
    error_.reset();
    return RemoteRefusal::None;
}

}  // namespace slmp::devicemodel
