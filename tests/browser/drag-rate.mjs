// Diagnosis: egui frames/s while hovering and while dragging a tool (tine) over the
// gallery design, on one backend: node drag-rate.mjs [webgpu|webgl2] [W] [H] [flags…]
import { attr, launch, openPage, sheet } from './harness.mjs';
const [backend = 'webgl2', width = '1024', height = '768', ...extra] = process.argv.slice(2);
const { browser, site } = await launch(backend, extra);
const { page } = await openPage(browser, site, '', { width: Number(width), height: Number(height) });
await page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: 240000 });
const s = await sheet(page);
await page.keyboard.press('3');
const x = s.x + 100 * s.scale, y = s.y + 200 * s.scale;
async function wiggle(ms) {
  const f0 = Number(await attr(page, 'data-frames')); const t0 = Date.now(); let i = 0;
  while (Date.now() - t0 < ms) { i++; await page.mouse.move(x + 3 * (i % 100), y + 30 * Math.sin(i / 10)); }
  return (1000 * (Number(await attr(page, 'data-frames')) - f0)) / (Date.now() - t0);
}
await page.mouse.move(x, y);
const hover = await wiggle(5000);
await page.mouse.down();
const drag = await wiggle(5000);
await page.mouse.up();
console.log(`${backend} ${width}×${height} ${extra.join(' ')}: hover ${hover.toFixed(1)} frames/s, drag ${drag.toFixed(1)} frames/s; ${await attr(page, 'data-gpu-work')}`);
await browser.close(); site.server.close();
