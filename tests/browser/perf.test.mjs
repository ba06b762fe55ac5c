// Frames while dragging a tool over a PERF_OPS-op (300 in `make test`, 1,000 for the
// numbers of docs/BENCHMARKS.md) 1024×768 design, in headless Chromium on
// SwiftShader (a CPU-emulated GPU), read from the app's own frame timings
// (data-frames: frames drawn) and GPU work counters (data-gpu-work); the drag's rate is
// taken after its first 2 s, once the preview has settled on its sample count.
// What is asserted (counts, never times): a drag draws only live-preview frames (no
// exact frame, no tile, no new preview cache), at least ten of them. The frame rates
// of hovering and dragging are printed for docs/BENCHMARKS.md. Fast paint
// (src/fast_paint/) is on here because the adapter is software; `?fast_paint=off` turns
// it off (no panel copies).
// `make test` runs it on WebGPU with Chromium's default GPU compositing; with
// PERF_SETUPS=all it also runs WebGL2 and WebGPU with --disable-gpu-compositing (how
// Chromium runs where it cannot use the GPU), and with PERF_SECONDS=8 it measures for
// as long as docs/BENCHMARKS.md's numbers did:
//   cd tests/browser && PERF_OPS=1000 PERF_SETUPS=all PERF_SECONDS=8 node --test perf.test.mjs
// PERF_QUERY='&fast_paint=off' measures the drag without the software-GPU shortcuts.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { MARBLING, READY_MS, attr, launch, longOnly, openPage, sheet } from './harness.mjs';
import { sweep as wiggle } from './probe.mjs';

const design = path.join(os.tmpdir(), `marbling-perf-${process.pid}.json`);

/** Parses data-gpu-work (`exact=…,preview=…,caches=…`). */
async function work(page) {
  return Object.fromEntries((await attr(page, 'data-gpu-work')).split(',').map((kv) => {
    const [k, v] = kv.split('=');
    return [k, Number(v)];
  }));
}

const ALL_SETUPS = [
  { name: 'webgpu', backend: 'webgpu', flags: [] },
  { name: 'webgl2', backend: 'webgl2', flags: [] },
  { name: 'webgpu, software compositing', backend: 'webgpu', flags: ['--disable-gpu-compositing'] },
];
const SETUPS = process.env.PERF_SETUPS === 'all' ? ALL_SETUPS : ALL_SETUPS.slice(0, 1);
const SECONDS = Number(process.env.PERF_SECONDS ?? 3);
// The design's ops: its first exact frame on SwiftShader is most of the test's time.
const OPS = Number(process.env.PERF_OPS ?? 300);

for (const { name, backend, flags } of SETUPS) {
  describe(`drag frames on ${name}`, longOnly, () => {
    let browser;
    let site;
    before(async () => {
      execFileSync(MARBLING, ['random', '--ops', String(OPS), '--size', '1024x768', '--seed', '11', '--mix', 'mixed', '-o', design]);
      ({ browser, site } = await launch(backend, flags));
    });
    after(async () => {
      await browser?.close();
      site?.server.close();
      fs.rmSync(design, { force: true });
    });

    test('dragging a tine over a many-op design draws only preview frames', async () => {
      const link = execFileSync(MARBLING, ['link', design, '--base', site.url]).toString().trim();
      const query = process.env.PERF_QUERY ?? '';
      const { page, context, errors } = await openPage(browser, site, query + link.slice(link.indexOf('#')), { width: 1024, height: 768 });
      assert.equal(await attr(page, 'data-ops'), String(OPS));
      // The app builds its live-preview cache in the idle frame after the exact one.
      await page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: READY_MS });
      const s = await sheet(page);
      await page.keyboard.press('3'); // tine
      const x = s.x + 100 * s.scale;
      const y = s.y + 384 * s.scale;
      await page.mouse.move(x, y);
      const hoverFps = await wiggle(page, x, y, SECONDS * 1000);
      const before = await work(page);
      await page.mouse.down();
      // The first 2 s: the preview settles on its sample count (src/fast_paint/preview_quality.rs
      // decides after 10 frames); the next SECONDS are the drag's steady rate.
      const settleFps = await wiggle(page, x, y, 2_000);
      const dragFps = await wiggle(page, x, y, SECONDS * 1000);
      const during = await work(page);
      await page.mouse.up();
      console.log(`${name}${query}: fast paint ${await attr(page, 'data-fast-paint')}`);
      console.log(`${name}${query}: ${OPS} ops at 1024×768 (scale ${s.scale.toFixed(3)}): hover ${hoverFps.toFixed(1)} frames/s, tine drag ${dragFps.toFixed(1)} frames/s (first 2 s: ${settleFps.toFixed(1)}), ${during.preview - before.preview} preview frames, preview ${during.preview_samples} sample(s)/px`);
      assert.equal(during.exact, before.exact, 'the drag re-rendered the design exactly');
      assert.equal(during.tiles, before.tiles, 'the drag drew tiles of an exact frame or cache');
      assert.equal(during.caches, before.caches, 'the drag rebuilt the preview cache');
      assert.ok(during.preview - before.preview >= 10, `only ${during.preview - before.preview} preview frames were drawn`);
      assert.deepEqual(errors, []);
      await context.close();
    });

    test('fast paint runs on the software adapter, and ?fast_paint=off switches it off', async () => {
      const copies = {};
      for (const flag of ['', '&fast_paint=off']) {
        const { page, context, errors } = await openPage(browser, site, flag, { width: 800, height: 600 });
        const s = await sheet(page);
        await page.keyboard.press('3');
        // Hovering over the sheet changes only the overlay: the panels stay the same.
        await wiggle(page, s.x + 40, s.y + 40, 1_000);
        copies[flag || 'auto'] = { hook: await attr(page, 'data-fast-paint'), panel: (await work(page)).panel_copies };
        assert.deepEqual(errors, []);
        await context.close();
      }
      console.log(`fast paint on ${name}: ${JSON.stringify(copies)}`);
      assert.equal(copies.auto.hook, 'on (software adapter)');
      assert.ok(copies.auto.panel > 0, 'the unchanged panels were not copied from the cache');
      assert.equal(copies['&fast_paint=off'].hook, 'off');
      assert.equal(copies['&fast_paint=off'].panel, 0, 'switched off, the panel cache still ran');
    });
  });
}
