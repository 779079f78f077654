// Program control (docs/program.md "Program control"). Jump targets
// are step indices resolved at load (op[0].value); a label costs nothing.
#include "program/handlers.hpp"

namespace slmp::program::detail {

SLMP_HANDLER(cj) {
    if (m.condition()) m.pc = s.op[0].value;
}
// SCJ jumps from the scan after r turned ON, while r stays ON (docs/program.md "Instructions"):
// the edge bit holds r of this step's previous execution.
SLMP_HANDLER(scj) {
    const bool now = m.condition();
    auto& before = m.edges[s.edge];
    const bool jump = now & (before != 0);
    before = now;
    if (jump) m.pc = s.op[0].value;
}
SLMP_HANDLER(jmp) { m.pc = s.op[0].value; }
SLMP_HANDLER(goend) {
    (void)s;
    if (m.condition()) m.pc = static_cast<std::uint32_t>(m.program->end_step);
}
SLMP_HANDLER(call) {
    if (!m.condition()) return;
    if (m.call_depth >= m.calls.size()) return m.raise(Cause::CallNest);
    m.calls[m.call_depth++] = m.pc;
    m.pc = s.op[0].value;
}
SLMP_HANDLER(ret) {
    (void)s;
    if (m.call_depth == 0) return m.raise(Cause::ReturnWithoutCall);
    m.pc = m.calls[--m.call_depth];
}
// FOR n: n <= 0 runs the loop once (docs/program.md "Instructions", inferred).
SLMP_HANDLER(for_) {
    const std::int32_t n = get16(m, s.op[0]);
    if (m.fault) return m.raise(m.cause);
    if (m.loop_depth >= m.loops.size()) return m.raise(Cause::ForNest);
    m.loops[m.loop_depth++] = Machine::Loop{m.pc, n < 1 ? 1 : n};
}
SLMP_HANDLER(next) {
    (void)s;
    if (m.loop_depth == 0) return m.raise(Cause::NextWithoutFor);
    auto& loop = m.loops[m.loop_depth - 1];
    if (--loop.remaining > 0) m.pc = loop.start;
    else --m.loop_depth;
}
// BREAK d Pn: d gets the repetitions left after the current one (chosen), the loop ends.
SLMP_HANDLER(break_) {
    if (!m.condition()) return;
    if (m.loop_depth == 0) return m.raise(Cause::BreakWithoutFor);
    probe(m, s.op[0], 1);
    if (m.fault) return m.raise(m.cause);
    put16(m, s.op[0], m.loops[m.loop_depth - 1].remaining - 1);
    --m.loop_depth;
    m.pc = s.op[1].value;
}
// WDT restarts the watchdog measurement (docs/program.md "Modelled time"); the modelled time still counts.
SLMP_HANDLER(wdt) {
    (void)s;
    if (m.condition()) m.limit_ps = m.cost_ps + m.wdt_ps;
}
SLMP_HANDLER(stop) {
    (void)s;
    if (m.condition()) m.stop_requested = true;
}

}  // namespace slmp::program::detail
