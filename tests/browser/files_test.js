#!/usr/bin/env node
// The web monitor's files panel (control/web/files.js) in a real headless
// Chromium against the real slmp-sim binary serving a --drive folder: the
// drives with their space used, a folder with sizes and DOS dates exactly as
// the host files have them, a sub-folder opened and left, a file created over
// SLMP appearing, and a lock taken over SLMP shown and released in the page.
//
// Usage: node files_test.js [path/to/slmp-sim]
//        (or SLMP_SIM_BINARY=...; CHROMIUM=... overrides /usr/bin/chromium)
// Prints one line per check and "N passed, N failed"; exits non-zero on failure.
'use strict';

const childProcess = require('child_process');
const fs = require('fs');
const net = require('net');
const os = require('os');
const path = require('path');
const { chromium } = require('playwright-core');

const binary = process.argv[2] || process.env.SLMP_SIM_BINARY || path.join(__dirname, '../../build/server/slmp-sim');
const browserPath = process.env.CHROMIUM || '/usr/bin/chromium';
const WAIT_MS = 10000;   // upper bound for anything to show up; never a fixed sleep

let passed = 0;
let failed = 0;
const out = (line) => process.stdout.write(line + '\n');

async function check(name, body) {
  try {
    await body();
    passed++;
    out(`ok   - ${name}`);
  } catch (e) {
    failed++;
    out(`FAIL - ${name}: ${e.message}`);
  }
}

function withTimeout(promise, ms, what) {
  let timer;
  return Promise.race([promise, new Promise((_, reject) => { timer = setTimeout(() => reject(new Error(`${what}: no result within ${ms} ms`)), ms); })])
    .finally(() => clearTimeout(timer));
}

// The drive folder: two files with fixed dates (local time, as the CPU shows
// them) and a sub-folder with one file.
const RECIPE_DATE = new Date(2024, 2, 5, 6, 7, 8);     // 2024-03-05 06:07:08 (an even second: DOS keeps 2 s)
const LOG_DATE = new Date(2023, 11, 31, 23, 59, 58);

function makeDrive(dir) {
  const drive = path.join(dir, 'plc');
  fs.mkdirSync(path.join(drive, 'LOGS'), { recursive: true });
  fs.writeFileSync(path.join(drive, 'RECIPE.CSV'), 'a,b\n1,2\n34');
  fs.utimesSync(path.join(drive, 'RECIPE.CSV'), RECIPE_DATE, RECIPE_DATE);
  fs.writeFileSync(path.join(drive, 'LOGS', 'A.LOG'), 'abc');
  fs.utimesSync(path.join(drive, 'LOGS', 'A.LOG'), LOG_DATE, LOG_DATE);
  return drive;
}

async function startSim(dir, drive) {
  const readyFile = path.join(dir, 'ready.json');
  const sim = childProcess.spawn(binary, ['--profile', 'R08CPU', '--tcp-port', '0', '--http-port', '0', '--bind', '127.0.0.1',
    '--ready-file', readyFile, '--log-level', 'warn', '--drive', `4=${drive}`], { stdio: ['ignore', 'inherit', 'inherit'] });
  const exited = new Promise((resolve) => sim.on('exit', (code, signal) => resolve({ code, signal })));
  const deadline = Date.now() + WAIT_MS;
  while (Date.now() < deadline) {
    if (sim.exitCode !== null) throw new Error(`slmp-sim exited early with ${sim.exitCode}`);
    try {
      return { sim, exited, ports: JSON.parse(fs.readFileSync(readyFile, 'utf8')) };
    } catch { /* not written yet */ }
    await new Promise((r) => setTimeout(r, 20));
  }
  sim.kill('SIGKILL');
  throw new Error('slmp-sim wrote no ready file within 10 s');
}

// ------------------------------------------------------- a tiny SLMP client --
// 3E binary frames built by hand from the SLMP Reference Manual §5.8 (subcommand 0040:
// UTF-16 names with a length, the iQ-R password as a length + characters).

function frame(command, subcommand, data) {
  const body = Buffer.concat([Buffer.from([0x10, 0x00, command & 0xFF, command >> 8, subcommand & 0xFF, subcommand >> 8]), data]);
  const head = Buffer.from([0x50, 0x00, 0x00, 0xFF, 0xFF, 0x03, 0x00, body.length & 0xFF, body.length >> 8]);
  return Buffer.concat([head, body]);
}

const u16 = (v) => { const b = Buffer.alloc(2); b.writeUInt16LE(v); return b; };
const u32 = (v) => { const b = Buffer.alloc(4); b.writeUInt32LE(v); return b; };
const utf16Name = (name) => Buffer.concat([u16(name.length), Buffer.from(name, 'utf16le')]);

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

  // 1820 New File: fixed 0 (4 bytes), drive, size, name.
  newFile(drive, name, size) {
    return this.exchange(frame(0x1820, 0x0040, Buffer.concat([u32(0), u16(drive), u32(size), utf16Name(name)])));
  }

  // 1827 Open File for writing, no password: the file pointer No.
  async openForWrite(drive, name) {
    const data = await this.exchange(frame(0x1827, 0x0040, Buffer.concat([u16(0), u16(0x0100), u16(drive), utf16Name(name)])));
    return data.readUInt16LE(0);
  }

  close() { this.socket.destroy(); }
}

async function apiJson(url, target) { return (await fetch(url + target)).json(); }

// --------------------------------------------------------------------- main --

async function main() {
  if (!fs.existsSync(binary)) throw new Error(`no slmp-sim at ${binary}; build first or pass its path`);
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'slmp-browser-files-'));
  const drive = makeDrive(dir);
  const { sim, exited, ports } = await startSim(dir, drive);
  const url = `http://127.0.0.1:${ports.http}/`;
  let context;
  const slmp = new SlmpClient(ports.tcp[0]);
  try {
    context = await chromium.launchPersistentContext(path.join(dir, 'profile'), {
      executablePath: browserPath,
      headless: true,
      viewport: { width: 1280, height: 1200 },
      args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
        '--disable-background-networking', '--disable-component-update', '--disable-sync'],
    });
    const page = context.pages()[0] || await context.newPage();
    page.setDefaultTimeout(WAIT_MS);
    const pageErrors = [];
    page.on('pageerror', (e) => pageErrors.push(e.message));
    const rows = (table) => page.evaluate((t) => [...document.querySelectorAll(`${t} tbody tr`)]
      .map((row) => [...row.cells].map((c) => c.textContent)), table);

    await check('the files panel lists the drives of an R08CPU, drive 4 in its folder', async () => {
      await page.goto(url);
      await page.waitForSelector('#files-section');
      await page.waitForFunction(() => document.querySelectorAll('#drives tbody tr').length === 4);
      const got = await rows('#drives');
      const want = [
        ['1', 'device/label memory', '', '', 'alias of drive 3', ''],
        ['2', 'SD memory card', '0', '8388608', 'ready', 'memory'],
        ['3', 'device/label memory', '0', '524288', 'ready', 'memory'],
        ['4', 'data memory', '13', '5242880', 'ready', drive],   // 10 + 3 bytes, the sub-folder counted
      ];
      if (JSON.stringify(got) !== JSON.stringify(want)) throw new Error(`got ${JSON.stringify(got)}`);
    });

    await check('drive 4 shows its folder: file Nos., sizes and the DOS dates of the host files', async () => {
      await page.click('#drives tr[data-drive="4"]');
      await page.waitForFunction(() => document.querySelector('#files-where').textContent === '4:');
      await page.waitForSelector('#files tr[data-name="RECIPE.CSV"]');
      const got = await rows('#files');
      const want = [
        ['1', 'LOGS', '', (await apiJson(url, 'api/drives/4/files')).entries[0].date.replace('T', ' '), 'folder'],
        ['2', 'RECIPE.CSV', '10', '2024-03-05 06:07:08', ''],
      ];
      if (JSON.stringify(got) !== JSON.stringify(want)) throw new Error(`got ${JSON.stringify(got)}`);
    });

    await check('a folder opens, and Up leaves it', async () => {
      await page.click('#files tr[data-name="LOGS"] a.folder');
      await page.waitForFunction(() => document.querySelector('#files-where').textContent === '4:LOGS');
      await page.waitForSelector('#files tr[data-name="A.LOG"]');
      const got = await rows('#files');
      // "." and ".." hold file Nos. 1 and 2 (§6.1); the page leaves them to the Up button.
      if (JSON.stringify(got) !== JSON.stringify([['3', 'A.LOG', '3', '2023-12-31 23:59:58', '']])) throw new Error(`got ${JSON.stringify(got)}`);
      await page.click('#files-up');
      await page.waitForFunction(() => document.querySelector('#files-where').textContent === '4:');
      await page.waitForSelector('#files tr[data-name="RECIPE.CSV"]');
    });

    await check('a file links to its download, byte for byte', async () => {
      const href = await page.getAttribute('#files tr[data-name="RECIPE.CSV"] a', 'href');
      const body = await (await fetch(new URL(href, url))).text();
      if (body !== 'a,b\n1,2\n34') throw new Error(`got ${JSON.stringify(body)}`);
    });

    await slmp.connect();

    await check('a file created over SLMP (1820) appears with its size', async () => {
      await slmp.newFile(4, 'NEW.BIN', 6);
      await page.waitForFunction(() => {
        const row = document.querySelector('#files tr[data-name="NEW.BIN"]');
        return row && row.cells[0].textContent === '3' && row.cells[2].textContent === '6';
      });
    });

    let pointer;
    await check('a lock taken over SLMP (1827) shows with its owner', async () => {
      pointer = await slmp.openForWrite(4, 'NEW.BIN');
      await page.waitForSelector(`#locks tr[data-pointer="${pointer}"]`);
      const got = await rows('#locks');
      const connection = (await apiJson(url, 'api/drives/locks')).locks[0].connection;
      const want = [[String(pointer), '4', 'NEW.BIN', 'write', `connection ${connection}`, 'Release']];
      if (JSON.stringify(got) !== JSON.stringify(want)) throw new Error(`got ${JSON.stringify(got)}`);
      await page.waitForFunction(() => document.querySelector('#lock-count').textContent === '(1)');
    });

    await check('Release in the page frees the lock', async () => {
      await page.click(`#locks tr[data-pointer="${pointer}"] button`);
      await page.waitForFunction(() => document.querySelectorAll('#locks tbody tr').length === 0);
      const locks = (await apiJson(url, 'api/drives/locks')).locks;
      if (locks.length !== 0) throw new Error(`the API still lists ${JSON.stringify(locks)}`);
    });

    await check('the page raised no script errors', async () => {
      if (pageErrors.length) throw new Error(pageErrors.join('; '));
    });
  } finally {
    slmp.close();
    if (context) await context.close().catch(() => {});
    sim.kill('SIGTERM');
    await withTimeout(exited, WAIT_MS, 'slmp-sim exit').catch(() => sim.kill('SIGKILL'));
    fs.rmSync(dir, { recursive: true, force: true });
  }
}

main()
  .catch((e) => { failed++; out(`FAIL - ${e.message}`); })
  .finally(() => {
    out(`${passed} passed, ${failed} failed`);
    process.exit(failed ? 1 : 0);
  });
