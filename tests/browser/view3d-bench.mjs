// Benchmark (docs/perf-log/view3d.md, never a test): the 3D view turning with and
// without a style, the whole interaction. A fresh 1280×800 page opens the Stone pattern
// by link, opens the 3D view and its Style section, picks hatching, turns the vase, and
// counts the view's frames over 6 s (`data-view3d-frames`); then the same with no
// style. Printed: frames/s of each and the style field's time in the page
// (`data-view3d.style.ms`, one thread of wasm).
//
//   cd tests/browser && node view3d-bench.mjs [webgpu|webgl2]
import { launch, openPage, clickControl, controls, attr, example, linkFragment } from './harness.mjs';
const backend = process.argv[2] ?? 'webgpu';
const { browser, site } = await launch(backend);
const stone = example('stone');
const { page, context, errors } = await openPage(browser, site, linkFragment(stone.design, 'tf'), { width: 1280, height: 800 });
const v3 = async () => JSON.parse(await attr(page, 'data-view3d'));
await clickControl(page, 'view3d');
await page.waitForFunction(() => Number(document.body.dataset.view3dFrames) >= 1, null, { timeout: 120000 });
const rate = async (s) => {
  const f0 = Number(await attr(page, 'data-view3d-frames')); const t0 = Date.now();
  await page.waitForTimeout(s * 1000);
  return (Number(await attr(page, 'data-view3d-frames')) - f0) / ((Date.now() - t0) / 1000);
};
await page.waitForTimeout(2000);
await clickControl(page, 'view3d-style-section');
await page.waitForFunction(() => `;${document.body.dataset.controls ?? ''}`.includes(';view3d-style='), null, { timeout: 60000 });
// The hooks lag the picture by a frame: move the mouse and wait two frames.
const fresh = async () => {
  await page.mouse.move(2, 2);
  const n = Number(await attr(page, 'data-frames'));
  await page.mouse.move(3, 3);
  await page.waitForFunction((m) => Number(document.body.dataset.frames) >= m, n + 2);
};
await fresh();
await clickControl(page, 'view3d-style');
await page.waitForFunction(() => `;${document.body.dataset.controls ?? ''}`.includes(';view3d-style-hatching='), null, { timeout: 60000 });
const f = Number(await attr(page, 'data-frames'));
await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, f + 2);
await clickControl(page, 'view3d-style-hatching');
await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).style?.kernels > 0, null, { timeout: 60000 });
await clickControl(page, 'view3d-turn');
await page.waitForTimeout(3000);
const styled = await rate(6);
const field = (await v3()).style;
await fresh();
await clickControl(page, 'view3d-style');
await page.waitForFunction(() => `;${document.body.dataset.controls ?? ''}`.includes(';view3d-style-none='), null, { timeout: 60000 });
await fresh();
await clickControl(page, 'view3d-style-none');
await page.waitForFunction(() => JSON.parse(document.body.dataset.view3d).style === null, null, { timeout: 60000 });
await page.waitForTimeout(2000);
const plain = await rate(6);
const pane = (await controls(page))['view3d-pane-0'];
console.log(`${backend} ${process.env.MARBLING_DIST ?? 'dist'}: pane ${pane.w}×${pane.h}, turning: plain ${plain.toFixed(2)} frames/s, hatching ${styled.toFixed(2)} frames/s, its field ${field.ms.toFixed(0)} ms (${field.kernels} kernels)`, errors);
await context.close(); await browser.close(); site.server.close();
