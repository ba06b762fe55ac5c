// Frames while dragging a tool over a 1,000-op 1024×768 design, in headless Chromium on
// SwiftShader (a CPU-emulated GPU), read from the app's own frame timings
// (data-frames: frames drawn) and GPU work counters (data-gpu-work); the drag's rate is
// taken after its first 2 s, once the preview has settled on its sample count. Three set-ups:
// WebGPU and WebGL2 with Chromium's default GPU compositing (the page's frames are
// composited by SwiftShader too), and WebGPU with --disable-gpu-compositing (how
// Chromium runs where it cannot use the GPU: software compositing, WebGPU still on
// SwiftShader). What is asserted: a drag draws only live-preview frames (no exact
// render, no new preview cache); it keeps at least 40 % of the frame rate of merely
// hovering over the same design (the preview is one draw over the sheet; an exact
// re-render of 1,000 ops per frame would be ~20× slower here); and when the preview
// still takes several samples per pixel, the drag keeps up (≥ 25 frames/s), otherwise
// it has dropped to one sample (src/preview_quality.rs). The frame rates are printed
// for docs/BENCHMARKS.md.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { MARBLING, READY_MS, attr, launch, openPage, sheet } from './harness.mjs';
import { sweep as wiggle } from './probe.mjs';

const design = path.join(os.tmpdir(), `marbling-perf-${process.pid}.json`);

/** Parses data-gpu-work (`exact=…,preview=…,caches=…`). */
async function work(page) {
  return Object.fromEntries((await attr(page, 'data-gpu-work')).split(',').map((kv) => {
    const [k, v] = kv.split('=');
    return [k, Number(v)];
  }));
}

const SETUPS = [
  { name: 'webgpu', backend: 'webgpu', flags: [] },
  { name: 'webgl2', backend: 'webgl2', flags: [] },
  { name: 'webgpu, software compositing', backend: 'webgpu', flags: ['--disable-gpu-compositing'] },
];

for (const { name, backend, flags } of SETUPS) {
  describe(`drag frames on ${name}`, () => {
    let browser;
    let site;
    before(async () => {
      execFileSync(MARBLING, ['random', '--ops', '1000', '--size', '1024x768', '--seed', '11', '--mix', 'mixed', '-o', design]);
      ({ browser, site } = await launch(backend, flags));
    });
    after(async () => {
      await browser?.close();
      site?.server.close();
      fs.rmSync(design, { force: true });
    });

    test('dragging a tine over a 1,000-op design draws only preview frames, as fast as hovering', async () => {
      const link = execFileSync(MARBLING, ['link', design, '--base', site.url]).toString().trim();
      const { page, context, errors } = await openPage(browser, site, link.slice(link.indexOf('#')), { width: 1024, height: 768 });
      assert.equal(await attr(page, 'data-ops'), '1000');
      // The app builds its live-preview cache in the idle frame after the exact one.
      await page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: READY_MS });
      const s = await sheet(page);
      await page.keyboard.press('3'); // tine
      const x = s.x + 100 * s.scale;
      const y = s.y + 384 * s.scale;
      await page.mouse.move(x, y);
      const hoverFps = await wiggle(page, x, y, 8_000);
      const before = await work(page);
      await page.mouse.down();
      // The first 2 s: the preview settles on its sample count (src/preview_quality.rs
      // decides after 10 frames); the next 8 s are the drag's steady rate.
      const settleFps = await wiggle(page, x, y, 2_000);
      const dragFps = await wiggle(page, x, y, 8_000);
      const during = await work(page);
      await page.mouse.up();
      console.log(`${name}: 1,000 ops at 1024×768 (scale ${s.scale.toFixed(3)}): hover ${hoverFps.toFixed(1)} frames/s, tine drag ${dragFps.toFixed(1)} frames/s (first 2 s: ${settleFps.toFixed(1)}), ${during.preview - before.preview} preview frames, preview ${during.preview_samples} sample(s)/px`);
      assert.equal(during.exact, before.exact, 'the drag re-rendered the design exactly');
      assert.equal(during.caches, before.caches, 'the drag rebuilt the preview cache');
      assert.ok(during.preview - before.preview >= 10, `only ${during.preview - before.preview} preview frames were drawn`);
      assert.ok(dragFps >= hoverFps / 2.5, `dragging (${dragFps.toFixed(1)} frames/s) is slower than hovering (${hoverFps.toFixed(1)} frames/s)`);
      assert.ok(during.preview_samples === 1 || dragFps >= 25,
        `the drag ran at ${dragFps.toFixed(1)} frames/s with ${during.preview_samples} preview samples per pixel`);
      assert.deepEqual(errors, []);
      await context.close();
    });
  });
}
