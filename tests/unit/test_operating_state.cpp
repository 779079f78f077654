// The operating-state machine as a table: every (state, switch, holder,
// command, mode, client) combination of the SLMP Reference Manual §5.6 with the
// refusal (end code chosen in protocol/commands/remote.cpp) and the resulting
// state and holder. A refused operation must leave state and holder unchanged.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "devicemodel/operating_state.hpp"

using namespace slmp::devicemodel;
using Kind = OperatingState::Hold::Kind;

namespace {

constexpr ClientId A = 1;   // the client that took the hold in the setup
constexpr ClientId B = 2;   // another client

enum class Setup { Run, StopByA, PauseByA, SwitchStop, SwitchStopStopByA };
enum class Op { Run1, Run3, Stop, Pause1, Pause3, LatchClear, ResetEnabled, ResetDisabled };

OperatingState make(Setup setup) {
    OperatingState s(setup == Setup::SwitchStop || setup == Setup::SwitchStopStopByA ? RunSwitch::Stop : RunSwitch::Run);
    if (setup == Setup::StopByA || setup == Setup::SwitchStopStopByA) s.remote_stop(A);
    if (setup == Setup::PauseByA) s.remote_pause(A, false);
    return s;
}

RemoteRefusal apply(OperatingState& s, Op op, ClientId c) {
    switch (op) {
        case Op::Run1: return s.remote_run(c, false);
        case Op::Run3: return s.remote_run(c, true);
        case Op::Stop: return s.remote_stop(c);
        case Op::Pause1: return s.remote_pause(c, false);
        case Op::Pause3: return s.remote_pause(c, true);
        case Op::LatchClear: return s.can_latch_clear(c);
        case Op::ResetEnabled: return s.can_reset(true);
        case Op::ResetDisabled: return s.can_reset(false);
    }
    return RemoteRefusal::None;
}

struct Row {
    Setup setup;
    ClientId client;
    Op op;
    RemoteRefusal refusal;
    RunState state;
    Kind hold;
    ClientId owner;
};

using R = RemoteRefusal;
using S = RunState;

const std::vector<Row> kTable = {
    // RUN, no holder
    {Setup::Run, B, Op::Run1, R::None, S::Run, Kind::None, 0},
    {Setup::Run, B, Op::Run3, R::None, S::Run, Kind::None, 0},
    {Setup::Run, B, Op::Stop, R::None, S::Stop, Kind::Stop, B},
    {Setup::Run, B, Op::Pause1, R::None, S::Pause, Kind::Pause, B},
    {Setup::Run, B, Op::Pause3, R::None, S::Pause, Kind::Pause, B},
    {Setup::Run, B, Op::LatchClear, R::NotInStop, S::Run, Kind::None, 0},
    {Setup::Run, B, Op::ResetEnabled, R::NotInStop, S::Run, Kind::None, 0},
    {Setup::Run, B, Op::ResetDisabled, R::ResetDisabled, S::Run, Kind::None, 0},
    // remote STOP held by A, switch RUN
    {Setup::StopByA, A, Op::Run1, R::None, S::Run, Kind::None, 0},
    {Setup::StopByA, B, Op::Run1, R::HeldByOther, S::Stop, Kind::Stop, A},
    {Setup::StopByA, B, Op::Run3, R::None, S::Run, Kind::None, 0},
    {Setup::StopByA, A, Op::Stop, R::None, S::Stop, Kind::Stop, A},
    {Setup::StopByA, B, Op::Stop, R::None, S::Stop, Kind::Stop, B},
    {Setup::StopByA, A, Op::Pause1, R::None, S::Pause, Kind::Pause, A},
    {Setup::StopByA, B, Op::Pause1, R::HeldByOther, S::Stop, Kind::Stop, A},
    {Setup::StopByA, B, Op::Pause3, R::None, S::Pause, Kind::Pause, B},
    {Setup::StopByA, A, Op::LatchClear, R::None, S::Stop, Kind::Stop, A},
    {Setup::StopByA, B, Op::LatchClear, R::HeldByOther, S::Stop, Kind::Stop, A},
    {Setup::StopByA, B, Op::ResetEnabled, R::None, S::Stop, Kind::Stop, A},
    {Setup::StopByA, A, Op::ResetDisabled, R::ResetDisabled, S::Stop, Kind::Stop, A},
    // remote PAUSE held by A, switch RUN
    {Setup::PauseByA, A, Op::Run1, R::None, S::Run, Kind::None, 0},
    {Setup::PauseByA, B, Op::Run1, R::HeldByOther, S::Pause, Kind::Pause, A},
    {Setup::PauseByA, B, Op::Run3, R::None, S::Run, Kind::None, 0},
    {Setup::PauseByA, B, Op::Stop, R::None, S::Stop, Kind::Stop, B},
    {Setup::PauseByA, B, Op::Pause1, R::HeldByOther, S::Pause, Kind::Pause, A},
    {Setup::PauseByA, A, Op::Pause1, R::None, S::Pause, Kind::Pause, A},
    {Setup::PauseByA, A, Op::LatchClear, R::NotInStop, S::Pause, Kind::Pause, A},
    {Setup::PauseByA, A, Op::ResetEnabled, R::NotInStop, S::Pause, Kind::Pause, A},
    // switch at STOP, no holder: RUN and PAUSE complete normally without effect (§5.2, §5.4)
    {Setup::SwitchStop, B, Op::Run1, R::None, S::Stop, Kind::None, 0},
    {Setup::SwitchStop, B, Op::Run3, R::None, S::Stop, Kind::None, 0},
    {Setup::SwitchStop, B, Op::Pause1, R::None, S::Stop, Kind::None, 0},
    {Setup::SwitchStop, B, Op::Pause3, R::None, S::Stop, Kind::None, 0},
    {Setup::SwitchStop, B, Op::Stop, R::None, S::Stop, Kind::Stop, B},
    {Setup::SwitchStop, B, Op::LatchClear, R::None, S::Stop, Kind::None, 0},
    {Setup::SwitchStop, B, Op::ResetEnabled, R::None, S::Stop, Kind::None, 0},
    {Setup::SwitchStop, B, Op::ResetDisabled, R::ResetDisabled, S::Stop, Kind::None, 0},
    // switch at STOP and a remote STOP held by A
    {Setup::SwitchStopStopByA, A, Op::Run1, R::None, S::Stop, Kind::None, 0},   // hold released (§15.3, inferred)
    {Setup::SwitchStopStopByA, B, Op::Run1, R::HeldByOther, S::Stop, Kind::Stop, A},
    {Setup::SwitchStopStopByA, B, Op::Run3, R::None, S::Stop, Kind::None, 0},
    {Setup::SwitchStopStopByA, B, Op::Pause1, R::HeldByOther, S::Stop, Kind::Stop, A},
    {Setup::SwitchStopStopByA, B, Op::Pause3, R::None, S::Stop, Kind::Stop, A},   // no effect at switch STOP
    {Setup::SwitchStopStopByA, B, Op::LatchClear, R::HeldByOther, S::Stop, Kind::Stop, A},
    {Setup::SwitchStopStopByA, A, Op::LatchClear, R::None, S::Stop, Kind::Stop, A},
};

}  // namespace

TEST_CASE("operating state: every row of the transition table", "[runtime][state]") {
    for (std::size_t i = 0; i < kTable.size(); ++i) {
        const auto& row = kTable[i];
        INFO("row " << i);
        auto s = make(row.setup);
        CHECK(apply(s, row.op, row.client) == row.refusal);
        CHECK(s.state() == row.state);
        CHECK(s.hold().kind == row.hold);
        if (row.hold != Kind::None) CHECK(s.hold().owner == row.owner);
    }
}

TEST_CASE("operating state: precedence and causes (SD203 bits 4-7)", "[runtime][state]") {
    OperatingState s(RunSwitch::Run);
    CHECK(s.state() == RunState::Run);
    s.remote_pause(A, false);
    CHECK(s.state() == RunState::Pause);
    CHECK(s.cause() == StopCause::Remote);
    s.set_switch(RunSwitch::Stop);   // STOP > PAUSE
    CHECK(s.state() == RunState::Stop);
    CHECK(s.cause() == StopCause::Switch);
    s.raise({0x3300, true});         // a stop error wins over everything
    CHECK(s.cause() == StopCause::Error);
    s.set_switch(RunSwitch::Run);
    CHECK(s.state() == RunState::Stop);
}

TEST_CASE("operating state: errors and restart", "[runtime][state]") {
    SECTION("a continuation error is cleared by Clear Error and the CPU keeps running") {
        OperatingState s;
        s.raise({0x1900, false});
        CHECK(s.state() == RunState::Run);
        CHECK(s.clear_error() == RemoteRefusal::None);
        CHECK_FALSE(s.error().has_value());
    }
    SECTION("a stop error needs a reset: Clear Error and RUN are refused, the error stays") {
        OperatingState s;
        s.raise({0x3300, true});
        CHECK(s.clear_error() == RemoteRefusal::StopError);
        CHECK(s.remote_run(A, true) == RemoteRefusal::StopError);
        CHECK(s.error()->code == 0x3300);
        CHECK(s.can_reset(true) == RemoteRefusal::None);
        s.restart();
        CHECK(s.state() == RunState::Run);
    }
    SECTION("power cycle erases the remote STOP: switch RUN + remote STOP + reset -> RUN (§5.1)") {
        OperatingState s;
        s.remote_stop(A);
        s.restart();
        CHECK(s.state() == RunState::Run);
        CHECK(s.hold().kind == Kind::None);
    }
    SECTION("RUN accepted at switch STOP releases the hold: the switch to RUN then runs") {
        OperatingState s(RunSwitch::Stop);
        s.remote_stop(A);
        CHECK(s.remote_run(A, false) == RemoteRefusal::None);
        s.set_switch(RunSwitch::Run);
        CHECK(s.state() == RunState::Run);
    }
}
