#!/usr/bin/env node
// The web monitor of a twin in differential mode (--upstream HOST:PORT
// --compare; docs/twin.md, "Compare"): the header names the mode and the
// upstream; a read whose value differs on the two sides (the upstream's D100
// set through its own HTTP API, the twin's left 0) shows live under
// "Differences" from its "compare" event; a read both answer the same adds none.
//
// Usage: node compare_test.js [path/to/slmp-sim]   (as monitor_test.js)
'use strict';

const fs = require('fs');
const { parseArgs, check, run, withMonitor, tempDir, startSim, stopSim, httpJson, SlmpClient } = require('./harness');

const { binary, browserPath } = parseArgs(process.argv);

run(async () => {
  const upstreamDir = tempDir();
  const upstream = await startSim(binary, ['--tcp-port', '0', '--udp-port', '0', '--http-port', '0', '--bind', '127.0.0.1'], upstreamDir);
  try {
    const args = ['--tcp-port', '0', '--udp-port', '0', '--http-port', '0', '--bind', '127.0.0.1',
      '--upstream', `127.0.0.1:${upstream.ready.tcp[0]}`, '--compare',
      // Answer times never count as a difference here: on a loaded machine one
      // side can take 50 ms longer, and this test is about the bytes.
      '--compare-slack', '600'];
    await withMonitor({ binary, browserPath, args }, async ({ page, pageErrors, ready, url }) => {
      const slmp = new SlmpClient(ready.tcp[0]);
      try {
        await check('the header names differential mode and the upstream', async () => {
          await page.goto(url);
          await page.waitForFunction(() => document.querySelector('#live').textContent === 'live');
          await page.waitForFunction((port) => document.querySelector('#ports').textContent.includes(`compare → 127.0.0.1:${port}`),
            upstream.ready.tcp[0]);
          if (!await page.isVisible('#compare-section')) throw new Error('no Differences panel');
        });

        await slmp.connect();

        await check('a read both sides answer the same adds no difference', async () => {
          await slmp.readWords('D', 200, 1);
          await page.waitForFunction(() => document.querySelector('#compare-count').textContent === '0 of 1 compared');
          if ((await page.$$('#differences tbody tr')).length !== 0) throw new Error('a difference row shows');
        });

        await check('a read of D100 that differs shows live as a bytes difference', async () => {
          await httpJson(`http://127.0.0.1:${upstream.ready.http}/api/devices/D100`, 'PUT', { values: [1234] });
          const [value] = await slmp.readWords('D', 100, 1);   // the client gets the upstream's answer
          if (value !== 1234) throw new Error(`read ${value}, not the upstream's 1234`);
          await page.waitForFunction(() => {
            const row = document.querySelector('#differences tbody tr');
            return row && row.textContent.includes('0401/0000') && row.textContent.includes('bytes');
          });
          await page.waitForFunction(() => document.querySelector('#compare-count').textContent === '1 of 2 compared');
        });

        await check('the page raised no script errors', async () => {
          if (pageErrors.length) throw new Error(pageErrors.join('; '));
        });
      } finally {
        slmp.close();
      }
    });
  } finally {
    await stopSim(upstream);
    fs.rmSync(upstreamDir, { recursive: true, force: true });
  }
});
