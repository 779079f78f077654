// The files panel of the web monitor: the CPU's file drives (kind, space used,
// card and LOCK switch, where the files live), one folder of the chosen drive
// (file No., name, size, DOS date, attribute; folders open, files download),
// and the open files with their locks, each releasable as close type 2 would.
// Kept fresh by a light poll: file commands raise no events. The panel builds
// its own markup so index.html only loads this script; hidden on a CPU
// without drives (FX5). Uses api(), stationPath(), showMessage() and $() from app.js;
// docs/api.md "File drives", docs/files.md. Everything is inside one function
// so its names cannot meet another panel's in the page's global scope.
'use strict';

(() => {

const FILES_POLL_MS = 2000;

const filesState = { drive: null, path: '', timer: null };

const FILES_MARKUP = `
  <h2>Files <span id="drive-count" class="count"></span></h2>
  <table id="drives" class="grid">
    <thead><tr><th>drive</th><th>kind</th><th>used</th><th>capacity</th><th>state</th><th>location</th></tr></thead>
    <tbody></tbody>
  </table>
  <h2 class="sub">Folder <span id="files-where" class="count"></span>
    <button id="files-up" type="button" title="The folder above">Up</button></h2>
  <table id="files" class="grid">
    <thead><tr><th>No.</th><th>name</th><th>size</th><th>date</th><th>attribute</th></tr></thead>
    <tbody></tbody>
  </table>
  <h2 class="sub">Open files and locks <span id="lock-count" class="count"></span></h2>
  <table id="locks" class="grid">
    <thead><tr><th>pointer</th><th>drive</th><th>path</th><th>mode</th><th>owner</th><th></th></tr></thead>
    <tbody></tbody>
  </table>`;

// "2:LOGS\A.CSV" as the CLI writes it (slmp file ls 2:LOGS).
function driveText(drive, path) { return `${drive}:${path}`; }

function driveState(d) {
  if (d.alias_of !== undefined) return `alias of drive ${d.alias_of}`;
  const flags = [];
  if (!d.present) flags.push('no card');
  if (d.write_protect) flags.push('LOCK');
  return flags.join(', ') || 'ready';
}

function attributeText(e) {
  if (e.directory) return 'folder';
  return e.read_only ? 'read-only' : '';
}

function openFolder(drive, path) {
  filesState.drive = drive;
  filesState.path = path;
  refreshFolder();
}

async function refreshDrives() {
  const data = await api('GET', stationPath('/drives'));
  const body = $('#drives tbody');
  body.replaceChildren();
  for (const d of data.drives) {
    const row = body.insertRow();
    row.dataset.drive = d.drive;
    if (d.drive === filesState.drive) row.className = 'chosen';
    const alias = d.alias_of !== undefined;
    for (const text of [d.drive, d.kind, alias ? '' : d.used, alias ? '' : d.capacity, driveState(d), alias ? '' : d.location])
      row.insertCell().textContent = text;
    if (!alias) row.addEventListener('click', () => openFolder(d.drive, ''));
  }
  $('#drive-count').textContent = `(${data.drives.length})`;
  return data.drives;
}

async function refreshFolder() {
  if (filesState.drive === null) return;
  const { drive, path } = filesState;
  $('#files-where').textContent = driveText(drive, path);
  $('#files-up').disabled = path === '';
  [...document.querySelectorAll('#drives tbody tr')].forEach((row) => row.classList.toggle('chosen', Number(row.dataset.drive) === drive));
  const body = $('#files tbody');
  let data;
  try {
    data = await api('GET', stationPath(`/drives/${drive}/files?path=${encodeURIComponent(path)}`));
  } catch (e) {
    body.replaceChildren();
    const cell = body.insertRow().insertCell();
    cell.colSpan = 5;
    cell.textContent = e.message;   // "no card in the slot" and the like
    return;
  }
  if (filesState.drive !== drive || filesState.path !== path) return;   // the user moved on meanwhile
  body.replaceChildren();
  for (const e of data.entries) {
    if (e.name === '.' || e.name === '..') continue;   // the Up button does their job
    const row = body.insertRow();
    row.dataset.name = e.name;
    row.insertCell().textContent = e.number;
    const nameCell = row.insertCell();
    const inner = path ? `${path}\\${e.name}` : e.name;
    const link = document.createElement('a');
    link.textContent = e.name;
    if (e.directory) {
      link.href = '#';
      link.className = 'folder';
      link.addEventListener('click', (event) => { event.preventDefault(); openFolder(drive, inner); });
    } else {
      link.href = stationPath(`/drives/${drive}/file?path=${encodeURIComponent(inner)}`);
      link.download = e.name;
      link.title = 'Download';
    }
    nameCell.append(link);
    row.insertCell().textContent = e.directory ? '' : e.size;
    row.insertCell().textContent = e.date.replace('T', ' ');
    row.insertCell().textContent = attributeText(e);
  }
}

async function refreshLocks() {
  const data = await api('GET', stationPath('/drives/locks'));
  const body = $('#locks tbody');
  body.replaceChildren();
  for (const l of data.locks) {
    const row = body.insertRow();
    row.dataset.pointer = l.pointer;
    for (const text of [l.pointer, l.drive, l.path, l.mode, l.peer || `connection ${l.connection}`])
      row.insertCell().textContent = text;
    const button = document.createElement('button');
    button.type = 'button';
    button.textContent = 'Release';
    button.title = 'Release this lock (as 182A close type 2 would, for this file only)';
    button.addEventListener('click', async () => {
      try { await api('DELETE', stationPath(`/drives/locks/${l.pointer}`)); } catch (e) { showMessage(e.message); }
      refreshLocks();
    });
    row.insertCell().append(button);
  }
  $('#lock-count').textContent = `(${data.locks.length})`;
}

async function refreshFiles() {
  try {
    await Promise.all([refreshDrives(), refreshFolder(), refreshLocks()]);
  } catch (e) {
    showMessage(`files: ${e.message}`);
  }
}

async function startFiles() {
  const data = await api('GET', stationPath('/drives'));
  if (!data.drives.length) return;   // no drives, no panel
  const section = document.createElement('section');
  section.className = 'files';
  section.id = 'files-section';
  section.innerHTML = FILES_MARKUP;   // static markup; every value below goes in as text
  $('#station-view').append(section);
  $('#files-up').addEventListener('click', () => {
    const parts = filesState.path.split('\\');
    parts.pop();
    openFolder(filesState.drive, parts.join('\\'));
  });
  // Open the first drive with files of its own (an iQ-R drive 1 is an alias).
  const first = data.drives.find((d) => d.alias_of === undefined && d.present);
  if (first) filesState.drive = first.drive;
  await refreshFiles();
  filesState.timer = setInterval(refreshFiles, FILES_POLL_MS);
}

// main.js starts it with the station page (a plant's overview has no files panel).
window.startFiles = startFiles;
})();
