// What the browser tests share: numbered checks and the summary, the real
// slmp-sim started on free ports (--ready-file), headless Chromium (Debian's
// /usr/bin/chromium driven by playwright-core; no browser is downloaded), a
// tiny SLMP client written from the manual's frame layout (so the tests share
// no code with the simulator), and HTTP JSON calls.
// Nothing waits for a fixed time: every wait is for a condition, bounded by WAIT_MS.
'use strict';

const childProcess = require('child_process');
const fs = require('fs');
const net = require('net');
const os = require('os');
const path = require('path');
const { chromium } = require('playwright-core');

const WAIT_MS = 10000;   // upper bound for anything to show up; never a fixed sleep

// ------------------------------------------------------------ arguments --

// [path/to/slmp-sim] [--screenshot FILE]; SLMP_SIM_BINARY and CHROMIUM override the defaults.
function parseArgs(argv) {
  const args = argv.slice(2);
  const screenshotAt = args.indexOf('--screenshot');
  const screenshot = screenshotAt >= 0 ? args.splice(screenshotAt, 2)[1] : null;
  const binary = args[0] || process.env.SLMP_SIM_BINARY || path.join(__dirname, '../../build/server/slmp-sim');
  return { binary, screenshot, browserPath: process.env.CHROMIUM || '/usr/bin/chromium' };
}

// --------------------------------------------------------------- checks --

const results = { passed: 0, failed: 0 };
const out = (line) => process.stdout.write(line + '\n');

async function check(name, body) {
  try {
    await body();
    results.passed++;
    out(`ok   - ${name}`);
  } catch (e) {
    results.failed++;
    out(`FAIL - ${name}: ${e.message}`);
  }
}

function fail(message) {
  results.failed++;
  out(`FAIL - ${message}`);
}

// Runs main(), prints "N passed, N failed" and exits non-zero on any failure (or no check at all).
function run(main) {
  main()
    .catch((e) => fail(e.message))
    .finally(() => {
      out(`${results.passed} passed, ${results.failed} failed`);
      process.exit(results.failed === 0 && results.passed > 0 ? 0 : 1);
    });
}

function withTimeout(promise, ms, what) {
  let timer;
  return Promise.race([promise, new Promise((_, reject) => { timer = setTimeout(() => reject(new Error(`${what}: no result within ${ms} ms`)), ms); })])
    .finally(() => clearTimeout(timer));
}

// Polls `read` until it returns `want` (bounded by WAIT_MS); for state outside the page.
async function eventually(read, want, what) {
  const deadline = Date.now() + WAIT_MS;
  let got;
  while (Date.now() < deadline) {
    got = await read();
    if (JSON.stringify(got) === JSON.stringify(want)) return;
    await new Promise((r) => setTimeout(r, 25));
  }
  throw new Error(`${what}: expected ${JSON.stringify(want)}, got ${JSON.stringify(got)}`);
}

function assertEqual(got, want, what) {
  if (JSON.stringify(got) !== JSON.stringify(want)) throw new Error(`${what}: expected ${JSON.stringify(want)}, got ${JSON.stringify(got)}`);
}

// ------------------------------------------------------------- slmp-sim --

function tempDir() { return fs.mkdtempSync(path.join(os.tmpdir(), 'slmp-browser-')); }

// Starts slmp-sim with `args` and waits for its ready file: {sim, exited, ready}.
async function startSim(binary, args, dir) {
  if (!fs.existsSync(binary)) throw new Error(`no slmp-sim at ${binary}; build first or pass its path`);
  const readyFile = path.join(dir, 'ready.json');
  const sim = childProcess.spawn(binary, [...args, '--ready-file', readyFile, '--log-level', 'warn'],
    { stdio: ['ignore', 'inherit', 'inherit'] });
  const exited = new Promise((resolve) => sim.on('exit', (code, signal) => resolve({ code, signal })));
  const deadline = Date.now() + WAIT_MS;
  while (Date.now() < deadline) {
    if (sim.exitCode !== null) throw new Error(`slmp-sim exited early with ${sim.exitCode}`);
    try {
      return { sim, exited, ready: JSON.parse(fs.readFileSync(readyFile, 'utf8')) };
    } catch { /* not written yet */ }
    await new Promise((r) => setTimeout(r, 20));
  }
  sim.kill('SIGKILL');
  throw new Error('slmp-sim wrote no ready file within 10 s');
}

// SIGTERM, and a check that it exits cleanly.
async function stopSim({ sim, exited }) {
  sim.kill('SIGTERM');
  const { code } = await withTimeout(exited, WAIT_MS, 'slmp-sim exit');
  if (code !== 0) fail(`slmp-sim exited with ${code} after SIGTERM`);
}

// -------------------------------------------------------------- browser --

// A persistent context on a fresh directory is Chromium's --user-data-dir
// (so localStorage starts empty). Returns {context, page, pageErrors}.
async function launchBrowser(browserPath, dir) {
  const context = await chromium.launchPersistentContext(path.join(dir, 'profile'), {
    executablePath: browserPath,
    headless: true,
    viewport: { width: 1280, height: 900 },
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const page = context.pages()[0] || await context.newPage();
  page.setDefaultTimeout(WAIT_MS);
  const pageErrors = [];
  page.on('pageerror', (e) => pageErrors.push(e.message));
  return { context, page, pageErrors };
}

// ----------------------------------------------------------------- HTTP --

// One simulator and one browser page for a test: starts slmp-sim with `args`
// (or args(dir), for files written to its temporary directory first), opens
// Chromium, runs body({page, pageErrors, ready, url, dir}) and always closes
// both and removes the directory.
async function withMonitor({ binary, browserPath, args }, body) {
  const dir = tempDir();
  const simulator = await startSim(binary, typeof args === 'function' ? args(dir) : args, dir);
  let context;
  try {
    const browser = await launchBrowser(browserPath, dir);
    context = browser.context;
    const { ready } = simulator;
    await body({ page: browser.page, pageErrors: browser.pageErrors, ready, url: `http://127.0.0.1:${ready.http}/`, dir });
  } finally {
    if (context) await context.close();
    await stopSim(simulator);
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

async function httpJson(url, method = 'GET', body = undefined) {
  const response = await fetch(url, body === undefined ? { method } : { method, body: JSON.stringify(body) });
  const data = await response.json();
  if (!response.ok) throw new Error(`${method} ${url}: HTTP ${response.status} ${JSON.stringify(data)}`);
  return data;
}

// ------------------------------------------------------- a tiny SLMP client --
// 3E binary frames built by hand from the manual's layout: subheader 5000,
// own-station route 00 FF 03FF 00, data length, monitoring timer 0010,
// command, subcommand.

const DEVICE_CODES = { D: 0xA8, M: 0x90, X: 0x9C, Y: 0x9D };

function frame(command, subcommand, data) {
  const body = Buffer.concat([Buffer.from([0x10, 0x00, command & 0xFF, command >> 8, subcommand & 0xFF, subcommand >> 8]), data]);
  const head = Buffer.from([0x50, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, body.length & 0xFF, body.length >> 8]);
  return Buffer.concat([head, body]);
}

function deviceField(symbol, number, points) {
  return Buffer.from([number & 0xFF, (number >> 8) & 0xFF, (number >> 16) & 0xFF, DEVICE_CODES[symbol], points & 0xFF, points >> 8]);
}

class SlmpClient {
  constructor(port) { this.port = port; this.pending = Buffer.alloc(0); this.waiter = null; }

  connect() {
    return withTimeout(new Promise((resolve, reject) => {
      this.socket = net.connect(this.port, '127.0.0.1', resolve);
      this.socket.on('error', reject);
      this.socket.on('data', (chunk) => { this.pending = Buffer.concat([this.pending, chunk]); if (this.waiter) this.waiter(); });
    }), WAIT_MS, 'SLMP connect');
  }

  // Sends a request and returns the response data after the end code; throws on a non-zero end code.
  async exchange(request) {
    this.socket.write(request);
    const response = await withTimeout(new Promise((resolve) => {
      const tryTake = () => {
        if (this.pending.length < 9) return;
        const size = 9 + this.pending.readUInt16LE(7);
        if (this.pending.length < size) return;
        const whole = this.pending.subarray(0, size);
        this.pending = this.pending.subarray(size);
        this.waiter = null;
        resolve(whole);
      };
      this.waiter = tryTake;
      tryTake();
    }), WAIT_MS, 'SLMP response');
    const endCode = response.readUInt16LE(9);
    if (endCode !== 0) throw new Error(`end code ${endCode.toString(16).padStart(4, '0').toUpperCase()}`);
    return response.subarray(11);
  }

  writeWords(symbol, number, words) {
    const data = Buffer.alloc(words.length * 2);
    words.forEach((w, i) => data.writeUInt16LE(w & 0xFFFF, i * 2));
    return this.exchange(frame(0x1401, 0x0000, Buffer.concat([deviceField(symbol, number, words.length), data])));
  }

  async readWords(symbol, number, count) {
    const data = await this.exchange(frame(0x0401, 0x0000, deviceField(symbol, number, count)));
    return Array.from({ length: count }, (_, i) => data.readUInt16LE(i * 2));
  }

  writeBits(symbol, number, bits) {
    const data = Buffer.alloc(Math.ceil(bits.length / 2));
    bits.forEach((b, i) => { if (b) data[i >> 1] |= i % 2 === 0 ? 0x10 : 0x01; });
    return this.exchange(frame(0x1401, 0x0001, Buffer.concat([deviceField(symbol, number, bits.length), data])));
  }

  async readBits(symbol, number, count) {
    const data = await this.exchange(frame(0x0401, 0x0001, deviceField(symbol, number, count)));
    return Array.from({ length: count }, (_, i) => (i % 2 === 0 ? data[i >> 1] >> 4 : data[i >> 1]) & 0x1);
  }

  close() { if (this.socket) this.socket.destroy(); }
}

module.exports = {
  WAIT_MS, parseArgs, check, fail, run, out, withTimeout, eventually, assertEqual,
  tempDir, startSim, stopSim, launchBrowser, withMonitor, httpJson, SlmpClient,
};
