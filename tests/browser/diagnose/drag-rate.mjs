// Diagnosis: egui frames/s while hovering and while dragging a tool (tine) over the
// gallery design, on one backend: node drag-rate.mjs [webgpu|webgl2] [W] [H] [flags…]
import { attr, launch, openPage } from '../harness.mjs';
import { tineOverSheet, wiggle } from '../probe.mjs';
const [backend = 'webgl2', width = '1024', height = '768', ...extra] = process.argv.slice(2);
const { browser, site } = await launch(backend, extra);
const { page } = await openPage(browser, site, '', { width: Number(width), height: Number(height) });
const at = await tineOverSheet(page);
const hover = await wiggle(page, at, 5000);
await page.mouse.down();
const drag = await wiggle(page, at, 5000);
await page.mouse.up();
console.log(`${backend} ${width}×${height} ${extra.join(' ')}: hover ${hover.toFixed(1)} frames/s, drag ${drag.toFixed(1)} frames/s; ${await attr(page, 'data-gpu-work')}`);
await browser.close(); site.server.close();
