// Shared by the diagnosis scripts (diagnose/: drag-rate, skip-draws, jit-profile, trace, gpu-calls,
// ab-drag; not run by npm test): the gallery design with its live-preview cache built,
// the tine tool chosen, and the pointer wiggled over the sheet; WebGPU draws skipped by
// pipeline label; and the perf test's gesture (`sweep`, used by perf.test.mjs too).
import { attr, sheet } from './harness.mjs';

/** Waits for the preview cache of the shown design, picks the tine tool (key 3) and
 *  parks the pointer over the sheet; returns that point. */
export async function tineOverSheet(page) {
  await page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: 240000 });
  const s = await sheet(page);
  await page.keyboard.press('3');
  const x = s.x + 100 * s.scale;
  const y = s.y + 200 * s.scale;
  await page.mouse.move(x, y);
  return { x, y };
}

/** The diagnosis scripts' gesture: `sweep` in a smaller wave (3 px steps, ±30 px)
 *  around (x, y) for `ms`; returns the app's frames per second meanwhile. */
export async function wiggle(page, { x, y }, ms) {
  return sweep(page, x, y, ms, 3, 30);
}

/** The perf test's gesture (perf.test.mjs, ab-drag.mjs): moves the pointer along a wave
 *  for `ms`, `step` px a move to the right (100 moves, then back to x) and ±`amplitude`
 *  px up and down (by default within 500 × 80 px right of and around (x, y), inside the
 *  sheet), and back to (x, y); returns the app's frame rate meanwhile (frames counted
 *  by the app, data-frames) in frames per second. */
export async function sweep(page, x, y, ms, step = 5, amplitude = 40) {
  const f0 = Number(await attr(page, 'data-frames'));
  const t0 = Date.now();
  let i = 0;
  while (Date.now() - t0 < ms) {
    i++;
    await page.mouse.move(x + step * (i % 100), y + amplitude * Math.sin(i / 10));
  }
  // Where the next gesture starts (a press beyond the sheet would start no drag).
  await page.mouse.move(x, y);
  const frames = Number(await attr(page, 'data-frames')) - f0;
  return (1000 * frames) / (Date.now() - t0);
}

/** Makes every page of `context` skip the WebGPU draws whose "LABEL COUNT" (the render
 *  pipeline's label, the draw's vertex or index count) matches the regex `skip`, and
 *  count the draws per label in `window.drawn`. */
export async function skipDraws(context, skip) {
  await context.addInitScript((skip) => {
    const re = new RegExp(skip);
    const labels = new WeakMap();
    window.drawn = {};
    const D = GPUDevice.prototype;
    for (const k of ['createRenderPipeline', 'createRenderPipelineAsync']) {
      const f = D[k];
      D[k] = function (desc) {
        const r = f.call(this, desc);
        if (r instanceof Promise) return r.then((p) => { labels.set(p, desc.label ?? '?'); return p; });
        labels.set(r, desc.label ?? '?');
        return r;
      };
    }
    const P = GPURenderPassEncoder.prototype;
    const setPipeline = P.setPipeline;
    P.setPipeline = function (p) { this.__label = labels.get(p) ?? '?'; return setPipeline.call(this, p); };
    for (const k of ['draw', 'drawIndexed']) {
      const f = P[k];
      P[k] = function (...a) {
        window.drawn[this.__label] = (window.drawn[this.__label] ?? 0) + 1;
        if (re.test(`${this.__label} ${a[0]}`)) return undefined;
        return f.apply(this, a);
      };
    }
  }, skip);
}
