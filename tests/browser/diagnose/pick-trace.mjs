// Diagnosis: a Chrome trace of picking a noise type in the Noise tab (the freeze the
// noise bench times); prints the longest tasks of each busy thread in the traced window,
// with the longest events nested in each (what a freeze is made of).
// node pick-trace.mjs [webgpu|webgl2] TYPE SECONDS OUT.json
import fs from 'node:fs';
import { attr, controls, launch } from '../harness.mjs';

const [backend = 'webgl2', type = 'gabor', seconds = '8', out = '/tmp/pick-trace.json'] = process.argv.slice(2);
const { browser, site } = await launch(backend);
const press = async (page, name) => {
  const c = (await controls(page))[name];
  if (!c) throw new Error(`no control ${name}`);
  await page.mouse.click(c.x + c.w / 2, c.y + c.h / 2);
};
try {
  const context = await browser.newContext({ viewport: { width: 1280, height: 800 }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  await page.goto(`${site.url}?landing=0`);
  await page.waitForFunction(() => document.body.dataset.ready === '1', null, { timeout: 600_000 });
  await press(page, 'mode-noise');
  await page.waitForFunction(() => document.body.dataset.mode === 'noise', null, { timeout: 600_000 });
  await page.waitForTimeout(20_000);
  await press(page, 'noise-type');
  await page.waitForTimeout(1000);
  await browser.startTracing(page, { path: out, categories: ['toplevel', 'gpu', 'gpu.service', 'v8', 'devtools.timeline', 'disabled-by-default-gpu.service', 'disabled-by-default-devtools.timeline'] });
  await press(page, `noise-type-${type}`);
  await page.waitForTimeout(Number(seconds) * 1000);
  await browser.stopTracing();
  console.log(`noise now: ${await attr(page, 'data-noise')}`);
  await context.close();
} finally {
  await browser.close();
  site.server.close();
}
const ev = JSON.parse(fs.readFileSync(out)).traceEvents;
const names = {};
for (const e of ev) if (e.ph === 'M' && e.name === 'thread_name') names[e.pid + ':' + e.tid] = e.args.name;
const per = {};
for (const e of ev) {
  if (e.ph !== 'X' || !e.dur) continue;
  (per[e.pid + ':' + e.tid] ??= []).push(e);
}
for (const [k, list] of Object.entries(per)) {
  list.sort((a, b) => a.ts - b.ts || b.dur - a.dur);
  const tops = [];
  let end = -1;
  for (const e of list) if (e.ts >= end) { tops.push(e); end = e.ts + e.dur; }
  const long = tops.filter((e) => e.dur > 150_000).sort((a, b) => b.dur - a.dur).slice(0, 4);
  if (long.length === 0) continue;
  console.log(`\n${names[k] ?? k}:`);
  for (const t of long) {
    console.log(`  ${(t.dur / 1000).toFixed(0)} ms  ${t.name}  at ${((t.ts - list[0].ts) / 1000).toFixed(0)} ms`);
    const inside = list.filter((e) => e !== t && e.ts >= t.ts && e.ts + e.dur <= t.ts + t.dur && e.dur > 20_000);
    const byName = {};
    for (const e of inside) byName[e.name] = Math.max(byName[e.name] ?? 0, e.dur);
    for (const [n, d] of Object.entries(byName).sort((a, b) => b[1] - a[1]).slice(0, 8)) console.log(`      ${(d / 1000).toFixed(0)} ms  ${n}`);
  }
}
