// Benchmark (docs/BENCHMARKS.md, never a test): what a user waits for after *Export SVG*.
// Each named example is opened as a #d= link on WebGL2; printed: the time from the click
// to the downloaded file, and the worst gap between two animation frames meanwhile (the
// trace runs a frame's budget at a time on the page's one thread, so this is how long
// the page was frozen at most).
//
//   cd tests/browser && node svg-export-bench.mjs [stone,serpentine,chevron]
import { download, example, launch, linkFragment, openPage, recordFrames } from './harness.mjs';

const names = (process.argv[2] ?? 'stone,serpentine,chevron').split(',');
const { site, browser } = await launch('webgl2');
console.log('| example | size | click to file (ms) | worst frame gap (ms) | SVG bytes | contour paths | forward paths |');
console.log('|---|---|---:|---:|---:|---:|---:|');
for (const name of names) {
  const { design } = example(name);
  const { page, context } = await openPage(browser, site, linkFragment(design, `svg-bench-${name}`));
  await page.evaluate(recordFrames);
  const from = await page.evaluate(() => performance.now());
  const start = Date.now();
  const svg = await download(page, 'export-svg');
  const ms = Date.now() - start;
  const to = await page.evaluate(() => performance.now());
  const times = await page.evaluate(() => window.frameTimes);
  let worst = 0;
  let at = 0;
  const gaps = [];
  for (let i = 1; i < times.length; i++) {
    if (times[i] > from && times[i - 1] < to) {
      const gap = times[i] - times[i - 1];
      gaps.push(gap);
      if (gap > worst) [worst, at] = [gap, times[i - 1] - from];
    }
  }
  gaps.sort((a, b) => a - b);
  if (process.env.GAPS) console.log(`${name}: ${gaps.length} frames, median ${gaps[gaps.length >> 1]?.toFixed(0)} ms, worst ${worst.toFixed(0)} ms at ${(at / 1000).toFixed(1)} s`);
  const text = svg.bytes.toString('utf8');
  const count = (method) => (text.match(new RegExp(`data-method="${method}"`, 'g')) || []).length;
  console.log(`| ${name} | ${design.width}×${design.height} | ${ms} | ${worst.toFixed(0)} | ${svg.bytes.length} | ${count('contour')} | ${count('forward')} |`);
  await context.close();
}
await browser.close();
site.server.close();
