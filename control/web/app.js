// The slmp-sim web monitor's station page: device watch lists that update
// live, in-place editing, the open connections, running scenarios with their
// fault counts and a call monitor of recent requests. main.js decides which
// station it shows; labels.js and trend.js add their panels.
// Talks only to the simulator's own HTTP API (docs/api.md).
'use strict';

// The station this page shows. Every API call of the station page (here, in
// labels.js and trend.js) is stationPath('/devices/...'), so the prefix lives
// only here: '/api' in a one-station process, '/api/stations/NAME' for a
// station of a plant (main.js sets it before anything is fetched).
const station = { name: '', base: '/api' };

function stationPath(rest) { return station.base + rest; }

// What the browser remembers (watches, plotted series) is per station: a
// plant's stations each keep their own; a one-station process keeps the key
// it always had.
function storageKey(what) { return station.name ? `slmp-sim.${what}.${station.name}` : `slmp-sim.${what}`; }

const state = {
  devices: new Map(),   // symbol -> {unit, radix, name}, from /api/info
  watches: [],          // {id, spec, symbol, start, count, format, values, element}
  nextWatchId: 1,
  paused: false,
  live: false,
  pollTimer: null,
  compare: null,        // {different, compared} in differential mode, else null
};
const MAX_WATCH_DEVICES = 1024;
const MAX_CALL_ROWS = 200;

const $ = (selector, root = document) => root.querySelector(selector);

// ---------------------------------------------------------------- API calls --

async function api(method, path, body) {
  const options = { method, headers: {} };
  if (body !== undefined) {
    options.headers['Content-Type'] = 'application/json';
    options.body = JSON.stringify(body);
  }
  const response = await fetch(path, options);
  const data = await response.json().catch(() => ({}));
  if (!response.ok) throw new Error(data.error || `${method} ${path}: HTTP ${response.status}`);
  return data;
}

function showMessage(text, isError = true) {
  const box = $('#message');
  box.textContent = text;
  box.className = isError ? 'message error' : 'message';
  box.hidden = false;
  clearTimeout(showMessage.timer);
  showMessage.timer = setTimeout(() => { box.hidden = true; }, 6000);
}

// ------------------------------------------------------------- addresses --

// Splits "D100" into its symbol and number, the longest symbol first
// ("LTN0" is LTN, not L), as the simulator's device table does. The radix
// comes from /api/info, which gives the CPU's own (an FX5 numbers X/Y in octal).
const RADIXES = {
  8: { pattern: /^[0-7]+$/, name: 'octal on this CPU', bitsPerRow: 8 },
  10: { pattern: /^[0-9]+$/, name: 'decimal', bitsPerRow: 10 },
  16: { pattern: /^[0-9A-F]+$/, name: 'hexadecimal', bitsPerRow: 16 },
};

function parseAddress(text) {
  const upper = text.trim().toUpperCase();
  let best = null;
  for (const symbol of state.devices.keys()) {
    if (upper.length > symbol.length && upper.startsWith(symbol) && (!best || symbol.length > best.length)) best = symbol;
  }
  if (!best) throw new Error(`unknown device in '${text.trim()}' (e.g. D100, M0, X1F)`);
  const spec = state.devices.get(best);
  const digits = upper.slice(best.length);
  const radix = RADIXES[spec.radix];
  if (!radix.pattern.test(digits)) {
    const next = spec.radix === 8 ? `: ${best}7 is followed by ${best}10` : '';
    throw new Error(`bad device number '${digits}' in '${text.trim()}' (${best} is numbered in ${radix.name}${next})`);
  }
  return { symbol: best, spec, number: parseInt(digits, spec.radix) };
}

function formatAddress(symbol, number) {
  const spec = state.devices.get(symbol);
  return symbol + number.toString(spec ? spec.radix : 10).toUpperCase();
}

// "D100-D119", "D100-119", "X0-X1F" or a single "D100".
function parseRange(text) {
  const [first, last] = text.split('-');
  const start = parseAddress(first);
  let end = start;
  if (last !== undefined) {
    // "D100-D119" names the end in full; "D100-119" and "X0-1F" give only its number.
    try {
      end = parseAddress(last);
    } catch {
      end = parseAddress(start.symbol + last.trim());
    }
    if (end.symbol !== start.symbol) throw new Error(`'${text}' mixes ${start.symbol} and ${end.symbol}; watch one device kind per range`);
    if (end.number < start.number) throw new Error(`'${text}' ends before it starts`);
  }
  const count = end.number - start.number + 1;
  if (count > MAX_WATCH_DEVICES) throw new Error(`'${text}' has ${count} devices; watch at most ${MAX_WATCH_DEVICES} at once`);
  return { symbol: start.symbol, spec: start.spec, start: start.number, count };
}

// ----------------------------------------------------------------- values --

function show(value, unit, format) {
  if (unit === 'bit') return String(value);
  const bits = unit === 'dword' ? 32 : 16;
  if (format === 'hex') return '0x' + value.toString(16).toUpperCase().padStart(bits / 4, '0');
  if (format === 'signed' && value >= 2 ** (bits - 1)) return String(value - 2 ** bits);
  return String(value);
}

function parseInput(text) {
  const t = text.trim();
  const value = /^-?0x[0-9a-f]+$/i.test(t) ? (t.startsWith('-') ? -parseInt(t.slice(3), 16) : parseInt(t.slice(2), 16)) : Number(t);
  if (t === '' || !Number.isInteger(value)) throw new Error(`'${text}' is not a whole number (e.g. 42, -1, 0x1F)`);
  return value;
}

// ---------------------------------------------------------------- watches --

function saveWatches() {
  const saved = state.watches.map(w => ({ symbol: w.symbol, start: w.start, count: w.count, format: w.format }));
  localStorage.setItem(storageKey('watches'), JSON.stringify(saved));
}

function watchTitle(w) {
  const first = formatAddress(w.symbol, w.start);
  return w.count === 1 ? first : `${first}-${formatAddress(w.symbol, w.start + w.count - 1)}`;
}

function addWatch(range, format = 'unsigned') {
  const w = { id: state.nextWatchId++, ...range, format, values: new Array(range.count).fill(null) };
  const element = $('#watch-template').content.firstElementChild.cloneNode(true);
  w.element = element;
  element.dataset.watch = watchTitle(w);
  $('.watch-title', element).textContent = `${watchTitle(w)} · ${w.spec.name}`;
  const select = $('.watch-format', element);
  select.value = format;
  select.hidden = w.spec.unit === 'bit';
  select.addEventListener('change', () => { w.format = select.value; render(w); saveWatches(); });
  $('.watch-remove', element).addEventListener('click', () => {
    state.watches = state.watches.filter(x => x !== w);
    element.remove();
    saveWatches();
  });
  buildCells(w);
  $('#watch-list').append(element);
  state.watches.push(w);
  saveWatches();
  refreshWatch(w);
}

// Bits in rows of 16 (hex-numbered devices), 8 (octal) or 10 (decimal); words in rows of 10.
function buildCells(w) {
  const body = $('.watch-body', w.element);
  body.replaceChildren();
  const table = document.createElement('table');
  table.className = w.spec.unit === 'bit' ? 'cells bits' : 'cells words';
  const perRow = w.spec.unit === 'bit' ? RADIXES[w.spec.radix].bitsPerRow : (w.spec.unit === 'dword' ? 4 : 10);
  let row = null;
  w.cells = [];
  for (let i = 0; i < w.count; i++) {
    if (i % perRow === 0) {
      row = table.insertRow();
      const head = document.createElement('th');
      head.textContent = formatAddress(w.symbol, w.start + i);
      row.append(head);
    }
    const cell = row.insertCell();
    const address = formatAddress(w.symbol, w.start + i);
    cell.className = 'value';
    cell.dataset.address = address;
    cell.title = address;
    cell.textContent = '·';
    cell.addEventListener('click', () => edit(w, i, cell));
    w.cells.push(cell);
  }
  body.append(table);
}

function render(w, changed = new Set()) {
  w.values.forEach((value, i) => {
    const cell = w.cells[i];
    if (cell.querySelector('input')) return;   // being edited
    cell.textContent = value === null ? '·' : show(value, w.spec.unit, w.format);
    if (w.spec.unit === 'bit') cell.classList.toggle('on', value === 1);
    if (changed.has(i)) {
      cell.classList.remove('flash');
      void cell.offsetWidth;   // restart the animation
      cell.classList.add('flash');
    }
  });
}

async function refreshWatch(w) {
  try {
    const data = await api('GET', stationPath(`/devices/${formatAddress(w.symbol, w.start)}?count=${w.count}`));
    const changed = new Set();
    data.values.forEach((v, i) => { if (w.values[i] !== null && w.values[i] !== v) changed.add(i); w.values[i] = v; });
    render(w, changed);
    w.element.classList.remove('failed');
  } catch (e) {
    w.element.classList.add('failed');
    showMessage(`${watchTitle(w)}: ${e.message}`);
  }
}

function refreshAll() { state.watches.forEach(refreshWatch); }

async function write(w, i, value) {
  const address = formatAddress(w.symbol, w.start + i);
  try {
    await api('PUT', stationPath(`/devices/${address}`), { values: [value] });
    // The event stream brings the new value; without it, read it back.
    if (!state.live) await refreshWatch(w);
  } catch (e) {
    showMessage(`${address}: ${e.message}`);
  }
}

function edit(w, i, cell) {
  if (w.spec.unit === 'bit') {
    write(w, i, w.values[i] === 1 ? 0 : 1);
    return;
  }
  if (cell.querySelector('input')) return;
  const input = document.createElement('input');
  input.className = 'edit';
  input.value = w.values[i] === null ? '' : show(w.values[i], w.spec.unit, w.format);
  cell.replaceChildren(input);
  input.focus();
  input.select();
  const finish = () => { cell.replaceChildren(); render(w); };
  input.addEventListener('keydown', async (event) => {
    if (event.key === 'Escape') finish();
    if (event.key !== 'Enter') return;
    let value;
    try {
      value = parseInput(input.value);
    } catch (e) {
      showMessage(e.message);
      return;
    }
    finish();
    await write(w, i, value);
  });
  input.addEventListener('blur', finish);
}

// A "devices" event: the values written from `device` on; update every
// watch that overlaps it.
function applyWrite(event) {
  let start;
  try { start = parseAddress(event.device); } catch { return; }
  for (const w of state.watches) {
    if (w.symbol !== start.symbol) continue;
    const changed = new Set();
    event.values.forEach((value, k) => {
      const i = start.number + k - w.start;
      if (i < 0 || i >= w.count) return;
      if (w.values[i] !== value) changed.add(i);
      w.values[i] = value;
    });
    if (event.truncated && start.number + event.values.length < w.start + w.count) refreshWatch(w);
    if (changed.size) render(w, changed);
  }
}

// ------------------------------------------------------------ connections --

async function refreshConnections() {
  try {
    const data = await api('GET', stationPath('/connections'));
    const body = $('#connections tbody');
    body.replaceChildren();
    for (const c of data.connections) {
      const row = body.insertRow();
      row.dataset.id = c.id;
      for (const text of [c.id, c.peer, c.port, c.opened.replace('T', ' ').replace('Z', ''), c.requests]) row.insertCell().textContent = text;
      const button = document.createElement('button');
      button.textContent = 'Close';
      button.title = 'Close this connection';
      button.addEventListener('click', async () => {
        try { await api('DELETE', stationPath(`/connections/${c.id}`)); } catch (e) { showMessage(e.message); }
        refreshConnections();
      });
      row.insertCell().append(button);
    }
    $('#connection-count').textContent = `(${data.connections.length})`;
  } catch (e) {
    showMessage(`connections: ${e.message}`);
  }
}

// ------------------------------------------------------ scenarios, faults --

// Polled: fault counts change with every request, too often for events.
async function refreshScenarios() {
  try {
    const [s, f] = await Promise.all([api('GET', stationPath('/scenarios')), api('GET', stationPath('/faults'))]);
    const scenarios = $('#scenarios tbody');
    scenarios.replaceChildren();
    for (const sc of s.scenarios) {
      const row = scenarios.insertRow();
      row.title = sc.description;
      for (const text of [sc.name, sc.source, `${(sc.clock_ms / 1000).toFixed(1)} s`]) row.insertCell().textContent = text;
      const button = document.createElement('button');
      button.textContent = 'Stop';
      button.title = 'Stop this scenario (its devices keep their values)';
      button.addEventListener('click', async () => {
        try { await api('DELETE', stationPath(`/scenarios/${encodeURIComponent(sc.name)}`)); } catch (e) { showMessage(e.message); }
        refreshScenarios();
      });
      row.insertCell().append(button);
    }
    $('#scenario-count').textContent = `(${s.scenarios.length})`;

    const faults = $('#faults tbody');
    faults.replaceChildren();
    for (const fault of f.faults) {
      const row = faults.insertRow();
      row.dataset.id = fault.id;
      for (const text of [fault.id, fault.scenario, fault.kind]) row.insertCell().textContent = text;
      const toggle = document.createElement('input');
      toggle.type = 'checkbox';
      toggle.checked = fault.enabled;
      toggle.title = 'Turn this fault on or off';
      toggle.addEventListener('change', async () => {
        try { await api('PUT', stationPath(`/faults/${encodeURIComponent(fault.id)}`), { enabled: toggle.checked }); } catch (e) { showMessage(e.message); }
        refreshScenarios();
      });
      row.insertCell().append(toggle);
      row.insertCell().textContent = fault.matched;
      const fired = row.insertCell();
      fired.textContent = fault.fired;
      fired.className = fault.fired > 0 ? 'fired' : '';
    }
    $('#fault-count').textContent = `(${f.faults.length})`;
  } catch (e) {
    showMessage(`scenarios: ${e.message}`);
  }
}

// ----------------------------------------------------------- call monitor --

function addCallRow(cells, className) {
  if (state.paused) return;
  const body = $('#calls tbody');
  const row = body.insertRow(0);
  row.className = className;
  for (const text of cells) row.insertCell().textContent = text;
  while (body.rows.length > MAX_CALL_ROWS) body.deleteRow(-1);
}

// SLMP requests and the protocol faces' (protocol the face's name: a command
// text, no subcommand, a two-character response code where 00 is normal).
function addCall(call) {
  const frontEnd = call.protocol && call.protocol !== 'slmp';
  const what = frontEnd ? `${call.protocol} ${call.command}` : `${call.command}/${call.subcommand}`;
  const command = call.command ? `${what}${call.name ? ' ' + call.name : ''}` : (frontEnd ? call.protocol : '—');
  const devices = call.device ? `${call.device} ×${call.points} ${call.unit}` : (call.named || '');
  const endCode = call.end_code ?? (call.reaction === 'closed' ? 'closed' : 'no answer');
  const ok = call.end_code === (frontEnd ? '00' : '0000');
  // A request a module's port passed on names the route it came by (network, station No.).
  const peer = call.route ? `${call.peer} ⇢ net ${call.route.network} st ${call.route.station}` : call.peer;
  addCallRow([call.time.slice(11, 23), peer, command, devices, endCode, `${call.latency_us.toFixed(1)} µs`, call.note],
    ok ? '' : 'error');
}

// An Ondemand push the CPU sent unasked (docs/timing.md): no request, no latency.
function addPush(push) {
  addCallRow([new Date().toISOString().slice(11, 23), `${push.transport}:${push.peer}`, '2101 Ondemand (pushed)',
    push.why || '', '—', '', `${push.frame.length / 2} bytes sent unasked`], 'push');
}

// ------------------------------------------------------------- differences --

// Differential mode (--upstream HOST:PORT --compare; docs/twin.md, "Compare"):
// the requests the upstream and this station answered differently, newest
// first — the report (GET /api/compare) when the stream (re)opens, then each
// "compare" event as it comes.
const MAX_DIFFERENCE_ROWS = 100;

function addDifferenceRow(d, body = $('#differences tbody')) {
  const row = body.insertRow(0);
  row.className = 'error';
  for (const text of [`#${d.number}`, d.time.slice(11, 23), `${d.command}/${d.subcommand}`, d.kind, d.text])
    row.insertCell().textContent = text;
  row.title = `request ${d.request}`;
  while (body.rows.length > MAX_DIFFERENCE_ROWS) body.deleteRow(-1);
}

function showDifferenceCount() {
  $('#compare-count').textContent = `${state.compare.different} of ${state.compare.compared} compared`;
}

async function refreshDifferences() {
  if (!state.compare) return;
  try {
    const report = await api('GET', stationPath('/compare'));
    const body = $('#differences tbody');
    body.replaceChildren();
    for (const d of report.differences) addDifferenceRow(d, body);
    state.compare.different = report.different;
    state.compare.compared = report.compared;
    showDifferenceCount();
  } catch (e) {
    showMessage(e.message);
  }
}

function addDifference(d) {
  if (!state.compare) return;
  addDifferenceRow(d);
  state.compare.different += 1;
  state.compare.compared = Math.max(state.compare.compared, d.number);
  showDifferenceCount();
}

// ---------------------------------------------------------- operating state --

async function refreshState() {
  try {
    const s = await api('GET', stationPath('/state'));
    const badge = $('#state');
    badge.textContent = s.state + (s.cause ? ` (${s.cause}${s.error ? ' ' + s.error.code : ''})` : '');
    badge.className = `state ${s.state.toLowerCase()}`;
    $('#switch-run').classList.toggle('active', s.switch === 'RUN');
    $('#switch-stop').classList.toggle('active', s.switch === 'STOP');
  } catch (e) {
    $('#state').textContent = '?';
  }
}

async function setSwitch(position) {
  try { await api('PUT', stationPath('/state'), { switch: position }); } catch (e) { showMessage(e.message); }
  refreshState();
}

// ----------------------------------------------------------------- events --

function setLive(live, text) {
  state.live = live;
  const badge = $('#live');
  badge.textContent = text;
  badge.className = live ? 'live on' : 'live off';
  clearInterval(state.pollTimer);
  // Without the event stream, poll: the page keeps working, only slower.
  if (!live) state.pollTimer = setInterval(() => { refreshAll(); refreshConnections(); refreshDifferences(); }, 1000);
}

function connectEvents() {
  const source = new EventSource(stationPath('/events'));
  source.onopen = () => { setLive(true, 'live'); refreshAll(); refreshConnections(); refreshDifferences(); };
  source.onerror = () => setLive(false, 'polling (event stream lost)');
  source.addEventListener('devices', (e) => applyWrite(JSON.parse(e.data)));
  source.addEventListener('request', (e) => addCall(JSON.parse(e.data)));
  source.addEventListener('ondemand', (e) => addPush(JSON.parse(e.data)));
  source.addEventListener('compare', (e) => addDifference(JSON.parse(e.data)));
  source.addEventListener('connection', () => refreshConnections());
  source.addEventListener('overflow', () => { refreshAll(); refreshDifferences(); });
}

// ------------------------------------------------------------------ start --

async function startStation() {
  const info = await api('GET', stationPath('/info'));
  for (const d of info.devices) state.devices.set(d.symbol, d);
  $('#cpu').textContent = `${info.profile.type_name} (${info.profile.name}, ${info.profile.family})`;
  const ports = info.ports;
  $('#ports').textContent = `SLMP TCP ${ports.tcp.join(', ') || '—'} · UDP ${ports.udp.join(', ') || '—'}`;
  document.title = `${station.name ? station.name + ' · ' : ''}${info.profile.name} — slmp-sim monitor`;
  if (info.timing) $('#timing').textContent = `timing ${info.timing.mode}`;
  // Proxy and differential mode (docs/twin.md): the clients get the upstream's answers.
  if (info.upstream) {
    $('#ports').textContent += ` · ${info.mode} → ${info.upstream.address}`;
    if (info.mode === 'compare') {
      state.compare = { different: 0, compared: 0 };
      $('#compare-section').hidden = false;
      // Requests answered the same give no event: the count of those compared follows the report.
      setInterval(refreshDifferences, 2000);
    }
  }

  $('#watch-form').addEventListener('submit', (event) => {
    event.preventDefault();
    const input = $('#watch-input');
    try {
      for (const part of input.value.split(',').map(s => s.trim()).filter(Boolean)) addWatch(parseRange(part));
      input.value = '';
    } catch (e) {
      showMessage(e.message);
    }
  });
  $('#calls-pause').addEventListener('click', (event) => {
    state.paused = !state.paused;
    event.target.textContent = state.paused ? 'Resume' : 'Pause';
  });
  $('#calls-clear').addEventListener('click', () => $('#calls tbody').replaceChildren());
  $('#switch-run').addEventListener('click', () => setSwitch('RUN'));
  $('#switch-stop').addEventListener('click', () => setSwitch('STOP'));
  // Remote RUN/STOP/PAUSE from SLMP clients change the state too; a light poll follows them.
  refreshState();
  setInterval(refreshState, 1000);
  refreshScenarios();
  setInterval(refreshScenarios, 2000);

  const saved = JSON.parse(localStorage.getItem(storageKey('watches')) || '[]');
  for (const s of saved) {
    const spec = state.devices.get(s.symbol);
    if (spec) addWatch({ symbol: s.symbol, spec, start: s.start, count: s.count }, s.format);
  }
  refreshConnections();
  setLive(false, 'connecting…');
  connectEvents();
}
