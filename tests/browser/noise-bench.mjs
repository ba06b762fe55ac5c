// Benchmark (docs/BENCHMARKS.md, never a test): how long the page freezes when a noise
// preview is drawn. For each type a fresh 1280×800 page opens the start-up design
// (?landing=0), switches to the Noise tab (`tab`: that switch is timed; the tab opens on
// the noise last used, Perlin fBm on a first visit), waits `seconds`, picks the type from
// the list, and the page itself records every animation frame for `seconds` after. Printed: the
// worst gap between two animation frames (the longest freeze), the sum of the gaps over
// 100 ms, and when the last such gap ended.
//
//   cd tests/browser && node noise-bench.mjs [webgpu|webgl2] [tab,gabor,perlin,...] [seconds]
import { attr, controls, launch, recordFrames } from './harness.mjs';

const backend = process.argv[2] ?? 'webgl2';
const types = (process.argv[3] ?? 'tab,gabor,perlin,worley,curl').split(',');
const seconds = Number(process.argv[4] ?? 60);

const { browser, site } = await launch(backend);
const press = async (page, name) => {
  const c = (await controls(page))[name];
  if (!c) throw new Error(`no control ${name}`);
  await page.mouse.click(c.x + c.w / 2, c.y + c.h / 2);
};
const frames = async (page, k) => {
  const n = Number(await attr(page, 'data-frames'));
  await page.waitForFunction((m) => Number(document.body.dataset.frames) >= m, n + k, { timeout: 600_000 });
};
try {
  for (const type of types) {
    const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
    const page = await context.newPage();
    await page.addInitScript(recordFrames);
    await page.goto(`${site.url}?landing=0`);
    await page.waitForFunction(() => document.body.dataset.ready === '1', null, { timeout: 600_000 });
    // `tab`: the switch itself is what is timed.
    let from = await page.evaluate(() => performance.now());
    await press(page, 'mode-noise');
    await page.waitForFunction(() => document.body.dataset.mode === 'noise', null, { timeout: 600_000 });
    if (type !== 'tab') {
      await page.waitForTimeout(seconds * 1000);
      await press(page, 'noise-type');
      await frames(page, 2);
      from = await page.evaluate(() => performance.now());
      await press(page, `noise-type-${type}`);
    }
    await page.waitForTimeout(seconds * 1000);
    const times = await page.evaluate(() => window.frameTimes);
    let worst = 0;
    let frozen = 0;
    let lastEnd = 0;
    for (let i = 1; i < times.length; i++) {
      if (times[i] < from) continue;
      const gap = times[i] - times[i - 1];
      worst = Math.max(worst, gap);
      if (gap > 100) {
        frozen += gap;
        lastEnd = (times[i] - from) / 1000;
      }
    }
    const what = type === 'tab' ? `opening the Noise tab (${JSON.parse(await attr(page, 'data-noise')).type})` : `picking ${type}`;
    console.log(`${backend} ${what}: worst frame gap ${worst.toFixed(0)} ms, ${(frozen / 1000).toFixed(1)} s in gaps over 100 ms, the last ending ${lastEnd.toFixed(1)} s after (${seconds} s watched)`);
    await context.close();
  }
} finally {
  await browser.close();
  site.server.close();
}
