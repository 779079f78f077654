// Which page the monitor shows. A one-station process shows its station page,
// as it always did. A plant (GET /api/stations names its stations) starts at
// the overview (plant.js); #/stations/NAME shows that station's page, with
// every API call under /api/stations/NAME (station.base in app.js).
'use strict';

function stationInHash() {
  const m = /^#\/stations\/([^/?#]+)/.exec(location.hash);
  return m ? decodeURIComponent(m[1]) : null;
}

function showStationPage(isPlant) {
  document.body.dataset.view = 'station';
  if (isPlant) {
    $('#plant-link').hidden = false;
    $('#station-name').hidden = false;
    $('#station-name').textContent = station.name;
  }
  startStation()
    .then(() => {
      // Both need the device table startStation() reads (device names, the watches the program fills).
      startProgram().catch((e) => showMessage(`program: ${e.message}`));
      return startTrend();
    })
    .catch((e) => showMessage(`cannot start the monitor: ${e.message}`));
  startLabels().catch((e) => showMessage(`labels: ${e.message}`));
  startFiles().catch((e) => showMessage(`files: ${e.message}`));
}

async function main() {
  // A station page starts timers, an event stream and its panels; rather than
  // tear them down piecemeal, moving to another page (a station's link, the
  // plant link, Back) loads the page afresh for the new address.
  const shown = stationInHash();
  window.addEventListener('hashchange', () => { if (stationInHash() !== shown) location.reload(); });
  let stations = [];
  let total = 0;
  try {
    ({ stations, total } = await fetchStations(''));
  } catch (e) {
    showMessage(`stations: ${e.message}`);   // still show the (first) station
  }
  const isPlant = stations.some((s) => s.name !== '');
  // A station past the first page of a large plant: ask for it by name.
  const known = async (name) => stations.some((s) => s.name === name) ||
    api('GET', `/api/stations/${encodeURIComponent(name)}`).then(() => true, () => false);
  if (isPlant && shown !== null && await known(shown)) {
    station.name = shown;
    station.base = `/api/stations/${encodeURIComponent(shown)}`;
  } else if (isPlant) {
    document.body.dataset.view = 'plant';
    startPlant(stations, total);
    if (shown !== null) showMessage(`no station '${shown}' in this plant; pick one below`);
    return;
  }
  showStationPage(isPlant);
}

main();
