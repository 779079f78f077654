// The CPU's operating state: RUN / STOP / PAUSE from the physical RUN/STOP
// switch, the remote STOP/PAUSE held by one client, and a simulated CPU error.
// Pure: no time, no memory, no protocol — every decision is a table row.
//
// Model (SLMP Reference Manual §5.6, precedence inferred there):
//   stop error             -> STOP (cause: error)
//   switch at STOP         -> STOP (cause: switch)
//   remote STOP held       -> STOP (cause: remote)
//   remote PAUSE held      -> PAUSE (cause: remote)
//   otherwise              -> RUN
// The holder is the client that sent the remote STOP/PAUSE; it keeps the hold
// after it disconnects (that is what the "forced" mode 0003 is for), and only a
// CPU restart (power cycle or Remote RESET) erases it (§5.1).
#pragma once

#include <cstdint>
#include <optional>

namespace slmp::devicemodel {

// SD203 low nibble (real-CPU measurements).
enum class RunState : std::uint8_t { Run = 0, Stop = 2, Pause = 3 };
// SD203 bits 4-7: why the CPU is in STOP/PAUSE (iQ-R/Q "STOP/PAUSE cause").
// Instruction: the program's STOP instruction (3, inferred; docs/program.md).
enum class StopCause : std::uint8_t { Switch = 0, Remote = 2, Instruction = 3, Error = 4 };
enum class RunSwitch : std::uint8_t { Run, Stop };

// Who a remote operation comes from: one TCP connection, or one UDP endpoint.
using ClientId = std::uint64_t;

// A simulated CPU error: the code published in SD0, and whether the CPU stops.
struct CpuError {
    std::uint16_t code = 0;
    bool stop = false;   // stop error (CPU goes to STOP) vs continuation error
};

// Why a remote operation was refused. The protocol layer maps each to an end code.
enum class RemoteRefusal : std::uint8_t {
    None,
    HeldByOther,      // mode 0001 while another client holds a remote STOP/PAUSE; latch clear likewise
    NotInStop,        // latch clear / reset needs STOP
    ResetDisabled,    // the "remote reset" parameter is off
    StopError,        // RUN/PAUSE while a stop error is pending; Clear Error on a stop error
};

class OperatingState {
public:
    explicit OperatingState(RunSwitch run_switch = RunSwitch::Run) : switch_(run_switch) {}

    RunState state() const;
    StopCause cause() const;
    RunSwitch run_switch() const { return switch_; }
    void set_switch(RunSwitch position) { switch_ = position; }

    struct Hold {
        enum class Kind : std::uint8_t { None, Stop, Pause };
        Kind kind = Kind::None;
        ClientId owner = 0;
    };
    const Hold& hold() const { return hold_; }
    const std::optional<CpuError>& error() const { return error_; }

    // Each returns RemoteRefusal::None when the operation was carried out (the state
    // may still be unchanged: RUN/PAUSE with the switch at STOP "complete
    // normally" without effect, §5.2/§5.4). A refused operation changes nothing.
    RemoteRefusal remote_run(ClientId client, bool forced);
    RemoteRefusal remote_stop(ClientId client);
    RemoteRefusal remote_pause(ClientId client, bool forced);
    RemoteRefusal can_latch_clear(ClientId client) const;
    RemoteRefusal can_reset(bool reset_enabled) const;
    RemoteRefusal clear_error();

    void raise(CpuError error) { error_ = error; }
    // The program's STOP instruction: a STOP hold that no client owns, so a
    // remote RUN from any client (or a switch cycle) starts the CPU again.
    static constexpr ClientId kProgramStop = ~ClientId{0};
    void stop_by_program() { hold_ = {Hold::Kind::Stop, kProgramStop}; }
    // Power cycle or Remote RESET: the remote hold and the error are erased.
    void restart() {
        hold_ = {};
        error_.reset();
    }

private:
    bool held_by_other(ClientId client) const {
        return hold_.kind != Hold::Kind::None && hold_.owner != client && hold_.owner != kProgramStop;
    }

    RunSwitch switch_;
    Hold hold_;
    std::optional<CpuError> error_;
};

}  // namespace slmp::devicemodel
