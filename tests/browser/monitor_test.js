#!/usr/bin/env node
// The web monitor in a real headless Chromium (Debian's /usr/bin/chromium,
// driven by playwright-core; no browser is downloaded; harness.js) against the real
// slmp-sim binary: load the page, add watches, see values written over SLMP
// appear live, edit values in the page and read them back over SLMP; the
// scenario loaded with --scenario and its fault show with their fire counts;
// the labels panel shows the --labels tree and edits labels in place.
//
// Usage: node monitor_test.js [path/to/slmp-sim] [--screenshot FILE]
//        (or SLMP_SIM_BINARY=...; CHROMIUM=... overrides /usr/bin/chromium)
// Prints one line per check and "N passed, N failed"; exits non-zero on failure.
'use strict';

const fs = require('fs');
const path = require('path');
const {
  parseArgs, check, run, out, eventually, withMonitor, SlmpClient,
} = require('./harness');

const { binary, screenshot: screenshotFile, browserPath } = parseArgs(process.argv);

// A scenario whose one fault answers C051 to word reads of D200-D209 (and
// nothing else the checks below do).
const SCENARIO = {
  name: 'browser-check',
  description: 'refuses reads of D200-D209',
  faults: [{ id: 'refuse-d200', do: 'end_code', end_code: 'C051', match: { command: '0401', devices: 'D200-D209' } }],
};

// Global labels for the labels panel: one on a device, a structure with a
// nested array of structures and a timer, a 2-D array.
const LABELS = {
  structures: [
    { name: 'Valve', members: [{ name: 'Open', type: 'Bit' }, { name: 'Pos', type: 'INT' }] },
    { name: 'TankT', members: [{ name: 'Level', type: 'REAL' }, { name: 'V', type: 'Valve', dims: [2] }, { name: 'Delay', type: 'Timer' }] },
  ],
  labels: [
    { name: 'LabelW', type: 'Word [Signed]', device: 'D9000' },
    { name: 'Tank1', type: 'TankT' },
    { name: 'Grid', type: 'Word [Signed](0..1,0..2)' },
  ],
};

// --------------------------------------------------------------------- main --

async function main() {
  const args = (dir) => {
    const scenarioFile = path.join(dir, 'scenario.json');
    const labelsFile = path.join(dir, 'labels.json');
    fs.writeFileSync(scenarioFile, JSON.stringify(SCENARIO));
    fs.writeFileSync(labelsFile, JSON.stringify(LABELS));
    return ['--tcp-port', '0', '--udp-port', '0', '--http-port', '0', '--bind', '127.0.0.1',
      '--scenario', scenarioFile, '--labels', labelsFile];
  };
  await withMonitor({ binary, browserPath, args }, async ({ page, pageErrors, ready, url }) => {
    const slmp = new SlmpClient(ready.tcp[0]);

    await check('the monitor loads and names the CPU', async () => {
      await page.goto(url);
      await page.waitForFunction(() => document.querySelector('#cpu').textContent.includes('R08CPU'));
      await page.waitForFunction(() => document.querySelector('#live').textContent === 'live');
    });

    await check('a one-station process opens on its station page: no overview, no plant link', async () => {
      if ((await page.getAttribute('body', 'data-view')) !== 'station') throw new Error('not the station page');
      if (await page.isVisible('#plant-view')) throw new Error('the plant overview shows');
      if (await page.isVisible('#plant-link') || await page.isVisible('#station-name')) throw new Error('plant header items show');
    });

    await check('watches D100-D109, M0-M15 and X0-X1F can be added', async () => {
      await page.fill('#watch-input', 'D100-D109, M0-M15, X0-X1F');
      await page.click('#watch-add');
      await page.waitForSelector('td.value[data-address="D109"]');
      await page.waitForSelector('td.value[data-address="M15"]');
      await page.waitForSelector('td.value[data-address="X1F"]');
      await page.waitForFunction(() => document.querySelector('td.value[data-address="D100"]').textContent === '0');
    });

    await slmp.connect();

    await check('a word written over SLMP appears in the watch', async () => {
      await slmp.writeWords('D', 100, [1234, 65535]);
      await page.waitForFunction(() => document.querySelector('td.value[data-address="D100"]').textContent === '1234');
      await page.waitForFunction(() => document.querySelector('td.value[data-address="D101"]').textContent === '65535');
    });

    await check('a bit written over SLMP lights up in the watch', async () => {
      await slmp.writeBits('M', 3, [1]);
      await page.waitForSelector('td.value.on[data-address="M3"]');
    });

    await check('a word edited in the page is read back over SLMP', async () => {
      await page.click('td.value[data-address="D105"]');
      await page.fill('td.value[data-address="D105"] input', '4321');
      await page.press('td.value[data-address="D105"] input', 'Enter');
      await eventually(() => slmp.readWords('D', 105, 1), [4321], 'D105 over SLMP');
      await page.waitForFunction(() => document.querySelector('td.value[data-address="D105"]').textContent === '4321');
    });

    await check('a bit clicked in the page is read back over SLMP', async () => {
      await page.click('td.value[data-address="M7"]');
      await eventually(() => slmp.readBits('M', 7, 1), [1], 'M7 over SLMP');
    });

    await check('the call monitor shows the SLMP requests decoded', async () => {
      await page.waitForFunction(() => [...document.querySelectorAll('#calls tbody tr')].some((row) =>
        row.textContent.includes('1401/0000') && row.textContent.includes('D100 ×2 words') && row.textContent.includes('0000')));
    });

    await check('the connections list shows the SLMP client', async () => {
      await page.waitForFunction(() => document.querySelectorAll('#connections tbody tr').length === 1);
    });

    await check('a bad edit shows the server message and changes nothing', async () => {
      await page.click('td.value[data-address="D106"]');
      await page.fill('td.value[data-address="D106"] input', '70000');
      await page.press('td.value[data-address="D106"] input', 'Enter');
      await page.waitForFunction(() => document.querySelector('#message').textContent.includes('does not fit a 16-bit word'));
      const words = await slmp.readWords('D', 106, 1);
      if (words[0] !== 0) throw new Error(`D106 changed to ${words[0]}`);
    });

    await check('the scenario from --scenario and its fault are listed', async () => {
      await page.waitForFunction(() => document.querySelector('#scenarios tbody').textContent.includes('browser-check'));
      await page.waitForFunction(() => {
        const row = document.querySelector('#faults tr[data-id="refuse-d200"]');
        return row && row.cells[2].textContent === 'end_code' && row.cells[5].textContent === '0';
      });
    });

    await check('a fault fired over SLMP shows its fire count', async () => {
      let error = null;
      await slmp.readWords('D', 200, 1).catch((e) => { error = e.message; });
      if (error !== 'end code C051') throw new Error(`expected end code C051, got ${error}`);
      await page.waitForFunction(() => document.querySelector('#faults tr[data-id="refuse-d200"]').cells[5].textContent === '1');
    });

    await check('a fault turned off in the page no longer fires', async () => {
      await page.click('#faults tr[data-id="refuse-d200"] input[type="checkbox"]');
      await eventually(() => slmp.readWords('D', 200, 1).catch((e) => e.message), [0], 'D200 over SLMP');
    });

    const labelText = (element) => page.evaluate((e) => {
      const cell = document.querySelector(`#labels span.value[data-element="${e}"]`);
      return cell ? cell.textContent : null;
    }, element);

    await check('the labels panel shows the tree: structure members, nested elements, timer members', async () => {
      await page.waitForSelector('#labels-section:not([hidden])');
      for (const row of ['LabelW', 'Tank1', 'Tank1.Level', 'Tank1.V[1].Pos', 'Tank1.Delay.N', 'Grid'])
        await page.waitForSelector(`#labels tr[data-label="${row}"]`);
      await page.waitForSelector('#labels span.value[data-element="Grid[1,2]"]');
    });

    await check('a label written over SLMP (its device D9000) appears in the panel', async () => {
      await slmp.writeWords('D', 9000, [777]);
      await page.waitForFunction(() => document.querySelector('#labels span.value[data-element="LabelW"]').textContent === '777');
    });

    await check('a label element edited in the panel is read back through the HTTP API', async () => {
      await page.click('#labels span.value[data-element="Grid[1,2]"]');
      await page.fill('#labels span.value[data-element="Grid[1,2]"] input', '-12');
      await page.press('#labels span.value[data-element="Grid[1,2]"] input', 'Enter');
      await eventually(async () => (await (await fetch(`${url}api/labels/Grid%5B1%2C2%5D`)).json()).values, [-12], 'Grid[1,2] over HTTP');
      await eventually(() => labelText('Grid[1,2]'), '-12', 'Grid[1,2] in the panel');
    });

    await check('a bit label member toggles when clicked', async () => {
      await eventually(() => labelText('Tank1.V[0].Open'), '0', 'Tank1.V[0].Open before');
      await page.click('#labels span.value[data-element="Tank1.V[0].Open"]');
      await eventually(async () => (await (await fetch(`${url}api/labels/Tank1.V%5B0%5D.Open`)).json()).values, [1], 'Tank1.V[0].Open over HTTP');
    });

    await check('an Ondemand push (POST /api/ondemand) shows in the call monitor', async () => {
      const answer = await (await fetch(`${url}api/ondemand`, { method: 'POST', body: JSON.stringify({ data: 'D100-D101' }) })).json();
      if (!answer.sent || answer.sent.length !== 1) throw new Error(`expected one push, got ${JSON.stringify(answer)}`);
      await page.waitForFunction(() => [...document.querySelectorAll('#calls tbody tr.push')].some((row) =>
        row.textContent.includes('2101 Ondemand (pushed)') && row.textContent.includes('bytes sent unasked')));
    });

    await check('the page raised no script errors', async () => {
      if (pageErrors.length) throw new Error(pageErrors.join('; '));
    });

    if (screenshotFile) {
      await page.fill('#watch-input', 'ZR0-ZR3');
      await page.click('#watch-add');
      await slmp.writeWords('D', 102, [42, 0x7FFF, 8, 9]);
      await page.waitForFunction(() => document.querySelector('td.value[data-address="D102"]').textContent === '42');
      await page.click('#message').catch(() => {});
      await page.evaluate(() => { document.querySelector('#message').hidden = true; });
      await page.screenshot({ path: screenshotFile, fullPage: true });
      out(`screenshot written to ${screenshotFile}`);
    }
    slmp.close();
  });
}

run(main);
