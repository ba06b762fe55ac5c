// Benchmark, not a test: what a first visit waits for in the gallery, and what playing
// a pattern's making costs. Opens the landing, times the thumbnails until all are shown
// (from the prerendered atlas; by the GPU where it is missing, `data-thumbnails-from`),
// opens a pattern and plays its making at the default speed, printing the player's
// frames and wall time. `node gallery-bench.mjs [webgpu|webgl2] [pattern]`
// (needs `make web`); results in docs/BENCHMARKS.md.
import { attr, clickControl, launch } from './harness.mjs';

const backend = process.argv[2] ?? 'webgl2';
const pattern = process.argv[3] ?? 'chevron';
const { browser, site } = await launch(backend);
const page = await (await browser.newContext({ viewport: { width: 1300, height: 820 }, deviceScaleFactor: 1 })).newPage();
const t0 = Date.now();
await page.goto(site.url);
await page.waitForFunction(() => document.body.dataset.landing === '1', null, { timeout: 600_000 });
const landed = Date.now();
let last = 0;
for (;;) {
  const [drawn, total] = ((await attr(page, 'data-thumbnails')) ?? '0/1').split('/').map(Number);
  if (drawn !== last) {
    last = drawn;
    if (drawn === 1 || drawn === total) console.log(`${backend}: thumbnail ${drawn}/${total} (${await attr(page, 'data-thumbnails-from')}) at ${((Date.now() - landed) / 1000).toFixed(1)} s after the landing (${((landed - t0) / 1000).toFixed(1)} s after the page opened)`);
  }
  if (drawn === total) break;
  await page.waitForTimeout(100);
}
await clickControl(page, `gallery-${pattern}`);
await page.waitForFunction(() => document.body.dataset.ready === '1', null, { timeout: 600_000 });
const frames0 = Number(await attr(page, 'data-frames'));
const p0 = Date.now();
await clickControl(page, 'play');
await page.waitForFunction(() => { const p = document.body.dataset.player ?? ''; const [a, b] = p.split('/'); return p && a === b; }, null, { timeout: 900_000 });
const frames = Number(await attr(page, 'data-frames')) - frames0;
const secs = (Date.now() - p0) / 1000;
console.log(`${backend}: played ${pattern} (${await attr(page, 'data-player')} steps at 0.8 steps/s) in ${secs.toFixed(1)} s, ${frames} frames (${(frames / secs).toFixed(1)} frames/s)`);
await browser.close();
site.server.close();
