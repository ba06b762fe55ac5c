// Diagnosis: every WebGPU draw of one tine-drag frame over the gallery design, with its
// pipeline label, index or vertex count, scissor and viewport (1024×768):
// node draw-list.mjs [flags…]
import { launch } from '../harness.mjs';
import { tineOverSheet } from '../probe.mjs';
const { browser, site } = await launch('webgpu', process.argv.slice(2));
const context = await browser.newContext({ viewport: { width: 1024, height: 768 }, deviceScaleFactor: 1 });
await context.addInitScript(() => {
  const labels = new WeakMap();
  window.drawLog = null;
  const D = GPUDevice.prototype;
  const create = D.createRenderPipeline;
  D.createRenderPipeline = function (d) { const p = create.call(this, d); labels.set(p, d.label); return p; };
  const P = GPURenderPassEncoder.prototype;
  const setPipeline = P.setPipeline;
  P.setPipeline = function (p) { this.__label = labels.get(p); return setPipeline.call(this, p); };
  const setScissor = P.setScissorRect;
  P.setScissorRect = function (...a) { this.__scissor = a.join(','); return setScissor.apply(this, a); };
  const setViewport = P.setViewport;
  P.setViewport = function (...a) { this.__viewport = a.slice(0, 4).map(Math.round).join(','); return setViewport.apply(this, a); };
  for (const k of ['draw', 'drawIndexed']) {
    const f = P[k];
    P[k] = function (...a) {
      window.drawLog?.push(`${this.__label} ${k}(${a[0]}) scissor ${this.__scissor} viewport ${this.__viewport}`);
      return f.apply(this, a);
    };
  }
});
const page = await context.newPage();
await page.goto(site.url);
const { x, y } = await tineOverSheet(page);
await page.mouse.down();
for (let i = 0; i < 5; i++) await page.mouse.move(x + 3 * i, y);
// One more pointer move, then the draws of the frames it causes.
await page.evaluate(() => { window.drawLog = []; });
await page.mouse.move(x + 30, y + 5);
const log = await page.evaluate(() => window.drawLog);
console.log(log.join('\n'));
await browser.close(); site.server.close();
