// Benchmark (docs/BENCHMARKS.md, never a test): what a user waits for when a big design
// arrives. For each op count, a random 800×600 `mixed` design is opened as a #d= link in
// a 1280×900 page, and the page itself records every animation frame. Printed: the worst
// gap between two animation frames (how long the page was frozen), the time until the
// exact frame was complete (data-ready) and until the live-preview cache was
// (data-preview-ready), the tiles drawn, and the GPU's measured speed.
//
//   cd tests/browser && node refine-bench.mjs [webgpu|webgl2] [1000,5000,20000] [limit s]
//
// A run that passes the time limit prints how far the exact frame got (data-progress).
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { MARBLING, attr, launch, recordFrames } from './harness.mjs';

const backend = process.argv[2] ?? 'webgpu';
const counts = (process.argv[3] ?? '1000,5000,20000').split(',').map(Number);
const limitS = Number(process.argv[4] ?? 900);

const { browser, site } = await launch(backend);
try {
  for (const ops of counts) {
    const file = path.join(os.tmpdir(), `marbling-bench-${ops}.json`);
    execFileSync(MARBLING, ['random', '--ops', String(ops), '--size', '800x600', '--seed', '1', '--mix', 'mixed', '-o', file]);
    const link = execFileSync(MARBLING, ['link', file, '--base', site.url], { maxBuffer: 64 << 20 }).toString().trim();
    const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
    const page = await context.newPage();
    await page.addInitScript(recordFrames);
    const start = Date.now();
    await page.goto(site.url + link.slice(link.indexOf('#')));
    // Loaded: the app has drawn its first frame with the design.
    await page.waitForFunction((n) => document.body.dataset.ops === String(n), ops, { timeout: limitS * 1000 });
    const loadedS = (Date.now() - start) / 1000;
    const loadedAt = await page.evaluate(() => performance.now());
    let readyS = null;
    let previewS = null;
    while ((Date.now() - start) / 1000 < limitS && previewS === null) {
      await page.waitForTimeout(250);
      const [ready, preview] = await Promise.all([attr(page, 'data-ready'), attr(page, 'data-preview-ready')]);
      if (ready === '1' && readyS === null) readyS = (Date.now() - start) / 1000;
      if (preview === '1') previewS = (Date.now() - start) / 1000;
    }
    const frames = await page.evaluate(() => window.frameTimes);
    // Gaps from the design's first frame on (the page's own start-up is not ours).
    const gaps = [];
    for (let i = 1; i < frames.length; i++) {
      if (frames[i] < loadedAt) continue;
      gaps.push([frames[i] - frames[i - 1], (frames[i - 1] - loadedAt) / 1000]);
    }
    const count = gaps.length;
    const sorted = gaps.map(([g]) => g).sort((x, y) => x - y);
    const worst = sorted.at(-1) ?? 0;
    const median = sorted[Math.floor(sorted.length / 2)] ?? 0;
    // The three longest gaps and when they began (s after the design's first frame).
    const longest = [...gaps].sort((x, y) => y[0] - x[0]).slice(0, 3)
      .map(([g, at]) => `${g.toFixed(0)} ms at ${at.toFixed(1)} s`).join(', ');
    const work = await attr(page, 'data-gpu-work');
    const progress = await attr(page, 'data-progress');
    const tiles = /tiles=(\d+)/.exec(work ?? '')?.[1];
    const units = /frame_units=(\d+)/.exec(work ?? '')?.[1];
    const fmt = (v) => (v === null ? `> ${limitS} s` : `${v.toFixed(1)} s`);
    console.log(`${backend}, ${ops} ops, 800×600 in 1280×900: loaded ${loadedS.toFixed(1)} s, exact frame ${fmt(readyS)}`
      + `${readyS === null ? ` (progress ${progress})` : ''}, preview cache ${fmt(previewS)}, ${tiles} tiles `
      + `(last frame budget ${units} op-samples), `
      + `${count} animation frames, median interval ${median.toFixed(0)} ms, worst gap ${worst.toFixed(0)} ms`
      + ` (longest: ${longest})`);
    await context.close();
    fs.rmSync(file, { force: true });
  }
} finally {
  await browser.close();
  site.server.close();
}
