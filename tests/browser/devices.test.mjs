// Hi-DPI screens, phones and tablets, and the installable offline app (one WebGL2
// browser for all): the backing store follows devicePixelRatio and the sheet is the CLI's
// render at the device's resolution; the portrait bottom sheet and landscape tool rail;
// touch (tap, one-finger drag, pinch and pan about the fingers' midpoint, a second finger
// cancelling a gesture); the service worker serving the app with the server stopped.
// Touches are sent through the Chrome DevTools Protocol (real touch events).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import {
  DIST, LONG, MARBLING, READY_MS, ROOT, SHOTS, attr, controls, crop, decode, differing, example, launch,
  linkFragment, openPage, serve, sheet, shootSheet, waitOps, waitReady,
} from './harness.mjs';

const PHONE = { width: 390, height: 844 };
const TABLET = { width: 820, height: 1180 };
const PHONE_LANDSCAPE = { width: 844, height: 390 };
const touchDevice = (deviceScaleFactor) => ({ deviceScaleFactor, hasTouch: true, isMobile: true });

/** Real touch events: `points` are the fingers down after this event ([x, y] CSS px). */
async function touch(cdp, type, points) {
  await cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: points.map(([x, y], id) => ({ x, y, id, radiusX: 4, radiusY: 4, force: 1 })),
  });
}

/** Moves the fingers from `from` to `to` in `steps` frames' worth of small moves. */
async function slide(page, cdp, from, to, steps = 8) {
  for (let k = 1; k <= steps; k++) {
    const t = k / steps;
    await touch(cdp, 'touchMove', from.map(([x, y], i) => [x + (to[i][0] - x) * t, y + (to[i][1] - y) * t]));
    await page.waitForTimeout(40);
  }
}

/** Waits for `k` more frames: a tap's effect is drawn in the frame after it. egui draws
 * only while something changes, so a page that went idle first is nudged with a Shift
 * press (no control reacts to it) each second until the frames come. */
async function frames(page, k = 3) {
  const want = Number(await attr(page, 'data-frames')) + k;
  const start = Date.now();
  for (;;) {
    try {
      await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, want, { timeout: 1000 });
      return;
    } catch (e) {
      if (e.name !== 'TimeoutError' || Date.now() - start > READY_MS) throw e;
      await page.keyboard.press('Shift');
    }
  }
}

/** The design point under page point `p` (CSS px), from `data-view`. */
async function designAt(page, p) {
  const s = await sheet(page);
  return [(p[0] - s.x) / s.scale, (p[1] - s.y) / s.scale];
}

/** Waits until `data-view` differs from `before` and holds still for a few frames. */
async function settledView(page, before) {
  await page.waitForFunction((b) => document.body.dataset.view !== b, before, { timeout: READY_MS });
  let last = '';
  for (let i = 0; i < 20; i++) {
    const now = await attr(page, 'data-view');
    if (now === last) break;
    last = now;
    await page.waitForTimeout(150);
  }
}

/** Compares the sheet on screen (device pixels) with the CLI's render at that scale. */
async function sheetMatchesCli(page, file, design, label) {
  const shot = await shootSheet(page, design.width, design.height);
  const scale = shot.scale * shot.dpr;
  const tmp = path.join(os.tmpdir(), `marbling-devices-${process.pid}-${label}.png`);
  execFileSync(MARBLING, ['render', file, '-o', tmp, '--scale', String(scale), '--aa', 'rgss']);
  const cpu = decode(fs.readFileSync(tmp));
  const w = Math.min(cpu.width, shot.img.width);
  const h = Math.min(cpu.height, shot.img.height);
  // Within a device pixel of the sheet's whole size: the render is at the device's resolution.
  assert.ok(Math.abs(cpu.width - shot.img.width) <= 2, `${label}: shot ${shot.img.width} px wide, render ${cpu.width}`);
  const frac = differing(crop(cpu, w, h), crop(shot.img, w, h), 24);
  if (process.env.KEEP_SHOTS) fs.writeFileSync(`/tmp/shot-${label.split(' ')[0]}.png`, (await import('pngjs')).PNG.sync.write(shot.img));
  console.log(`${label}: sheet at ${shot.dpr}× vs CLI render at scale ${scale.toFixed(4)}: ${(100 * frac).toFixed(3)} % of ${w}×${h} px differ by > 24/255`);
  assert.ok(frac <= 0.01, `${label}: ${(100 * frac).toFixed(2)} % of pixels differ`);
}

const { browser, site } = await launch('webgl2');
test.after(async () => { await browser.close(); site.server.close(); });

test('a ratio-2 laptop: device-pixel backing store, CSS-px hooks, the CLI render at 2×', { timeout: 600_000 }, async () => {
  const { file, design } = example('v3-drops');
  const { page, context, errors } = await openPage(browser, site, linkFragment(design, 'dpr2'), { width: 1024, height: 640 }, { deviceScaleFactor: 2 });
  await waitOps(page, design.ops.length);
  const store = await page.evaluate(() => {
    const c = document.getElementById('marbling_canvas');
    return [c.width, c.height, c.getBoundingClientRect().width, c.getBoundingClientRect().height];
  });
  assert.deepEqual(store, [2048, 1280, 1024, 640], 'backing store = CSS size × devicePixelRatio');
  assert.equal(await attr(page, 'data-layout'), 'desktop');
  // One egui point is one CSS pixel: the side panel keeps its 240–360 px and the hooks
  // agree with each other (the canvas control holds the sheet).
  const c = await controls(page);
  assert.ok(c.canvas.x >= 240 && c.canvas.x <= 380, `canvas starts at ${c.canvas.x} CSS px`);
  const s = await sheet(page);
  assert.ok(s.x >= c.canvas.x && s.x + design.width * s.scale <= c.canvas.x + c.canvas.w + 1, `sheet at ${s.x} outside the canvas control`);
  await sheetMatchesCli(page, file, design, 'laptop 1024×640 @2');
  await page.screenshot({ path: path.join(SHOTS, 'hidpi-1024x640@2.png'), timeout: READY_MS });

  assert.deepEqual(errors, []);
  await context.close();
});

test('a phone: bottom sheet, 44-px targets, tap, drag, pinch, pan, a second finger cancels', { timeout: 600_000 }, async () => {
  const { file, design } = example('v3-drops');
  const n = design.ops.length;
  const { page, context, errors } = await openPage(browser, site, linkFragment(design, 'phone'), PHONE, touchDevice(2));
  await waitOps(page, n);
  assert.equal(await attr(page, 'data-layout'), 'portrait');
  const store = await page.evaluate(() => document.getElementById('marbling_canvas').width);
  assert.equal(store, PHONE.width * 2);
  let c = await controls(page);
  const canvasShare = (c.canvas.w * c.canvas.h) / (PHONE.width * PHONE.height);
  console.log(`phone: the canvas takes ${(100 * canvasShare).toFixed(1)} % of the viewport with the sheet open`);
  assert.ok(canvasShare >= 0.55, `canvas ${(100 * canvasShare).toFixed(1)} % of the viewport`);
  for (const name of ['sheet-tools', 'sheet-ink', 'sheet-history', 'sheet-files', 'sheet-noise', 'sheet-toggle', 'tool-drop', 'tool-comb']) {
    assert.ok(c[name], `no ${name} in data-controls`);
    assert.ok(c[name].h >= 44 && c[name].w >= 44, `${name} is ${c[name].w}×${c[name].h} CSS px`);
  }
  await sheetMatchesCli(page, file, design, 'phone 390×844 @2');
  await page.screenshot({ path: path.join(SHOTS, 'phone-390x844.png'), timeout: READY_MS });

  const cdp = await context.newCDPSession(page);
  const tap = async (name) => {
    const r = (await controls(page))[name];
    assert.ok(r, `no control ${name}`);
    await page.touchscreen.tap(r.x + r.w / 2, r.y + r.h / 2);
    await frames(page);
  };
  const s = await sheet(page);
  // A point of the sheet, as fractions of its width and height.
  const at = (fx, fy) => [s.x + fx * design.width * s.scale, s.y + fy * design.height * s.scale];

  // A tap drops one drop.
  await tap('tool-drop');
  const [tx, ty] = at(0.5, 0.5);
  await touch(cdp, 'touchStart', [[tx, ty]]);
  await page.waitForTimeout(60);
  await touch(cdp, 'touchEnd', []);
  await waitOps(page, n + 1);

  // One finger drags a comb.
  await tap('tool-comb');
  const from = at(0.16, 0.25);
  const to = at(0.84, 0.75);
  await touch(cdp, 'touchStart', [from]);
  await slide(page, cdp, [from], [to]);
  await touch(cdp, 'touchEnd', []);
  await waitOps(page, n + 2);

  // A second finger arriving mid-drag cancels the comb: nothing committed, nothing lost.
  await touch(cdp, 'touchStart', [from]);
  await slide(page, cdp, [from], [at(0.47, 0.37)], 4);
  await touch(cdp, 'touchStart', [at(0.47, 0.37), at(0.62, 0.75)]);
  await slide(page, cdp, [at(0.47, 0.37), at(0.62, 0.75)], [at(0.5, 0.4), at(0.66, 0.77)], 3);
  await touch(cdp, 'touchEnd', [at(0.5, 0.4)]);
  await touch(cdp, 'touchEnd', []);
  await page.waitForTimeout(800);
  assert.equal(await attr(page, 'data-ops'), String(n + 2), 'the cancelled gesture committed ops');

  // A pinch zooms about the fingers' midpoint: the design point under it stays.
  const mid = at(0.5, 0.5);
  const before = await attr(page, 'data-view');
  const anchor = await designAt(page, mid);
  const a0 = [[mid[0] - 40, mid[1]], [mid[0] + 40, mid[1]]];
  const a1 = [[mid[0] - 110, mid[1]], [mid[0] + 110, mid[1]]];
  await touch(cdp, 'touchStart', a0);
  await slide(page, cdp, a0, a1, 10);
  await touch(cdp, 'touchEnd', []);
  await settledView(page, before);
  const zoomed = await sheet(page);
  const after = await designAt(page, mid);
  const drift = Math.hypot(after[0] - anchor[0], after[1] - anchor[1]) * zoomed.scale;
  console.log(`phone: pinch ×${(zoomed.scale / s.scale).toFixed(2)}, the midpoint's design point moved ${drift.toFixed(2)} CSS px`);
  assert.ok(zoomed.scale / s.scale > 2, `the pinch zoomed only ×${(zoomed.scale / s.scale).toFixed(2)}`);
  assert.ok(drift <= 1, `the design point under the midpoint moved ${drift.toFixed(2)} CSS px`);

  // Two fingers moving together pan the view by their displacement.
  const p0 = [[mid[0] - 60, mid[1]], [mid[0] + 60, mid[1]]];
  const p1 = p0.map(([x, y]) => [x - 50, y - 70]);
  const panBefore = await attr(page, 'data-view');
  await touch(cdp, 'touchStart', p0);
  await slide(page, cdp, p0, p1, 8);
  await touch(cdp, 'touchEnd', []);
  await settledView(page, panBefore);
  const panned = await sheet(page);
  console.log(`phone: two-finger pan moved the sheet by ${(panned.x - zoomed.x).toFixed(1)}, ${(panned.y - zoomed.y).toFixed(1)} CSS px`);
  assert.ok(Math.abs(panned.x - zoomed.x + 50) <= 3 && Math.abs(panned.y - zoomed.y + 70) <= 3, 'the view did not follow the fingers');
  assert.equal(await attr(page, 'data-ops'), String(n + 2), 'navigating committed ops');

  // Zoomed, the status bar holds a finger-sized *Zoom to…*; the open box takes a row of
  // its own with its field, Go and Close on the screen.
  const fingerSized = async (names) => {
    const all = await controls(page);
    for (const name of names) {
      const r = all[name];
      assert.ok(r, `no ${name} in data-controls`);
      assert.ok(r.h >= 44 && r.x >= 0 && r.x + r.w <= PHONE.width && r.y + r.h <= PHONE.height,
        `${name} at ${r.x},${r.y} ${r.w}×${r.h} on a ${PHONE.width}×${PHONE.height} screen`);
    }
  };
  await fingerSized(['zoom-to']);
  await tap('zoom-to');
  await page.waitForFunction(() => /(^|;)zoom-to-close=/.test(document.body.dataset.controls ?? ''), null, { timeout: READY_MS });
  await fingerSized(['zoom-to-text', 'zoom-to-go', 'zoom-to-close']);
  await page.screenshot({ path: path.join(SHOTS, 'phone-zoom-to.png'), timeout: READY_MS });
  await tap('zoom-to-close');
  await page.waitForFunction(() => /(^|;)zoom-to=/.test(document.body.dataset.controls ?? ''), null, { timeout: READY_MS });

  // The sheet's tabs: History's Undo takes the comb back; the arrow collapses the sheet
  // and the canvas grows; Noise opens the noise playground.
  await tap('sheet-history');
  await page.waitForFunction(() => (document.body.dataset.controls ?? '').includes('undo='), null, { timeout: READY_MS });
  await tap('undo');
  await waitOps(page, n + 1);
  c = await controls(page);
  const openHeight = c.canvas.h;
  await tap('sheet-toggle');
  await page.waitForFunction((h) => {
    const m = /(?:^|;)canvas=[\d.]+,[\d.]+,[\d.]+,([\d.]+)/.exec(document.body.dataset.controls ?? '');
    return m && Number(m[1]) > h + 100;
  }, openHeight, { timeout: READY_MS });
  await tap('sheet-noise');
  await page.waitForFunction(() => document.body.dataset.mode === 'noise', null, { timeout: READY_MS });
  await tap('sheet-tools');
  await page.waitForFunction(() => document.body.dataset.mode === 'marbling', null, { timeout: READY_MS });
  assert.deepEqual(errors, []);
  await context.close();
});

test('a tablet and a landscape phone: bottom sheet and tool rail', { timeout: 600_000 }, async () => {
  // A light design: each page's first exact frame is drawn by SwiftShader.
  const light = linkFragment(example('v3-drops').design, 'light');
  const tablet = await openPage(browser, site, light, TABLET, touchDevice(1));
  assert.equal(await attr(tablet.page, 'data-layout'), 'portrait');
  const c = await controls(tablet.page);
  const share = (c.canvas.w * c.canvas.h) / (TABLET.width * TABLET.height);
  console.log(`tablet: the canvas takes ${(100 * share).toFixed(1)} % of the viewport`);
  assert.ok(share >= 0.55);
  await tablet.page.screenshot({ path: path.join(SHOTS, 'tablet-820x1180.png'), timeout: READY_MS });
  await tablet.context.close();

  // A first visit on a phone lands on the gallery, full screen, with 44-px controls.
  const first = await browser.newContext({ viewport: PHONE, serviceWorkers: 'block', ...touchDevice(1) });
  const landing = await first.newPage();
  await landing.goto(site.url);
  await landing.waitForFunction(() => document.body.dataset.landing === '1', null, { timeout: READY_MS });
  await landing.waitForFunction(() => (document.body.dataset.controls ?? '').includes('gallery-close='), null, { timeout: READY_MS });
  const back = (await controls(landing))['gallery-close'];
  assert.ok(back.h >= 44, `"Back to the editor" is ${back.h} CSS px high`);
  assert.equal((await controls(landing))['sheet-tools'], undefined, 'the bottom sheet is hidden under the gallery');
  await first.close();

  const phone = await openPage(browser, site, light, PHONE_LANDSCAPE, touchDevice(1));
  const { page } = phone;
  assert.equal(await attr(page, 'data-layout'), 'landscape');
  let r = await controls(page);
  assert.ok(r['rail-drop'] && r['rail-drop'].h >= 44, 'the rail has 44-px tool buttons');
  assert.equal(r['mode-marbling'], undefined, 'the full panel is closed');
  const ops = Number(await attr(page, 'data-ops'));
  // Each tap in a frame of its own (two taps merged into one slow frame are one press).
  await page.touchscreen.tap(r['rail-drop'].x + 20, r['rail-drop'].y + 20);
  await frames(page);
  await page.touchscreen.tap(r.canvas.x + r.canvas.w / 2, r.canvas.y + r.canvas.h / 2);
  await waitOps(page, ops + 1);

  // The keyboard reaches the controls: Tab walks the rail to Undo, Enter presses it.
  let tabs = 0;
  while ((await attr(page, 'data-focus')) !== 'rail-undo') {
    assert.ok(tabs++ < 40, `Tab never reached Undo (focus: ${await attr(page, 'data-focus')})`);
    await page.keyboard.press('Tab');
    await frames(page, 2);
  }
  console.log(`landscape phone: Undo takes the focus after ${tabs} Tab presses`);
  await page.keyboard.press('Enter');
  await waitOps(page, ops);
  r = await controls(page);
  await page.touchscreen.tap(r['rail-panel'].x + 20, r['rail-panel'].y + 20);
  await page.waitForFunction(() => (document.body.dataset.controls ?? '').includes('mode-marbling='), null, { timeout: READY_MS });
  await page.screenshot({ path: path.join(SHOTS, 'phone-landscape-844x390.png'), timeout: READY_MS });
  assert.deepEqual(phone.errors, []);
  await phone.context.close();
});

/** Pairs of `data-controls` entries whose rectangles overlap by more than a pixel. */
function overlaps(c) {
  const names = Object.keys(c);
  const out = [];
  for (let i = 0; i < names.length; i++) {
    for (let j = i + 1; j < names.length; j++) {
      const [a, b] = [c[names[i]], c[names[j]]];
      const w = Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x);
      const h = Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y);
      if (w > 1 && h > 1) out.push(`${names[i]} × ${names[j]}`);
    }
  }
  return out;
}

// The overlap finder finds what it should (a test of the comparator).
assert.deepEqual(overlaps({ a: { x: 0, y: 0, w: 10, h: 10 }, b: { x: 8, y: 8, w: 10, h: 10 }, c: { x: 10, y: 0, w: 5, h: 5 } }), ['a × b']);

test('the player with Explain on fits every screen: controls inside and apart, the sheet fitted, the canvas keeps 40 %; the panel keeps one width', { timeout: 600_000 }, async () => {
  // Chevron at 320×200: its first step lays 288 drops (the hardest step to explain).
  const file = path.join(os.tmpdir(), `marbling-devices-${process.pid}-chevron.json`);
  execFileSync(MARBLING, ['pattern', 'chevron', '--size', '320x200', '-o', file]);
  const design = JSON.parse(fs.readFileSync(file, 'utf8'));
  const link = linkFragment(design, 'chevron-layout');
  const screens = [
    ['laptop', { width: 1280, height: 800 }, {}],
    ['teacher', { width: 1440, height: 900 }, {}],
    ['phone', PHONE, touchDevice(2)],
    ['landscape-phone', PHONE_LANDSCAPE, touchDevice(2)],
  ].filter(([name]) => LONG || name === 'laptop' || name === 'phone');
  for (const [name, viewport, device] of screens) {
    const { page, context, errors } = await openPage(browser, site, link, viewport, device);
    const press = async (control) => {
      const c = (await controls(page))[control];
      assert.ok(c, `${name}: no ${control} in data-controls`);
      if (device.hasTouch) await page.touchscreen.tap(c.x + c.w / 2, c.y + c.h / 2);
      else await page.mouse.click(c.x + c.w / 2, c.y + c.h / 2);
      await frames(page);
    };
    const layout = await attr(page, 'data-layout');
    if (layout === 'portrait') await press('sheet-history');
    if (layout === 'landscape') await press('rail-panel');
    // Play is in the panel's History section, maybe below the fold: scroll to it.
    let c = await controls(page);
    for (let i = 0; i < 8 && c.play.y + c.play.h > viewport.height; i++) {
      await page.mouse.move(c.play.x + 10, viewport.height / 2);
      await page.mouse.wheel(0, c.play.y - viewport.height / 2);
      await frames(page, 10);
      c = await controls(page);
    }
    await press('play');
    await page.waitForFunction(() => /\//.test(document.body.dataset.player ?? ''), null, { timeout: READY_MS });
    await press('player-play'); // pause
    c = await controls(page);
    const tl = c['player-timeline'];
    await page.mouse.click(tl.x + tl.w / (design.recipe.captions.length * 1.0), tl.y + 11);
    await page.waitForFunction(() => (document.body.dataset.player ?? '').startsWith('1/'), null, { timeout: READY_MS });
    await press('player-explain');
    await frames(page, 4);
    c = await controls(page);
    const outside = Object.entries(c)
      .filter(([, r]) => r.x < viewport.width && r.y < viewport.height && r.x + r.w > 0 && r.y + r.h > 0)
      .filter(([, r]) => r.x < -1 || r.y < -1 || r.x + r.w > viewport.width + 1 || r.y + r.h > viewport.height + 1)
      .map(([n, r]) => `${n} at ${r.x},${r.y} ${r.w}×${r.h}`);
    assert.deepEqual(outside, [], `${name}: controls cut by the screen's edge`);
    assert.deepEqual(overlaps(c), [], `${name}: controls on top of each other`);
    const s = await sheet(page);
    const [sw, sh] = [design.width * s.scale, design.height * s.scale];
    const cv = c.canvas;
    assert.ok(s.x >= cv.x - 1 && s.y >= cv.y - 1 && s.x + sw <= cv.x + cv.w + 1 && s.y + sh <= cv.y + cv.h + 1,
      `${name}: the sheet (${s.x},${s.y} ${sw}×${sh}) is not inside the canvas (${cv.x},${cv.y} ${cv.w}×${cv.h})`);
    console.log(`${name} ${viewport.width}×${viewport.height}: the canvas keeps ${(100 * cv.h / viewport.height).toFixed(0)} % of the height, the sheet is ${sw.toFixed(0)}×${sh.toFixed(0)} px`);
    if (device.hasTouch) assert.ok(cv.h >= 0.4 * viewport.height - 1, `${name}: the canvas keeps ${cv.h} of ${viewport.height} px`);
    await page.screenshot({ path: path.join(SHOTS, `explain-chevron-step1-${viewport.width}x${viewport.height}.png`), timeout: READY_MS });
    if (name === 'laptop') {
      // One panel width whatever the tool or the noise type.
      const widths = new Set();
      for (const tool of ['drop', 'spray', 'tine', 'comb', 'stylus', 'wavy', 'jiggle', 'circular', 'vortex', 'shift', 'turn']) {
        await press(`tool-${tool}`);
        widths.add((await controls(page)).canvas.x);
      }
      // The noise panel (Gabor's long labels); each further noise type costs SwiftShader
      // 13–51 s of preview, so the others are left to the panel's fixed size.
      await press('mode-noise');
      await page.waitForFunction(() => document.body.dataset.mode === 'noise', null, { timeout: READY_MS });
      widths.add((await controls(page)).canvas.x);
      assert.deepEqual([...widths], [widths.values().next().value], `the panel's width changed: ${[...widths].join(', ')}`);
    }
    assert.deepEqual(errors, [], name);
    await context.close();
  }
});

test('installable and offline: manifest, icons, and the service worker serves the app with the server stopped', { timeout: 600_000 }, async () => {
  const manifest = JSON.parse(await (await fetch(`${site.url}manifest.webmanifest`)).text());
  const sizes = manifest.icons.map((i) => i.sizes);
  assert.ok(sizes.includes('192x192') && sizes.includes('512x512') && sizes.includes('any'), `icons ${sizes}`);
  assert.equal(manifest.display, 'standalone');
  for (const icon of manifest.icons) assert.equal((await fetch(`${site.url}${icon.src}`)).status, 200, icon.src);
  // `make dist` is hosted as it is under any path: no URL in the page starts at the root.
  const html = fs.readFileSync(path.join(DIST, 'index.html'), 'utf8');
  assert.deepEqual(html.match(/(?:href|src)="\/[^"]*"|(?:from |module_or_path: )'\/[^']*'/g), null);


  // Each build's service worker lists that build's files under a version of its own, so
  // installing a new build's worker replaces the old cache; the module is listed in its
  // compressed forms only, and its name section is gone (tools/build/post_build.mjs on a
  // staging folder, as tools/build/build.mjs runs it).
  const stage = fs.mkdtempSync(path.join(os.tmpdir(), 'marbling-stage-'));
  const stageBuild = () => {
    fs.copyFileSync(path.join(ROOT, 'web/sw.js'), path.join(stage, 'sw.js'));
    execFileSync(process.execPath, [path.join(ROOT, 'tools/build/post_build.mjs'), stage], { stdio: 'pipe' });
    const sw = fs.readFileSync(path.join(stage, 'sw.js'), 'utf8');
    return { version: /const BUILD = '([0-9a-f]{16})'/.exec(sw)?.[1], files: JSON.parse(/const FILES = (\[.*\]);/.exec(sw)[1].replace(/'/g, '"')) };
  };
  // Two tiny modules: the header, a custom section "name" (dropped) and one "keep" (kept).
  const header = Buffer.from('0061736d01000000', 'hex');
  const custom = (name, bytes) => Buffer.concat([Buffer.from([0, 1 + name.length + bytes.length, name.length]), Buffer.from(name), Buffer.from(bytes)]);
  fs.writeFileSync(path.join(stage, 'index.html'), 'page');
  fs.writeFileSync(path.join(stage, 'app-1.wasm'), Buffer.concat([header, custom('name', [1, 2, 3]), custom('keep', [4])]));
  const first = stageBuild();
  assert.deepEqual(fs.readFileSync(path.join(stage, 'app-1.wasm')), Buffer.concat([header, custom('keep', [4])]), 'the name section stays');
  assert.deepEqual(zlib.gunzipSync(fs.readFileSync(path.join(stage, 'app-1.wasm.gz'))), fs.readFileSync(path.join(stage, 'app-1.wasm')));
  assert.deepEqual(zlib.brotliDecompressSync(fs.readFileSync(path.join(stage, 'app-1.wasm.br'))), fs.readFileSync(path.join(stage, 'app-1.wasm')));
  for (const f of fs.readdirSync(stage).filter((f) => f.startsWith('app-1'))) fs.rmSync(path.join(stage, f));
  fs.writeFileSync(path.join(stage, 'app-2.wasm'), Buffer.concat([header, custom('keep', [5, 6])]));
  const second = stageBuild();
  assert.deepEqual([first.files, second.files], [['./', 'app-1.wasm.br', 'app-1.wasm.gz', 'index.html'], ['./', 'app-2.wasm.br', 'app-2.wasm.gz', 'index.html']]);
  assert.ok(first.version && second.version && first.version !== second.version, `versions ${first.version}, ${second.version}`);
  fs.rmSync(stage, { recursive: true });

  // A server of its own, stopped after the first visit.
  const own = await serve(DIST);
  const context = await browser.newContext({ viewport: { width: 800, height: 600 }, serviceWorkers: 'allow' });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${own.url}?landing=0`);
  await waitReady(page);
  // Installed (every file cached) and in control of the page.
  await page.waitForFunction(async () => (await navigator.serviceWorker.ready).active?.state === 'activated'
    && navigator.serviceWorker.controller !== null, null, { timeout: READY_MS, polling: 200 });
  own.server.close();
  own.server.closeAllConnections();
  assert.equal(await fetch(own.url).then(() => 'up', () => 'down'), 'down', 'the server still answers');
  await page.reload();
  await waitReady(page);
  assert.equal(await attr(page, 'data-backend'), 'webgl2');
  assert.ok(Number(await attr(page, 'data-ops')) > 0, 'the offline page shows no design');
  assert.deepEqual(errors, []);
  await context.close();
});
