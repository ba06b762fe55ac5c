// Diagnosis: compares two builds of the web app on the perf test's workload (the
// 1,000-op 1024×768 design, tine drag) in alternating runs, so that the machine's drift
// hits both alike: node ab-drag.mjs DIST_A DIST_B [RUNS] [flags…]. Each run: hover 3 s,
// then drag 5 s (after 2 s of drag, so the preview has settled on its sample count);
// prints frames/s per run and the medians. Not run by npm test.
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { MARBLING, launch, openPage, serve, sheet } from '../harness.mjs';
import { sweep as wiggle } from '../probe.mjs';

const [distA, distB, runs = '3', ...flags] = process.argv.slice(2);
const design = path.join(os.tmpdir(), `marbling-ab-${process.pid}.json`);
execFileSync(MARBLING, ['random', '--ops', '1000', '--size', '1024x768', '--seed', '11', '--mix', 'mixed', '-o', design]);

async function run(dist) {
  const { browser, site: own } = await launch('webgpu', flags);
  own.server.close();
  const site = await serve(dist);
  try {
    const link = execFileSync(MARBLING, ['link', design, '--base', site.url]).toString().trim();
    const { page } = await openPage(browser, site, link.slice(link.indexOf('#')), { width: 1024, height: 768 });
    await page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: 240000 });
    const s = await sheet(page);
    await page.keyboard.press('3');
    const [x, y] = [s.x + 100 * s.scale, s.y + 384 * s.scale];
    await page.mouse.move(x, y);
    const hover = await wiggle(page, x, y, 3000);
    await page.mouse.down();
    await wiggle(page, x, y, 2000);
    const drag = await wiggle(page, x, y, 5000);
    await page.mouse.up();
    return { hover, drag };
  } finally {
    await browser.close();
    site.server.close();
  }
}

const median = (v) => [...v].sort((a, b) => a - b)[Math.floor(v.length / 2)];
const out = { A: [], B: [] };
for (let i = 0; i < Number(runs); i++) {
  for (const [k, dist] of [['A', distA], ['B', distB]]) {
    const r = await run(dist);
    out[k].push(r);
    console.log(`${k} run ${i + 1}: hover ${r.hover.toFixed(1)}, drag ${r.drag.toFixed(1)} frames/s`);
  }
}
for (const k of ['A', 'B']) {
  console.log(`${k} (${k === 'A' ? distA : distB}): median hover ${median(out[k].map((r) => r.hover)).toFixed(1)}, drag ${median(out[k].map((r) => r.drag)).toFixed(1)} frames/s`);
}
fs.rmSync(design, { force: true });
