// End-to-end tests of the web playground in Debian's Chromium, on both GPU paths:
// WebGPU (SwiftShader Vulkan) and WebGL2 (ANGLE on SwiftShader). Run by `make browser-test`
// after `trunk build --release`; they read the app's automation hooks on <body>
// (data-ready, data-backend, data-ops, data-error, data-view, data-frame-ms).
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';

const ROOT = path.resolve(import.meta.dirname, '../..');
const DIST = path.join(ROOT, 'dist');
const MARBLING = process.env.MARBLING_BIN || path.join(ROOT, 'target/release/marbling');
const SHOTS = path.join(ROOT, 'docs/screenshots');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
const READY_MS = 240_000;

const COMMON = ['--no-sandbox', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--disable-gpu-sandbox'];
const BACKENDS = {
  webgpu: ['--enable-unsafe-webgpu', '--enable-features=Vulkan', '--use-vulkan=swiftshader',
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  webgl2: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
};

/** Serves `dir` on 127.0.0.1 (a free port); resolves to its base URL. */
function serve(dir) {
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm',
    '.png': 'image/png', '.json': 'application/json', '.css': 'text/css' };
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://x');
    const file = path.join(dir, url.pathname === '/' ? 'index.html' : decodeURIComponent(url.pathname));
    if (!file.startsWith(dir) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'content-type': types[path.extname(file)] || 'application/octet-stream' });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve({ server, url: `http://127.0.0.1:${server.address().port}/` })));
}

const decode = (buf) => PNG.sync.read(buf);

/** Fraction of pixels of two equally sized decoded PNGs differing by more than `threshold`. */
function differing(a, b, threshold) {
  assert.equal(a.width, b.width);
  assert.equal(a.height, b.height);
  let n = 0;
  for (let i = 0; i < a.data.length; i += 4) {
    const d = Math.max(Math.abs(a.data[i] - b.data[i]), Math.abs(a.data[i + 1] - b.data[i + 1]), Math.abs(a.data[i + 2] - b.data[i + 2]));
    if (d > threshold) n++;
  }
  return n / (a.width * a.height);
}

/** The top-left `w × h` of a decoded PNG. */
function crop(img, w, h) {
  const out = new PNG({ width: w, height: h });
  for (let y = 0; y < h; y++) img.data.copy(out.data, y * w * 4, y * img.width * 4, (y * img.width + w) * 4);
  return out;
}

async function attr(page, name) {
  return page.evaluate((n) => document.body.getAttribute(n), name);
}

async function waitReady(page) {
  await page.waitForFunction(() => document.body.dataset.ready === '1', null, { timeout: READY_MS });
}

/** Waits until the design has `ops` ops and its exact frame is on screen. */
async function waitOps(page, ops) {
  await page.waitForFunction((n) => document.body.dataset.ops === String(n) && document.body.dataset.ready === '1', ops, { timeout: READY_MS });
}

/** The sheet's position on the page and its scale, from `data-view`. */
async function sheet(page) {
  const [x, y, scale] = (await attr(page, 'data-view')).split(',').map(Number);
  return { x, y, scale };
}

/** A screenshot of the page region of `w × h` design pixels at the sheet's corner. */
async function shootSheet(page, w, h) {
  // Park the pointer on the panel so no tool footprint is drawn over the sheet.
  await page.mouse.move(2, 2);
  await page.waitForTimeout(300);
  const s = await sheet(page);
  const clip = { x: Math.round(s.x), y: Math.round(s.y), width: Math.floor(w * s.scale), height: Math.floor(h * s.scale) };
  return { img: decode(await page.screenshot({ clip })), ...s };
}

const STONE = JSON.parse(fs.readFileSync(path.join(ROOT, 'examples/designs/stone.json'), 'utf8'));

for (const backend of Object.keys(BACKENDS)) {
  describe(`playground on ${backend}`, () => {
    let browser;
    let site;
    before(async () => {
      assert.ok(fs.existsSync(path.join(DIST, 'index.html')), 'dist/ is missing: run trunk build --release first');
      site = await serve(DIST);
      browser = await chromium.launch({ executablePath: CHROMIUM, headless: true, args: [...COMMON, ...BACKENDS[backend]] });
    });
    after(async () => {
      await browser?.close();
      site?.server.close();
    });

    /** A fresh page (empty storage) with console errors collected. */
    async function open(hash = '') {
      const context = await browser.newContext({ viewport: { width: 1300, height: 820 }, deviceScaleFactor: 1 });
      const page = await context.newPage();
      const errors = [];
      page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
      page.on('pageerror', (e) => errors.push(String(e)));
      await page.goto(site.url + hash);
      await waitReady(page);
      return { page, context, errors };
    }

    test('loads without console errors on the expected backend', async () => {
      const { page, context, errors } = await open();
      assert.equal(await attr(page, 'data-backend'), backend);
      assert.equal(await attr(page, 'data-ops'), String(STONE.ops.length));
      assert.equal(await attr(page, 'data-error'), null);
      const { img } = await shootSheet(page, STONE.width, STONE.height);
      // Not a blank canvas: the stone design has many colours.
      const colours = new Set();
      for (let i = 0; i < img.data.length; i += 4 * 97) colours.add(img.data.readUInt32BE(i));
      assert.ok(colours.size > 5, `only ${colours.size} colours on the canvas`);
      fs.mkdirSync(SHOTS, { recursive: true });
      await page.screenshot({ path: path.join(SHOTS, `playground-${backend}.png`) });
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('a drop click, a rake drag and undo change and restore the pixels', async () => {
      const { page, context, errors } = await open();
      const n = STONE.ops.length;
      const before = await shootSheet(page, STONE.width, STONE.height);
      const cx = before.x + (STONE.width * before.scale) / 2;
      const cy = before.y + (STONE.height * before.scale) / 2;
      await page.mouse.click(cx, cy);
      await waitOps(page, n + 1);
      const dropped = await shootSheet(page, STONE.width, STONE.height);
      assert.ok(differing(before.img, dropped.img, 8) > 0.01, 'the drop did not change the canvas');

      await page.keyboard.press('4'); // rake
      await page.mouse.move(cx - 150, cy - 120);
      await page.mouse.down();
      for (let i = 1; i <= 20; i++) await page.mouse.move(cx - 150, cy - 120 + i * 12);
      await page.mouse.up();
      await waitOps(page, n + 2);
      const raked = await shootSheet(page, STONE.width, STONE.height);
      assert.ok(differing(dropped.img, raked.img, 8) > 0.05, 'the rake did not change the canvas');
      await page.screenshot({ path: path.join(SHOTS, `raked-${backend}.png`) });

      await page.keyboard.press('Control+z');
      await waitOps(page, n + 1);
      const undone = await shootSheet(page, STONE.width, STONE.height);
      assert.ok(differing(dropped.img, undone.img, 2) < 0.001, 'undo did not restore the pixels');
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('a #d= link shows the same picture as `marbling render`', async () => {
      const design = path.join(ROOT, 'examples/designs/gel-git.json');
      const d = JSON.parse(fs.readFileSync(design, 'utf8'));
      const link = execFileSync(MARBLING, ['link', design, '--base', site.url]).toString().trim();
      const { page, context, errors } = await open(link.slice(link.indexOf('#')));
      assert.equal(await attr(page, 'data-ops'), String(d.ops.length));
      const shot = await shootSheet(page, d.width, d.height);
      const tmp = path.join(os.tmpdir(), `marbling-cpu-${process.pid}-${backend}.png`);
      execFileSync(MARBLING, ['render', design, '-o', tmp, '--scale', String(shot.scale), '--aa', 'rgss']);
      const cpu = decode(fs.readFileSync(tmp));
      const w = Math.min(cpu.width, shot.img.width);
      const h = Math.min(cpu.height, shot.img.height);
      const frac = differing(crop(cpu, w, h), crop(shot.img, w, h), 24);
      console.log(`${backend}: link vs CLI render at scale ${shot.scale.toFixed(4)}: ${(100 * frac).toFixed(3)} % of ${w}×${h} px differ by > 24/255`);
      assert.ok(frac <= 0.01, `${(100 * frac).toFixed(2)} % of pixels differ`);
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('autosave survives a reload', async () => {
      const { page, context } = await open();
      const s = await sheet(page);
      await page.mouse.click(s.x + 100, s.y + 100);
      await waitOps(page, STONE.ops.length + 1);
      const shot = await shootSheet(page, STONE.width, STONE.height);
      await page.reload();
      await waitOps(page, STONE.ops.length + 1);
      const again = await shootSheet(page, STONE.width, STONE.height);
      assert.ok(differing(shot.img, again.img, 2) < 0.001, 'the reloaded design differs');
      await context.close();
    });

    test('a malformed link shows an error and keeps the page usable', async () => {
      const { page, context } = await open('#d=this-is-not-a-design');
      const error = await attr(page, 'data-error');
      assert.match(error ?? '', /^share link: /);
      const ops = Number(await attr(page, 'data-ops'));
      const s = await sheet(page);
      await page.mouse.click(s.x + 50, s.y + 50);
      await waitOps(page, ops + 1);
      await context.close();
    });
  });
}
