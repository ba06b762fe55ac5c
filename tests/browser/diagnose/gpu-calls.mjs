// Diagnosis: the WebGPU calls the app makes per frame while hovering (or dragging).
import { attr, launch } from '../harness.mjs';
import { tineOverSheet } from '../probe.mjs';
const [mode = 'hover', ...extra] = process.argv.slice(2);
const { browser, site } = await launch('webgpu', extra);
const context = await browser.newContext({ viewport: { width: 1024, height: 768 }, deviceScaleFactor: 1 });
await context.addInitScript(() => {
  window.calls = {};
  for (const cls of ['GPUQueue', 'GPUDevice', 'GPUCommandEncoder', 'GPURenderPassEncoder', 'GPUCanvasContext', 'GPUBuffer', 'GPUTexture']) {
    const P = globalThis[cls].prototype;
    for (const k of Object.getOwnPropertyNames(P)) {
      const d = Object.getOwnPropertyDescriptor(P, k);
      if (typeof d.value !== 'function' || k === 'constructor') continue;
      const f = d.value;
      P[k] = function (...a) {
        let key = cls + '.' + k;
        if (k === 'writeBuffer') key += '(' + (a[4] ?? (a[2].byteLength - (a[3] ?? 0))) + ')';
        if (k === 'createBuffer' || k === 'createTexture') key += '(' + JSON.stringify(a[0].size) + ')';
        if (k === 'writeTexture') key += '(' + JSON.stringify(a[3]) + ')';
        window.calls[key] = (window.calls[key] || 0) + 1;
        return f.apply(this, a);
      };
    }
  }
});
const page = await context.newPage();
await page.goto(site.url);
const { x, y } = await tineOverSheet(page);
if (mode === 'drag') await page.mouse.down();
for (let i = 0; i < 5; i++) await page.mouse.move(x + 3 * i, y);
await page.evaluate(() => { window.calls = {}; });
const f0 = Number(await attr(page, 'data-frames'));
for (let i = 0; i < 30; i++) await page.mouse.move(x + 3 * i, y + 10 * Math.sin(i));
const frames = Number(await attr(page, 'data-frames')) - f0;
const calls = await page.evaluate(() => window.calls);
console.log('frames', frames);
for (const [k, v] of Object.entries(calls).sort((a, b) => b[1] - a[1])) console.log((v / frames).toFixed(2), k);
await browser.close(); site.server.close();
