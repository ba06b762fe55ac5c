// Diagnosis, not a test: the playground's frame rate in headless Chromium while the
// pointer hovers over the gallery design, next to the browser's own requestAnimationFrame
// rate and the rate at which Playwright's pointer moves are acknowledged.
//
//   node frame-rate.mjs [webgpu|webgl2] [WIDTH] [HEIGHT] [extra Chromium flags…]
//
// Prints one line: idle rAF/s (nothing drawn by the app), then while hovering for 6 s:
// egui frames/s (data-frames), rAF/s and pointer moves/s. Results: docs/BENCHMARKS.md.
import { attr, launch, openPage } from '../harness.mjs';

const [backend = 'webgl2', width = '1024', height = '768', ...extra] = process.argv.slice(2);
const { browser, site } = await launch(backend, extra);
const { page } = await openPage(browser, site, '', { width: Number(width), height: Number(height) });
await page.evaluate(() => {
  window.rafCount = 0;
  const tick = () => {
    window.rafCount++;
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
});
const rafs = () => page.evaluate(() => window.rafCount);
await page.waitForTimeout(3000);
const idle0 = await rafs();
await page.waitForTimeout(3000);
const idle = ((await rafs()) - idle0) / 3;
const f0 = Number(await attr(page, 'data-frames'));
const r0 = await rafs();
const t0 = Date.now();
let moves = 0;
while (Date.now() - t0 < 6000) {
  moves++;
  await page.mouse.move(400 + 5 * (moves % 100), 300 + 40 * Math.sin(moves / 10));
}
const s = (Date.now() - t0) / 1000;
const frames = Number(await attr(page, 'data-frames')) - f0;
const raf = (await rafs()) - r0;
const rate = (n) => (n / s).toFixed(1);
console.log(`${backend} ${width}×${height} ${extra.join(' ')}: idle rAF ${idle.toFixed(1)}/s; hovering: ` +
  `egui ${rate(frames)} frames/s, rAF ${rate(raf)}/s, pointer moves ${rate(moves)}/s`);
await browser.close();
site.server.close();
