import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import { launch, attr } from './harness.mjs';
const M = '/work/main/target/debug/marbling';
const ops = Number(process.argv[2] ?? 20000);
const { browser, site } = await launch('webgpu');
try {
  execFileSync(M, ['random', '--ops', String(ops), '--size', '800x600', '--seed', '1', '--mix', 'mixed', '-o', '/tmp/h.json']);
  const link = execFileSync(M, ['link', '/tmp/h.json', '--base', site.url], { maxBuffer: 64 << 20 }).toString().trim();
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  await page.goto(site.url + link.slice(link.indexOf('#')));
  await page.waitForFunction((n) => document.body.dataset.ops === String(n), ops, { timeout: 300000 });
  await page.waitForTimeout(15000);
  const f0 = Number(await attr(page, 'data-frames'));
  const out = '/tmp/bigtrace.json';
  await browser.startTracing(page, { path: out, categories: ['toplevel', 'gpu', 'viz', 'cc', 'devtools.timeline', 'blink', 'v8', 'disabled-by-default-devtools.timeline', 'gpu.dawn', 'disabled-by-default-gpu.dawn', 'gpu.service', 'gpu.capture'] });
  await page.waitForTimeout(5000);
  await browser.stopTracing();
  const frames = Number(await attr(page, 'data-frames')) - f0;
  console.log('frames', frames, 'work', await attr(page, 'data-gpu-work'), 'progress', await attr(page, 'data-progress'));
  const ev = JSON.parse(fs.readFileSync(out)).traceEvents;
  const names = {};
  for (const e of ev) if (e.ph === 'M' && e.name === 'thread_name') names[e.pid + ':' + e.tid] = e.args.name;
  const per = {};
  for (const e of ev) { if (e.ph !== 'X' || !e.dur) continue; (per[e.pid + ':' + e.tid] ??= []).push(e); }
  for (const [k, list] of Object.entries(per)) {
    list.sort((a, b) => a.ts - b.ts);
    let end = -1; const top = {}; let busy = 0; const second = {}; let end2 = -1;
    for (const e of list) {
      if (e.ts >= end) { top[e.name] = (top[e.name] ?? 0) + e.dur; busy += e.dur; end = e.ts + e.dur; end2 = -1; }
      else if (e.ts >= end2) { second[e.name] = (second[e.name] ?? 0) + e.dur; end2 = e.ts + e.dur; }
    }
    top['  >'] = 0; const incl = {}; for (const e of list) incl[e.name] = (incl[e.name] ?? 0) + e.dur; for (const [n, d] of Object.entries(incl)) top['  * ' + n] = d;
    for (const [n, d] of Object.entries(second)) top['  > ' + n] = d;
    if (busy < 100000) continue;
    console.log(`\n${names[k] ?? k}: busy ${(busy / 1000).toFixed(0)} ms = ${(busy / 1000 / frames).toFixed(1)} ms/frame`);
    for (const [n, d] of Object.entries(top).sort((a, b) => b[1] - a[1]).slice(0, 40)) console.log(`  ${(d / 1000 / frames).toFixed(2)} ms/frame  ${n}`);
  }
  // main-thread second level: children of the biggest top-level events on the renderer main
} catch (e) { console.log(String(e).slice(0, 400)); }
await browser.close(); site.server.close();
