// The trend plots of the station page: devices (D100, M0, TN5) and global
// labels (LabelW, Tank1.Level) read twice a second into a rolling window and
// drawn as step lines by uPlot (embedded from control/web-deps). Bits get a
// 0/1 scale of their own on the right. Pause freezes the chart while the
// samples keep coming; a drag across it zooms in (and pauses), a double-click
// zooms out.
// Sampled with GET .../devices/{address}?count=1 and .../labels/{name} rather
// than the event stream: labels in the label area raise no device events, and
// one sample time for every series is what uPlot's aligned columns want. A
// change shorter than the sampling interval may not show.
// Uses api(), stationPath(), storageKey(), parseAddress(), formatAddress(),
// showMessage() and $() from app.js, labelPath() from labels.js.
'use strict';

const TREND_SAMPLE_MS = 500;
const TREND_MAX_SERIES = 8;
const TREND_HEIGHT = 280;
const TREND_COLORS = ['#0b6bcb', '#c62828', '#1f9d55', '#b7791f', '#7b3fb5', '#00838f', '#d81b60', '#546e7a'];

// Also window.__trend, where the browser test reads the sampled data.
const trend = {
  series: [],          // {name, path, bit, color, chip}
  data: [[]],          // uPlot's columns: sample times (s since the epoch), then one per series; replaced, never mutated, so a paused chart keeps its own
  windowSeconds: 300,
  following: true,     // false: paused (the button or a zoom); samples still collect
  chart: null,
  sampling: false,     // a sample is in flight; the next tick skips rather than piles up
};
window.__trend = trend;

// -------------------------------------------------------------- series --

// A device or, failing that, a global label; read once so a typo or a
// string label is refused when it is added, not every half second after.
async function resolveSeries(text) {
  let address = null;
  try { address = parseAddress(text); } catch { /* not a device: try a label */ }
  if (address) {
    const name = formatAddress(address.symbol, address.number);
    const path = stationPath(`/devices/${name}?count=1`);
    await api('GET', path);
    return { name, path, bit: address.spec.unit === 'bit' };
  }
  if (/^[A-Za-z]+[0-9A-Fa-f]+-/.test(text)) throw new Error(`plot one device at a time ('${text.split('-')[0]}'), not a range`);
  const path = `${labelPath(text)}?count=1`;
  const first = await api('GET', path);
  if (typeof first.values[0] !== 'number') throw new Error(`${text} is a ${first.type}; only numbers can be plotted`);
  return { name: first.name, path, bit: first.type === 'Bit' };
}

async function addSeries(text) {
  if (trend.series.length >= TREND_MAX_SERIES) throw new Error(`plot at most ${TREND_MAX_SERIES} series at once; remove one first`);
  const s = await resolveSeries(text.trim());
  if (trend.series.some((x) => x.name === s.name)) throw new Error(`${s.name} is already plotted`);
  s.color = TREND_COLORS.find((c) => !trend.series.some((x) => x.color === c));
  trend.series.push(s);
  // The new series has no past: nulls, which uPlot leaves as a gap.
  trend.data = [...trend.data, trend.data[0].map(() => null)];
  seriesChanged();
}

function removeSeries(s) {
  const k = trend.series.indexOf(s);
  if (k < 0) return;
  trend.series.splice(k, 1);
  trend.data = trend.data.filter((_, i) => i !== k + 1);
  seriesChanged();
}

function seriesChanged() {
  localStorage.setItem(storageKey('trend'), JSON.stringify({ series: trend.series.map((s) => s.name), window: trend.windowSeconds }));
  showSeriesList();
  buildChart();
}

function showSeriesList() {
  const list = $('#trend-series');
  list.replaceChildren();
  for (const s of trend.series) {
    const chip = document.createElement('span');
    chip.className = 'series-chip';
    chip.dataset.series = s.name;
    const swatch = document.createElement('i');
    swatch.style.background = s.color;
    const remove = document.createElement('button');
    remove.type = 'button';
    remove.textContent = '✕';
    remove.title = `Stop plotting ${s.name}`;
    remove.addEventListener('click', () => removeSeries(s));
    chip.append(swatch, s.name, remove);
    list.append(chip);
    s.chip = chip;
  }
}

// ------------------------------------------------------------ sampling --

async function readSeries(s) {
  try {
    const data = await api('GET', s.path);
    s.chip.classList.remove('failed');
    s.chip.title = '';
    return data.values[0];
  } catch (e) {
    s.chip.classList.add('failed');   // a gap in the line; the reason on hover
    s.chip.title = e.message;
    return null;
  }
}

// One row: the time and a value per series; rows older than the window go.
function appendRow(at, values) {
  const first = trend.data[0].findIndex((t) => t >= at - trend.windowSeconds);
  const keep = first < 0 ? trend.data[0].length : first;
  trend.data = trend.data.map((column, k) => column.slice(keep).concat([k === 0 ? at : values[k - 1]]));
}

async function sample() {
  if (trend.sampling || !trend.series.length) return;
  trend.sampling = true;
  try {
    // performance.now() only goes forward: the columns stay sorted when the wall clock is set back.
    const at = (performance.timeOrigin + performance.now()) / 1000;
    const sampled = trend.series.slice();
    const values = new Map(sampled.map((s, i) => [s, i]));
    const read = await Promise.all(sampled.map(readSeries));
    // A series added or removed meanwhile: the row follows the series as they are now.
    appendRow(at, trend.series.map((s) => (values.has(s) ? read[values.get(s)] : null)));
    draw();
  } finally {
    trend.sampling = false;
  }
}

// --------------------------------------------------------------- chart --

function draw() { if (trend.chart && trend.following) trend.chart.setData(trend.data); }

function setFollowing(following) {
  trend.following = following;
  const button = $('#trend-pause');
  button.textContent = following ? 'Pause' : 'Resume';
  button.classList.toggle('active', !following);
  draw();   // resuming shows what was sampled meanwhile, zoomed out
}

function buildChart() {
  const box = $('#trend-chart');
  if (trend.chart) trend.chart.destroy();
  trend.chart = null;
  box.hidden = trend.series.length === 0;
  if (box.hidden) return;
  const bits = trend.series.some((s) => s.bit);
  const numbers = trend.series.some((s) => !s.bit);
  const step = uPlot.paths.stepped({ align: 1 });   // a sampled value holds until the next sample
  const axes = [{}];
  if (numbers) axes.push({ scale: 'value' });
  if (bits) axes.push({ scale: 'bit', side: 1, size: 36, splits: () => [0, 1], grid: { show: !numbers } });
  trend.chart = new uPlot({
    width: box.clientWidth,
    height: TREND_HEIGHT,
    scales: { x: { time: true }, bit: { range: [-0.1, 1.1] } },
    series: [{ label: 'time' }, ...trend.series.map((s) => ({
      label: s.name, stroke: s.color, width: 2, scale: s.bit ? 'bit' : 'value', paths: step, points: { show: false },
    }))],
    axes,
    cursor: { drag: { x: true, y: false } },
    // uPlot zooms on a drag by itself; a live chart would undo that at the next sample.
    hooks: { setSelect: [(u) => { if (u.select.width > 0) setFollowing(false); }] },
  }, trend.data, box);
}

// --------------------------------------------------------------- start --

// After startStation(): device names need the device table from /api/info.
async function startTrend() {
  $('#trend-form').addEventListener('submit', async (event) => {
    event.preventDefault();
    const input = $('#trend-input');
    const parts = input.value.split(',').map((p) => p.trim()).filter(Boolean);
    const failed = [];
    for (const part of parts) {
      try { await addSeries(part); } catch (e) { failed.push(part); showMessage(`${part}: ${e.message}`); }
    }
    input.value = failed.join(', ');
  });
  $('#trend-pause').addEventListener('click', () => setFollowing(!trend.following));
  const windowSelect = $('#trend-window');
  windowSelect.addEventListener('change', () => {
    trend.windowSeconds = Number(windowSelect.value);
    seriesChanged();
  });
  const box = $('#trend-chart');
  new ResizeObserver(() => { if (trend.chart && box.clientWidth) trend.chart.setSize({ width: box.clientWidth, height: TREND_HEIGHT }); }).observe(box);

  const saved = JSON.parse(localStorage.getItem(storageKey('trend')) || '{}');
  if ([...windowSelect.options].some((o) => Number(o.value) === saved.window)) {
    trend.windowSeconds = saved.window;
    windowSelect.value = String(saved.window);
  }
  for (const name of saved.series || []) {
    try { await addSeries(name); } catch (e) { showMessage(`trend ${name}: ${e.message}`); }
  }
  setInterval(sample, TREND_SAMPLE_MS);
}
