// The plant overview: the start page of a process serving many stations
// (docs/plants.md). One row per station from GET /api/stations, polled every
// second; requests/s is the change of a station's request count between two
// polls. The filter box hides rows client-side (a name containing the text,
// any case) and keeps the text in the address as #/?filter=TEXT, so a link or
// a reload opens the same view. Each name opens that station's page.
// (In the fragment, not the query: the server serves / with no parameters.)
// A plant of more than PLANT_PAGE stations (a 10 000-station process) is read a
// page at a time: the first PLANT_PAGE stations whose name contains the filter
// (the server filters, any case), so typing narrows what is polled.
// Below the list, the plant's networks (GET /api/networks) when it has any.
// Uses api(), showMessage() and $() from app.js.
'use strict';

const PLANT_POLL_MS = 1000;
const PLANT_PAGE = 500;

const plant = {
  rows: new Map(),       // station name -> its <tr>
  previous: new Map(),   // station name -> {requests, at}: the last poll, for the rate
  polling: false,        // a poll is in flight; the next tick skips rather than piles up
  total: 0,              // stations in the plant (X-Total-Count without a filter)
  large: false,          // more than PLANT_PAGE: poll a filtered page, not every station
};

// A page of the overview: {stations, total} where total counts the matches.
async function fetchStations(filter) {
  const path = `/api/stations?limit=${PLANT_PAGE}${filter ? `&filter=${encodeURIComponent(filter.trim())}` : ''}`;
  const response = await fetch(path);
  if (!response.ok) throw new Error(`GET ${path}: HTTP ${response.status}`);
  const stations = await response.json();
  return { stations, total: Number(response.headers.get('X-Total-Count') || stations.length) };
}

// Requests per second between two polls of one station, each {requests, at}
// (`at` in ms). null without an earlier poll, or when the count went back.
function requestRate(before, now) {
  if (!before || now.at <= before.at || now.requests < before.requests) return null;
  return (now.requests - before.requests) * 1000 / (now.at - before.at);
}

function showRate(rate) {
  if (rate === null) return '—';
  return rate >= 100 ? rate.toFixed(0) : rate.toFixed(1);
}

function stationMatches(name, filter) { return name.toLowerCase().includes(filter.trim().toLowerCase()); }

function slmpPorts(s) {
  const part = (transport, ports) => (ports.length ? `${transport} ${ports.join(', ')}` : '');
  return [s.bind, part('TCP', s.tcp), part('UDP', s.udp)].filter(Boolean).join(' · ');
}

function stationRow(s) {
  const row = document.createElement('tr');
  row.dataset.station = s.name;
  // data-column, not a class: .state and friends already style the header.
  for (const column of ['name', 'type', 'state', 'slmp', 'connections', 'requests', 'rate', 'errors']) row.insertCell().dataset.column = column;
  const link = document.createElement('a');
  link.href = `#/stations/${encodeURIComponent(s.name)}`;
  link.textContent = s.name;
  row.cells[0].append(link);
  for (const k of [5, 6, 7]) row.cells[k].classList.add('number');
  return row;
}

function updateRow(row, s, rate) {
  const [, type, stateCell, slmp, connections, requests, rateCell, errors] = row.cells;
  type.textContent = s.type_name;
  type.title = `profile ${s.profile}, ${s.family}`;
  stateCell.replaceChildren();
  const badge = document.createElement('span');
  badge.className = `state-badge ${s.state.toLowerCase()}`;
  badge.textContent = s.state;
  stateCell.append(badge);
  slmp.textContent = slmpPorts(s);
  connections.textContent = s.connections;
  requests.textContent = s.requests;
  rateCell.textContent = showRate(rate);
  errors.textContent = s.errors;
  errors.classList.toggle('nonzero', s.errors > 0);
}

function applyFilter() {
  const filter = $('#station-filter').value;
  let shown = 0;
  for (const [name, row] of plant.rows) {
    row.hidden = !stationMatches(name, filter);
    if (!row.hidden) shown++;
  }
  const total = plant.total;
  $('#station-count').textContent = shown === total ? `(${total})` : `(${shown} of ${total})`;
}

function showStations(stations, at, matching = stations.length) {
  const body = $('#stations tbody');
  const seen = new Set();
  let running = 0;
  for (const s of stations) {
    seen.add(s.name);
    let row = plant.rows.get(s.name);
    if (!row) {
      row = stationRow(s);
      plant.rows.set(s.name, row);
    }
    body.append(row);   // keeps the rows in the plant's order
    const now = { requests: s.requests, at };
    updateRow(row, s, requestRate(plant.previous.get(s.name), now));
    plant.previous.set(s.name, now);
    if (s.state === 'RUN') running++;
  }
  for (const [name, row] of plant.rows) {
    if (!seen.has(name)) { row.remove(); plant.rows.delete(name); plant.previous.delete(name); }
  }
  $('#plant-summary').textContent = plant.large
    ? `plant of ${plant.total} stations · ${matching} match, the first ${stations.length} shown: type in the filter to narrow`
    : `plant of ${plant.total} stations · ${running} in RUN`;
  applyFilter();
}

async function pollStations() {
  if (plant.polling) return;
  plant.polling = true;
  try {
    const page = await fetchStations(plant.large ? $('#station-filter').value : '');
    if (!plant.large) plant.total = page.total;
    showStations(page.stations, performance.now(), page.total);
  } catch (e) {
    showMessage(`stations: ${e.message}`);
  } finally {
    plant.polling = false;
  }
}

// The plant's networks from GET /api/networks (fixed while the process runs,
// so read once): a bus line a network with its stations by station No., the
// master in bold, and "⇄ 2" on a station that relays to network 2.
async function showNetworks() {
  let networks;
  try {
    const response = await fetch('/api/networks');
    if (!response.ok) throw new Error(`GET /api/networks: HTTP ${response.status}`);
    networks = await response.json();
  } catch (e) {
    showMessage(`networks: ${e.message}`);
    return;
  }
  const list = $('#network-list');
  list.replaceChildren();
  for (const n of networks) {
    const row = document.createElement('div');
    row.className = 'network';
    row.dataset.network = n.number;
    const name = document.createElement('span');
    name.className = 'network-name';
    name.textContent = `network ${n.number}`;
    const bus = document.createElement('div');
    bus.className = 'network-bus';
    for (const s of n.stations) {
      const chip = document.createElement('a');
      chip.className = `network-station${s.master ? ' master' : ''}`;
      chip.href = `#/stations/${encodeURIComponent(s.name)}`;
      chip.dataset.station = s.name;
      chip.textContent = `${s.station} ${s.name}`;
      chip.title = `station No. ${s.station} on network ${n.number}${s.master ? ', the master' : ''}`;
      const relay = n.relays.find((r) => r.name === s.name);
      if (relay) {
        const mark = document.createElement('span');
        mark.className = 'relay';
        mark.textContent = `⇄ ${relay.to_networks.join(', ')}`;
        mark.title = `relays to network ${relay.to_networks.join(', ')}`;
        chip.append(mark);
      }
      bus.append(chip);
    }
    row.append(name, bus);
    list.append(row);
  }
  $('#networks').hidden = networks.length === 0;
}

function startPlant(stations, total) {
  plant.total = total;
  plant.large = total > PLANT_PAGE;
  document.title = `plant (${total} stations) — slmp-sim monitor`;
  const filter = $('#station-filter');
  const filterInHash = () => new URLSearchParams(location.hash.split('?')[1] || '').get('filter') || '';
  filter.value = filterInHash();
  filter.addEventListener('input', () => {
    // replaceState: no history entry per keystroke, and no hashchange.
    history.replaceState(null, '', filter.value ? `#/?filter=${encodeURIComponent(filter.value)}` : '#/');
    applyFilter();
  });
  // The address edited by hand (main.js reloads only for another station).
  window.addEventListener('hashchange', () => { filter.value = filterInHash(); applyFilter(); });
  showStations(stations, performance.now(), total);
  showNetworks();
  setInterval(pollStations, PLANT_POLL_MS);
}
