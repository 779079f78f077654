#!/usr/bin/env node
// The web monitor of an FX5U (iQ-F), whose X and Y are numbered in octal: a
// watch of X0-X17 names X0-X7 then X10-X17 in rows of 8; bits written over
// SLMP at X7 and X10 (bit indexes 7 and 8) light up side by side; X8 is
// refused with the simulator's message; the call monitor names X7.
//
// Usage: node octal_test.js [path/to/slmp-sim]   (as monitor_test.js)
'use strict';

const { parseArgs, check, run, withMonitor, SlmpClient } = require('./harness');

const { binary, browserPath } = parseArgs(process.argv);
const args = ['--profile', 'FX5U-32MR', '--tcp-port', '0', '--udp-port', '0', '--http-port', '0', '--bind', '127.0.0.1'];

run(() => withMonitor({ binary, browserPath, args }, async ({ page, pageErrors, ready, url }) => {
  const slmp = new SlmpClient(ready.tcp[0]);
  try {
    await check('the monitor loads an FX5U', async () => {
      await page.goto(url);
      await page.waitForFunction(() => document.querySelector('#cpu').textContent.includes('FX5U-32MR'));
      await page.waitForFunction(() => document.querySelector('#live').textContent === 'live');
    });

    await check('a watch of X0-X17 has X0-X7 and X10-X17 in rows of 8, and no X8', async () => {
      await page.fill('#watch-input', 'X0-X17');
      await page.click('#watch-add');
      await page.waitForSelector('td.value[data-address="X17"]');
      const heads = await page.$$eval('.cells.bits th', (cells) => cells.map((c) => c.textContent));
      if (JSON.stringify(heads) !== JSON.stringify(['X0', 'X10'])) throw new Error(`row heads ${JSON.stringify(heads)}`);
      if (await page.$('td.value[data-address="X8"]')) throw new Error('an X8 cell exists');
    });

    await slmp.connect();

    await check('bits 7 and 8 written over SLMP light X7 and X10', async () => {
      await slmp.writeBits('X', 7, [1, 1]);   // binary frames carry the bit index
      await page.waitForSelector('td.value.on[data-address="X7"]');
      await page.waitForSelector('td.value.on[data-address="X10"]');
    });

    await check('the call monitor names the head device in octal', async () => {
      await page.waitForFunction(() => [...document.querySelectorAll('#calls tbody tr')].some((row) =>
        row.textContent.includes('1401/0001') && row.textContent.includes('X7 ×2 bits')));
    });

    await check('X8 is refused with the reason', async () => {
      await page.fill('#watch-input', 'X8');
      await page.click('#watch-add');
      await page.waitForFunction(() => document.querySelector('#message').textContent.includes(
        'X is numbered in octal on this CPU: X7 is followed by X10'));
    });

    await check('the page raised no script errors', async () => {
      if (pageErrors.length) throw new Error(pageErrors.join('; '));
    });
  } finally {
    slmp.close();
  }
}));
