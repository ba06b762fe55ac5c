// The playground's files, exports, history playback and navigation, end to end in
// Chromium on WebGPU and WebGL2 (SwiftShader): buttons are clicked where the app says it
// drew them (data-controls), downloads and file choosers are the browser's own.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { PNG } from 'pngjs';
import zlib from 'node:zlib';
import {
  BACKENDS, DESKTOP, MARBLING, longOnly, READY_MS, SHOTS, attr, clickControl, controls, crop, decode, differing, download, example,
  launch, openPage, sheet, shootSheet, waitOps, waitReady,
} from './harness.mjs';

const STONE = example('stone');
const GEL = example('gel-git');
const tmp = (name) => path.join(os.tmpdir(), `marbling-${process.pid}-${name}`);

/** Renders `file` with the CLI at `scale` (rgss, as the app) and decodes it. */
function cliRender(file, scale, name) {
  const out = tmp(name);
  execFileSync(MARBLING, ['render', file, '-o', out, '--scale', String(scale), '--aa', 'rgss']);
  return decode(fs.readFileSync(out));
}

/** The pixels per metre of a PNG's `pHYs` chunk (unit metre), or null. */
function pixelsPerMetre(bytes) {
  const at = bytes.indexOf('pHYs', 8, 'latin1');
  if (at < 0) return null;
  assert.equal(bytes[at + 12], 1, 'pHYs unit is the metre');
  return bytes.readUInt32BE(at + 4);
}

/** The `x, y` window of `w × h` pixels of a decoded PNG. */
function window(img, x, y, w, h) {
  const out = new PNG({ width: w, height: h });
  for (let r = 0; r < h; r++) img.data.copy(out.data, r * w * 4, ((y + r) * img.width + x) * 4, ((y + r) * img.width + x + w) * 4);
  return out;
}

/** Waits until `data-view` stops changing and the exact frame is on screen. */
async function settle(page) {
  let last = '';
  for (let i = 0; i < 400; i++) {
    await page.waitForTimeout(250);
    const now = await attr(page, 'data-view');
    if (now === last && (await attr(page, 'data-ready')) === '1') return;
    last = now;
  }
  throw new Error('the view never settled');
}

for (const backend of Object.keys(BACKENDS)) {
  describe(`files, exports, playback and navigation on ${backend}`, () => {
    let browser;
    let site;
    before(async () => {
      ({ browser, site } = await launch(backend));
    });
    after(async () => {
      await browser?.close();
      site?.server.close();
    });
    // SwiftShader is slow: the UI features run on WebGL2 only; WebGPU runs the export
    // (its own read-back path) besides the load, tool, link, autosave, device-loss and
    // drag tests of the other files.
    const webgl2Only = backend === 'webgpu' ? { skip: 'UI features are tested on webgl2' } : {};

    test('Save JSON downloads the design; Open loads a file; a bad file keeps the design', webgl2Only, async () => {
      const { page, context, errors } = await openPage(browser, site);
      const saved = await download(page, 'save-json');
      assert.equal(saved.name, 'design.json');
      assert.deepEqual(JSON.parse(saved.bytes.toString('utf8')), STONE.design);

      const [chooser] = await Promise.all([page.waitForEvent('filechooser', { timeout: READY_MS }), clickControl(page, 'open')]);
      await chooser.setFiles(GEL.file);
      await waitOps(page, GEL.design.ops.length);
      assert.equal(await attr(page, 'data-error'), null);

      const bad = tmp('bad.json');
      const broken = structuredClone(STONE.design);
      broken.ops[3].radii[0] = -2;
      fs.writeFileSync(bad, JSON.stringify(broken));
      const [again] = await Promise.all([page.waitForEvent('filechooser', { timeout: READY_MS }), clickControl(page, 'open')]);
      await again.setFiles(bad);
      await page.waitForFunction(() => document.body.dataset.error !== undefined, null, { timeout: READY_MS });
      assert.match(await attr(page, 'data-error'), /ops\[3\]\.radii\[0\]: must be > 0/);
      assert.equal(await attr(page, 'data-ops'), String(GEL.design.ops.length), 'the current design was lost');

      // Palettes: a .gpl imported becomes the palette, its first colour the ink.
      const inks = async () => Object.keys(await controls(page)).filter((n) => /^ink-\d+$/.test(n)).length;
      // The swatches of the palette, once a frame has drawn them.
      const swatches = (n) => page.waitForFunction((k) => (document.body.dataset.controls ?? '').split(';').filter((c) => /^ink-\d+=/.test(c)).length === k, n, { timeout: READY_MS });
      const status = (re) => page.waitForFunction((s) => new RegExp(s).test(document.body.dataset.status ?? ''), re.source, { timeout: READY_MS });
      const gpl = tmp('Ebru.gpl');
      fs.writeFileSync(gpl, 'GIMP Palette\nName: Ebru\nColumns: 3\n#\n 29  53  87\tIndigo\n230  57  70 Red\n244 236 216 Paper\n');
      const [pick] = await Promise.all([page.waitForEvent('filechooser', { timeout: READY_MS }), clickControl(page, 'palette-import')]);
      await pick.setFiles(gpl);
      await status(/palette Ebru of 3 colours/);
      await swatches(3);
      fs.mkdirSync(SHOTS, { recursive: true });
      await page.screenshot({ path: path.join(SHOTS, 'palette-import.png'), timeout: READY_MS });
      // Save .gpl writes what `marbling palette` makes of the same file.
      const savedGpl = await download(page, 'palette-save');
      assert.equal(savedGpl.name, 'Ebru.gpl');
      assert.equal(savedGpl.bytes.toString('utf8'), execFileSync(MARBLING, ['palette', gpl]).toString());
      // A drop takes the palette's first colour.
      const s = await sheet(page);
      await page.mouse.click(s.x + 100 * s.scale, s.y + 100 * s.scale);
      await waitOps(page, GEL.design.ops.length + 1);
      const dropped = JSON.parse((await download(page, 'save-json')).bytes.toString('utf8'));
      assert.equal(dropped.ops.at(-1).color, '#1d3557');
      // A bad palette file is named with its line and keeps the palette.
      const badGpl = tmp('bad.gpl');
      fs.writeFileSync(badGpl, 'GIMP Palette\nName: x\n10 20 30\n300 0 0 Too red\n');
      const [pick2] = await Promise.all([page.waitForEvent('filechooser', { timeout: READY_MS }), clickControl(page, 'palette-import')]);
      await pick2.setFiles(badGpl);
      await page.waitForFunction(() => /bad\.gpl: line 4: expected three numbers 0–255/.test(document.body.dataset.error ?? ''), null, { timeout: READY_MS });
      const frames = Number(await attr(page, 'data-frames'));
      await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, frames + 2, { timeout: READY_MS });
      assert.equal(await inks(), 3, 'a bad file changed the palette');
      // Hex colours typed into the field and Enter.
      await clickControl(page, 'palette-hex');
      await page.keyboard.type('#112233, #445566');
      await page.keyboard.press('Enter');
      await status(/palette of 2 pasted colours/);
      await swatches(2);
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('A first visit lands on the gallery: prerendered thumbnails, a pattern opens, a blank sheet', webgl2Only, async () => {
      const context = await browser.newContext({ viewport: DESKTOP, deviceScaleFactor: 1, acceptDownloads: true });
      const page = await context.newPage();
      const errors = [];
      page.on('pageerror', (e) => errors.push(String(e)));
      await page.goto(site.url);
      await page.waitForFunction(() => document.body.dataset.landing === '1', null, { timeout: READY_MS });
      // Every card shows its thumbnail from the prerendered atlas.
      await page.waitForFunction(() => document.body.dataset.thumbnails === '27/27', null, { timeout: READY_MS });
      assert.equal(await attr(page, 'data-thumbnails-from'), 'atlas');
      assert.equal(await attr(page, 'data-ready'), null, 'no canvas behind the gallery');
      const all = await controls(page);
      for (const id of ['gallery-blank', 'gallery-stone', 'gallery-chevron', 'gallery-hearts', 'gallery-close']) assert.ok(all[id], `no ${id}`);
      // The stone card shows the stone pattern: the thumbnail against the CPU render.
      const c = all['gallery-stone'];
      const shot = decode(await page.screenshot({ clip: { x: c.x, y: c.y, width: c.w, height: c.h }, timeout: READY_MS }));
      const cpu = tmp(`stone-thumb-${backend}.png`);
      execFileSync(MARBLING, ['render', STONE.file, '-o', cpu, '--width', String(c.w), '--aa', 'rgss']);
      const frac = differing(crop(decode(fs.readFileSync(cpu)), c.w, c.h), crop(shot, c.w, c.h), 64);
      console.log(`${backend}: gallery thumbnail vs CLI render: ${(100 * frac).toFixed(2)} % of ${c.w}×${c.h} px differ by > 64/255`);
      assert.ok(frac <= 0.03, `${(100 * frac).toFixed(2)} % of the thumbnail differs from the pattern`);
      fs.mkdirSync(SHOTS, { recursive: true });
      await page.screenshot({ path: path.join(SHOTS, 'gallery.png'), timeout: READY_MS });

      const chevron = example('chevron');
      await clickControl(page, 'gallery-chevron');
      await waitOps(page, chevron.design.ops.length);
      assert.equal(await attr(page, 'data-landing'), null);
      const saved = await download(page, 'save-json');
      assert.deepEqual(JSON.parse(saved.bytes.toString('utf8')), chevron.design, 'the pattern opens as its recipe');
      await clickControl(page, 'gallery');
      await page.waitForFunction(() => document.body.dataset.landing === '1', null, { timeout: READY_MS });
      await clickControl(page, 'gallery-blank');
      await waitOps(page, 0);
      await page.keyboard.press('Control+z');
      await waitOps(page, chevron.design.ops.length);
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('Export PNG at 2× equals `marbling render --scale 2`', backend === 'webgl2' ? longOnly : {}, async () => {
      const { page, context, errors } = await openPage(browser, site);
      await clickControl(page, 'export-size-2x');
      const png = await download(page, 'export-png');
      const w = STONE.design.width * 2;
      const h = STONE.design.height * 2;
      assert.equal(png.name, `marbling-${STONE.design.ops.length}ops-${w}x${h}.png`);
      const img = decode(png.bytes);
      assert.deepEqual([img.width, img.height], [w, h]);
      const cpu = cliRender(STONE.file, 2, `export-${backend}.png`);
      const frac = differing(cpu, img, 24);
      console.log(`${backend}: Export PNG 2× vs CLI: ${(100 * frac).toFixed(3)} % of ${w}×${h} px differ by > 24/255`);
      assert.ok(frac <= 0.01, `${(100 * frac).toFixed(2)} % of pixels differ`);
      assert.equal(await attr(page, 'data-exporting'), null);
      if (backend === 'webgl2') {
        // Export for print: A4 (turned to the landscape design) at 150 DPI with the
        // 3 mm bleed: 297 mm / 25.4 × 150 = 1754 + 2 × 18 px; the DPI in pHYs; the pixels
        // those of `marbling render --print A4 --dpi 150 --bleed 3mm`.
        await clickControl(page, 'print');
        await clickControl(page, 'print-a4');
        await clickControl(page, 'print-dpi-150');
        fs.mkdirSync(SHOTS, { recursive: true });
        await page.screenshot({ path: path.join(SHOTS, 'print-panel.png'), timeout: READY_MS });
        const print = await download(page, 'print-export');
        assert.equal(print.name, `marbling-${STONE.design.ops.length}ops-297x210mm-150dpi.png`);
        const img = decode(print.bytes);
        assert.deepEqual([img.width, img.height], [1790, 1276]);
        assert.equal(pixelsPerMetre(print.bytes), 5906, '150 DPI = 5906 px/m in pHYs');
        const cli = tmp('print-a4.png');
        execFileSync(MARBLING, ['render', STONE.file, '-o', cli, '--print', 'A4', '--dpi', '150', '--bleed', '3mm']);
        const cpu = decode(fs.readFileSync(cli));
        const off = differing(cpu, img, 24);
        console.log(`${backend}: Export for print A4 150 DPI vs CLI --print: ${(100 * off).toFixed(3)} % of 1790×1276 px differ by > 24/255`);
        assert.ok(off <= 0.01, `${(100 * off).toFixed(2)} % of the print differs from the CLI's`);
      }
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('Export SVG downloads what `marbling svg` writes', webgl2Only, async () => {
      const { page, context, errors } = await openPage(browser, site);
      // The trace runs a frame's budget at a time: the page draws while it runs and
      // shows how far it got, and Cancel stops it without a file.
      let files = 0;
      page.on('download', () => files++);
      await clickControl(page, 'export-svg');
      await page.waitForFunction(() => /^svg \d+%$/.test(document.body.dataset.exporting ?? ''), null, { timeout: READY_MS });
      const frames = Number(await attr(page, 'data-frames'));
      await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, frames + 2, { timeout: READY_MS });
      assert.match(await attr(page, 'data-exporting') ?? '', /^svg \d+%$/, 'the trace ended within three frames: nothing was spread out');
      await clickControl(page, 'export-cancel');
      await page.waitForFunction(() => document.body.dataset.exporting === undefined, null, { timeout: READY_MS });
      await page.waitForTimeout(500);
      assert.equal(files, 0, 'a cancelled export still offered its file');
      const svg = await download(page, 'export-svg');
      assert.equal(svg.name, `marbling-${STONE.design.ops.length}ops-${STONE.design.width}x${STONE.design.height}.svg`);
      const out = tmp(`stone-${backend}.svg`);
      execFileSync(MARBLING, ['svg', STONE.file, '-o', out]);
      assert.ok(svg.bytes.equals(fs.readFileSync(out)), 'the app and the CLI wrote different SVGs');
      assert.match(svg.bytes.toString('utf8', 0, 200), /<svg /);
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('The step player: captions, scrubbing to step k shows k steps, the end is the design, explain', webgl2Only, async () => {
      // Chevron at 320×200 in a small window keeps SwiftShader's exact frames cheap.
      const file = tmp(`chevron-small-${backend}.json`);
      execFileSync(MARBLING, ['pattern', 'chevron', '--size', '320x200', '-o', file]);
      const d = JSON.parse(fs.readFileSync(file, 'utf8'));
      const steps = d.recipe.captions.length;
      const link = execFileSync(MARBLING, ['link', file, '--base', site.url]).toString().trim();
      const { page, context, errors } = await openPage(browser, site, link.slice(link.indexOf('#')), { width: 900, height: 600 });
      await clickControl(page, 'play');
      await page.waitForFunction(() => /^0\.\d+\//.test(document.body.dataset.player ?? ''), null, { timeout: READY_MS });
      await clickControl(page, 'player-play');
      await waitReady(page);
      const positionIs = (v) => page.waitForFunction((want) => document.body.dataset.player === want && document.body.dataset.ready === '1', v, { timeout: READY_MS });
      const sheetVsCli = async (k, name) => {
        const shot = await shootSheet(page, d.width, d.height);
        const out = tmp(`${name}-${backend}.png`);
        execFileSync(MARBLING, ['render', file, '-o', out, '--scale', String(shot.scale), '--aa', 'rgss', '--steps', String(k)]);
        const cpu = decode(fs.readFileSync(out));
        const w = Math.min(cpu.width, shot.img.width);
        const h = Math.min(cpu.height, shot.img.height);
        const frac = differing(crop(cpu, w, h), crop(shot.img, w, h), 24);
        console.log(`${backend}: player at ${k} of ${steps} steps vs \`render --steps ${k}\`: ${(100 * frac).toFixed(3)} % differ by > 24/255`);
        assert.ok(frac <= 0.01, `${(100 * frac).toFixed(2)} % of pixels differ at step ${k}`);
      };
      // Scrub: a click on the timeline's tick 2 shows the first two steps.
      const tl = (await controls(page))['player-timeline'];
      await page.mouse.click(tl.x + (tl.w * 2) / steps, tl.y + tl.h / 2);
      await positionIs(`2/${steps}`);
      await sheetVsCli(2, 'step2');
      // Step forward once, then the last tick: the player's last frame is the design.
      await clickControl(page, 'player-forward');
      await positionIs(`3/${steps}`);
      await page.mouse.click(tl.x + tl.w - 1, tl.y + tl.h / 2);
      await positionIs(`${steps}/${steps}`);
      await sheetVsCli(steps, 'end');
      // Explain: the last step's formula with its numbers, the grid and the probe.
      await clickControl(page, 'player-explain');
      await page.waitForTimeout(500);
      await page.screenshot({ path: path.join(SHOTS, 'player-explain.png'), timeout: READY_MS });
      // Record films the making from the first step (MediaRecorder on the canvas);
      // stopping it downloads the WebM. The row keeps its place meanwhile (Close stays
      // under the pointer).
      const closeAt = async () => JSON.stringify((await controls(page))['player-close']);
      const closeBefore = await closeAt();
      await clickControl(page, 'player-record');
      await page.waitForFunction(() => /^0\.\d+\//.test(document.body.dataset.player ?? ''), null, { timeout: READY_MS });
      await page.waitForTimeout(1500);
      assert.equal(await closeAt(), closeBefore, 'Close moved when the recording started');
      const video = await download(page, 'player-record');
      await page.waitForTimeout(300);
      assert.equal(await closeAt(), closeBefore, 'Close moved when the recording stopped');
      assert.match(video.name, /^marbling-\d+ops-320x200\.webm$/);
      assert.ok(video.bytes.length > 1000 && video.bytes.readUInt32BE(0) === 0x1a45dfa3, `not a WebM (${video.bytes.length} bytes)`);
      // A looping recording (reverse on, the 1 s hold, the speed at its top): the making,
      // the finished design held, then the making backwards; the video downloads by
      // itself back on the bare tank.
      await page.waitForFunction(() => /(^|;)player-reverse=/.test(document.body.dataset.controls ?? ''), null, { timeout: READY_MS });
      await clickControl(page, 'player-reverse');
      const speed = (await controls(page))['player-speed'];
      // The control's rectangle holds the rail (egui's 100-point slider width), the
      // value and the unit: the click goes near the rail's right end.
      await page.mouse.click(speed.x + 96, speed.y + speed.h / 2);
      let looped = null;
      const loopDownload = page.waitForEvent('download', { timeout: READY_MS }).then((d) => { looped = d; });
      await clickControl(page, 'player-record');
      const seen = [];
      while (!looped) {
        seen.push([Date.now(), await attr(page, 'data-player')]);
        await Promise.race([loopDownload, page.waitForTimeout(100)]);
      }
      const at = (v) => Number((v ?? '-1/').split('/')[0]);
      const first = seen.findIndex(([, v]) => at(v) === steps);
      const last = seen.findLastIndex(([, v]) => at(v) === steps);
      assert.ok(first >= 0, `the loop never reached the end: ${seen.map(([, v]) => v).join(' ')}`);
      assert.ok(seen[last][0] - seen[first][0] >= 800, `the finished design was held ${seen[last][0] - seen[first][0]} ms, not 1 s`);
      assert.ok(seen.slice(last).some(([, v]) => at(v) > 0 && at(v) < steps), `the making was not played backwards: ${[...new Set(seen.map(([, v]) => v))].join(" ")}`);
      assert.equal(at(await attr(page, 'data-player')), 0, 'the loop ended away from the bare tank');
      const loopFile = fs.readFileSync(await looped.path());
      assert.ok(loopFile.length > 1000 && loopFile.readUInt32BE(0) === 0x1a45dfa3, `the loop is not a WebM (${loopFile.length} bytes)`);
      await clickControl(page, 'player-close');
      await page.waitForFunction(() => document.body.dataset.player === undefined, null, { timeout: READY_MS });
      await waitOps(page, d.ops.length);
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('wheel zoom renders exactly at the new scale; a middle drag pans', webgl2Only, async () => {
      const { page, context, errors } = await openPage(browser, site);
      const fit = await sheet(page);
      const c = (await controls(page)).canvas;
      const at = { x: fit.x + 200 * fit.scale, y: fit.y + 150 * fit.scale };
      await page.mouse.move(at.x, at.y);
      for (let i = 0; i < 4; i++) await page.mouse.wheel(0, -120);
      await settle(page);
      const zoomed = await sheet(page);
      assert.ok(zoomed.scale > 1.5 * fit.scale, `zoom went from ${fit.scale} to ${zoomed.scale}`);
      // The canvas region inside the sheet, compared with a CLI render at that scale.
      const x0 = Math.ceil(Math.max(c.x + 2, zoomed.x));
      const y0 = Math.ceil(Math.max(c.y + 2, zoomed.y));
      const x1 = Math.floor(Math.min(c.x + c.w - 2, zoomed.x + STONE.design.width * zoomed.scale));
      const y1 = Math.floor(Math.min(c.y + c.h - 2, zoomed.y + STONE.design.height * zoomed.scale));
      await page.mouse.move(2, 2);
      await page.waitForTimeout(300);
      const shot = decode(await page.screenshot({ clip: { x: x0, y: y0, width: x1 - x0, height: y1 - y0 }, timeout: READY_MS }));
      const cpu = cliRender(STONE.file, zoomed.scale, `zoom-${backend}.png`);
      const ox = Math.round(x0 - zoomed.x);
      const oy = Math.round(y0 - zoomed.y);
      const frac = differing(window(cpu, ox, oy, x1 - x0, y1 - y0), shot, 24);
      console.log(`${backend}: zoomed ×${(zoomed.scale / fit.scale).toFixed(2)} vs CLI at scale ${zoomed.scale.toFixed(4)}: ${(100 * frac).toFixed(3)} % differ`);
      assert.ok(frac <= 0.01, `${(100 * frac).toFixed(2)} % of pixels differ at zoom`);
      await page.screenshot({ path: path.join(SHOTS, `zoomed-${backend}.png`), timeout: READY_MS });

      await page.mouse.move(c.x + c.w / 2, c.y + c.h / 2);
      await page.mouse.down({ button: 'middle' });
      for (let i = 1; i <= 10; i++) await page.mouse.move(c.x + c.w / 2 + 6 * i, c.y + c.h / 2 + 4 * i);
      await page.mouse.up({ button: 'middle' });
      await settle(page);
      const panned = await sheet(page);
      // The sheet follows the drag (egui starts a drag after a few pixels, so the first
      // pixels of the movement may not count).
      const dx = panned.x - zoomed.x;
      const dy = panned.y - zoomed.y;
      assert.ok(dx >= 30 && dx <= 61 && Math.abs(dx * 40 - dy * 60) <= 60, `pan moved the sheet by ${dx}, ${dy}`);
      assert.equal(panned.scale, zoomed.scale);
      assert.equal(await attr(page, 'data-ops'), String(STONE.design.ops.length), 'navigation changed the design');
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('the Noise panel shows the noise on the canvas and marbles it into the design', async () => {
      const { page, context, errors } = await openPage(browser, site);
      const n = STONE.design.ops.length;
      const before = await shootSheet(page, STONE.design.width, STONE.design.height);
      await clickControl(page, 'mode-noise');
      await page.waitForFunction(() => document.body.dataset.mode === 'noise' && document.body.dataset.ops === '0' && document.body.dataset.ready === '1', null, { timeout: READY_MS });
      const noise = await shootSheet(page, STONE.design.width, STONE.design.height);
      assert.ok(differing(before.img, noise.img, 24) > 0.5, 'the canvas does not show the noise');
      // The status line names the noise, not the (empty) op count.
      const status = await attr(page, 'data-status');
      assert.match(status, / · perlin noise · /);
      assert.doesNotMatch(status, /\bops\b/);
      await page.screenshot({ path: path.join(SHOTS, `noise-panel-${backend}.png`), timeout: READY_MS });
      await clickControl(page, 'noise-background');
      await page.waitForFunction((k) => document.body.dataset.mode === 'marbling' && document.body.dataset.ops === String(k) && document.body.dataset.ready === '1', n, { timeout: READY_MS });
      const marbled = await shootSheet(page, STONE.design.width, STONE.design.height);
      const changed = differing(before.img, marbled.img, 24);
      assert.ok(changed > 0.05, `the background did not change (${(100 * changed).toFixed(1)} %)`);
      await page.screenshot({ path: path.join(SHOTS, `noise-marbled-${backend}.png`), timeout: READY_MS });
      assert.match(await attr(page, 'data-status'), new RegExp(` · ${n} ops · `));
      // The design now carries the noise: Save JSON writes it (version 3: the stone
      // pattern's drop sets are v3 ops; a noise background needs at least 2).
      const saved = JSON.parse((await download(page, 'save-json')).bytes.toString('utf8'));
      assert.equal(saved.version, 3);
      assert.equal(saved.background.noise.type, 'perlin');
      assert.equal(saved.ops.length, n);
      assert.deepEqual(errors, []);
      await context.close();
    });

    // One backend is enough: links and storage do not touch the GPU.
    test('a #n= link opens the Noise tab, a broken one keeps it, and the setup survives a reload', { skip: backend !== 'webgpu' }, async () => {
      // Encoded as the app encodes it: raw DEFLATE, base64url without padding.
      const spec = { type: 'worley', frequency: 0.04, feature: 'f2', metric: 'euclidean', seed: 5, palette: 'ember' };
      const link = `#n=${zlib.deflateRawSync(Buffer.from(JSON.stringify(spec))).toString('base64url')}`;
      const { page, context, errors } = await openPage(browser, site, link);
      await page.waitForFunction(() => document.body.dataset.mode === 'noise' && document.body.dataset.ready === '1', null, { timeout: READY_MS });
      const opened = JSON.parse(await attr(page, 'data-noise'));
      for (const [k, v] of Object.entries(spec)) assert.equal(opened[k], v, `${k} of the opened spec`);
      assert.equal(await attr(page, 'data-error'), null);
      await page.evaluate(() => { window.location.hash = '#n=@@not-base64'; });
      await page.waitForFunction(() => document.body.dataset.error !== undefined, null, { timeout: READY_MS });
      assert.match(await attr(page, 'data-error'), /^share link: not valid base64url/);
      assert.equal(await attr(page, 'data-mode'), 'noise');
      assert.deepEqual(JSON.parse(await attr(page, 'data-noise')), opened, 'a broken link changed the noise');
      // A reload without the link restores the setup from storage.
      await page.waitForTimeout(1500);
      await page.goto(`${site.url}?landing=0`);
      await waitReady(page);
      assert.deepEqual(JSON.parse(await attr(page, 'data-noise')), opened, 'the noise setup was not kept');
      // The threshold transfer from the panel goes into the spec.
      await clickControl(page, 'mode-noise');
      await page.waitForFunction(() => document.body.dataset.mode === 'noise', null, { timeout: READY_MS });
      await clickControl(page, 'noise-threshold');
      await page.waitForFunction(() => JSON.parse(document.body.dataset.noise).transfer?.type === 'threshold', null, { timeout: READY_MS });
      assert.deepEqual(JSON.parse(await attr(page, 'data-noise')).transfer, { type: 'threshold', threshold: 0, width: 0.5, invert: false });
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('phasor noise from a link on the canvas, its relief lit on the plane, and a 16-bit normal map', backend === 'webgpu' ? longOnly : { skip: true }, async () => {
      const link = (spec) => `#n=${zlib.deflateRawSync(Buffer.from(JSON.stringify(spec))).toString('base64url')}`;
      const phasor = { type: 'phasor', profile: 'square', frequency: 0.04, orientation: 0.5, bandwidth: 0.02, impulses: 3, seed: 5 };
      // Three kernels per point and a small page: SwiftShader draws the phasor in ~10 s.
      const { page, context, errors } = await openPage(browser, site, link(phasor), { width: 1000, height: 1000 });
      await page.waitForFunction(() => document.body.dataset.mode === 'noise' && document.body.dataset.ready === '1', null, { timeout: READY_MS });
      assert.equal(JSON.parse(await attr(page, 'data-noise')).profile, 'square');
      // The GPU draws the square profile: two levels, about half each (not a blank sheet).
      const shot = await shootSheet(page, STONE.design.width, STONE.design.height);
      let dark = 0;
      for (let i = 0; i < shot.img.data.length; i += 4) dark += shot.img.data[i] < 128 ? 1 : 0;
      const share = dark / (shot.img.data.length / 4);
      assert.ok(share > 0.2 && share < 0.8, `dark share ${share.toFixed(3)}`);
      // A normal map chosen: the relief view lights the noise on the plane.
      await clickControl(page, 'noise-export-normal');
      await page.waitForFunction(() => /noise-relief-toggle=/.test(document.body.dataset.controls), null, { timeout: READY_MS });
      await clickControl(page, 'noise-relief-toggle');
      await page.waitForFunction(() => /noise-relief-view=/.test(document.body.dataset.controls), null, { timeout: READY_MS });
      // Scroll the panel until the whole picture is on screen.
      await page.mouse.move(150, 600);
      for (let i = 0; i < 10 && (await controls(page))['noise-relief-view'].y + (await controls(page))['noise-relief-view'].h > 990; i++) {
        await page.mouse.wheel(0, 200);
        await page.waitForTimeout(200);
      }
      const r = (await controls(page))['noise-relief-view'];
      assert.ok(r.y >= 0 && r.y + r.h <= 1000, `the relief view at ${JSON.stringify(r)}`);
      const full = decode(await page.screenshot({ timeout: READY_MS }));
      const view = window(full, Math.round(r.x + 4), Math.round(r.y + 4), Math.round(r.w - 8), Math.round(r.h - 8));
      const levels = new Set();
      for (let i = 0; i < view.data.length; i += 4) levels.add(view.data[i] >> 3);
      assert.ok(levels.size > 8, `the relief view shows ${levels.size} levels of red`);
      await page.screenshot({ path: path.join(SHOTS, `noise-relief-${backend}.png`), timeout: READY_MS });
      // A Perlin's 16-bit normal map (cheap enough at 1024²): unit normals facing out.
      await page.evaluate((h) => { window.location.hash = h; }, link({ type: 'perlin', frequency: 0.01, octaves: 3, seed: 2 }));
      await page.waitForFunction(() => JSON.parse(document.body.dataset.noise).type === 'perlin', null, { timeout: READY_MS });
      const file = await download(page, 'noise-export-png');
      assert.equal(file.name, 'noise-perlin-1024-normal.png');
      assert.equal(file.bytes[24], 16, 'bit depth');
      assert.equal(file.bytes[25], 2, 'colour type RGB');
      const png = PNG.sync.read(file.bytes, { skipRescale: true });
      const max = 65535;
      for (const k of [0, 1234, 500_000, 1024 * 1024 - 1]) {
        const n = [0, 1, 2].map((c) => 2 * png.data[4 * k + c] / max - 1);
        assert.ok(Math.abs(Math.hypot(...n) - 1) < 2e-3 && n[2] > 0, `normal ${n} at ${k}`);
      }
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('the Noise panel: a seamless export, a layer on 2×2 tiles, and Khlebnikov et al. 2013 weather data', backend === 'webgpu' ? longOnly : { skip: true }, async () => {
      // A laptop's page (clickControl scrolls the Noise panel to what lies below).
      const { page, context, errors } = await openPage(browser, site, '', { width: 1000, height: 900 });
      await clickControl(page, 'mode-noise');
      await page.waitForFunction(() => document.body.dataset.mode === 'noise' && document.body.dataset.ready === '1', null, { timeout: READY_MS });
      assert.equal(await attr(page, 'data-noise-preview'), 'off', 'a plain noise needs no CPU preview');
      const plain = await shootSheet(page, STONE.design.width, STONE.design.height);
      // A tileable Perlin exported at 1024²: greyscale, seamless over its size.
      await clickControl(page, 'noise-tile');
      await page.waitForFunction(() => JSON.parse(document.body.dataset.noise).tile === 256, null, { timeout: READY_MS });
      const file = await download(page, 'noise-export-png');
      assert.equal(file.name, 'noise-perlin-1024-8bit.png');
      const png = PNG.sync.read(file.bytes, { skipRescale: true });
      assert.equal(png.width, 1024);
      const grey = (x, y) => png.data[4 * (y * 1024 + x)];
      let seam = 0;
      let inner = 0;
      for (let y = 0; y < 1024; y++) {
        seam += Math.abs(grey(1023, y) - grey(0, y));
        inner += Math.abs(grey(511, y) - grey(512, y));
      }
      assert.ok(seam <= 1.25 * inner + 1024, `seam ${seam} vs interior ${inner}`);
      // A layer on top, shown as 2×2 copies of one tile.
      await clickControl(page, 'noise-add-layer');
      await page.waitForFunction(() => JSON.parse(document.body.dataset.noise).layers?.length === 1, null, { timeout: READY_MS });
      const layered = JSON.parse(await attr(page, 'data-noise'));
      assert.deepEqual([layered.layers[0].type, layered.layers[0].combine, layered.layers[0].weight], ['worley', 'add', 0.5]);
      await page.waitForFunction(() => document.body.dataset.noisePreview === 'tiles 256x256', null, { timeout: READY_MS });
      await page.screenshot({ path: path.join(SHOTS, `noise-tiles-${backend}.png`), timeout: READY_MS });
      // Khlebnikov et al. 2013: the weather data drives a Gabor, drawn by the CPU preview.
      await clickControl(page, 'noise-weather');
      await page.waitForFunction(() => JSON.parse(document.body.dataset.noise).frequency_field?.data === 'weather', null, { timeout: READY_MS });
      const spec = JSON.parse(await attr(page, 'data-noise'));
      assert.deepEqual([spec.kind, spec.frequency_field.channel, spec.orientation_field.channel, spec.blend.value.channel], ['random-phase', 1, 2, 3]);
      assert.deepEqual(spec.transfer, { type: 'spline-decay', value: { data: 'weather', channel: 1 } });
      // Coarse first, then the finer picture of the whole sheet.
      await page.waitForFunction(() => /^sheet 256x\d+$/.test(document.body.dataset.noisePreview), null, { timeout: READY_MS });
      const weather = await shootSheet(page, STONE.design.width, STONE.design.height);
      // The panel grew with the layer, so the sheet may be drawn a little smaller now.
      const [w, h] = [Math.min(plain.img.width, weather.img.width), Math.min(plain.img.height, weather.img.height)];
      assert.ok(differing(crop(plain.img, w, h), crop(weather.img, w, h), 24) > 0.3, 'the canvas does not show the data-driven noise');
      await page.screenshot({ path: path.join(SHOTS, `noise-weather-${backend}.png`), timeout: READY_MS });
      // The setup, data references included, survives a reload.
      await page.waitForTimeout(1500);
      await page.goto(`${site.url}?landing=0`);
      await waitReady(page);
      assert.deepEqual(JSON.parse(await attr(page, 'data-noise')), spec, 'the data-driven setup was not kept');
      assert.equal(await attr(page, 'data-error'), null);
      assert.deepEqual(errors, []);
      await context.close();
    });
  });
}
