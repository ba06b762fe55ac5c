// The editor tells the truth and never drops an edit, tried as a stranger would: links on
// a first visit (fresh profiles, no `?landing=0`), a reload at once after an edit (no
// wait) for every way in, quick Ctrl+Z presses, a panic, and `data-ready` after a zoom
// compared with the CLI's render on both backends.
import { describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { PNG } from 'pngjs';
import {
  DESKTOP, LONG, MARBLING, READY_MS, SHOTS, attr, clickControl, controls, crop, decode, differing, dropFile, example,
  linkFragment, sharedBrowser, sheet, shootSheet, twoColourPng, waitOps, waitReady,
} from './harness.mjs';

const GEL = example('gel-git');
/** A small laptop's window (CSS pixels). */
const SMALL = { width: 760, height: 540 };
const tmp = (name) => path.join(os.tmpdir(), `marbling-trust-${process.pid}-${name}`);
const noiseLink = (spec) => `#n=${zlib.deflateRawSync(Buffer.from(JSON.stringify(spec))).toString('base64url')}`;

describe('trust: links, reloads, panics and data-ready on webgl2', () => {
  const shared = sharedBrowser('webgl2');
  const firstVisit = (hash) => freshVisit(shared.browser, shared.site, hash);

  test('a link on a first visit wins over the gallery: the design, the noise, or the error', async () => {
    const gel = linkFragment(GEL.design, 'gel');
    const cases = [
      { hash: gel, ops: GEL.design.ops.length },
      { hash: '#d=!!not-a-link', error: /^share link: / },
      { hash: noiseLink({ type: 'worley', frequency: 0.04, feature: 'f2', metric: 'euclidean', seed: 5, palette: 'ember' }), mode: 'noise' },
      { hash: '#n=@@not-base64', error: /^share link: not valid base64url/ },
    ];
    for (const c of cases) {
      const { context, page, errors } = await freshVisit(shared.browser, shared.site, c.hash, SMALL);
      await waitReady(page);
      assert.equal(await attr(page, 'data-landing'), null, `${c.hash.slice(0, 12)}: the gallery hid the link`);
      if (c.ops !== undefined) assert.equal(await attr(page, 'data-ops'), String(c.ops));
      if (c.error) assert.match(await attr(page, 'data-error') ?? '', c.error, `${c.hash.slice(0, 12)}: no error shown`);
      else assert.equal(await attr(page, 'data-error'), null);
      if (c.mode) assert.equal(await attr(page, 'data-mode'), c.mode);
      // The page stays usable: the gallery opens from the panel.
      await clickControl(page, 'gallery');
      await page.waitForFunction(() => document.body.dataset.landing === '1', null, { timeout: READY_MS });
      assert.deepEqual(errors, []);
      await context.close();
    }
  });

  /** Waits until the page holds `n` ops and shows the exact frame. */
  const waitFrame = async (page, n) => {
    await waitOps(page, n);
    await waitReady(page);
  };

  test('an edit survives a reload made at once, for every way in', async () => {
    const spec = { type: 'worley', frequency: 0.04, feature: 'f2', metric: 'euclidean', seed: 5, palette: 'ember' };
    // Each way in: the fragment of the first visit, and what brings the page to an
    // editable design of `n` ops.
    const ways = {
      link: { hash: linkFragment(GEL.design, 'gel-reload'), n: GEL.design.ops.length },
      card: { n: GEL.design.ops.length, go: (page) => clickControl(page, 'gallery-gel-git') },
      blank: { n: 0, go: (page) => clickControl(page, 'gallery-blank') },
      json: {
        n: GEL.design.ops.length,
        go: async (page) => {
          await clickControl(page, 'gallery-blank');
          await waitOps(page, 0);
          const [chooser] = await Promise.all([page.waitForEvent('filechooser', { timeout: READY_MS }), clickControl(page, 'open')]);
          await chooser.setFiles(GEL.file);
        },
      },
      picture: {
        n: 0,
        go: async (page) => {
          await clickControl(page, 'gallery-blank');
          await waitFrame(page, 0);
          const paper = await shootSheet(page, 300, 200);
          await dropFile(page, 'halves.png', 'image/png', twoColourPng());
          // The picture shows where the paper did.
          for (let t = Date.now(); differing(paper.img, (await shootSheet(page, 300, 200)).img, 24) < 0.05;) {
            assert.ok(Date.now() - t < READY_MS, 'the dropped picture never showed');
          }
        },
      },
      noise: {
        hash: noiseLink(spec),
        go: async (page) => {
          // The linked noise becomes the background of the design behind it.
          await page.waitForFunction(() => document.body.dataset.mode === 'noise', null, { timeout: READY_MS });
          await clickControl(page, 'noise-background');
          await clickControl(page, 'mode-marbling');
          await page.waitForFunction(() => document.body.dataset.mode === 'marbling', null, { timeout: READY_MS });
          return Number(await attr(page, 'data-ops'));
        },
      },
    };
    // The short tier: a link, a blank sheet and a noise link; the long one every way.
    for (const [way, w] of Object.entries(ways).filter(([way]) => LONG || ['link', 'blank', 'noise'].includes(way))) {
      // A small laptop's window keeps the three exact frames of each way cheap; the
      // gallery's card needs the whole gallery in view.
      const viewport = way === 'card' ? DESKTOP : SMALL;
      const { context, page, errors } = await freshVisit(shared.browser, shared.site, w.hash ?? '', viewport);
      if (!w.hash) await page.waitForFunction(() => document.body.dataset.landing === '1', null, { timeout: READY_MS });
      const n = (await w.go?.(page)) ?? w.n;
      await waitFrame(page, n);
      const before = await shootSheet(page, 300, 200);
      const s = await sheet(page);
      await page.keyboard.press('1'); // drop
      await page.mouse.click(s.x + 150 * s.scale, s.y + 120 * s.scale);
      await waitFrame(page, n + 1);
      const edited = await shootSheet(page, 300, 200);
      assert.ok(differing(before.img, edited.img, 24) > 0.001, `${way}: the drop changed nothing on screen`);
      await page.reload();
      await waitFrame(page, n + 1);
      assert.equal(await attr(page, 'data-landing'), null, `${way}: the reload landed on the gallery`);
      assert.equal(await attr(page, 'data-mode'), 'marbling', `${way}: the reload showed another mode`);
      const back = await shootSheet(page, 300, 200);
      // The side panel has one width whatever its content (the noise panel's too): the
      // sheet after the reload is the same size, drawn the same.
      assert.deepEqual([back.img.width, back.img.height], [edited.img.width, edited.img.height], `${way}: the view changed size across the reload`);
      const off = differing(edited.img, back.img, 24);
      assert.ok(off <= 0.01, `${way}: ${(100 * off).toFixed(2)} % of the sheet differs after the reload`);
      assert.deepEqual(errors, [], way);
      console.log(`${way}: ${n + 1} ops after the reload, ${(100 * off).toFixed(3)} % of the sheet differs`);
      await context.close();
    }
  });

  test('every Ctrl+Z counts, however fast they come', async () => {
    const { context, page, errors } = await firstVisit(linkFragment(GEL.design, 'gel-undo'));
    const n = GEL.design.ops.length;
    await waitOps(page, n);
    const s = await sheet(page);
    await page.keyboard.press('1');
    for (let k = 0; k < 6; k++) await page.mouse.click(s.x + (60 + 30 * k) * s.scale, s.y + 100 * s.scale);
    await waitOps(page, n + 6);
    // Six presses with no wait: a slow frame collects several.
    for (let k = 0; k < 6; k++) await page.keyboard.press('Control+z');
    await waitOps(page, n);
    await page.waitForTimeout(500);
    assert.equal(await attr(page, 'data-ops'), String(n));
    assert.deepEqual(errors, []);
    await context.close();
  });

  test('an Undo shows the state it returns to at once, never half of each', async () => {
    const { context, page, errors } = await firstVisit(linkFragment(GEL.design, 'gel-undo-look'));
    const { width: w, height: h } = GEL.design;
    const n = GEL.design.ops.length;
    const previewReady = () => page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: READY_MS });
    await waitOps(page, n);
    await previewReady();
    const s = await sheet(page);
    // A comb across the whole sheet: every row of the design moves.
    await page.keyboard.press('4');
    await page.mouse.move(s.x + 10 * s.scale, s.y + (h / 2) * s.scale);
    await page.mouse.down();
    for (let k = 1; k <= 12; k++) await page.mouse.move(s.x + (10 + k * (w - 20) / 12) * s.scale, s.y + (h / 2) * s.scale);
    await page.mouse.up();
    await waitOps(page, n + 1);
    await previewReady();
    const combed = await shootSheet(page, w, h);
    await page.keyboard.press('Control+z');
    await page.waitForFunction((k) => document.body.dataset.ops === String(k), n, { timeout: READY_MS });
    const drawing = await attr(page, 'data-progress');
    const dpr = await page.evaluate(() => devicePixelRatio);
    const device = (v, round) => round(v * dpr) / dpr;
    const clip = { x: device(s.x, Math.round), y: device(s.y, Math.round), width: device(w * s.scale, Math.floor), height: device(h * s.scale, Math.floor) };
    const undone = decode(await page.screenshot({ clip, timeout: READY_MS }));
    const after = await attr(page, 'data-progress');
    // The preview's sampling: its cache holds 2 × 2 samples per screen pixel (no
    // antialiasing), read back at the pixel's centre (their mean).
    const cpuFile = tmp('undo-look.png');
    execFileSync(MARBLING, ['render', GEL.file, '-o', cpuFile, '--scale', String(2 * s.scale * dpr), '--aa', 'none']);
    const cpu = halve(decode(fs.readFileSync(cpuFile)));
    // The exact frame's tiles (rgss, the app's antialiasing) replace the stand-in while
    // the shot is taken: a pixel shows the state it returns to when it matches either.
    const exactFile = tmp('undo-exact.png');
    execFileSync(MARBLING, ['render', GEL.file, '-o', exactFile, '--scale', String(s.scale * dpr)]);
    const exact = decode(fs.readFileSync(exactFile));
    const cw = Math.min(cpu.width, exact.width, undone.width, combed.img.width), ch = Math.min(cpu.height, exact.height, undone.height, combed.img.height);
    const off = differingFromBoth(crop(cpu, cw, ch), crop(exact, cw, ch), crop(undone, cw, ch), 48);
    const combOff = differingFromBoth(crop(cpu, cw, ch), crop(exact, cw, ch), crop(combed.img, cw, ch), 48);
    console.log(`right after Ctrl+Z (the exact frame drawn to ${drawing ?? '0'}, then ${after ?? 'done'} after the shot): ${(100 * off).toFixed(2)} % of ${cw}×${ch} px differ by > 48/255 from both CLI renders of the state before the comb (the preview's sampling and the exact frame's); the combed frame: ${(100 * combOff).toFixed(2)} %`);
    assert.ok(off <= 0.01, `${(100 * off).toFixed(2)} % of the sheet right after Undo is not the state it returns to`);
    // The comparator sees the comb.
    assert.ok(combOff > 0.3, `the comb changed only ${(100 * combOff).toFixed(2)} % of the sheet`);
    await waitOps(page, n);
    assert.deepEqual(errors, []);
    await context.close();
  });

  test('a panic keeps the design and says so; the reload shows it', async () => {
    const { context, page } = await firstVisit(linkFragment(GEL.design, 'gel-panic'));
    const n = GEL.design.ops.length;
    await waitOps(page, n);
    const s = await sheet(page);
    await page.keyboard.press('1');
    await page.mouse.click(s.x + 200 * s.scale, s.y + 100 * s.scale);
    await waitOps(page, n + 1);
    await page.evaluate(() => window.marblingPanic());
    await page.waitForFunction(() => document.body.dataset.panic !== undefined, null, { timeout: READY_MS });
    assert.match(await attr(page, 'data-error'), /Something broke; your design is kept/);
    assert.match(await page.textContent('#marbling-alert'), /your design is kept — reload/);
    assert.match(await attr(page, 'data-panic'), /window\.marblingPanic\(\) asked for a panic/);
    await page.reload();
    await waitOps(page, n + 1);
    assert.equal(await attr(page, 'data-error'), null);
    await context.close();
  });

  test('data-ready after a zoom means the exact frame of that view is on screen', () => readyAfterZoom(shared.browser, shared.site, 'webgl2'));
});

/** A decoded PNG at half its size, each pixel the mean of the 2 × 2 it stands for. */
/** The share of `img`'s pixels that differ from both `a` and `b` by more than `threshold`
 * in some channel. */
function differingFromBoth(a, b, img, threshold) {
  const far = (ref, i) => Math.max(...[0, 1, 2].map((c) => Math.abs(ref.data[i + c] - img.data[i + c]))) > threshold;
  let n = 0;
  for (let i = 0; i < img.data.length; i += 4) if (far(a, i) && far(b, i)) n++;
  return n / (img.width * img.height);
}

function halve(img) {
  const w = img.width >> 1, h = img.height >> 1;
  const out = new PNG({ width: w, height: h });
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      for (let c = 0; c < 4; c++) {
        let sum = 0;
        for (const [dx, dy] of [[0, 0], [1, 0], [0, 1], [1, 1]]) sum += img.data[((2 * y + dy) * img.width + 2 * x + dx) * 4 + c];
        out.data[(y * w + x) * 4 + c] = Math.round(sum / 4);
      }
    }
  }
  return out;
}

/** A fresh profile (no autosave: a first visit) at `hash`, with its page errors. */
async function freshVisit(browser, site, hash, viewport = DESKTOP) {
  const context = await browser.newContext({ viewport, deviceScaleFactor: 1, acceptDownloads: true, serviceWorkers: 'block' });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${site.url}${hash}`);
  return { context, page, errors };
}

/** Zooms out on a design opened by link; at `data-ready` the screenshot must be the
 * CLI's render at the shown scale (and not the one before the zoom). */
async function readyAfterZoom(browser, site, backend) {
  const { context, page, errors } = await freshVisit(browser, site, linkFragment(GEL.design, `gel-zoom-${backend}`));
  const { width: w, height: h } = GEL.design;
  await waitOps(page, GEL.design.ops.length);
  const before = await sheet(page);
  // Zoom out about the sheet's middle: the whole sheet stays on screen.
  await page.mouse.move(before.x + (w / 2) * before.scale, before.y + (h / 2) * before.scale);
  await page.mouse.wheel(0, 300);
  // A new view: ready falls until its exact frame is drawn.
  await page.waitForFunction((scale) => Number(document.body.dataset.view.split(',')[2]) < scale, before.scale, { timeout: READY_MS });
  await waitReady(page);
  const shot = await shootSheet(page, w, h);
  assert.ok(shot.scale < before.scale * 0.95, `the view did not zoom out (${before.scale} → ${shot.scale})`);
  const cpuFile = tmp(`zoom-${backend}.png`);
  execFileSync(MARBLING, ['render', GEL.file, '-o', cpuFile, '--scale', String(shot.scale), '--aa', 'rgss']);
  const cpu = decode(fs.readFileSync(cpuFile));
  const cw = Math.min(cpu.width, shot.img.width), ch = Math.min(cpu.height, shot.img.height);
  const off = differing(crop(cpu, cw, ch), crop(shot.img, cw, ch), 24);
  console.log(`${backend}: data-ready after a zoom to ${shot.scale.toFixed(3)}: ${(100 * off).toFixed(2)} % of ${cw}×${ch} px differ from the CLI render by > 24/255`);
  assert.ok(off <= 0.01, `${(100 * off).toFixed(2)} % of the zoomed view differs from the CLI render`);
  // The comparator sees a wrong scale: the render before the zoom differs.
  const wrongFile = tmp(`zoom-wrong-${backend}.png`);
  execFileSync(MARBLING, ['render', GEL.file, '-o', wrongFile, '--scale', String(before.scale), '--aa', 'rgss']);
  assert.ok(differing(crop(decode(fs.readFileSync(wrongFile)), cw, ch), crop(shot.img, cw, ch), 24) > 0.05);
  assert.deepEqual(errors, []);
  await context.close();
}

/** A drop pulled by a tine through its rim point (80, 40): the rim comes to a tip at
 * (100, 40), where a view a million times deep still shows ink and paper. */
const TIP = {
  version: 1, width: 120, height: 80, background: '#f3ead7',
  ops: [
    { type: 'drop', center: [60, 40], radius: 20, color: '#1d3557' },
    { type: 'tine', origin: [0, 40], direction: [1, 0], alpha: 20, lambda: 5 },
  ],
};

/** A link holding a view 10⁶× deep (`&v=x,y,zoom`) on a first visit: at data-ready the
 * middle of the canvas is `marbling render --view` of the same window; again after a
 * pan at that depth. */
async function deepLink(browser, site, backend) {
  const hash = `${linkFragment(TIP, `tip-${backend}`)}&v=99.99999,40.00002,1000000`;
  const { context, page, errors } = await freshVisit(browser, site, hash, SMALL);
  await waitOps(page, TIP.ops.length);
  const status = await attr(page, 'data-status');
  assert.ok(status.includes('zoom 1000000×'), status);
  await page.mouse.move(2, 2);
  await page.waitForTimeout(300);
  await waitReady(page);
  const first = await sheet(page);
  // A 150×100 CSS px box (the design's 3:2) on the page, centred on the link's point.
  const [cx, cy] = [first.x + 99.99999 * first.scale, first.y + 40.00002 * first.scale];
  const clip = { x: Math.round(cx - 75), y: Math.round(cy - 50), width: 150, height: 100 };
  const render = (name, view) => {
    const file = tmp(name);
    fs.writeFileSync(`${file}.json`, JSON.stringify(TIP));
    execFileSync(MARBLING, ['render', `${file}.json`, '-o', file, '--view', view, '--width', '150']);
    return decode(fs.readFileSync(file));
  };
  /** The box's screenshot against the CLI's render of the window it shows now. */
  const check = async (what) => {
    const s = await sheet(page);
    const shot = decode(await page.screenshot({ clip, timeout: READY_MS }));
    const [x0, y0] = [(clip.x - s.x) / s.scale, (clip.y - s.y) / s.scale];
    const centre = (x, y) => `${x + 75 / s.scale},${y + 50 / s.scale},${s.scale}`;
    const cpu = render(`deep-${what}-${backend}.png`, centre(x0, y0));
    const off = differing(cpu, shot, 24);
    console.log(`${backend}: 10⁶× deep, ${what}: ${(100 * off).toFixed(2)} % of 150×100 px differ from marbling render --view`);
    assert.ok(off <= 0.01, `${what}: ${(100 * off).toFixed(2)} % of the deep view differs from the CLI render`);
    const colours = new Set();
    for (let i = 0; i < shot.data.length; i += 4) colours.add(shot.data.readUInt32BE(i));
    assert.ok(colours.size > 2, `${what}: the deep view shows one colour`);
    // The comparator sees a window 20 pixels aside (twice the budget at least).
    const aside = render(`deep-aside-${what}-${backend}.png`, centre(x0 + 20 / s.scale, y0));
    const apart = differing(aside, shot, 24);
    assert.ok(apart > 0.02, `${what}: a window 20 px aside should differ, ${(100 * apart).toFixed(2)} %`);
    return shot;
  };
  fs.writeFileSync(path.join(SHOTS, 'deep-link.png'), PNG.sync.write(await check('the link')));
  // Pan by a middle-button drag: 40 px left, 10 down; the new frame is exact too.
  await page.mouse.move(cx, cy);
  await page.mouse.down({ button: 'middle' });
  await page.mouse.move(cx - 40, cy + 10, { steps: 4 });
  await page.mouse.up({ button: 'middle' });
  await page.mouse.move(2, 2);
  await page.waitForFunction((x) => Number(document.body.dataset.view.split(',')[0]) < x - 30, first.x, { timeout: READY_MS });
  await waitReady(page);
  await check('after a pan');
  // The status bar's Zoom to box: a bad view is said and the box stays; a good one is
  // centred at its zoom, exact too.
  const type = async (text) => {
    await clickControl(page, 'zoom-to-text');
    await page.keyboard.press('Control+a');
    await page.keyboard.type(text);
    await page.keyboard.press('Enter');
  };
  await clickControl(page, 'zoom-to');
  await page.waitForFunction(() => /(^|;)zoom-to-text=/.test(document.body.dataset.controls ?? ''), null, { timeout: READY_MS });
  await type('99.99999, 40.00002, 0');
  await page.waitForFunction(() => /Zoom to: .*scale/.test(document.body.dataset.status ?? ''), null, { timeout: READY_MS });
  const box = await controls(page);
  assert.ok(box['zoom-to-text'], 'the box closed on a bad view');
  // A small laptop's status bar keeps Go and Close on screen.
  for (const name of ['zoom-to-go', 'zoom-to-close']) assert.ok(box[name] && box[name].x + box[name].w <= SMALL.width, `${name} is off the screen`);
  await page.screenshot({ path: path.join(SHOTS, `zoom-to-${backend}.png`), timeout: READY_MS });
  await type('99.99999, 40.00002, 500000');
  await page.waitForFunction(() => (document.body.dataset.status ?? '').includes('zoom 500000×'), null, { timeout: READY_MS });
  assert.equal((await controls(page))['zoom-to-text'], undefined, 'the box stayed open after a good view');
  await page.mouse.move(2, 2);
  await waitReady(page);
  await check('zoomed to 500000×');
  assert.deepEqual(errors, []);
  await context.close();
}

describe('data-ready on webgpu', () => {
  const shared = sharedBrowser('webgpu');
  test('data-ready after a zoom means the exact frame of that view is on screen', () => readyAfterZoom(shared.browser, shared.site, 'webgpu'));
  test('a link 10⁶× deep shows the exact window the CLI renders', () => deepLink(shared.browser, shared.site, 'webgpu'));
});
