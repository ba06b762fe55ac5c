// Diagnosis: frames/s while hovering and dragging a tine over the gallery design on WebGPU
// when the draws of the render pipelines whose label matches SKIP (a regex) are skipped,
// which bounds what each pipeline costs: node skip-draws.mjs SKIP [flags…]. SKIP is
// matched against "LABEL COUNT" (COUNT: the draw's vertex or index count).
import { attr, launch, sheet } from './harness.mjs';
const [skip = '^$', ...extra] = process.argv.slice(2);
const { browser, site } = await launch('webgpu', extra);
const context = await browser.newContext({ viewport: { width: 1024, height: 768 }, deviceScaleFactor: 1 });
await context.addInitScript((skip) => {
  const re = new RegExp(skip);
  const labels = new WeakMap();
  window.drawn = {};
  const D = GPUDevice.prototype;
  for (const k of ['createRenderPipeline', 'createRenderPipelineAsync']) {
    const f = D[k];
    D[k] = function (desc) {
      const r = f.call(this, desc);
      if (r instanceof Promise) return r.then((p) => { labels.set(p, desc.label ?? '?'); return p; });
      labels.set(r, desc.label ?? '?');
      return r;
    };
  }
  const P = GPURenderPassEncoder.prototype;
  const setPipeline = P.setPipeline;
  P.setPipeline = function (p) { this.__label = labels.get(p) ?? '?'; return setPipeline.call(this, p); };
  for (const k of ['draw', 'drawIndexed']) {
    const f = P[k];
    P[k] = function (...a) {
      window.drawn[this.__label] = (window.drawn[this.__label] ?? 0) + 1;
      if (re.test(`${this.__label} ${a[0]}`)) return undefined;
      return f.apply(this, a);
    };
  }
}, skip);
const page = await context.newPage();
await page.goto(site.url);
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
const hover = await wiggle(4000);
await page.mouse.down();
const drag = await wiggle(4000);
await page.mouse.up();
console.log(`skip /${skip}/ ${extra.join(' ')}: hover ${hover.toFixed(1)} frames/s, drag ${drag.toFixed(1)} frames/s; draws ${JSON.stringify(await page.evaluate(() => window.drawn))}`);
await browser.close(); site.server.close();
