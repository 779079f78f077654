#!/usr/bin/env node
// The trend plots in a real headless Chromium (harness.js) against the real
// slmp-sim: D100 added to the plot follows the values written through the
// HTTP API, in order; a bit device and a label join it (the bit on its own
// scale); what cannot be plotted is refused with the reason; Pause freezes the
// chart while sampling goes on; a drag zooms in (and pauses), a double-click
// zooms out; a series is removed; the plotted series survive a reload.
// The page exposes its sampled data as window.__trend (control/web/trend.js);
// every wait is for a value to arrive there, never for a time.
//
// Usage: node trend_test.js [path/to/slmp-sim] [--screenshot FILE]
//        (or SLMP_SIM_BINARY=...; CHROMIUM=... overrides /usr/bin/chromium)
// Prints one line per check and "N passed, N failed"; exits non-zero on failure.
'use strict';

const fs = require('fs');
const path = require('path');
const {
  parseArgs, check, run, out, assertEqual, withMonitor, httpJson,
} = require('./harness');

const { binary, screenshot: screenshotFile, browserPath } = parseArgs(process.argv);

const LABELS = {
  labels: [
    { name: 'LabelW', type: 'Word [Signed]', device: 'D9000' },
    { name: 'Name', type: 'String(16)' },
  ],
};

// The values a series took, one per run of equal samples, without the gaps
// (null) before it was added.
const runs = (column) => column.filter((v, i) => v !== null && v !== column[i - 1]);

async function main() {
  const args = (dir) => {
    const labelsFile = path.join(dir, 'labels.json');
    fs.writeFileSync(labelsFile, JSON.stringify(LABELS));
    return ['--tcp-port', '0', '--udp-port', '0', '--http-port', '0', '--bind', '127.0.0.1', '--labels', labelsFile];
  };
  await withMonitor({ binary, browserPath, args }, async ({ page, pageErrors, ready }) => {
    const base = `http://127.0.0.1:${ready.http}`;
    const put = (device, value) => httpJson(`${base}/api/devices/${device}`, 'PUT', { values: [value] });

    const trend = () => page.evaluate(() => ({
      series: window.__trend.series.map((s) => s.name),
      data: window.__trend.data,
      chartData: window.__trend.chart ? window.__trend.chart.data : null,
      following: window.__trend.following,
    }));
    // Until series k (1-based column) has sampled `value`.
    const sampled = (k, value) => page.waitForFunction(([col, v]) => (window.__trend.data[col] || []).includes(v), [k, value]);
    const addToPlot = async (text) => {
      await page.fill('#trend-input', text);
      await page.click('#trend-add');
    };

    await check('the station page has a trend panel and no chart until something is plotted', async () => {
      await page.goto(`${base}/`);
      await page.waitForFunction(() => document.querySelector('#live').textContent === 'live');
      await page.waitForSelector('#trend-form');
      if (await page.isVisible('#trend-chart')) throw new Error('an empty chart shows');
    });

    await check('D100 added to the plot is sampled into the chart', async () => {
      await addToPlot('D100');
      await page.waitForSelector('#trend-series .series-chip[data-series="D100"]');
      await page.waitForSelector('#trend-chart canvas');
      await sampled(1, 0);
      assertEqual((await trend()).series, ['D100'], 'series');
      assertEqual(await page.inputValue('#trend-input'), '', 'the input, cleared');
    });

    await check('values written to D100 through the HTTP API appear in the series, in order', async () => {
      for (const value of [11, 22, 33]) {
        await put('D100', value);
        await sampled(1, value);
      }
      const { data, chartData } = await trend();
      assertEqual(runs(data[1]), [0, 11, 22, 33], 'D100 runs');
      if (!data[0].every((t, i) => i === 0 || t > data[0][i - 1])) throw new Error('sample times do not increase');
      assertEqual(data[0].length, data[1].length, 'column lengths');
      if (chartData[0].length === 0 || chartData[1].length !== chartData[0].length) throw new Error('the chart has not the data');
    });

    await check('a bit device and a label join the plot; the bit on its own 0/1 scale', async () => {
      await addToPlot('M0, LabelW');
      await page.waitForSelector('#trend-series .series-chip[data-series="LabelW"]');
      assertEqual((await trend()).series, ['D100', 'M0', 'LabelW'], 'series');
      assertEqual(await page.evaluate(() => window.__trend.chart.series.slice(1).map((s) => s.scale)), ['value', 'bit', 'value'], 'scales');
      await sampled(2, 0);
      await sampled(3, 0);
      await put('M0', 1);
      await httpJson(`${base}/api/labels/LabelW`, 'PUT', { values: [-5] });
      await sampled(2, 1);
      await sampled(3, -5);
      const { data } = await trend();
      if (data[2][0] !== null || data[3][0] !== null) throw new Error('the new series have values from before they were added');
      assertEqual(runs(data[2]), [0, 1], 'M0 runs');
      assertEqual(runs(data[3]), [0, -5], 'LabelW runs');
    });

    await check('what cannot be plotted is refused with the reason and stays in the input', async () => {
      const refusals = [
        ['Name', 'Name: Name is a String(16); only numbers can be plotted'],
        ['D100', 'D100: D100 is already plotted'],
        ['D100-D109', "D100-D109: plot one device at a time ('D100'), not a range"],
        ['NoSuchLabel', 'NoSuchLabel: '],
      ];
      for (const [text, message] of refusals) {
        await addToPlot(text);
        await page.waitForFunction((m) => document.querySelector('#message').textContent.startsWith(m), message);
        assertEqual(await page.inputValue('#trend-input'), text, `input after ${text}`);
        await page.evaluate(() => { document.querySelector('#message').textContent = ''; });
      }
      assertEqual((await trend()).series, ['D100', 'M0', 'LabelW'], 'series');
    });

    await check('Pause freezes the chart while sampling goes on; Resume shows what came meanwhile', async () => {
      await page.click('#trend-pause');
      assertEqual(await page.textContent('#trend-pause'), 'Resume', 'button');
      await put('D100', 44);
      await sampled(1, 44);
      let { chartData, following } = await trend();
      assertEqual(following, false, 'following');
      if (chartData[1].includes(44)) throw new Error('the paused chart took the new sample');
      await page.click('#trend-pause');
      ({ chartData, following } = await trend());
      assertEqual(following, true, 'following');
      if (!chartData[1].includes(44)) throw new Error('the resumed chart lacks the sample taken while paused');
    });

    await check('a drag across the chart zooms in and pauses; a double-click zooms out', async () => {
      const box = await page.locator('#trend-chart .u-over').boundingBox();
      const y = box.y + box.height / 2;
      await page.mouse.move(box.x + box.width * 0.2, y);
      await page.mouse.down();
      await page.mouse.move(box.x + box.width * 0.6, y, { steps: 5 });
      await page.mouse.up();
      const zoomed = await page.evaluate(() => {
        const u = window.__trend.chart;
        return { min: u.scales.x.min, max: u.scales.x.max, first: u.data[0][0], last: u.data[0][u.data[0].length - 1] };
      });
      assertEqual((await trend()).following, false, 'following after the drag');
      assertEqual(await page.textContent('#trend-pause'), 'Resume', 'button');
      if (!(zoomed.min > zoomed.first && zoomed.max < zoomed.last)) throw new Error(`not zoomed: ${JSON.stringify(zoomed)}`);
      await page.mouse.dblclick(box.x + box.width / 2, y);
      const reset = await page.evaluate(() => {
        const u = window.__trend.chart;
        return [u.scales.x.min === u.data[0][0], u.scales.x.max === u.data[0][u.data[0].length - 1]];
      });
      assertEqual(reset, [true, true], 'zoomed out to all the data');
      await page.click('#trend-pause');
      assertEqual((await trend()).following, true, 'following after Resume');
    });

    await check('a series is removed with its ✕, its column with it', async () => {
      await page.click('#trend-series .series-chip[data-series="D100"] button');
      const { series, data } = await trend();
      assertEqual(series, ['M0', 'LabelW'], 'series');
      assertEqual(data.length, 3, 'columns');
      assertEqual(runs(data[1]), [0, 1], 'M0 runs');
    });

    await check('the plotted series survive a reload', async () => {
      await page.reload();
      await page.waitForSelector('#trend-series .series-chip[data-series="LabelW"]');
      assertEqual((await trend()).series, ['M0', 'LabelW'], 'series');
      await sampled(2, -5);
    });

    await check('the page raised no script errors', async () => {
      if (pageErrors.length) throw new Error(pageErrors.join('; '));
    });

    if (screenshotFile) {
      // A picture with some shape: D100 a slow wave, D101 a ramp, M0 a pulse train, LabelW a setpoint.
      await page.setViewportSize({ width: 1280, height: 1400 });
      await addToPlot('D100, D101');
      await page.waitForSelector('#trend-series .series-chip[data-series="D101"]');
      for (let k = 0; k < 40; k++) {
        const wave = Math.round(500 + 400 * Math.sin(k / 5));
        const ramp = (k * 25) % 700;
        await put('D100', wave);
        await put('D101', ramp);
        await put('M0', k % 8 < 3 ? 1 : 0);
        await httpJson(`${base}/api/labels/LabelW`, 'PUT', { values: [k < 20 ? 750 : 300] });
        await page.waitForFunction(([w, r]) => {
          const d = window.__trend.data;
          return d[3][d[3].length - 1] === w && d[4][d[4].length - 1] === r;
        }, [wave, ramp]);
      }
      await page.locator('section.trend').screenshot({ path: screenshotFile });
      out(`screenshot written to ${screenshotFile}`);
    }
  });
}

run(main);
