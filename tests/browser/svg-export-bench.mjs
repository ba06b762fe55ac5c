// Benchmark (docs/BENCHMARKS.md, never a test): what a user waits for after *Export SVG*.
// Each named example is opened as a #d= link on WebGL2, and the time from the click to
// the downloaded file is printed. The export is CPU work in wasm on the page's one
// thread, so the page is frozen for that long.
//
//   cd tests/browser && node svg-export-bench.mjs [stone,serpentine,chevron]
import { download, example, launch, linkFragment, openPage } from './harness.mjs';

const names = (process.argv[2] ?? 'stone,serpentine,chevron').split(',');
const { site, browser } = await launch('webgl2');
console.log('| example | size | click to file (ms) | SVG bytes | contour paths | forward paths |');
console.log('|---|---|---:|---:|---:|---:|');
for (const name of names) {
  const { design } = example(name);
  const { page, context } = await openPage(browser, site, linkFragment(design, `svg-bench-${name}`));
  const start = Date.now();
  const svg = await download(page, 'export-svg');
  const ms = Date.now() - start;
  const text = svg.bytes.toString('utf8');
  const count = (method) => (text.match(new RegExp(`data-method="${method}"`, 'g')) || []).length;
  console.log(`| ${name} | ${design.width}×${design.height} | ${ms} | ${svg.bytes.length} | ${count('contour')} | ${count('forward')} |`);
  await context.close();
}
await browser.close();
site.server.close();
