// The program panel of the station page: the CPU's PLC program (the
// instruction list of GET .../program?lines=1) drawn as ladder rungs in SVG,
// with the live state of its operands from GET .../program/monitor: contacts
// and coils filled green when energised, word values under their operands,
// the rung of the last operation error in red, the scan count and times, and
// a search that highlights every element naming a device.
// The rungs are worked out once per program (keyed on its load number, file, name and steps)
// and each is drawn when it first scrolls near; a poll then only changes the
// classes and texts of the operands whose state changed, so a program of a
// few thousand rungs stays cheap to watch. The poll runs only while the panel
// is on screen and the tab is visible.
// At page start an empty device watch list is filled with the devices the
// program writes. (GET /api/scenarios names no devices, so a station without
// a program gets no such list.)
// Uses api(), stationPath(), state, addWatch(), parseAddress() and $() from
// app.js. Everything is inside one function so its names cannot meet another
// panel's; window.__program exposes the pure parts and the view for tests.
'use strict';

(() => {

const PROGRAM_POLL_MS = 300;
const PROGRAM_IDLE_MS = 1000;   // no program loaded: only notice one arriving
const PREFILL_MAX = 16;

// Geometry in px. One grid column per contact; a row holds the device name
// above the wire and the value and comment below it.
const CW = 84;        // column width
const RH = 68;        // row height
const WY = 28;        // the wire's y within a row
const RAIL = 60;      // x of the left rail; the step number and a pointer label sit left of it
const CHAR = 6.7;     // one character of the ladder's 11 px monospace font
const MIN_COLS = 8;   // short programs still get a readable width
const CLIP = 12;      // characters of a device name or comment shown in one column

// ------------------------------------------------------- the instructions --

// Contacts: the three ways an instruction takes a contact (LD starts a block,
// AND puts it in series, OR in parallel with the block) and its kind.
const CONTACTS = new Map();
for (const [base, nc, role] of [['LD', 'LDI', 'load'], ['AND', 'ANI', 'and'], ['OR', 'ORI', 'or']]) {
  CONTACTS.set(base, { role, nc: false, edge: '' });
  CONTACTS.set(nc, { role, nc: true, edge: '' });
  CONTACTS.set(base + 'P', { role, nc: false, edge: 'rise' });
  CONTACTS.set(base + 'F', { role, nc: false, edge: 'fall' });
  CONTACTS.set(base + 'PI', { role, nc: true, edge: 'rise' });
  CONTACTS.set(base + 'FI', { role, nc: true, edge: 'fall' });
}
// Bit-of-word contacts (iQ-R BLD D0 K5): the bit is the second operand.
for (const [m, role, nc] of [['BLD', 'load', false], ['BLDI', 'load', true], ['BAND', 'and', false],
  ['BANI', 'and', true], ['BOR', 'or', false], ['BORI', 'or', true]]) CONTACTS.set(m, { role, nc, edge: '', bitOf: true });

// Compare contacts: LD= AND<> OR>=, typed LDD> LDE< LD$= LDED=, unsigned LD=_U / LD_U=.
const COMPARE = /^(LD|AND|OR)(ED|[DE$])?(_U)?(<>|<=|>=|=|<|>)(_U)?$/;
const COMPARE_ROLE = { LD: 'load', AND: 'and', OR: 'or' };

// Series elements without a device of their own (EGP/EGF name their edge relay).
const SERIES = { INV: '/', MEP: '↑', MEF: '↓', EGP: '↑', EGF: '↓' };

// Instructions that take no input condition: wired straight from the left
// rail, each a rung of its own.
const UNCONDITIONAL = new Set(['END', 'FEND', 'MCR', 'RET', 'SRET', 'IRET', 'FOR', 'NEXT']);
const SKIPPED = new Set(['NOP', 'NOPLF', 'PAGE']);

// Where a bit instruction's destination is its first operand.
const BIT_OUTPUTS = new Set(['OUT', 'OUTH', 'SET', 'RST', 'PLS', 'PLF', 'FF', 'ALT', 'ALTP']);
// Instructions that write no device worth watching (jumps, calls, loops, control).
const NO_DESTINATION = /^(CJ|SCJ|JMP|CALL|FCALL|ECALL|XCALL|GOEND|FOR|NEXT|BREAK|RET|SRET|IRET|END|FEND|MCR|WDT|EI|DI|IMASK|STOP|COM|NOP)P?$/;

function classify(mnemonic, operands = []) {
  const m = mnemonic.toUpperCase();
  const contact = CONTACTS.get(m);
  if (contact) return { type: 'contact', ...contact };
  const compare = COMPARE.exec(m);
  if (compare) {
    return { type: 'compare', role: COMPARE_ROLE[compare[1]], prefix: compare[2] || '', op: compare[4], unsigned: Boolean(compare[3] || compare[5]) };
  }
  if (m === 'ANB' || m === 'ORB' || m === 'MPS' || m === 'MRD' || m === 'MPP') return { type: 'stack', role: m.toLowerCase() };
  if (SERIES[m]) return { type: 'series', role: 'and', mark: SERIES[m] };
  if (SKIPPED.has(m)) return { type: 'skip', role: 'skip' };
  if (UNCONDITIONAL.has(m)) return { type: 'box', role: 'output', unconditional: true };
  // A bit coil: OUT Y0, SET M0, RST Y1 (OUT T0 K20 names its setting: a box).
  if ((m === 'OUT' || m === 'SET' || m === 'RST') && operands.length === 1) return { type: 'coil', role: 'output', letter: m === 'OUT' ? '' : m[0] };
  return { type: 'box', role: 'output' };
}

// ------------------------------------------------------------------ rungs --
// A rung is a tree. A node has a condition (a series: elements and parallel
// groups, each branch of a parallel group a series again) and, after it, its
// outputs: output elements and child nodes (the branches of MPS/MRD/MPP, or
// an AND that continues after an output). While a node's condition is built,
// `blocks` is the MELSEC block stack: LD pushes, AND/OR work on the top,
// ANB/ORB combine the top two. A branch's stack starts with an empty series:
// the result MPS saved, which ANB after MPP combines with.

function newNode(branch) { return { blocks: branch ? [[]] : [], cond: null, outs: [] }; }

function childOf(node) {
  const child = newNode(true);
  node.outs.push({ t: 'node', node: child });
  return child;
}

function seal(node) {
  if (node.cond) return;
  if (node.blocks.length > 1) throw new Error('a block is left open (ANB or ORB missing)');
  node.cond = node.blocks[0] || [];
  node.blocks = null;
}

function topBlock(node) {
  const block = node.blocks[node.blocks.length - 1];
  if (!block) throw new Error('AND or OR without LD');
  return block;
}

// `a` or `b` in parallel; a group gets one more branch rather than a nested group.
function parallel(a, b) {
  if (!a.length || !b.length) throw new Error('OR or ORB without a block');
  if (a.length === 1 && a[0].t === 'par') return [{ t: 'par', items: [...a[0].items, b] }];
  return [{ t: 'par', items: [a, b] }];
}

function applyLine(rung, el) {
  const role = el.info.role;
  let node = rung.cur;
  if (role === 'load') {
    if (node.cond) throw new Error('LD after an output inside an MPS branch without MRD or MPP');
    node.blocks.push([el]);
  } else if (role === 'and') {
    if (node.cond) node = rung.cur = childOf(node);   // LD X0 / OUT Y0 / AND X1 / OUT Y1
    topBlock(node).push(el);
  } else if (role === 'or') {
    if (node.cond) throw new Error('OR after an output');
    node.blocks.push(parallel(node.blocks.pop() || [], [el]));
  } else if (role === 'anb' || role === 'orb') {
    if (node.cond || node.blocks.length < 2) throw new Error(`${role.toUpperCase()} needs two blocks`);
    const b = node.blocks.pop();
    const a = node.blocks.pop();
    node.blocks.push(role === 'anb' ? [...a, ...b] : parallel(a, b));
  } else if (role === 'mps') {
    if (node.cond) throw new Error('MPS after an output');
    seal(node);
    rung.branches.push(node);
    rung.cur = childOf(node);
  } else if (role === 'mrd' || role === 'mpp') {
    const point = role === 'mrd' ? rung.branches[rung.branches.length - 1] : rung.branches.pop();
    if (!point) throw new Error(`${role.toUpperCase()} without MPS`);
    if (!node.cond) throw new Error(`a branch without an output before ${role.toUpperCase()}`);
    rung.cur = childOf(point);
  } else {
    seal(node);
    node.outs.push({ t: 'out', el });
  }
}

function finishRung(rung) {
  if (rung.error || !rung.root) return;
  if (rung.branches.length) rung.error = 'MPS without MPP';
  else if (!rung.cur.cond) rung.error = 'the rung ends without an output';
  if (rung.error) rung.root = null;
}

// Splits the program's lines into rungs. A rung starts at an LD-class
// instruction that follows an output when no MPS branch is open, at an
// instruction without input condition (END, MCR, FOR...), after one, and
// after a pointer label. Statements wait for the next rung and show above
// it; a pointer shows at its left rail. A rung the stack rules cannot draw
// keeps its lines (rung.error says why) and is shown as a list.
function buildRungs(lines) {
  const rungs = [];
  let rung = null;
  let statements = [];
  let labels = [];
  const start = () => {
    rung = { lines: [], statements, labels, root: newNode(false), cur: null, branches: [], depth: 0, lastOutput: false, closed: false, error: null };
    rung.cur = rung.root;
    statements = [];
    labels = [];
    rungs.push(rung);
  };
  for (const line of lines) {
    if (line.kind === 'statement') { statements.push(line.statement || ''); continue; }
    if (line.kind === 'pointer') {
      if (rung) finishRung(rung);
      rung = null;
      labels.push(line.mnemonic);
      continue;
    }
    const operands = line.operands || [];
    const info = classify(line.mnemonic || '', operands);
    const el = { line, info, ops: operands };
    if (info.type === 'skip') { if (rung) rung.lines.push(el); continue; }
    const startsRung = !rung || rung.closed
      || (info.role === 'load' && rung.lastOutput && rung.depth === 0)
      || (info.unconditional && rung.lines.length > 0);
    if (startsRung) {
      if (rung) finishRung(rung);
      start();
    }
    rung.lines.push(el);
    // Kept apart from the tree so that a rung which cannot be drawn still splits where it should.
    if (info.role === 'mps') rung.depth++;
    if (info.role === 'mpp') rung.depth = Math.max(0, rung.depth - 1);
    rung.lastOutput = info.role === 'output';
    rung.closed = Boolean(info.unconditional);
    if (!rung.error) {
      try { applyLine(rung, el); } catch (e) { rung.error = e.message; rung.root = null; }
    }
  }
  if (rung) finishRung(rung);
  if (statements.length || labels.length) rungs.push({ lines: [], statements, labels, root: null, error: null });
  return rungs;
}

// ----------------------------------------------------------------- layout --
// In grid units: a series is as wide as its items together and as tall as
// its tallest; a parallel group as wide as its widest branch and as tall as
// its branches together. Every item's wire enters and leaves on its top row.

const sizes = new WeakMap();

function elementCols(el) {
  if (el.info.type === 'compare') return 2;
  if (el.info.type === 'series' && !el.ops.length) return 0.5;
  return 1;
}

function size(item) {
  let s = sizes.get(item);
  if (s) return s;
  if (Array.isArray(item)) {
    s = { w: 0, h: 1 };
    for (const x of item) { const k = size(x); s.w += k.w; s.h = Math.max(s.h, k.h); }
  } else if (item.t === 'par') {
    s = { w: 0, h: 0 };
    for (const b of item.items) { const k = size(b); s.w = Math.max(s.w, k.w); s.h += k.h; }
  } else {
    s = { w: elementCols(item), h: 1 };
  }
  sizes.set(item, s);
  return s;
}

function nodeRows(node) {
  let outs = 0;
  for (const o of node.outs) outs += o.t === 'node' ? nodeRows(o.node) : 1;
  return Math.max(size(node.cond).h, outs, 1);
}

// Columns of conditions from the node's start to its rightmost contact.
function nodeCols(node) {
  let after = 0;
  for (const o of node.outs) if (o.t === 'node') after = Math.max(after, nodeCols(o.node));
  return size(node.cond).w + after;
}

function outputsOf(node, list = []) {
  for (const o of node.outs) {
    if (o.t === 'node') outputsOf(o.node, list);
    else list.push(o.el);
  }
  return list;
}

function clip(text, n) { return text.length > n ? `${text.slice(0, n - 1)}…` : text; }

// The fields of an output box: the mnemonic, then one per operand.
function boxFields(el) {
  const fields = [{ text: el.line.mnemonic, w: Math.max(3, el.line.mnemonic.length) * CHAR + 14 }];
  for (const op of el.ops) fields.push({ text: clip(op, 18), op, w: Math.max(7, Math.min(op.length, 18)) * CHAR + 14 });
  return fields;
}

function outputWidth(el) {
  if (el.info.type === 'coil') return CW;
  return boxFields(el).reduce((sum, f) => sum + f.w, 0) + 12;
}

// The columns every rung is drawn with, so the right rails line up.
function ladderLayout(rungs) {
  let cols = MIN_COLS;
  let out = CW;
  for (const r of rungs) {
    if (!r.root) continue;
    cols = Math.max(cols, nodeCols(r.root));
    for (const el of outputsOf(r.root)) out = Math.max(out, outputWidth(el));
  }
  const railX = RAIL + cols * CW + out;
  return { cols, railX, width: railX + 12 };
}

// --------------------------------------------------- what the program writes --

// The devices the program writes, in program order, as watch ranges: OUT/SET/
// RST/PLS/PLF/FF destinations, timer and counter coils (current value and
// contact), and the last device operand of the other instructions (MOV K1 D0,
// + D1 D2 D3, BMOV D10 D30 K2: D30). Constants, indexed operands and what the
// device table does not know are skipped; a digit designation K4M0 watches M0-M15.
function writtenDevices(lines, parse, max = PREFILL_MAX) {
  const found = [];
  const seen = new Set();
  const add = (range) => {
    const key = `${range.symbol}:${range.start}`;
    if (seen.has(key) || found.length >= max) return;
    seen.add(key);
    found.push(range);
  };
  const device = (text) => {
    const upper = text.toUpperCase();
    const counter = /^(LST|LT|ST|LC|T|C)(\d+)$/.exec(upper);
    if (counter) return [`${counter[1]}N${counter[2]}`, `${counter[1]}S${counter[2]}`].map((a) => one(a, 1)).filter(Boolean);
    const digits = /^K([1-8])([A-Z]+[0-9A-F]+)$/.exec(upper);
    if (digits) { const r = one(digits[2], Number(digits[1]) * 4); return r ? [r] : []; }
    const r = one(upper.split('.')[0], 1);
    return r ? [r] : [];
  };
  const one = (text, count) => {
    try {
      const a = parse(text);
      return { symbol: a.symbol, spec: a.spec, start: a.number, count };
    } catch {
      return null;   // a constant, an indexed operand, a pointer
    }
  };
  for (const line of lines) {
    if (line.kind !== 'instruction' || !line.operands || !line.operands.length) continue;
    const m = line.mnemonic.toUpperCase();
    const info = classify(m, line.operands);
    if (info.role !== 'output' || NO_DESTINATION.test(m)) continue;
    let candidates;
    if (BIT_OUTPUTS.has(m)) candidates = [line.operands[0]];
    else candidates = [...line.operands].reverse();
    for (const text of candidates) {
      const ranges = device(text);
      if (!ranges.length) continue;
      ranges.forEach(add);
      break;
    }
    if (found.length >= max) break;
  }
  return found;
}

// --------------------------------------------------------------- drawing --

const SVG_NS = 'http://www.w3.org/2000/svg';

function svg(tag, attrs, parent) {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.append(e);
  return e;
}

function label(parent, x, y, content, cls, anchor = 'middle') {
  const t = svg('text', { x, y, class: cls, 'text-anchor': anchor }, parent);
  t.textContent = content;
  return t;
}

function line(parent, x1, y1, x2, y2, cls = 'wire') { return svg('line', { x1, y1, x2, y2, class: cls }, parent); }

// Device comments match whatever zero-padding the program or the comment file used (X000A, XA).
function commentKey(device) { return device.toUpperCase().replace(/^([A-Z]+)0+(?=[0-9A-F])/, '$1'); }

// Signed or unsigned 16 bits of a constant (K-5, H8000) or a device's value; null when unknown.
function word16(text, devices, unsigned) {
  let v = null;
  const k = /^K(-?\d+)$/i.exec(text);
  const h = /^H([0-9A-F]+)$/i.exec(text);
  if (k) v = Number(k[1]);
  else if (h) v = parseInt(h[1], 16);
  else if (devices[text] && devices[text].value !== undefined) v = devices[text].value;
  if (v === null) return null;
  v &= 0xFFFF;
  return unsigned || v < 0x8000 ? v : v - 0x10000;
}

const COMPARISONS = {
  '=': (a, b) => a === b, '<>': (a, b) => a !== b, '<': (a, b) => a < b,
  '>': (a, b) => a > b, '<=': (a, b) => a <= b, '>=': (a, b) => a >= b,
};

// What a drawing keeps besides the DOM. From the program, for every rung:
// `places` (the rung box of each element naming a device, for the search)
// and `rungOfRow` (for the error). From the rungs drawn so far: `updaters`
// (per operand, run when its state changes), `named` (the elements naming a
// device) and `rows` (the element of a source row).
function newIndex() { return { places: new Map(), rungOfRow: new Map(), updaters: new Map(), named: new Map(), rows: new Map() }; }

function searchKeys(operand) { const upper = operand.toUpperCase(); return new Set([upper, upper.split('.')[0]]); }

function addTo(map, key, value) {
  if (!map.has(key)) map.set(key, []);
  map.get(key).push(value);
}

// `fn(devices)` runs when `operand` changes, and once when its rung is drawn.
function onUpdate(ctx, operand, fn) {
  addTo(ctx.index.updaters, operand, fn);
  ctx.fresh.push(fn);
}

function nameIn(ctx, operand, element) {
  for (const key of searchKeys(operand)) {
    addTo(ctx.index.named, key, element);
    if (key === view.searchKey) { element.classList.add('found'); view.found.push(element); }
  }
}

function rowIn(ctx, row, element) {
  ctx.index.rows.set(row, element);
  if (view.error && view.error.row === row) { element.classList.add('error'); view.error.element = element; }
}

function tooltip(g, el, comments) {
  const parts = [`${el.line.mnemonic} ${el.ops.join(' ')}`.trim()];
  for (const op of el.ops) if (comments.has(commentKey(op))) parts.push(`${op}: ${comments.get(commentKey(op))}`);
  if (el.line.note) parts.push(el.line.note);
  parts.push(`row ${el.line.row}${el.line.step !== undefined ? `, step ${el.line.step}` : ''}`);
  svg('title', {}, g).textContent = parts.join('\n');
}

// The group of one element at (x, y) px, with a highlight rect behind it for the search.
function elementGroup(parent, el, kind, x, y, w, ctx) {
  const g = svg('g', { class: `el ${kind}`, transform: `translate(${x},${y})` }, parent);
  svg('rect', { class: 'hl', x: 3, y: 2, width: w - 6, height: RH - 4, rx: 3 }, g);
  if (el.ops[0]) g.dataset.device = el.ops[0];
  g.dataset.row = el.line.row;
  for (const op of el.ops) nameIn(ctx, op, g);
  rowIn(ctx, el.line.row, g);
  tooltip(g, el, ctx.comments);
  return g;
}

function commentText(g, x, y, op, ctx, chars = CLIP) {
  const c = ctx.comments.get(commentKey(op));
  if (c) label(g, x, y, clip(c, chars), 'cmt');
}

function drawContact(parent, el, x, y, ctx) {
  const g = elementGroup(parent, el, 'contact', x, y, CW, ctx);
  const cx = CW / 2;
  const op = el.ops[0] || '';
  line(g, 0, WY, cx - 7, WY);
  line(g, cx + 7, WY, CW, WY);
  svg('rect', { class: 'body', x: cx - 7, y: WY - 10, width: 14, height: 20 }, g);
  line(g, cx - 7, WY - 10, cx - 7, WY + 10, 'bar');
  line(g, cx + 7, WY - 10, cx + 7, WY + 10, 'bar');
  if (el.info.nc) line(g, cx - 7, WY + 10, cx + 7, WY - 10, 'mark');
  if (el.info.edge) label(g, cx, WY + 4, el.info.edge === 'rise' ? '↑' : '↓', 'arrow');
  const name = el.info.bitOf ? `${op}.${(el.ops[1] || '').replace(/^K/i, '')}` : op;
  label(g, cx, 13, clip(name, CLIP), 'name');
  const value = label(g, cx, WY + 23, '', 'val');
  commentText(g, cx, WY + 35, op, ctx);
  if (el.info.bitOf) {
    // BLD D0 K5: the contact is bit 5 of D0's value.
    const bit = /^K(\d+)$/i.exec(el.ops[1] || '');
    onUpdate(ctx, op, (devices) => {
      const s = devices[op];
      const known = Boolean(s && s.value !== undefined && bit);
      const on = known && ((s.value >> Number(bit[1])) & 1) === 1;
      g.classList.toggle('on', known && on !== el.info.nc);
    });
    return;
  }
  onUpdate(ctx, op, (devices) => {
    const s = devices[op];
    const known = Boolean(s && s.on !== undefined);
    g.classList.toggle('on', known && (s.on === 1) !== el.info.nc);
    value.textContent = s && s.value !== undefined ? String(s.value) : '';
  });
}

function drawCompare(parent, el, x, y, ctx) {
  const w = 2 * CW;
  const g = elementGroup(parent, el, 'compare', x, y, w, ctx);
  const [a = '', b = ''] = el.ops;
  line(g, 0, WY, 8, WY);
  line(g, w - 8, WY, w, WY);
  svg('rect', { class: 'body frame', x: 8, y: WY - 12, width: w - 16, height: 24 }, g);
  const op = el.info.op + (el.info.unsigned ? 'U' : '');
  label(g, 8 + 4, WY + 4, `${el.info.prefix}${op}`, 'mnem', 'start');
  label(g, w / 2 + 8, WY + 4, clip(`${a} ${b}`, 17), 'name');
  const value = label(g, w / 2, WY + 23, '', 'val');
  commentText(g, w / 2, WY + 35, a, ctx, 24);
  // The contact's state is worked out here for 16-bit compares only: a
  // 32-bit, real or string compare needs more than the monitor's one word.
  const evaluable = el.info.prefix === '';
  const update = (devices) => {
    const shown = [a, b].filter((o) => devices[o] && devices[o].value !== undefined).map((o) => `${o}=${devices[o].value}`);
    value.textContent = clip(shown.join(' '), 26);
    if (!evaluable) return;
    const va = word16(a, devices, el.info.unsigned);
    const vb = word16(b, devices, el.info.unsigned);
    g.classList.toggle('on', va !== null && vb !== null && COMPARISONS[el.info.op](va, vb));
  };
  onUpdate(ctx, a, update);
  if (b !== a) onUpdate(ctx, b, update);
}

function drawSeriesElement(parent, el, x, y, ctx) {
  const w = elementCols(el) * CW;
  const g = elementGroup(parent, el, 'series', x, y, w, ctx);
  const cx = w / 2;
  line(g, 0, WY, w, WY);
  if (el.info.mark === '/') line(g, cx - 6, WY + 9, cx + 6, WY - 9, 'mark');
  else {
    // An arrow across the wire: up for the rising edge (MEP, EGP), down for the falling one.
    const tip = el.info.mark === '↑' ? WY - 10 : WY + 10;
    const back = el.info.mark === '↑' ? tip + 5 : tip - 5;
    line(g, cx, WY - 10, cx, WY + 10, 'mark');
    svg('path', { class: 'mark', d: `M${cx - 4},${back} L${cx},${tip} L${cx + 4},${back}` }, g);
  }
  label(g, cx, 13, clip(el.ops[0] || el.line.mnemonic.toUpperCase(), CLIP), 'name');
}

function drawCoil(parent, el, x, y, ctx) {
  const g = elementGroup(parent, el, 'coil', x, y, CW, ctx);
  const cx = CW / 2;
  const op = el.ops[0] || '';
  line(g, 0, WY, cx - 10, WY);
  line(g, cx + 10, WY, CW, WY);
  svg('ellipse', { class: 'body', cx, cy: WY, rx: 9, ry: 10 }, g);
  svg('path', { class: 'bar', d: `M${cx - 4},${WY - 11} A14,14 0 0 0 ${cx - 4},${WY + 11}` }, g);
  svg('path', { class: 'bar', d: `M${cx + 4},${WY - 11} A14,14 0 0 1 ${cx + 4},${WY + 11}` }, g);
  if (el.info.letter) label(g, cx, WY + 4, el.info.letter, 'letter');
  label(g, cx, 13, clip(op, CLIP), 'name');
  const value = label(g, cx, WY + 23, '', 'val');
  commentText(g, cx, WY + 35, op, ctx);
  onUpdate(ctx, op, (devices) => {
    const s = devices[op];
    g.classList.toggle('on', Boolean(s && s.on === 1));
    value.textContent = s && s.value !== undefined ? String(s.value) : '';
  });
}

function drawBox(parent, el, x, y, ctx) {
  const fields = boxFields(el);
  const w = outputWidth(el);
  const g = elementGroup(parent, el, 'box', x, y, w, ctx);
  line(g, 0, WY, 4, WY);
  svg('path', { class: 'bar', d: `M12,${WY - 12} H4 V${WY + 12} H12` }, g);
  svg('path', { class: 'bar', d: `M${w - 12},${WY - 12} H${w - 4} V${WY + 12} H${w - 12}` }, g);
  let fx = 6;
  const timerSetting = /^OUTH?$/i.test(el.line.mnemonic) && el.ops.length === 2;
  fields.forEach((f, i) => {
    const cx = fx + f.w / 2;
    if (i === 0) label(g, cx, WY + 4, f.text, 'mnem');
    else {
      const op = f.op;
      const body = svg('rect', { class: 'field', x: fx + 2, y: WY - 10, width: f.w - 4, height: 20, rx: 2 }, g);
      label(g, cx, WY + 4, f.text, 'name');
      const value = label(g, cx, WY + 23, '', 'val');
      commentText(g, cx, WY + 35, op, ctx, Math.floor(f.w / CHAR));
      // OUT T0 K20: under T0 its current value against the setting ("12/K20").
      const setting = timerSetting && i === 1 ? el.ops[1] : null;
      const update = (devices) => {
        const s = devices[op];
        body.classList.toggle('on', Boolean(s && s.on === 1));
        let text = s && s.value !== undefined ? String(s.value) : '';
        if (setting !== null && text) {
          const sv = devices[setting];
          text += `/${sv && sv.value !== undefined ? sv.value : setting}`;
        }
        value.textContent = text;
      };
      onUpdate(ctx, op, update);
      if (setting !== null) onUpdate(ctx, setting, update);
    }
    fx += f.w;
  });
}

function drawElement(parent, el, x, y, ctx) {
  const py = y * RH;
  switch (el.info.type) {
    case 'contact': return drawContact(parent, el, x, py, ctx);
    case 'compare': return drawCompare(parent, el, x, py, ctx);
    case 'series': return drawSeriesElement(parent, el, x, py, ctx);
    case 'coil': return drawCoil(parent, el, x, py, ctx);
    default: return drawBox(parent, el, x, py, ctx);
  }
}

// Rows `from` and `to` joined by a vertical link at x.
function vlink(parent, x, from, to) { if (to > from) line(parent, x, from * RH + WY, x, to * RH + WY); }

function drawSeries(parent, items, x, y, ctx) {
  for (const item of items) {
    if (item.t === 'par') drawParallel(parent, item, x, y, ctx);
    else drawElement(parent, item, x, y, ctx);
    x += size(item).w * CW;
  }
}

function drawParallel(parent, par, x, y, ctx) {
  const right = x + size(par).w * CW;
  let row = y;
  let last = y;
  for (const branch of par.items) {
    last = row;
    drawSeries(parent, branch, x, row, ctx);
    const end = x + size(branch).w * CW;
    if (end < right) line(parent, end, row * RH + WY, right, row * RH + WY);
    row += size(branch).h;
  }
  vlink(parent, x, y, last);
  vlink(parent, right, y, last);
}

function drawNode(parent, node, x, y, ctx) {
  drawSeries(parent, node.cond, x, y, ctx);
  const bx = x + size(node.cond).w * CW;
  let row = y;
  let last = y;
  for (const o of node.outs) {
    last = row;
    if (o.t === 'node') {
      drawNode(parent, o.node, bx, row, ctx);
      row += nodeRows(o.node);
    } else {
      const left = ctx.layout.railX - outputWidth(o.el);
      line(parent, bx, row * RH + WY, left, row * RH + WY);
      drawElement(parent, o.el, left, row, ctx);
      row += 1;
    }
  }
  vlink(parent, bx, y, last);
}

// A rung the stack rules cannot draw: its instructions as a list, operands still live.
function drawList(box, rung, ctx) {
  const note = document.createElement('div');
  note.className = 'rung-note';
  note.textContent = `shown as a list: ${rung.error}`;
  const list = document.createElement('div');
  list.className = 'rung-list';
  for (const el of rung.lines) {
    const row = document.createElement('div');
    row.dataset.row = el.line.row;
    rowIn(ctx, el.line.row, row);
    const step = document.createElement('span');
    step.className = 'step';
    step.textContent = el.line.step !== undefined ? el.line.step : '';
    const mnemonic = document.createElement('b');
    mnemonic.textContent = el.line.mnemonic;
    row.append(step, mnemonic);
    for (const op of el.ops) {
      const span = document.createElement('span');
      span.className = 'op';
      span.textContent = op;
      nameIn(ctx, op, span);
      onUpdate(ctx, op, (devices) => {
        const s = devices[op];
        span.classList.toggle('on', Boolean(s && s.on === 1));
        span.title = s && s.value !== undefined ? `${op} = ${s.value}` : '';
      });
      row.append(' ', span);
    }
    list.append(row);
  }
  box.append(note, list);
}

function pointerLabel(box, rung) {
  if (rung.labels.length) box.append(Object.assign(document.createElement('div'), { className: 'pointer-label', textContent: rung.labels.join(' ') }));
}

// A rung's box: its statements, a placeholder as tall as its drawing (drawn
// when it scrolls near: renderRung) and a line for an error message.
function rungShell(rung, number, ctx) {
  const box = document.createElement('div');
  box.className = 'rung';
  box.dataset.rung = number;
  for (const text of rung.statements) {
    const s = document.createElement('div');
    s.className = 'statement';
    s.textContent = text;
    box.append(s);
  }
  for (const el of rung.lines) {
    ctx.index.rungOfRow.set(el.line.row, box);
    for (const op of el.ops) for (const key of searchKeys(op)) addTo(ctx.index.places, key, box);
  }
  if (rung.root) {
    const placeholder = document.createElement('div');
    placeholder.className = 'rung-placeholder';
    placeholder.style.height = `${nodeRows(rung.root) * RH}px`;
    box.append(placeholder);
  } else {
    pointerLabel(box, rung);
  }
  const error = document.createElement('div');
  error.className = 'rung-error';
  error.hidden = true;
  box.append(error);
  return box;
}

// Draws a rung into its box (once) and gives it the devices' current state.
function renderRung(entry, ctx) {
  if (entry.drawn) return;
  entry.drawn = true;
  const { rung, box } = entry;
  const fresh = [];
  const rctx = { ...ctx, fresh };
  if (rung.root) {
    const height = nodeRows(rung.root) * RH;
    const width = ctx.layout.width;
    const root = svg('svg', { class: 'ladder', width, height, viewBox: `0 0 ${width} ${height}` });
    line(root, RAIL, 0, RAIL, height, 'rail');
    line(root, ctx.layout.railX, 0, ctx.layout.railX, height, 'rail');
    const first = rung.lines[0];
    if (first && first.line.step !== undefined) label(root, RAIL - 6, 13, String(first.line.step), 'step', 'end');
    rung.labels.forEach((p, i) => label(root, 4, WY + 4 + i * 14, p, 'pointer', 'start'));
    drawNode(root, rung.root, RAIL, 0, rctx);
    $('.rung-placeholder', box).replaceWith(root);
  } else if (rung.lines.length) {
    const part = document.createDocumentFragment();
    drawList(part, rung, rctx);
    box.insertBefore(part, $('.rung-error', box));
  }
  for (const fn of fresh) fn(view.devices);
}

// ------------------------------------------------------------------ panel --

const view = {
  key: null,             // load|file|name|steps of the program drawn; null: nothing drawn yet
  index: newIndex(),
  last: new Map(),       // operand -> its state at the last poll, as text, to see what changed
  devices: {},
  rungs: [],             // {rung, box, drawn} in program order
  ctx: null,             // what renderRung draws with: layout, comments, index
  observer: null,        // draws the rungs that scroll near
  error: null,           // {key, row, rung, element} highlighted for last_error
  searchKey: '',         // the device searched for, upper case
  found: [],             // elements drawn so far that the search highlights
  foundAt: 0,
  timer: null,           // the next poll, while polling
  busy: false,           // a poll is in flight
  onScreen: false,
};
window.__program = { classify, buildRungs, writtenDevices, ladderLayout, nodeRows, nodeCols, view };

// `load` counts the programs written to this CPU, so a new program with the same
// file name and size is drawn afresh.
function programKey(p) { return p.state === 'loaded' ? `${p.load}|${p.file}|${p.name}|${p.steps}` : 'none'; }

function microseconds(us) { return `${Number(us).toFixed(us < 10 ? 2 : 1)} µs`; }

function showStatus(p) {
  const status = $('#program-status');
  if (p.state !== 'loaded') { status.textContent = `CPU ${p.cpu_state}`; return; }
  const m = p.modelled_us || {};
  status.textContent = `CPU ${p.cpu_state} · ${p.steps} steps · scans ${p.scans} · executed ${p.executed_last} instructions`
    + ` · scan (modelled) ${microseconds(m.last || 0)} (min ${microseconds(m.min || 0)}, max ${microseconds(m.max || 0)})`
    + ` · host ${microseconds(p.host_us_last || 0)} · operation errors ${p.operation_errors}`;
}

function showError(err) {
  if (view.error) {
    if (view.error.rung) {
      view.error.rung.classList.remove('error');
      $('.rung-error', view.error.rung).hidden = true;
    }
    if (view.error.element) view.error.element.classList.remove('error');
    view.error = null;
  }
  if (!err) return;
  const rung = view.index.rungOfRow.get(err.row) || null;
  const element = view.index.rows.get(err.row) || null;   // or when its rung is drawn (rowIn)
  view.error = { key: JSON.stringify(err), row: err.row, rung, element };
  if (!rung) return;
  rung.classList.add('error');
  const box = $('.rung-error', rung);
  box.textContent = `error ${err.code} at ${err.mnemonic} (row ${err.row}, step ${err.step}): ${err.message}`;
  box.hidden = false;
  if (element) element.classList.add('error');
}

function stateText(s) { return s ? `${s.on ?? ''},${s.value ?? ''}` : '-'; }

// Runs the updaters of the operands whose state changed (all of them after a new drawing).
function applyDevices(devices) {
  view.devices = devices;
  const run = new Set();
  for (const [op, s] of Object.entries(devices)) {
    const text = stateText(s);
    if (view.last.get(op) === text) continue;
    view.last.set(op, text);
    for (const fn of view.index.updaters.get(op) || []) run.add(fn);
  }
  for (const fn of run) fn(devices);
}

// Highlights every element naming the device (those drawn later too) and
// scrolls to the first place; `step` 1 goes on to the next place.
function search(text, step = 0) {
  for (const e of view.found) e.classList.remove('found');
  const key = text.trim().toUpperCase();
  view.searchKey = key;
  view.found = key ? [...(view.index.named.get(key) || [])] : [];
  for (const e of view.found) e.classList.add('found');
  const places = key ? (view.index.places.get(key) || []) : [];
  $('#program-found').textContent = key ? `${places.length} ${places.length === 1 ? 'place' : 'places'}` : '';
  if (!places.length) return;
  view.foundAt = step ? (view.foundAt + step) % places.length : 0;
  places[view.foundAt].scrollIntoView({ block: 'nearest' });
}

function draw(info) {
  const ladder = $('#ladder');
  const loaded = info.state === 'loaded';
  $('#program-none').hidden = loaded;
  $('#program-name').textContent = loaded ? `${info.name} · ${info.file} (${info.format})` : '';
  const warnings = $('#program-warnings');
  warnings.hidden = !loaded || !(info.warnings || []).length;
  if (!warnings.hidden) {
    $('summary', warnings).textContent = `${info.warnings.length} warning${info.warnings.length === 1 ? '' : 's'}`;
    const list = $('ul', warnings);
    list.replaceChildren(...info.warnings.map((w) => Object.assign(document.createElement('li'), { textContent: w })));
  }
  if (view.observer) view.observer.disconnect();
  view.index = newIndex();
  view.last = new Map();
  view.error = null;
  view.found = [];
  view.rungs = [];
  if (!loaded) {
    ladder.replaceChildren();
    $('#program-rungs').textContent = '';
    return;
  }
  const comments = new Map((info.comments || []).map((c) => [commentKey(c.device), c.comment]));
  const rungs = buildRungs(info.lines || []);
  view.ctx = { layout: ladderLayout(rungs), comments, index: view.index };
  const fragment = document.createDocumentFragment();
  view.rungs = rungs.map((rung, i) => {
    const box = rungShell(rung, i, view.ctx);
    fragment.append(box);
    return { rung, box, drawn: false };
  });
  ladder.replaceChildren(fragment);
  // Only the rungs near the visible part of the ladder are drawn: a program
  // of thousands of rungs would otherwise be hundreds of thousands of SVG nodes.
  const entries = new Map(view.rungs.map((e) => [e.box, e]));
  view.observer = new IntersectionObserver((seen) => {
    for (const s of seen) {
      if (!s.isIntersecting) continue;
      renderRung(entries.get(s.target), view.ctx);
      view.observer.unobserve(s.target);
    }
  }, { root: ladder, rootMargin: '600px 0px' });
  for (const e of view.rungs) view.observer.observe(e.box);
  $('#program-rungs').textContent = `(${rungs.length} rung${rungs.length === 1 ? '' : 's'})`;
  search($('#program-search').value);
}

async function load() {
  const info = await api('GET', stationPath('/program?lines=1'));
  draw(info);
  view.key = programKey(info);
  return info;
}

async function poll() {
  view.timer = null;
  if (view.busy) return;
  view.busy = true;
  let next = PROGRAM_POLL_MS;
  try {
    const p = await api('GET', stationPath('/program/monitor'));
    if (programKey(p) !== view.key) await load();
    showStatus(p);
    if (p.state === 'loaded') {
      applyDevices(p.devices || {});
      const errKey = p.last_error ? JSON.stringify(p.last_error) : null;
      if ((view.error && view.error.key) !== errKey) showError(p.last_error);
    } else {
      next = PROGRAM_IDLE_MS;
    }
    $('#program').classList.remove('failed');
  } catch (e) {
    $('#program').classList.add('failed');
    $('#program-status').textContent = `monitor: ${e.message}`;
    next = PROGRAM_IDLE_MS;
  } finally {
    view.busy = false;
  }
  schedule(next);
}

function polling() { return view.onScreen && document.visibilityState === 'visible'; }

function schedule(ms) {
  clearTimeout(view.timer);
  view.timer = polling() ? setTimeout(poll, ms) : null;
}

// Back on screen (or the tab shown again): poll now, unless one is already on its way.
function resume() { if (polling() && !view.timer && !view.busy) poll(); }

// Fills an empty watch list with what the program writes (once, at page start).
function prefillWatches(info) {
  if (state.watches.length || info.state !== 'loaded') return;
  for (const range of writtenDevices(info.lines || [], parseAddress)) addWatch(range, range.spec.unit === 'bit' ? 'unsigned' : 'signed');
}

async function startProgram() {
  let info;
  try {
    info = await api('GET', stationPath('/program?lines=1'));
  } catch {
    return;   // a station without a scan cycle runs no program: no panel
  }
  const section = $('#program');
  section.hidden = false;
  prefillWatches(info);
  draw(info);
  view.key = programKey(info);
  const input = $('#program-search');
  input.addEventListener('input', () => search(input.value));
  input.addEventListener('keydown', (event) => { if (event.key === 'Enter') { event.preventDefault(); search(input.value, 1); } });
  // Poll only while someone can see it: on screen (or nearly) in a visible tab.
  new IntersectionObserver((entries) => {
    view.onScreen = entries.some((e) => e.isIntersecting);
    resume();
  }, { rootMargin: '200px' }).observe(section);
  document.addEventListener('visibilitychange', resume);
}

// main.js starts it after startStation(): the watches need the device table.
window.startProgram = startProgram;
})();
