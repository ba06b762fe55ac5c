// Shared by the diagnosis scripts (drag-rate, skip-draws, trace, gpu-calls, ab-drag;
// not run by npm test): the gallery design with its live-preview cache built, the tine
// tool chosen, and the pointer wiggled over the sheet; and the perf test's gesture
// (`sweep`, used by perf.test.mjs too).
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
