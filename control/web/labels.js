// The labels panel of the web monitor: the CPU's global labels as a tree
// (structures open into their members, timer-family labels into S/C/N), each
// leaf with its values, kept fresh by a light poll (label-area writes raise no
// device events). Click a number or text to edit it, a bit to toggle it.
// Uses api(), stationPath(), showMessage() and $() from app.js; docs/api.md "Labels".
'use strict';

const TIMER_TYPES = new Set(['Timer', 'Counter', 'Retentive Timer', 'Long Timer', 'Long Counter', 'Long Retentive Timer']);
const MAX_LABEL_LEAVES = 64;      // rows polled once a second
const MAX_ELEMENTS_SHOWN = 32;    // values shown per array row
const MAX_STRUCT_ELEMENTS = 8;    // elements opened per array of structures or timers

const labelState = { leaves: [], timer: null };

// "Word [Signed](0..1,0..19)" -> {base: "Word [Signed]", dims: [2, 20]}; "String(32)" has no dims.
function splitDims(type) {
  const m = /^(.*)\((\d+\.\.\d+(?:,\d+\.\.\d+)*)\)$/.exec(type);
  if (!m) return { base: type, dims: [] };
  return { base: m[1], dims: m[2].split(',').map((r) => { const [lo, hi] = r.split('..').map(Number); return hi - lo + 1; }) };
}

// The name of element `k` (row-major) of an array with `dims`: "A[1,3]".
function elementName(name, dims, k) {
  const index = [];
  for (let d = dims.length - 1; d >= 0; d--) { index.unshift(k % dims[d]); k = Math.floor(k / dims[d]); }
  return `${name}[${index.join(',')}]`;
}

// Depth-first: a leaf is a basic scalar or a whole basic array (one row).
function expandLabel(name, type, structures, depth, out) {
  if (out.length >= MAX_LABEL_LEAVES) return;
  const { base, dims } = splitDims(type);
  const structure = structures.get(base);
  const timer = TIMER_TYPES.has(base);
  if (!structure && !timer) {
    const count = dims.reduce((a, b) => a * b, 1);
    out.push({ name, depth, type, dims, first: dims.length ? elementName(name, dims, 0) : name, count });
    return;
  }
  if (dims.length) {
    out.push({ name, depth, type, heading: true });
    const count = Math.min(dims.reduce((a, b) => a * b, 1), MAX_STRUCT_ELEMENTS);
    for (let k = 0; k < count; k++) expandLabel(elementName(name, dims, k), base, structures, depth + 1, out);
    return;
  }
  out.push({ name, depth, type, heading: true });
  if (timer) {
    for (const m of ['S', 'C', 'N']) out.push({ name: `${name}.${m}`, depth: depth + 1, type: m === 'N' ? 'current value' : 'Bit', dims: [], first: `${name}.${m}`, count: 1 });
    return;
  }
  for (const m of structure.members) expandLabel(`${name}.${m.name}`, m.type, structures, depth + 1, out);
}

function labelPath(name) { return stationPath(`/labels/${encodeURIComponent(name)}`); }

function showLabelValue(value) { return typeof value === 'string' ? JSON.stringify(value) : String(value); }

async function refreshLeaf(leaf) {
  try {
    const data = await api('GET', `${labelPath(leaf.first)}?count=${Math.min(leaf.count, MAX_ELEMENTS_SHOWN)}`);
    leaf.valueType = data.type;
    data.values.forEach((v, i) => {
      const cell = leaf.cells[i];
      if (!cell || cell.querySelector('input')) return;   // being edited
      const text = showLabelValue(v);
      if (leaf.values[i] !== undefined && leaf.values[i] !== v) {
        cell.classList.remove('flash');
        void cell.offsetWidth;   // restart the animation
        cell.classList.add('flash');
      }
      leaf.values[i] = v;
      cell.textContent = text;
      cell.classList.toggle('on', data.type === 'Bit' && v === 1);
    });
  } catch (e) {
    leaf.row.classList.add('failed');
  }
}

async function writeLabel(leaf, i, body) {
  const name = leaf.dims.length ? elementName(leaf.name, leaf.dims, i) : leaf.first;
  try {
    await api('PUT', labelPath(name), body);
  } catch (e) {
    showMessage(`${name}: ${e.message}`);
  }
  await refreshLeaf(leaf);
}

function editLabel(leaf, i, cell) {
  if (leaf.valueType === 'Bit') {
    writeLabel(leaf, i, { values: [leaf.values[i] === 1 ? 0 : 1] });
    return;
  }
  if (cell.querySelector('input')) return;
  const text = typeof leaf.values[i] === 'string';
  const input = document.createElement('input');
  input.className = 'edit';
  input.value = leaf.values[i] === undefined ? '' : String(leaf.values[i]);
  cell.replaceChildren(input);
  input.focus();
  input.select();
  const finish = () => { cell.replaceChildren(); cell.textContent = leaf.values[i] === undefined ? '·' : showLabelValue(leaf.values[i]); };
  input.addEventListener('keydown', async (event) => {
    if (event.key === 'Escape') finish();
    if (event.key !== 'Enter') return;
    const raw = input.value.trim();
    const number = Number(raw);
    if (!text && (raw === '' || Number.isNaN(number))) {
      showMessage(`${leaf.name}: '${raw}' is not a number`);
      return;
    }
    finish();
    await writeLabel(leaf, i, text ? { string: input.value } : { values: [number] });
  });
  input.addEventListener('blur', finish);
}

function buildLabelRows(leaves) {
  const body = $('#labels tbody');
  body.replaceChildren();
  for (const leaf of leaves) {
    const row = body.insertRow();
    leaf.row = row;
    row.dataset.label = leaf.name;
    const nameCell = row.insertCell();
    nameCell.textContent = leaf.name.split('.').pop();
    nameCell.title = leaf.name;
    nameCell.style.paddingLeft = `${0.5 + leaf.depth * 1.2}em`;
    row.insertCell().textContent = leaf.type;
    const valuesCell = row.insertCell();
    if (leaf.heading) { row.className = 'heading'; continue; }
    leaf.values = [];
    leaf.cells = [];
    const shown = Math.min(leaf.count, MAX_ELEMENTS_SHOWN);
    for (let i = 0; i < shown; i++) {
      const cell = document.createElement('span');
      cell.className = 'value';
      cell.dataset.element = leaf.dims.length ? elementName(leaf.name, leaf.dims, i) : leaf.name;
      cell.textContent = '·';
      cell.addEventListener('click', () => editLabel(leaf, i, cell));
      valuesCell.append(cell);
      leaf.cells.push(cell);
    }
    if (leaf.count > shown) valuesCell.append(` … ${leaf.count - shown} more`);
  }
}

function refreshLabels() { labelState.leaves.filter((l) => !l.heading).forEach(refreshLeaf); }

async function startLabels() {
  const data = await api('GET', stationPath('/labels'));
  if (!data.labels.length) return;   // the panel stays hidden
  const structures = new Map(data.structures.map((s) => [s.name, s]));
  const leaves = [];
  for (const l of data.labels) expandLabel(l.name, l.type, structures, 0, leaves);
  labelState.leaves = leaves;
  $('#label-count').textContent = leaves.length >= MAX_LABEL_LEAVES
    ? `${data.labels.length} (first ${MAX_LABEL_LEAVES} rows)` : String(data.labels.length);
  buildLabelRows(leaves);
  $('#labels-section').hidden = false;
  refreshLabels();
  labelState.timer = setInterval(refreshLabels, 1000);
}
