#!/usr/bin/env node
// The plant overview in a real headless Chromium (harness.js) against the real
// slmp-sim serving a plant of three stations p1..p3: the start page lists them
// with their type, state, SLMP port, connections, requests and errors as SLMP
// clients use them; the filter box (and #/?filter=) narrows the list; a name
// opens that station's page, whose every call goes to /api/stations/NAME —
// a value written in the page lands in that station only, a value written to
// it through the API shows, and its trend plot reads it; the plant link leads
// back; an unknown station falls back to the overview with a message.
//
// Usage: node plant_test.js [path/to/slmp-sim] [--screenshot FILE]
//        (or SLMP_SIM_BINARY=...; CHROMIUM=... overrides /usr/bin/chromium)
// Prints one line per check and "N passed, N failed"; exits non-zero on failure.
'use strict';

const fs = require('fs');
const path = require('path');
const {
  parseArgs, check, run, out, eventually, assertEqual, withMonitor, httpJson, SlmpClient,
} = require('./harness');

const { binary, screenshot: screenshotFile, browserPath } = parseArgs(process.argv);

// p2 is network 1's master and relays to network 2, where p3 is.
const PLANT = {
  bind: '127.0.0.1',
  http: { port: 0 },
  stations: [
    { name: 'p1', tcp_port: 0, networks: [{ number: 1, station: 1 }] },
    { name: 'p2', tcp_port: 0, networks: [{ number: 1, station: 2, master: true }, { number: 2, station: 1 }] },
    { name: 'p3', tcp_port: 0, networks: [{ number: 2, station: 2 }] },
  ],
};

async function main() {
  const args = (dir) => {
    const configFile = path.join(dir, 'plant.json');
    fs.writeFileSync(configFile, JSON.stringify(PLANT));
    return ['--config', configFile, '--threads', '2'];
  };
  await withMonitor({ binary, browserPath, args }, async ({ page, pageErrors, ready }) => {
    const base = `http://127.0.0.1:${ready.http}`;
    const tcpPort = (name) => ready.stations.find((s) => s.name === name).tcp[0];
    const p2 = new SlmpClient(tcpPort('p2'));

    const rowTexts = () => page.evaluate(() => [...document.querySelectorAll('#stations tbody tr')]
      .filter((row) => !row.hidden).map((row) => row.dataset.station));
    const cell = (name, column) => page.evaluate(([n, c]) => {
      const found = document.querySelector(`#stations tr[data-station="${n}"] td[data-column="${c}"]`);
      return found ? found.textContent : null;
    }, [name, column]);

    await check('a plant starts at the overview listing p1, p2, p3', async () => {
      await page.goto(`${base}/`);
      await page.waitForSelector('body[data-view="plant"]');
      await page.waitForSelector('#stations tr[data-station="p3"]');
      assertEqual(await rowTexts(), ['p1', 'p2', 'p3'], 'rows');
      assertEqual(await page.textContent('#station-count'), '(3)', 'count');
      assertEqual(await page.textContent('#plant-summary'), 'plant of 3 stations · 3 in RUN', 'summary');
      if (await page.isVisible('#station-view')) throw new Error('the station page shows too');
    });

    await check('each row names the type, state and the station\'s own SLMP port, and links to its page', async () => {
      for (const name of ['p1', 'p2', 'p3']) {
        assertEqual(await cell(name, 'type'), 'R08CPU', `${name} type`);
        assertEqual(await cell(name, 'state'), 'RUN', `${name} state`);
        assertEqual(await cell(name, 'slmp'), `127.0.0.1 · TCP ${tcpPort(name)}`, `${name} SLMP`);
        assertEqual(await page.getAttribute(`#stations tr[data-station="${name}"] td[data-column="name"] a`, 'href'), `#/stations/${name}`, `${name} link`);
      }
    });

    await check('the networks panel draws each network with its stations, the master and the relay', async () => {
      await page.waitForSelector('#networks:not([hidden]) .network[data-network="2"]');
      const drawn = await page.evaluate(() => [...document.querySelectorAll('#network-list .network')].map((n) => [
        n.querySelector('.network-name').textContent,
        [...n.querySelectorAll('.network-station')].map((s) => `${s.textContent}${s.classList.contains('master') ? ' (master)' : ''}`)]));
      assertEqual(drawn, [['network 1', ['1 p1', '2 p2⇄ 2 (master)']], ['network 2', ['1 p2⇄ 1', '2 p3']]], 'networks');
      assertEqual(await page.getAttribute('#network-list .network[data-network="2"] a[data-station="p3"]', 'href'), '#/stations/p3', 'p3 link');
    });

    await check('requests over SLMP to p2 count in p2\'s row only: connections, requests, errors', async () => {
      await p2.connect();
      for (let i = 0; i < 3; i++) await p2.readWords('D', 0, 1);
      const refused = await p2.readWords('D', 0xFFFFF0, 1).then(() => 'answered', (e) => e.message);
      assertEqual(refused, 'end code 4031', 'a read past the end of D');
      await page.waitForFunction(() => {
        const row = document.querySelector('#stations tr[data-station="p2"]');
        return row.querySelector('td[data-column="requests"]').textContent === '4' && row.querySelector('td[data-column="errors"]').textContent === '1'
          && row.querySelector('td[data-column="connections"]').textContent === '1';
      });
      if (!(await page.getAttribute('#stations tr[data-station="p2"] td[data-column="errors"]', 'class')).includes('nonzero')) throw new Error('errors not marked');
      for (const name of ['p1', 'p3']) {
        assertEqual([await cell(name, 'requests'), await cell(name, 'errors'), await cell(name, 'connections')], ['0', '0', '0'], name);
      }
    });

    await check('requests/s is the change between two polls', async () => {
      const rates = await page.evaluate(() => [
        requestRate({ requests: 10, at: 1000 }, { requests: 40, at: 3000 }),
        requestRate(undefined, { requests: 40, at: 3000 }),
        requestRate({ requests: 40, at: 3000 }, { requests: 5, at: 4000 }),
        showRate(15), showRate(0.25), showRate(1234.4), showRate(null)]);
      assertEqual(rates, [15, null, null, '15.0', '0.3', '1234', '—'], 'rates');
      // Once polled twice, every row shows a rate (its value depends on when the polls ran).
      await page.waitForFunction(() => [...document.querySelectorAll('#stations td[data-column="rate"]')].every((c) => /^\d+(\.\d)?$/.test(c.textContent)));
    });

    await check('the filter box keeps the names containing the text (any case) and puts it in the address', async () => {
      await page.fill('#station-filter', '2');
      assertEqual(await rowTexts(), ['p2'], 'rows for "2"');
      assertEqual(await page.textContent('#station-count'), '(1 of 3)', 'count');
      assertEqual(new URL(page.url()).hash, '#/?filter=2', 'address');
      await page.fill('#station-filter', 'P');
      assertEqual(await rowTexts(), ['p1', 'p2', 'p3'], 'rows for "P"');
      await page.fill('#station-filter', 'x');
      assertEqual(await rowTexts(), [], 'rows for "x"');
      assertEqual(await page.textContent('#station-count'), '(0 of 3)', 'count');
    });

    await check('#/?filter= in the address opens the overview filtered', async () => {
      await page.goto(`${base}/#/?filter=3`);
      await page.waitForSelector('#stations tr[data-station="p3"]');
      assertEqual(await rowTexts(), ['p3'], 'rows');
      assertEqual(await page.inputValue('#station-filter'), '3', 'filter box');
    });

    await check('a station\'s name opens its page (#/stations/p2), named in the header', async () => {
      await page.goto(`${base}/`);
      await page.click('#stations tr[data-station="p2"] td[data-column="name"] a');
      await page.waitForSelector('body[data-view="station"]');
      assertEqual(new URL(page.url()).hash, '#/stations/p2', 'address');
      await page.waitForFunction(() => document.querySelector('#cpu').textContent.includes('R08CPU'));
      await page.waitForFunction(() => document.querySelector('#live').textContent === 'live');
      assertEqual(await page.textContent('#station-name'), 'p2', 'station name');
      assertEqual(await page.textContent('#ports'), `SLMP TCP ${tcpPort('p2')} · UDP —`, 'ports');
      if (!(await page.isVisible('#plant-link'))) throw new Error('no link back to the plant');
      if (await page.isVisible('#plant-view')) throw new Error('the overview shows too');
    });

    await check('the station page lists p2\'s own connection', async () => {
      await page.waitForFunction(() => document.querySelectorAll('#connections tbody tr').length === 1);
    });

    await check('D100 edited in p2\'s page is written to p2 only', async () => {
      await page.fill('#watch-input', 'D100-D101');
      await page.click('#watch-add');
      await page.waitForFunction(() => document.querySelector('td.value[data-address="D100"]').textContent === '0');
      await page.click('td.value[data-address="D100"]');
      await page.fill('td.value[data-address="D100"] input', '4321');
      await page.press('td.value[data-address="D100"] input', 'Enter');
      await eventually(async () => (await httpJson(`${base}/api/stations/p2/devices/D100`)).values, [4321], 'p2 D100 over HTTP');
      assertEqual(await p2.readWords('D', 100, 1), [4321], 'p2 D100 over SLMP');
      for (const name of ['p1', 'p3']) assertEqual((await httpJson(`${base}/api/stations/${name}/devices/D100`)).values, [0], `${name} D100`);
    });

    await check('a value written to p2 through the API shows in its page, one written to p1 does not', async () => {
      await httpJson(`${base}/api/stations/p1/devices/D101`, 'PUT', { values: [7] });
      await httpJson(`${base}/api/stations/p2/devices/D101`, 'PUT', { values: [555] });
      await page.waitForFunction(() => document.querySelector('td.value[data-address="D101"]').textContent === '555');
      assertEqual(await page.textContent('td.value[data-address="D100"]'), '4321', 'D100');
    });

    await check('p2\'s trend plot reads p2\'s D100', async () => {
      await page.fill('#trend-input', 'D100');
      await page.click('#trend-add');
      await page.waitForFunction(() => window.__trend.data[1] && window.__trend.data[1].includes(4321));
      assertEqual(await page.evaluate(() => window.__trend.series.map((s) => s.name)), ['D100'], 'series');
      assertEqual(await page.evaluate(() => [...new Set(window.__trend.data[1])]), [4321], 'values');
    });

    await check('the plant link leads back to the overview', async () => {
      await page.click('#plant-link');
      await page.waitForSelector('body[data-view="plant"]');
      await page.waitForSelector('#stations tr[data-station="p1"]');
      assertEqual(await rowTexts(), ['p1', 'p2', 'p3'], 'rows');
    });

    await check('an unknown station in the address shows the overview and says so', async () => {
      await page.goto(`${base}/#/stations/nope`);
      await page.waitForSelector('body[data-view="plant"]');
      await page.waitForFunction(() => document.querySelector('#message').textContent.includes("no station 'nope'"));
    });

    await check('the pages raised no script errors', async () => {
      if (pageErrors.length) throw new Error(pageErrors.join('; '));
    });

    if (screenshotFile) {
      // Some life for the picture: p3 switched to STOP, traffic on p2.
      await httpJson(`${base}/api/stations/p3/state`, 'PUT', { switch: 'STOP' });
      await page.goto(`${base}/`);
      await page.waitForFunction(() => document.querySelector('#stations tr[data-station="p3"] td[data-column="state"]').textContent === 'STOP');
      let traffic = true;
      // Paced like a SCADA poll (a few hundred requests/s), not flat out.
      const load = (async () => { while (traffic) { await p2.readWords('D', 100, 2); await new Promise((r) => setTimeout(r, 4)); } })();
      await page.waitForFunction(() => Number(document.querySelector('#stations tr[data-station="p2"] td[data-column="rate"]').textContent) > 0);
      await page.screenshot({ path: screenshotFile, fullPage: false, clip: { x: 0, y: 0, width: 1280, height: 260 } });
      traffic = false;
      await load;
      out(`screenshot written to ${screenshotFile}`);
    }
    p2.close();
  });
}

run(main);
