// Benchmark (docs/BENCHMARKS.md, never a test): what the page holds after a long session
// of gestures on one design. For `minutes`, real drags with tools changed by key go on
// the sheet; after every 10 gestures all 10 are undone, so the design stays the same
// size and the history only gains abandoned branches (at most MAX_BRANCHES are kept).
// Each minute prints the JS heap, the wasm memory and the GPU buffers and textures alive
// (`data-memory`). Memory must stop growing once the history is bounded.
//
//   cd tests/browser && node soak.mjs [minutes=30] [webgl2|webgpu]
import { attr, launch, openPage, sheet } from './harness.mjs';

const minutes = Number(process.argv[2] ?? 30);
const backend = process.argv[3] ?? 'webgl2';
const { site, browser } = await launch(backend, ['--enable-precise-memory-info']);
const { page, context, errors } = await openPage(browser, site, '', { width: 1100, height: 760 });
const s = await sheet(page);
const start = Date.now();
let gestures = 0;
let next = 0;
const rows = [];
const sample = async () => {
  const heap = await page.evaluate(() => performance.memory?.usedJSHeapSize ?? null);
  const memory = (await attr(page, 'data-memory')) ?? '';
  const field = (name) => /(?:^|,)NAME=([^,]+)/.source.replace('NAME', name);
  const get = (name) => new RegExp(field(name)).exec(memory)?.[1] ?? '-';
  const mb = (v) => (v === null || v === '-' ? '-' : (Number(v) / 1048576).toFixed(1));
  const row = `| ${((Date.now() - start) / 60000).toFixed(0)} | ${gestures} | ${await attr(page, 'data-ops')} | ${mb(heap)} | ${mb(get('wasm'))} | ${get('buffers')} | ${get('textures')} |`;
  rows.push(row);
  console.log(row);
};
console.log(`soak: ${minutes} min on ${backend}, 1100×760, stone`);
console.log('| minute | gestures | ops | JS heap (MB) | wasm memory (MB) | GPU buffers | GPU textures |');
console.log('|---:|---:|---:|---:|---:|---:|---:|');
await sample();
const keys = ['1', '2', '3', '4', '5', '6', '7', '8'];
while (Date.now() - start < minutes * 60000) {
  await page.keyboard.press(keys[gestures % keys.length]);
  const x = s.x + (100 + ((gestures * 97) % 440)) * s.scale;
  const y = s.y + (80 + ((gestures * 61) % 240)) * s.scale;
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let k = 1; k <= 6; k++) await page.mouse.move(x + k * 12, y + k * 7 * (gestures % 2 ? 1 : -1));
  await page.mouse.up();
  gestures++;
  if (gestures % 10 === 0) {
    for (let k = 0; k < 10; k++) await page.keyboard.press('Control+z');
  }
  await page.waitForTimeout(300);
  if (Date.now() - start >= (next + 1) * 60000) {
    next++;
    await sample();
  }
}
await sample();
if (errors.length) console.log(`page errors: ${errors.join(' | ')}`);
await context.close();
await browser.close();
site.server.close();
