// Sequence instructions (docs/program.md "Instructions"). The result
// stack slots are fixed by the compiler (each LD writes the value it covers to
// `s.slot`, a rung start writes a scratch slot), so no handler counts depth.
#include "program/handlers.hpp"

namespace slmp::program::detail {

namespace {
inline bool& edge_of(Machine& m, const Step& s) { return reinterpret_cast<bool&>(m.edges[s.edge]); }
// The signal a pulse contact watches: the device, forced OFF in an OFF MC block (docs/program.md "The scan").
inline bool rose(Machine& m, const Step& s) {
    const bool now = read_bit(m, s.op[0]) & !m.mc_off;
    bool& before = edge_of(m, s);
    const bool up = now & !before;
    before = now;
    return up;
}
inline bool fell(Machine& m, const Step& s) {
    const bool now = read_bit(m, s.op[0]) & !m.mc_off;
    bool& before = edge_of(m, s);
    const bool down = !now & before;
    before = now;
    return down;
}
inline void load(Machine& m, const Step& s, bool value) {
    m.stack[s.slot] = m.acc;
    m.acc = value;
}
// A contact whose index ran past the end: the error, and OFF for the rung.
inline bool checked(Machine& m, bool value) {
    if (m.fault) [[unlikely]] {
        m.raise(m.cause);
        return false;
    }
    return value;
}
}  // namespace

SLMP_HANDLER(pulse) {
    const bool now = m.condition();
    bool& before = edge_of(m, s);
    const bool up = now & !before;
    before = now;
    if (up) s.body(m, s);
}

SLMP_HANDLER(ld) { load(m, s, checked(m, read_bit(m, s.op[0]))); }
SLMP_HANDLER(ldi) { load(m, s, checked(m, !read_bit(m, s.op[0]))); }
SLMP_HANDLER(and_) { m.acc = m.acc & checked(m, read_bit(m, s.op[0])); }
SLMP_HANDLER(ani) { m.acc = m.acc & checked(m, !read_bit(m, s.op[0])); }
SLMP_HANDLER(or_) { m.acc = m.acc | checked(m, read_bit(m, s.op[0])); }
SLMP_HANDLER(ori) { m.acc = m.acc | checked(m, !read_bit(m, s.op[0])); }
SLMP_HANDLER(ldp) { load(m, s, checked(m, rose(m, s))); }
SLMP_HANDLER(ldf) { load(m, s, checked(m, fell(m, s))); }
SLMP_HANDLER(andp) { m.acc = m.acc & checked(m, rose(m, s)); }
SLMP_HANDLER(andf) { m.acc = m.acc & checked(m, fell(m, s)); }
SLMP_HANDLER(orp) { m.acc = m.acc | checked(m, rose(m, s)); }
SLMP_HANDLER(orf) { m.acc = m.acc | checked(m, fell(m, s)); }
// Negated pulses (iQ-R, iQ-F): ON except in the scan of the edge.
SLMP_HANDLER(ldpi) { load(m, s, !checked(m, rose(m, s))); }
SLMP_HANDLER(ldfi) { load(m, s, !checked(m, fell(m, s))); }
SLMP_HANDLER(andpi) { m.acc = m.acc & !checked(m, rose(m, s)); }
SLMP_HANDLER(andfi) { m.acc = m.acc & !checked(m, fell(m, s)); }
SLMP_HANDLER(orpi) { m.acc = m.acc | !checked(m, rose(m, s)); }
SLMP_HANDLER(orfi) { m.acc = m.acc | !checked(m, fell(m, s)); }

SLMP_HANDLER(anb) { m.acc = m.stack[s.slot] & m.acc; }
SLMP_HANDLER(orb) { m.acc = m.stack[s.slot] | m.acc; }
SLMP_HANDLER(mps) { m.branch[s.slot] = m.acc; }
SLMP_HANDLER(mrd) { m.acc = m.branch[s.slot]; }
SLMP_HANDLER(mpp) { m.acc = m.branch[s.slot]; }
SLMP_HANDLER(inv) {
    (void)s;
    m.acc = !m.acc;
}
SLMP_HANDLER(mep) {
    bool& before = edge_of(m, s);
    const bool now = m.acc & !m.mc_off;
    m.acc = now & !before;
    before = now;
}
SLMP_HANDLER(mef) {
    bool& before = edge_of(m, s);
    const bool now = m.acc & !m.mc_off;
    m.acc = !now & before;
    before = now;
}

SLMP_HANDLER(out_bit) {
    write_bit(m, s.op[0], m.condition());
    if (m.fault) [[unlikely]] m.raise(m.cause);
}
SLMP_HANDLER(set_bit) {
    if (!m.condition()) return;
    write_bit(m, s.op[0], true);
    if (m.fault) [[unlikely]] m.raise(m.cause);
}
SLMP_HANDLER(rst_bit) {
    if (!m.condition()) return;
    write_bit(m, s.op[0], false);
    if (m.fault) [[unlikely]] m.raise(m.cause);
}
SLMP_HANDLER(rst_word) {
    if (!m.condition()) return;
    put16(m, s.op[0], 0);
    if (m.fault) [[unlikely]] m.raise(m.cause);
}
// PLS/PLF: d follows the edge of r at every execution (docs/program.md "The scan").
SLMP_HANDLER(pls) {
    const bool now = m.condition();
    bool& before = edge_of(m, s);
    const bool up = now & !before;
    before = now;
    write_bit(m, s.op[0], up);
    if (m.fault) [[unlikely]] m.raise(m.cause);
}
SLMP_HANDLER(plf) {
    const bool now = m.condition();
    bool& before = edge_of(m, s);
    const bool down = !now & before;
    before = now;
    write_bit(m, s.op[0], down);
    if (m.fault) [[unlikely]] m.raise(m.cause);
}
SLMP_HANDLER(ff) {
    const bool now = m.condition();
    bool& before = edge_of(m, s);
    const bool up = now & !before;
    before = now;
    if (!up) return;
    const bool current = read_bit(m, s.op[0]);
    write_bit(m, s.op[0], !current);
    if (m.fault) [[unlikely]] m.raise(m.cause);
}

// MC n d (docs/program.md "Instructions"): with r OFF (or forced OFF by an outer level) level n turns
// OFF and every step up to its MCR sees r forced OFF through m.mc_off.
SLMP_HANDLER(mc) {
    const bool on = m.condition();
    const auto level = static_cast<std::uint16_t>(1u << s.op[0].value);
    if (on) m.mc_mask = static_cast<std::uint16_t>(m.mc_mask & ~level);
    else m.mc_mask = static_cast<std::uint16_t>(m.mc_mask | level);
    write_bit(m, s.op[1], on);
    m.mc_off = m.mc_mask != 0;
    if (m.fault) [[unlikely]] m.raise(m.cause);
}
// MCR n ends level n and every deeper one.
SLMP_HANDLER(mcr) {
    m.mc_mask = static_cast<std::uint16_t>(m.mc_mask & ((1u << s.op[0].value) - 1u));
    m.mc_off = m.mc_mask != 0;
}
SLMP_HANDLER(nop) { (void)m, (void)s; }
// END/FEND: END processing's modelled time; the watchdog includes it (docs/program.md "Modelled time").
SLMP_HANDLER(end) {
    (void)s;
    m.cost_ps += m.program->costs.end_ps;
    m.halt_now(m.cost_ps > m.wdt_limit() ? Machine::Halt::Watchdog : Machine::Halt::End);
}
SLMP_HANDLER(fend) { end(m, s); }

}  // namespace slmp::program::detail
