// Execution: one CPU running one program (docs/program.md "Engine", "The
// scan"). The scan loop below is the only place that walks the steps.
#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "program/engine.hpp"

namespace slmp::program {

using devicemodel::Area;
using namespace detail;

struct Execution::State {
    std::shared_ptr<const Program> program;
    std::vector<std::uint8_t> edges;
    std::vector<std::uint64_t> accumulators;   // µs, per timer slot
    std::vector<std::uint8_t> coils;           // the coil of each timer slot at its last OUT
    std::optional<ScanOutcome::Error> last_error;
    ModelledTimes times;
    bool timed = false;
};

namespace detail {

void Machine::raise(Cause why) {
    fault = false;
    const auto index = pc == 0 ? 0 : pc - 1;
    const auto family = program->profile.family;
    const auto& info = program->info[index];
    const auto code = error_code(family, why);
    error = ScanOutcome::Error{code, index, info.row, info.mnemonic, std::string(cause_text(why))};
    if (program->options.operation_error == OnOperationError::Stop) {
        halt_now(Halt::StopError);
        return;
    }
    // Continue (docs/program.md "Operation errors"): SM0 = SM1 = 1 (SM56 on Q/L), SD0 = code; the step wrote nothing.
    const auto sm = m_size(Area::SM);
    if (sm > 1) {
        store_byte(*this, Plane::Bits, Area::SM, 0, true);
        store_byte(*this, Plane::Bits, Area::SM, 1, true);
    }
    const bool q_family = family != devicemodel::Family::IQR && family != devicemodel::Family::IQF;
    if (q_family && sm > 56) store_byte(*this, Plane::Bits, Area::SM, 56, true);
    if (m_size(Area::SD) > 0) store_word(*this, Area::SD, 0, code);
}

}  // namespace detail

Execution::Execution(std::shared_ptr<const Program> program) : state_(std::make_unique<State>()) {
    state_->program = std::move(program);
    state_->edges.assign(state_->program->edge_count, 0);
    state_->accumulators.assign(state_->program->timers.size(), 0);
    state_->coils.assign(state_->program->timers.size(), 0);
}
Execution::~Execution() = default;
Execution::Execution(Execution&&) noexcept = default;
Execution& Execution::operator=(Execution&&) noexcept = default;

const Program& Execution::program() const { return *state_->program; }

ScanOutcome Execution::scan(devicemodel::DeviceMemory& memory) {
    const Program& program = *state_->program;
    // The steps were range-checked against the profile's sizes: a smaller memory would be overrun.
    for (std::size_t a = 0; a < kAreas; ++a)
        if (memory.size(static_cast<Area>(a)) < program.profile.sizes[a])
            throw std::invalid_argument("program: device memory is smaller than " + program.profile.name +
                                        ", the profile the program was compiled for");
    Machine m;
    // Plane base pointers once per scan: memory may have been restored or replaced since the last one.
    for (std::size_t a = 0; a < kAreas; ++a) {
        const auto area = static_cast<Area>(a);
        m.bytes[0][a] = memory.bit_plane(area).data();
        m.bytes[1][a] = memory.coil_plane(area).data();
        m.words[a] = memory.value_plane(area).data();
        m.size[a] = memory.size(area);
    }
    m.memory = &memory;
    m.observed = memory.observed();
    m.program = &program;
    m.steps = program.steps.data();
    m.edges = state_->edges.data();
    m.timer_accumulators = state_->accumulators.data();
    m.timer_coils = state_->coils.data();
    m.wdt_ps = std::uint64_t{program.options.wdt_ms} * 1'000'000'000ull;
    m.limit_ps = m.wdt_ps;
    m.max_steps = program.options.max_steps_per_scan;

    // The loop (docs/program.md "Engine"): one indirect call per step, one
    // combined check for END/stop (halt_now zeroes both limits), watchdog and step guard.
    const Step* const steps = program.steps.data();
    for (;;) {
        const Step& step = steps[m.pc++];
        m.cost_ps += step.cost_ps;
        ++m.executed;
        step.run(m, step);
        if ((m.cost_ps > m.limit_ps) | (m.executed > m.max_steps)) [[unlikely]]
            break;
    }

    ScanOutcome outcome;
    outcome.executed = m.executed;
    outcome.modelled = std::chrono::nanoseconds(m.cost_ps / 1000);
    switch (m.halt) {
        case Machine::Halt::End:
            outcome.kind = m.stop_requested ? ScanOutcome::Kind::StopInstruction : ScanOutcome::Kind::Ok;
            break;
        case Machine::Halt::StopError: outcome.kind = ScanOutcome::Kind::StopError; break;
        case Machine::Halt::Running:    // the limit or the step guard stopped the loop
        case Machine::Halt::Watchdog: {
            outcome.kind = ScanOutcome::Kind::Watchdog;
            const auto index = m.pc == 0 ? 0 : m.pc - 1;
            const auto& info = program.info[index];
            const bool steps_guard = m.halt == Machine::Halt::Running && m.executed > program.options.max_steps_per_scan;
            m.error = ScanOutcome::Error{
                error_code(program.profile.family, Cause::Watchdog), index, info.row, info.mnemonic,
                steps_guard ? "more than " + std::to_string(program.options.max_steps_per_scan) +
                                  " instructions in one scan (max_steps_per_scan)"
                            : "modelled scan time passed wdt_ms = " + std::to_string(program.options.wdt_ms) + " ms"};
            break;
        }
    }
    outcome.error = m.error;
    if (m.error) state_->last_error = m.error;
    auto& times = state_->times;
    times.last = outcome.modelled;
    if (!state_->timed || outcome.modelled < times.min) times.min = outcome.modelled;
    if (!state_->timed || outcome.modelled > times.max) times.max = outcome.modelled;
    state_->timed = true;
    return outcome;
}

void Execution::end_of_scan(std::chrono::microseconds scan_time) {
    const auto add = static_cast<std::uint64_t>(std::max<std::int64_t>(scan_time.count(), 0));
    for (std::size_t i = 0; i < state_->coils.size(); ++i)
        if (state_->coils[i]) state_->accumulators[i] += add;
}

void Execution::restart() {
    std::fill(state_->edges.begin(), state_->edges.end(), 0);
    std::fill(state_->accumulators.begin(), state_->accumulators.end(), 0);
    std::fill(state_->coils.begin(), state_->coils.end(), 0);
    state_->times = {};
    state_->timed = false;
}

void Execution::resume() { std::fill(state_->accumulators.begin(), state_->accumulators.end(), 0); }

const std::optional<ScanOutcome::Error>& Execution::last_error() const { return state_->last_error; }
void Execution::clear_last_error() { state_->last_error.reset(); }
Execution::ModelledTimes Execution::modelled_times() const { return state_->times; }

// Layout: "SLPE", edge count, timer count (u32 each), edges, then per timer
// its accumulator (u64) and coil (u8). Refused when the counts differ.
std::vector<std::uint8_t> Execution::save_state() const {
    std::vector<std::uint8_t> bytes{'S', 'L', 'P', 'E'};
    auto put = [&](const void* data, std::size_t size) {
        const auto* p = static_cast<const std::uint8_t*>(data);
        bytes.insert(bytes.end(), p, p + size);
    };
    const auto edges = static_cast<std::uint32_t>(state_->edges.size());
    const auto timers = static_cast<std::uint32_t>(state_->accumulators.size());
    put(&edges, 4);
    put(&timers, 4);
    put(state_->edges.data(), edges);
    for (std::uint32_t i = 0; i < timers; ++i) {
        put(&state_->accumulators[i], 8);
        put(&state_->coils[i], 1);
    }
    return bytes;
}

bool Execution::restore_state(const std::vector<std::uint8_t>& bytes) {
    if (bytes.size() < 12 || std::memcmp(bytes.data(), "SLPE", 4) != 0) return false;
    std::uint32_t edges = 0, timers = 0;
    std::memcpy(&edges, bytes.data() + 4, 4);
    std::memcpy(&timers, bytes.data() + 8, 4);
    if (edges != state_->edges.size() || timers != state_->accumulators.size()) return false;
    if (bytes.size() != 12 + edges + std::size_t{timers} * 9) return false;
    const auto* p = bytes.data() + 12;
    std::copy_n(p, edges, state_->edges.begin());   // not memcpy: a program without edges has no buffer
    p += edges;
    for (std::uint32_t i = 0; i < timers; ++i, p += 9) {
        std::memcpy(&state_->accumulators[i], p, 8);
        state_->coils[i] = p[8];
    }
    return true;
}

}  // namespace slmp::program
