#!/usr/bin/env node
// The program panel of the web monitor in a real headless Chromium (harness.js)
// against the real slmp-sim running the self-holding circuit of the program
// spec (tests/data/programs/example_8_1.il: LD X0 / OR Y0 / ANI X1 / OUT Y0)
// on a frozen clock: the ladder shows the contacts and the coil, the device
// watch opens with what the program writes, and a scan stepped through the
// HTTP API after writing X0 lights X0's contact and Y0's coil; the circuit
// then holds itself, and X1 breaks it. The search highlights a device's places,
// and the page's rung builder turns §8.4's MPS/MRD/MPP and ANB/ORB into branches.
//
// Usage: node program_test.js [path/to/slmp-sim] [--screenshot FILE]
//        (or SLMP_SIM_BINARY=...; CHROMIUM=... overrides /usr/bin/chromium)
// Prints one line per check and "N passed, N failed"; exits non-zero on failure.
'use strict';

const fs = require('fs');
const path = require('path');
const { parseArgs, check, run, out, assertEqual, withMonitor, httpJson } = require('./harness');

const { binary, screenshot: screenshotFile, browserPath } = parseArgs(process.argv);
const PROGRAM = path.join(__dirname, '../data/programs/example_8_1.il');

// The ladder element of `kind` (contact, coil) drawn for `device`.
const element = (kind, device) => `#ladder g.${kind}[data-device="${device}"]`;

async function main() {
  const args = ['--tcp-port', '0', '--udp-port', '0', '--http-port', '0', '--bind', '127.0.0.1',
    '--clock', 'frozen', '--program', PROGRAM];
  await withMonitor({ binary, browserPath, args }, async ({ page, pageErrors, url }) => {
    const isOn = (selector) => page.evaluate((s) => {
      const e = document.querySelector(s);
      return e ? e.classList.contains('on') : null;
    }, selector);
    // Waits (bounded by the harness's WAIT_MS) until the element's ON state is `on`.
    const waitOn = (selector, on) => page.waitForFunction(([s, want]) => {
      const e = document.querySelector(s);
      return e !== null && e.classList.contains('on') === want;
    }, [selector, on]);
    const step = async (device, value) => {
      await httpJson(`${url}api/devices/${device}`, 'PUT', { values: [value] });
      await httpJson(`${url}api/clock/step`, 'POST', { scans: 1 });
    };

    await check('the station page shows the program panel with the file loaded', async () => {
      await page.goto(url);
      await page.waitForSelector('#program:not([hidden])');
      await page.locator('#program').scrollIntoViewIfNeeded();   // it polls only while on screen
      await page.waitForFunction(() => document.querySelector('#program-name').textContent.includes('example_8_1'));
      await page.waitForFunction(() => document.querySelector('#program-status').textContent.includes('scans'));
    });

    await check('the ladder draws X0, Y0 (self-hold) and X1 as contacts, Y0 as a coil, and END', async () => {
      for (const selector of [element('contact', 'X0'), element('contact', 'Y0'), element('contact', 'X1'), element('coil', 'Y0')])
        await page.waitForSelector(selector);
      await page.waitForFunction(() => [...document.querySelectorAll('#ladder g.box text.mnem')].some((t) => t.textContent === 'END'));
      const rungs = await page.$$eval('#ladder .rung', (r) => r.length);
      if (rungs !== 2) throw new Error(`expected 2 rungs (the circuit, END), got ${rungs}`);
    });

    await check("before X0: X0's contact is off, X1's normally closed contact conducts, Y0's coil is off", async () => {
      await waitOn(element('contact', 'X1'), true);   // the monitor's state has arrived
      if (await isOn(element('contact', 'X0')) !== false) throw new Error('X0 shows ON');
      if (await isOn(element('coil', 'Y0')) !== false) throw new Error('Y0 shows ON');
    });

    await check('the device watch opens with what the program writes: Y0', async () => {
      await page.waitForSelector('#watch-list .watch[data-watch="Y0"]');
    });

    await check("X0 written and one scan stepped: X0's contact and Y0's coil show ON", async () => {
      await step('X0', 1);
      await waitOn(element('contact', 'X0'), true);
      await waitOn(element('coil', 'Y0'), true);
      await waitOn(element('contact', 'Y0'), true);
    });

    await check('X0 released: the circuit holds itself (X0 off, Y0 still on)', async () => {
      await step('X0', 0);
      await waitOn(element('contact', 'X0'), false);
      if (await isOn(element('coil', 'Y0')) !== true) throw new Error('Y0 dropped out');
    });

    await check("X1 on: its normally closed contact opens and Y0's coil drops out", async () => {
      await step('X1', 1);
      await waitOn(element('contact', 'X1'), false);
      await waitOn(element('coil', 'Y0'), false);
    });

    await check('searching Y0 highlights its two places (contact and coil)', async () => {
      await page.fill('#program-search', 'y0');
      await page.waitForFunction(() => document.querySelector('#program-found').textContent === '2 places');
      const found = await page.$$eval('#ladder .found', (e) => e.map((x) => x.dataset.device));
      if (JSON.stringify(found.sort()) !== '["Y0","Y0"]') throw new Error(`highlighted ${JSON.stringify(found)}`);
    });

    await check('the stack rules: §8.4 draws MPS/MRD/MPP as three branches and ANB/ORB as nested blocks', async () => {
      // The page's own rung builder (window.__program) on example_8_4.il's lines,
      // read here the way the text form is written: ";;" statements, one instruction a line.
      const lines = fs.readFileSync(path.join(__dirname, '../data/programs/example_8_4.il'), 'utf8').split('\n')
        .map((text, i) => ({ text: text.trim(), row: i + 1 })).filter((l) => l.text)
        .map(({ text, row }) => (text.startsWith(';')
          ? { row, kind: 'statement', statement: text.replace(/^;+\s*/, '') }
          : { row, kind: 'instruction', mnemonic: text.split(/\s+/)[0], operands: text.split(/\s+/).slice(1) }));
      const shapes = await page.evaluate((list) => {
        const show = (item) => (Array.isArray(item) ? item.map(show).join(' ')
          : item.t === 'par' ? `(${item.items.map(show).join(' | ')})` : (item.info.nc ? '/' : '') + (item.ops[0] || item.line.mnemonic));
        const node = (n) => `[${show(n.cond)} -> ${n.outs.map((o) => (o.t === 'node' ? node(o.node) : o.el.ops[0] || o.el.line.mnemonic)).join(', ')}]`;
        return window.__program.buildRungs(list).map((r) => (r.root ? node(r.root) : `list: ${r.error}`));
      }, lines);
      assertEqual(shapes, [
        '[X0 -> [X1 -> Y0], [X2 -> Y1], [/X1 -> Y2]]',
        '[((X3 | X4) (X5 | X6) | X7 X10) -> Y3]',
        '[ -> END]',
      ], 'rungs of example_8_4.il');
    });

    await check('the page raised no script errors', async () => {
      if (pageErrors.length) throw new Error(pageErrors.join('; '));
    });

    if (screenshotFile) {
      await page.locator('#program').screenshot({ path: screenshotFile });
      out(`screenshot written to ${screenshotFile}`);
    }
  });
}

run(main);
