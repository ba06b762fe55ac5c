// Shared by the browser tests: the static server of dist/ (tools/build/serve.mjs), Chromium on each GPU path,
// pixel comparison of screenshots, and readers of the app's automation hooks on <body>
// (the `data-*` attributes listed in the README; positions in CSS px).
import assert from 'node:assert/strict';
import { after, before } from 'node:test';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { PNG } from 'pngjs';
import { serve } from '../../tools/build/serve.mjs';

export { serve };

export const ROOT = path.resolve(import.meta.dirname, '../..');
export const DIST = process.env.MARBLING_DIST ?? path.join(ROOT, 'dist');
export const MARBLING = process.env.MARBLING_BIN || path.join(ROOT, 'target/release/marbling');
export const SHOTS = path.join(ROOT, 'docs/screenshots');
const CHROMIUM = process.env.CHROMIUM || '/usr/bin/chromium';
export const READY_MS = 240_000;

/**
 * The long tier: `make test-long` (MARBLING_LONG=1) runs every test; `make test` (and CI)
 * skips the ones given `longOnly`, which repeat on a second backend or a second screen
 * what the short tier checks once, or measure rather than check (tile schedules, drag
 * frames), to keep `make test` short on SwiftShader.
 */
export const LONG = process.env.MARBLING_LONG === '1';
/** Test options of a test of the long tier. */
export const longOnly = LONG ? {} : { skip: 'long tier: make test-long' };

const COMMON = ['--no-sandbox', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync', '--disable-gpu-sandbox'];
export const BACKENDS = {
  webgpu: ['--enable-unsafe-webgpu', '--enable-features=Vulkan', '--use-vulkan=swiftshader',
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  webgl2: ['--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
};

export const decode = (buf) => PNG.sync.read(buf);

/** Fraction of pixels of two equally sized decoded PNGs differing by more than `threshold`. */
export function differing(a, b, threshold) {
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
export function crop(img, w, h) {
  const out = new PNG({ width: w, height: h });
  for (let y = 0; y < h; y++) img.data.copy(out.data, y * w * 4, y * img.width * 4, (y * img.width + w) * 4);
  return out;
}

export async function attr(page, name) {
  return page.evaluate((n) => document.body.getAttribute(n), name);
}

export async function waitReady(page) {
  await page.waitForFunction(() => document.body.dataset.ready === '1', null, { timeout: READY_MS });
}

/** Waits until the design has `ops` ops and its exact frame is on screen. */
export async function waitOps(page, ops) {
  await page.waitForFunction((n) => document.body.dataset.ops === String(n) && document.body.dataset.ready === '1', ops, { timeout: READY_MS });
}

/** The sheet's position on the page and its scale, from `data-view`. */
export async function sheet(page) {
  const [x, y, scale] = (await attr(page, 'data-view')).split(',').map(Number);
  return { x, y, scale };
}

/** A screenshot of the page region of `w × h` design pixels at the sheet's corner. */
export async function shootSheet(page, w, h) {
  // Park the pointer on the panel so no tool footprint is drawn over the sheet.
  await page.mouse.move(2, 2);
  await page.waitForTimeout(300);
  const s = await sheet(page);
  // The shot has the screen's device pixels, `dpr` per CSS pixel; the sheet starts on a
  // device pixel (half a CSS pixel at a ratio of 2).
  const dpr = await page.evaluate(() => devicePixelRatio);
  const device = (v, round) => round(v * dpr) / dpr;
  const clip = { x: device(s.x, Math.round), y: device(s.y, Math.round), width: device(w * s.scale, Math.floor), height: device(h * s.scale, Math.floor) };
  // A screenshot waits for the GPU to finish the frame: slow on SwiftShader under load.
  return { img: decode(await page.screenshot({ clip, timeout: READY_MS })), dpr, ...s };
}


/**
 * Chromium on `backend` for the tests of the enclosing `describe`: launched before them,
 * closed after. Returns an object whose `browser` and `site` are set once launched.
 */
export function sharedBrowser(backend) {
  const shared = {};
  before(async () => Object.assign(shared, await launch(backend)));
  after(async () => {
    await shared.browser?.close();
    shared.site?.server.close();
  });
  return shared;
}

/** Chromium with the flags of `backend` (and `extra` flags), and the site served from
 * `dir` (dist/ unless given). */
export async function launch(backend, extra = [], dir = DIST) {
  assert.ok(fs.existsSync(path.join(dir, 'index.html')), `${dir} has no index.html: run make web first`);
  const site = await serve(dir);
  const browser = await chromium.launch({ executablePath: CHROMIUM, headless: true, args: [...COMMON, ...BACKENDS[backend], ...extra] });
  return { site, browser };
}

/**
 * The window of the desktop tests, CSS px: a small laptop's. The sheet's pixels set what
 * each exact frame costs on SwiftShader (a CPU): Stone opens in 22 s at 1300×820 (the
 * sheet at 151 %), 9.6 s at 1000×660 (104 %), measured on 2 cores.
 */
export const DESKTOP = { width: 1000, height: 660 };

/**
 * Opens the app on a fresh page and waits for its first exact frame. A first visit lands
 * on the gallery; `?landing=0` opens the first pattern instead, which the tests edit.
 * `device` overrides the context's options (deviceScaleFactor, hasTouch, isMobile).
 */
export async function openPage(browser, site, hash = '', viewport = DESKTOP, device = {}) {
  // The offline service worker (web/sw.js) would copy every file of the app into each
  // fresh context's cache: only the test of offline use lets it run.
  const context = await browser.newContext({ viewport, deviceScaleFactor: 1, acceptDownloads: true, serviceWorkers: 'block', ...device });
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${site.url}?landing=0${hash}`);
  await waitReady(page);
  return { page, context, errors };
}

/** Where the app drew its named controls, from `data-controls` (CSS pixels). */
export async function controls(page) {
  const text = (await attr(page, 'data-controls')) ?? '';
  const out = {};
  for (const entry of text.split(';').filter(Boolean)) {
    const [name, rect] = entry.split('=');
    const [x, y, w, h] = rect.split(',').map(Number);
    out[name] = { x, y, w, h };
  }
  return out;
}

/**
 * Scrolls the panel by `dy` CSS pixels with the wheel over it (over the listed control,
 * other than the canvas, nearest the middle of the window's height) and waits two frames.
 */
async function scrollPanel(page, all, dy) {
  const { height } = page.viewportSize();
  const inPanel = Object.entries(all)
    .filter(([n, r]) => n !== 'canvas' && r.y >= 0 && r.y + r.h <= height)
    .sort(([, a], [, b]) => Math.abs(a.y - height / 2) - Math.abs(b.y - height / 2));
  if (inPanel.length === 0) return;
  const [, r] = inPanel[0];
  const frames = Number(await attr(page, 'data-frames'));
  await page.mouse.move(r.x + r.w / 2, r.y + r.h / 2);
  await page.mouse.wheel(0, dy);
  await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, frames + 2, { timeout: READY_MS });
}

/**
 * Clicks the control named `name` (a real click through egui), first scrolling the
 * panel under it with the wheel when it lies below or above the viewport, or up (then
 * down) when it is not listed: a scroll can leave its centre just outside its scroll
 * area, where `data-controls` leaves it out.
 */
export async function clickControl(page, name) {
  const { height } = page.viewportSize();
  let c;
  for (let tries = 0; ; tries++) {
    let all = await controls(page);
    for (const dy of [-3000, 6000]) {
      if (all[name]) break;
      await scrollPanel(page, all, dy);
      all = await controls(page);
    }
    c = all[name];
    assert.ok(c, `no control ${name} in data-controls (have: ${Object.keys(all).join(', ')})`);
    const y = c.y + c.h / 2;
    if ((y >= 0 && y <= height) || tries === 8) break;
    const frames = Number(await attr(page, 'data-frames'));
    await page.mouse.move(c.x + c.w / 2, Math.min(Math.max(y, 8), height - 8));
    await page.mouse.wheel(0, y - height / 2);
    await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, frames + 2, { timeout: READY_MS });
  }
  await page.mouse.click(c.x + c.w / 2, c.y + c.h / 2);
}

/** Clicks `name` and returns the file it downloads: { name, bytes }. */
export async function download(page, name) {
  const [dl] = await Promise.all([page.waitForEvent('download', { timeout: READY_MS }), clickControl(page, name)]);
  const file = await dl.path();
  return { name: dl.suggestedFilename(), bytes: fs.readFileSync(file) };
}

/** The pattern `name` from examples/patterns, else the example design from examples/designs. */
export function example(name) {
  const pattern = path.join(ROOT, 'examples/patterns', `${name}.json`);
  const file = fs.existsSync(pattern) ? pattern : path.join(ROOT, 'examples/designs', `${name}.json`);
  return { file, design: JSON.parse(fs.readFileSync(file, 'utf8')) };
}

/** The `#d=` fragment of `design` (made by the CLI, like a shared link); `name` keeps
 * the temporary files of one test run apart. */
export function linkFragment(design, name) {
  const file = path.join(os.tmpdir(), `marbling-link-${process.pid}-${name}.json`);
  fs.writeFileSync(file, JSON.stringify(design));
  const link = execFileSync(MARBLING, ['link', file, '--base', 'http://x/']).toString().trim();
  return link.slice(link.indexOf('#'));
}

/** A 64×48 PNG: left half blue, right half yellow. */
export function twoColourPng() {
  const png = new PNG({ width: 64, height: 48 });
  for (let y = 0; y < 48; y++) {
    for (let x = 0; x < 64; x++) {
      const i = (y * 64 + x) * 4;
      const c = x < 32 ? [30, 60, 220] : [240, 210, 20];
      png.data.set([...c, 255], i);
    }
  }
  return PNG.sync.write(png);
}

/** Drops `bytes` as file `name` on the page's canvas (a real drop event with a DataTransfer). */
export async function dropFile(page, name, mime, bytes) {
  await page.evaluate(({ name, mime, data }) => {
    const dt = new DataTransfer();
    dt.items.add(new File([Uint8Array.from(atob(data), (c) => c.charCodeAt(0))], name, { type: mime }));
    const canvas = document.querySelector('canvas');
    for (const type of ['dragenter', 'dragover', 'drop']) {
      canvas.dispatchEvent(new DragEvent(type, { dataTransfer: dt, bubbles: true, cancelable: true }));
    }
  }, { name, mime, data: Buffer.from(bytes).toString('base64') });
}

/** Every animation frame's time stamp, recorded by the page into `window.frameTimes`. */
export function recordFrames() {
  window.frameTimes = [];
  const tick = (t) => {
    window.frameTimes.push(t);
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
}
