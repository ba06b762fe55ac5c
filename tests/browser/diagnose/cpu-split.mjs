// Diagnosis: the page's main-thread time per frame (Chrome's Performance.getMetrics:
// script and task durations) while hovering and while dragging the tine over the
// gallery design, 5 s each: node cpu-split.mjs [webgpu|webgl2] [extra Chromium flags…]
// Results: docs/BENCHMARKS.md, "Where the time went".
import { attr, launch, openPage, sheet } from '../harness.mjs';

const [backend = 'webgpu', ...extra] = process.argv.slice(2);
const { browser, site } = await launch(backend, extra);
const { page } = await openPage(browser, site, '', { width: 1024, height: 768 });
await page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: 240_000 });
const cdp = await page.context().newCDPSession(page);
await cdp.send('Performance.enable');
const metrics = async () => Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
const s = await sheet(page);
await page.keyboard.press('3'); // tine
const x = s.x + 100 * s.scale;
const y = s.y + 200 * s.scale;
await page.mouse.move(x, y);

async function phase(name) {
  const a = await metrics();
  const f0 = Number(await attr(page, 'data-frames'));
  const t0 = Date.now();
  let i = 0;
  while (Date.now() - t0 < 5000) {
    i++;
    await page.mouse.move(x + 3 * (i % 100), y + 30 * Math.sin(i / 10));
  }
  const b = await metrics();
  const frames = Number(await attr(page, 'data-frames')) - f0;
  const per = (k) => ((1000 * (b[k] - a[k])) / frames).toFixed(1);
  console.log(`${backend} ${extra.join(' ')} ${name}: ${(frames / ((Date.now() - t0) / 1000)).toFixed(1)} frames/s; ` +
    `per frame: script ${per('ScriptDuration')} ms, tasks ${per('TaskDuration')} ms`);
}

await phase('hover');
await page.mouse.down();
await phase('drag');
await page.mouse.up();
await browser.close();
site.server.close();
