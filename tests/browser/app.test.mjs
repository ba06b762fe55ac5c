// End-to-end tests of the web playground in Debian's Chromium, on both GPU paths:
// WebGPU (SwiftShader Vulkan) and WebGL2 (ANGLE on SwiftShader): loading, tools, undo,
// share links and autosave. Run by `make browser-test` after `make web`.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { PNG } from 'pngjs';
import { BACKENDS, MARBLING, longOnly, READY_MS, SHOTS, attr, clickControl, controls, crop, decode, differing, download, example, launch, openPage, sheet, shootSheet, waitOps } from './harness.mjs';

const STONE = example('stone').design;

/**
 * `n` ops on a 120×90 sheet that stay well conditioned, so f32 (GPU) and f64 (CLI)
 * renders agree: small drops and sprays, a gentle wavy comb every 500 ops. (A random
 * `mixed` design of 5,000 ops is chaotic: f32 and f64 disagree on most pixels.)
 */
function manyOps(n) {
  let seed = 12345;
  const rnd = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);
  const hex = () => `#${[0, 1, 2].map(() => Math.floor(40 + rnd() * 200).toString(16).padStart(2, '0')).join('')}`;
  const ops = [];
  for (let i = 0; i < n; i++) {
    const center = [Math.round(rnd() * 12000) / 100, Math.round(rnd() * 9000) / 100];
    if (i % 500 === 499) ops.push({ type: 'wavy', angle: Math.round(rnd() * 3000) / 1000, amplitude: 2, wavelength: 60, phase: 0 });
    else if (i % 5 === 0) ops.push({ type: 'drop', center, radius: 1.5, color: hex() });
    else ops.push({ type: 'spray', center, radius: 1.2, color: hex() });
  }
  return { version: 1, width: 120, height: 90, background: '#f4ecd8', ops };
}

for (const backend of Object.keys(BACKENDS)) {
  describe(`playground on ${backend}`, () => {
    let browser;
    let site;
    before(async () => {
      ({ browser, site } = await launch(backend));
    });
    after(async () => {
      await browser?.close();
      site?.server.close();
    });

    const open = (hash = '') => openPage(browser, site, hash);
    const webgpuOnly = backend === 'webgpu' ? {} : { skip: 'the tile schedule does not depend on the backend' };
    const webgl2Only = backend === 'webgl2' ? {} : { skip: 'UI, storage and links: tested on webgl2 (WebGPU loads, renders links, the 3D view and the tile schedule)' };

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
      await page.screenshot({ path: path.join(SHOTS, `playground-${backend}.png`), timeout: READY_MS });
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('the 3D view shows the design on a vase, every pixel walked by the GPU', backend === 'webgl2' ? longOnly : {}, async () => {
      const { page, context, errors } = await open();
      // Closed whatever happens: a turning view left open would starve the next tests.
      try {
        await clickControl(page, 'view3d');
        await page.waitForFunction(() => Number(document.body.dataset.view3dFrames) >= 1, null, { timeout: READY_MS });
        await page.mouse.move(2, 2);
        await page.waitForTimeout(300);
        const pane = (await controls(page))['view3d-pane-0'];
        assert.ok(pane, 'no 3D pane');
        const img = decode(await page.screenshot({ clip: { x: pane.x, y: pane.y, width: pane.w, height: pane.h }, timeout: READY_MS }));
        const at = (fx, fy) => {
          const i = (Math.floor(fy * img.height) * img.width + Math.floor(fx * img.width)) * 4;
          return [img.data[i], img.data[i + 1], img.data[i + 2]];
        };
        // The corners are the backdrop (dark grey, r ≈ g ≈ b); the vase in the middle
        // carries the stone design's colours: not a blank pane.
        const corner = at(0.02, 0.02);
        assert.ok(corner[0] < 90 && Math.abs(corner[0] - corner[2]) < 12, `corner ${corner}`);
        const colours = new Set();
        for (let y = 0.2; y < 0.8; y += 0.02) for (let x = 0.42; x < 0.58; x += 0.02) colours.add(at(x, y).join());
        assert.ok(colours.size > 8, `only ${colours.size} colours on the vase`);
        if (backend === 'webgpu') await page.screenshot({ path: path.join(SHOTS, 'view3d-vase.png'), timeout: READY_MS });

        // Turn: the camera spins by itself, and the pane changes with it.
        const view3d = async () => JSON.parse(await attr(page, 'data-view3d'));
        const still = await view3d();
        assert.equal(still.turning, false);
        await clickControl(page, 'view3d-turn');
        await page.waitForFunction((y) => {
          const v = JSON.parse(document.body.dataset.view3d);
          return v.turning && Math.abs(v.yaw - y) > 5;
        }, still.yaw, { timeout: READY_MS });
        const turned = decode(await page.screenshot({ clip: { x: pane.x, y: pane.y, width: pane.w, height: pane.h }, timeout: READY_MS }));
        assert.ok(differing(img, turned, 24) > 0.02, 'the turning vase looks the same');
        if (backend === 'webgpu') {
          // The speed slider's rail at its right end: nearly the fastest turn. Record
          // films the turning pane; Stop ends it early (after 2 frames came back from the
          // GPU) and the video downloads.
          const speed = (await controls(page))['view3d-turn-speed'];
          await page.mouse.click(speed.x + 96, speed.y + speed.h / 2);
          await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).speed > 120, null, { timeout: READY_MS });
          const t0 = Date.now();
          await clickControl(page, 'view3d-record');
          await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).recording?.frames >= 2, null, { timeout: READY_MS });
          const video = await download(page, 'view3d-record');
          assert.equal(video.name, 'marbling-3d-turn.webm');
          assert.deepEqual([...video.bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'an EBML (WebM) header');
          console.log(`3D view: ${((Date.now() - t0) / 1000).toFixed(1)} s of a turn at ${(await view3d()).speed.toFixed(0)}°/s recorded, ${video.bytes.length} bytes`);
          assert.ok(video.bytes.length > 1000, `a ${video.bytes.length}-byte video`);
          assert.equal((await view3d()).recording, null);
        }
        await clickControl(page, 'view3d-turn');
        await page.waitForFunction(() => !JSON.parse(document.body.dataset.view3d).turning, null, { timeout: READY_MS });
        await styles(page, backend);
        await displacement(page, backend);
        assert.equal(await attr(page, 'data-error'), null);
        assert.deepEqual(errors, []);
      } finally {
        await context.close();
      }
    });

    /**
     * Displace (Kung 2019) in the standing 3D view: the amount slider near its right
     * end moves the surface by Perlin noise, Flow moves the noise with time. The camera
     * first dollies out (the object about a tenth of the pane): on SwiftShader each
     * displaced RGSS frame costs about 100 noise samples per sample where the object is.
     */
    /** The 3D pane once neither a new frame was drawn nor the pane moved for 0.8 s (a
     * frame is drawn only when what it shows changed). */
    async function settledPane(page) {
      await page.mouse.move(2, 2);
      // The frame count and where the pane is (opening a section moves it).
      const state = async () => `${await attr(page, 'data-view3d-frames')} ${JSON.stringify((await controls(page))['view3d-pane-0'])}`;
      for (let n = '', m = await state(); n !== m; m = await state()) {
        n = m;
        await page.waitForTimeout(800);
      }
      // The hooks lag the picture by a frame: two more frames make them its.
      const f = Number(await attr(page, 'data-frames'));
      await page.mouse.move(3, 3);
      await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, f + 2, { timeout: READY_MS });
      const pane = (await controls(page))['view3d-pane-0'];
      return decode(await page.screenshot({ clip: { x: pane.x, y: pane.y, width: pane.w, height: pane.h }, timeout: READY_MS }));
    }

    /**
     * Pixels showing the object in either shot (off the backdrop, which is constant
     * along a row), how many of them differ between the shots, and how many backdrop
     * pixels do.
     */
    function objectChange(a, b, t = 24) {
      const px = (img, x, y) => [0, 1, 2].map((k) => img.data[(y * img.width + x) * 4 + k]);
      const off = (p, q, t) => p.some((v, k) => Math.abs(v - q[k]) > t);
      let [object, changed, backdrop] = [0, 0, 0];
      for (let y = 0; y < a.height; y++) {
        for (let x = 0; x < a.width; x++) {
          const [f, g] = [px(a, x, y), px(b, x, y)];
          const shown = off(f, px(a, 2, y), 12) || off(g, px(b, 2, y), 12);
          if (shown) object++;
          if (off(f, g, t)) {
            if (shown) changed++;
            else backdrop++;
          }
        }
      }
      return { object, changed, backdrop, pixels: a.width * a.height };
    }

    /**
     * Style (Bénard et al. 2010; Kaplan & Cohen 2005): hatching inks the object only and
     * counts its kernels; anchored on the screen the marks are other marks; paper lays
     * fibres over the backdrop too; watercolor works the object's colour in the shader;
     * none gives back the plain pane.
     */
    async function styles(page, backend) {
      const style = async () => JSON.parse(await attr(page, 'data-view3d')).style;
      const pick = async (menu, item) => {
        await clickControl(page, menu);
        await page.waitForFunction((n) => `;${document.body.dataset.controls ?? ''}`.includes(`;${n}=`), item, { timeout: READY_MS });
        // A popup's first frame is egui's sizing pass (drawn elsewhere, invisible): click
        // where it stands two frames on.
        const frames = Number(await attr(page, 'data-frames'));
        await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, frames + 2, { timeout: READY_MS });
        await clickControl(page, item);
      };
      await clickControl(page, 'view3d-style-section');
      await page.waitForFunction(() => `;${document.body.dataset.controls ?? ''}`.includes(';view3d-style='), null, { timeout: READY_MS });
      const plain = await settledPane(page);
      await pick('view3d-style', 'view3d-style-hatching');
      await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).style?.kernels > 0, null, { timeout: READY_MS });
      const hatched = await settledPane(page);
      const h = objectChange(plain, hatched);
      const s = await style();
      console.log(`${backend}: hatching: ${s.kernels} kernels in ${s.ms.toFixed(0)} ms; ${h.changed} of ${h.object} object pixels changed, ${h.backdrop} backdrop pixels`);
      assert.ok(h.object > 500 && h.changed > 0.05 * h.object, `hatching changed ${h.changed} of ${h.object} object pixels`);
      assert.ok(h.backdrop < 0.01 * h.object, `hatching reached ${h.backdrop} backdrop pixels`);
      if (backend === 'webgpu') fs.writeFileSync(path.join(SHOTS, 'view3d-hatching.png'), PNG.sync.write(hatched));
      await pick('view3d-style-anchoring', 'view3d-style-anchoring-screen');
      await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).style?.anchoring === 'screen', null, { timeout: READY_MS });
      const screen = objectChange(hatched, await settledPane(page));
      assert.ok(screen.changed > 0.05 * screen.object, `a screen noise changed ${screen.changed} of ${screen.object} object pixels`);
      await pick('view3d-style', 'view3d-style-paper');
      await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).style?.fibres > 0, null, { timeout: READY_MS });
      const papered = await settledPane(page);
      // One fibre is faint (12 % of a brown): count changes of 4/255.
      const paper = objectChange(plain, papered, 4);
      if (backend === 'webgpu') fs.writeFileSync(path.join(SHOTS, 'view3d-paper.png'), PNG.sync.write(papered));
      console.log(`${backend}: paper: ${(await style()).fibres} fibres; ${paper.backdrop} backdrop pixels changed`);
      assert.ok(paper.backdrop > 0.02 * paper.pixels, `paper changed ${paper.backdrop} backdrop pixels`);
      // Watercolor works the design's own colour in the panes' shader (overlay blend):
      // most of the object changes, the backdrop not at all.
      await pick('view3d-style', 'view3d-style-watercolor');
      await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).style?.style === 'watercolor', null, { timeout: READY_MS });
      const washed = objectChange(plain, await settledPane(page), 8);
      console.log(`${backend}: watercolor: ${washed.changed} of ${washed.object} object pixels changed, ${washed.backdrop} backdrop pixels`);
      assert.ok(washed.changed > 0.3 * washed.object, `watercolor changed ${washed.changed} of ${washed.object} object pixels`);
      assert.ok(washed.backdrop < 0.01 * washed.object, `watercolor reached ${washed.backdrop} backdrop pixels`);
      if (backend === 'webgpu') fs.writeFileSync(path.join(SHOTS, 'view3d-watercolor.png'), PNG.sync.write(await settledPane(page)));
      await pick('view3d-style', 'view3d-style-none');
      await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).style === null, null, { timeout: READY_MS });
      assert.ok(differing(plain, await settledPane(page), 2) < 0.001, 'style none should give back the plain pane');
    }

    async function displacement(page, backend) {
      const view3d = async () => JSON.parse(await attr(page, 'data-view3d'));
      const settled = () => settledPane(page);
      const slider = async (name, share) => {
        const c = (await controls(page))[name];
        await page.mouse.click(c.x + 100 * share, c.y + c.h / 2);
      };
      await clickControl(page, 'view3d-style-section');
      await clickControl(page, 'view3d-displace-section');
      await page.waitForFunction(() => `;${document.body.dataset.controls ?? ''}`.includes(';view3d-displace='), null, { timeout: READY_MS });
      await slider('view3d-dolly', 0.75);
      await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).dolly > 2, null, { timeout: READY_MS });
      const flat = await settled();
      await slider('view3d-displace', 0.8);
      await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).displace.amount > 0.3, null, { timeout: READY_MS });
      const bumpy = await settled();
      const { object, changed } = objectChange(flat, bumpy);
      console.log(`${backend}: displaced 3D view at dolly ${(await view3d()).dolly.toFixed(2)}: ${changed} of ${object} object pixels changed`);
      if (backend === 'webgpu') fs.writeFileSync(path.join(SHOTS, 'view3d-displaced.png'), PNG.sync.write(bumpy));
      assert.ok(object > 500 && changed > 0.3 * object, `displacing changed ${changed} of ${object} object pixels`);
      await clickControl(page, 'view3d-displace-flow');
      await page.waitForFunction(() => {
        const d = JSON.parse(document.body.dataset.view3d).displace;
        return d.flowing && d.offset[1] !== 0;
      }, null, { timeout: READY_MS });
      await clickControl(page, 'view3d-displace-flow');
      assert.equal((await view3d()).displace.flowing, false);
    }

    test('a drop click, a rake drag and undo change and restore the pixels', webgl2Only, async () => {
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
      await page.screenshot({ path: path.join(SHOTS, `raked-${backend}.png`), timeout: READY_MS });

      await page.keyboard.press('Control+z');
      await waitOps(page, n + 1);
      const undone = await shootSheet(page, STONE.width, STONE.height);
      assert.ok(differing(dropped.img, undone.img, 2) < 0.001, 'undo did not restore the pixels');
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('a #d= link shows the same picture as `marbling render`', async () => {
      const design = example('gel-git').file;
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

    // Progressive exact rendering (crates/marbling-app/src/gpu/refine.rs): a 5,000-op link is
    // drawn in tiles over many frames; `data-ready` says 1 only after the last one, and
    // the picture is then the CLI's. An edit after that shows the preview at once (the
    // design before the edit, with the new drop walked over it) while the tiles sharpen
    // it. Small sizes keep it cheap on SwiftShader (a 180×135-px sheet).
    test('a 5,000-op link refines in tiles, the preview stands in, ready only at the end', { ...webgpuOnly, ...longOnly }, async () => {
      const file = path.join(os.tmpdir(), `marbling-5000-${process.pid}.json`);
      fs.writeFileSync(file, JSON.stringify(manyOps(5000)));
      const link = execFileSync(MARBLING, ['link', file, '--base', site.url]).toString().trim();
      const context = await browser.newContext({ viewport: { width: 560, height: 360 }, deviceScaleFactor: 1 });
      const page = await context.newPage();
      const errors = [];
      page.on('pageerror', (e) => errors.push(String(e)));
      // Every change of the hooks, in order, seen by the page itself.
      await page.addInitScript(() => {
        window.hookLog = [];
        const names = ['data-ready', 'data-progress', 'data-ops', 'data-gpu-work'];
        new MutationObserver((changes) => {
          for (const c of changes) window.hookLog.push([c.attributeName, c.target.getAttribute(c.attributeName)]);
        }).observe(document, { subtree: true, attributes: true, attributeFilter: names });
      });
      await page.goto(site.url + link.slice(link.indexOf('#')));
      await waitOps(page, 5000);
      const log = await page.evaluate(() => window.hookLog);
      const tilesOf = (v) => Number(/tiles=(\d+)/.exec(v)?.[1] ?? 0);
      const progress = log.filter(([n, v]) => n === 'data-progress' && v !== null).map(([, v]) => Number(v));
      const firstReady = log.findIndex(([n, v]) => n === 'data-ready' && v === '1');
      const lastProgress = log.findLastIndex(([n, v]) => n === 'data-progress' && v !== null);
      const tiles = tilesOf(log.findLast(([n]) => n === 'data-gpu-work')?.[1]);
      console.log(`${backend}: 5,000 ops: ${tiles} tiles, ${progress.length} progress steps before ready`);
      assert.ok(progress.length >= 3, `only ${progress.length} progress steps: not refined in tiles`);
      assert.ok(progress.every((p, i) => p > 0 && p < 1 && (i === 0 || p >= progress[i - 1])), `progress not rising in (0, 1): ${progress}`);
      assert.ok(firstReady > lastProgress, 'data-ready said 1 while tiles were still being drawn');
      assert.equal(await attr(page, 'data-progress'), null);

      const shot = await shootSheet(page, 120, 90);
      const cpuFile = path.join(os.tmpdir(), `marbling-5000-${process.pid}.png`);
      execFileSync(MARBLING, ['render', file, '-o', cpuFile, '--scale', String(shot.scale), '--aa', 'rgss']);
      const cpu = decode(fs.readFileSync(cpuFile));
      const w = Math.min(cpu.width, shot.img.width);
      const h = Math.min(cpu.height, shot.img.height);
      const frac = differing(crop(cpu, w, h), crop(shot.img, w, h), 24);
      console.log(`${backend}: 5,000-op link vs CLI render: ${(100 * frac).toFixed(3)} % of ${w}×${h} px differ by > 24/255`);
      assert.ok(frac <= 0.01, `${(100 * frac).toFixed(2)} % of pixels differ from the CLI render`);

      // An edit: the preview cache of the design stands in at once, sharpened by tiles.
      await page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: READY_MS });
      const written = async () => Number(/ops_written=(\d+)/.exec(await attr(page, 'data-gpu-work'))?.[1]);
      const writtenBefore = await written();
      await page.keyboard.press('1'); // drop
      // Low on the sheet: its tiles come last, so the shot below is taken before them.
      await page.mouse.click(shot.x + 60 * shot.scale, shot.y + 70 * shot.scale);
      await page.waitForFunction(() => document.body.dataset.ops === '5001' && document.body.dataset.progress !== undefined, null, { timeout: READY_MS });
      const mid = await shootSheet(page, 120, 90);
      const midProgress = await attr(page, 'data-progress');
      fs.writeFileSync(path.join(SHOTS, `refining-5000-${backend}.png`), PNG.sync.write(mid.img));
      await waitOps(page, 5001);
      const done = await shootSheet(page, 120, 90);
      const off = differing(mid.img, done.img, 48);
      const changed = differing(shot.img, done.img, 48);
      console.log(`${backend}: while refining (progress ${midProgress}): ${(100 * off).toFixed(2)} % of pixels off the exact frame; the drop changed ${(100 * changed).toFixed(2)} %`);
      assert.ok(changed > 0.02, 'the drop did not change the picture');
      assert.ok(off < changed / 2, 'the frame shown while refining was not the preview of the edit');
      // Views without copies: the edit wrote its one op into the GPU's op texture.
      assert.equal((await written()) - writtenBefore, 1, 'the drop uploaded the design again');
      await page.screenshot({ path: path.join(SHOTS, `refined-5000-${backend}.png`), timeout: READY_MS });
      assert.deepEqual(errors, []);
      fs.rmSync(file, { force: true });
      fs.rmSync(cpuFile, { force: true });
      await context.close();
    });

    test('autosave survives a reload', { ...webgl2Only, ...longOnly }, async () => {
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

    test('a malformed link shows an error and keeps the page usable', { ...webgl2Only, ...longOnly }, async () => {
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
