// Diagnosis: what single draws cost SwiftShader in a bare WebGPU page (draw-cost/index.html,
// no app): a 1024×768 canvas cleared every frame plus the draws of each case, 2.5 s a case,
// three rounds. Prints frames/s (capped at 60 by the display) and the machine's CPU time
// per frame (all processes, from /proc/stat, so not capped): node draw-cost.mjs [flags…].
// Results: docs/BENCHMARKS.md, "eighth session".
import fs from 'node:fs';
import path from 'node:path';
import { launch, serve } from '../harness.mjs';

/** CPU milliseconds used by the whole machine so far (user, nice, system, irq, softirq). */
function cpuMs() {
  const f = fs.readFileSync('/proc/stat', 'utf8').split('\n')[0].trim().split(/\s+/).slice(1).map(Number);
  return (f[0] + f[1] + f[2] + f[5] + f[6]) * 10;
}

const { browser, site: own } = await launch('webgpu', process.argv.slice(2));
own.server.close();
const site = await serve(path.join(import.meta.dirname, 'draw-cost'));
const context = await browser.newContext({ viewport: { width: 1024, height: 768 }, deviceScaleFactor: 1 });
const page = await context.newPage();
page.on('console', (m) => { if (m.type() === 'error' || m.type() === 'warning') console.log(m.text()); });
page.on('pageerror', (e) => console.log(String(e)));
await page.goto(site.url);
await page.waitForFunction(() => window.started === true);
// Scissor rectangles: x, y, width, height.
const full = [0, 0, 1024, 768];
const panel = [0, 0, 300, 768];
const sheet = [316, 156, 692, 432];
const tiny = [400, 400, 8, 8];
const cases = {
  'clear only': [],
  'copy (textureLoad), panel': [{ fs: 'copy', rect: panel }],
  'copy (textureLoad), sheet': [{ fs: 'copy', rect: sheet }],
  'copy (textureLoad), full': [{ fs: 'copy', rect: full }],
  'copy (nearest sample), full': [{ fs: 'sample', rect: full }],
  'copy (storage buffer), full': [{ fs: 'buffer_copy', rect: full }],
  'flat colour, full': [{ fs: 'flat', rect: full }],
  'flat colour, 8×8, 1 draw': [{ fs: 'flat', rect: tiny }],
  'flat colour, 8×8, 8 draws': Array(8).fill({ fs: 'flat', rect: tiny }),
  'tine + bilinear 2× texture, sheet': [{ fs: 'preview', rect: sheet, sampler: 'linear' }],
  'tine + nearest 2× texture, sheet': [{ fs: 'preview', rect: sheet }],
  'tine + bilinear 2× storage buffer, sheet': [{ fs: 'preview_buffer', rect: sheet }],
  // A 700×8 strip (5,600 pixels) as 2 or 100 triangles, drawn like egui draws or flat.
  'egui-like, strip, 2 triangles': [{ fs: 'egui_like strip', sampler: 'linear', vertices: 6 }],
  'egui-like, strip, 100 triangles': [{ fs: 'egui_like strip', sampler: 'linear 50', vertices: 300 }],
  'flat colour, strip, 100 triangles': [{ fs: 'flat strip', sampler: 'linear 50', vertices: 300 }],
};
const results = {};
for (let round = 0; round < 3; round++) {
  for (const [name, draws] of Object.entries(cases)) {
    const before = cpuMs();
    const fps = await page.evaluate((d) => window.measure(d, 2500), draws);
    (results[name] ??= []).push([fps, (cpuMs() - before) / (fps * 2.5)]);
  }
}
const median = (v) => [...v].sort((a, b) => a - b)[1];
for (const [name, v] of Object.entries(results)) {
  console.log(`${name.padEnd(42)} ${median(v.map((r) => r[0])).toFixed(1)} frames/s, CPU ${median(v.map((r) => r[1])).toFixed(1)} ms/frame`);
}
await browser.close();
site.server.close();
