// Diagnosis: a Chrome trace of 3 s of hovering or dragging a tine over the gallery design;
// prints the busiest threads and their top-level events per frame.
// node trace.mjs [webgpu|webgl2] [hover|drag] OUT.json [flags…]
import fs from 'node:fs';
import { launch, openPage } from '../harness.mjs';
import { tineOverSheet, wiggle } from '../probe.mjs';
const [backend = 'webgpu', mode = 'drag', out = '/tmp/trace.json', ...extra] = process.argv.slice(2);
const { browser, site } = await launch(backend, extra);
const { page } = await openPage(browser, site, '', { width: 1024, height: 768 });
const at = await tineOverSheet(page);
if (mode === 'drag') await page.mouse.down();
await wiggle(page, at, 2000);
await browser.startTracing(page, { path: out, categories: ['toplevel', 'gpu', 'viz', 'cc', 'benchmark', 'disabled-by-default-devtools.timeline', 'devtools.timeline', 'blink', 'skia', 'v8'] });
const frames = Math.round(3 * (await wiggle(page, at, 3000)));
await browser.stopTracing();
await browser.close(); site.server.close();
const ev = JSON.parse(fs.readFileSync(out)).traceEvents;
const names = {};
for (const e of ev) if (e.ph === 'M' && e.name === 'thread_name') names[e.pid + ':' + e.tid] = e.args.name;
const per = {};
for (const e of ev) {
  if (e.ph !== 'X' || !e.dur) continue;
  const k = e.pid + ':' + e.tid;
  (per[k] ??= []).push(e);
}
console.log(`${frames} app frames in ~3 s`);
for (const [k, list] of Object.entries(per)) {
  list.sort((a, b) => a.ts - b.ts);
  // top-level = not inside the previous top-level event
  let end = -1; const top = {};
  let busy = 0;
  for (const e of list) {
    if (e.ts >= end) { top[e.name] = (top[e.name] ?? 0) + e.dur; busy += e.dur; end = e.ts + e.dur; }
  }
  if (busy < 100000) continue;
  console.log(`\n${names[k] ?? k}: busy ${(busy / 1000).toFixed(0)} ms = ${(busy / 1000 / frames).toFixed(1)} ms/frame`);
  for (const [n, d] of Object.entries(top).sort((a, b) => b[1] - a[1]).slice(0, 8)) console.log(`  ${(d / 1000 / frames).toFixed(2)} ms/frame  ${n}`);
}
