// Time to the first exact frame: opens `?landing=0` (the Stone pattern) in the browser
// tests' 1000×660 window N times per backend in one browser and prints the time to
// `data-ready` (docs/BENCHMARKS.md, "Progressive exact rendering"). Needs `make web`.
//   cd tests/browser && node boot-bench.mjs [webgl2,webgpu] [N]
import { launch, openPage } from './harness.mjs';

const backends = (process.argv[2] ?? 'webgl2,webgpu').split(',');
const n = Number(process.argv[3] ?? 2);
for (const backend of backends) {
  const { browser, site } = await launch(backend);
  for (let i = 0; i < n; i++) {
    const t0 = Date.now();
    const { context } = await openPage(browser, site);
    console.log(`${backend}: open ${i + 1}: data-ready after ${((Date.now() - t0) / 1000).toFixed(1)} s`);
    await context.close();
  }
  await browser.close();
  site.server.close();
}
