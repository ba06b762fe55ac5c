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

/** Moves the pointer along a wave around (x, y) for `ms`; returns the app's frames per
 *  second meanwhile (data-frames). */
export async function wiggle(page, { x, y }, ms) {
  const f0 = Number(await attr(page, 'data-frames'));
  const t0 = Date.now();
  let i = 0;
  while (Date.now() - t0 < ms) {
    i++;
    await page.mouse.move(x + 3 * (i % 100), y + 30 * Math.sin(i / 10));
  }
  return (1000 * (Number(await attr(page, 'data-frames')) - f0)) / (Date.now() - t0);
}

/** The perf test's gesture (perf.test.mjs, ab-drag.mjs): moves the pointer along a wave
 *  for `ms`, within 500 × 80 px right of and around (x, y) (inside the sheet), and back
 *  to (x, y); returns the app's frame rate meanwhile (frames counted by the app,
 *  data-frames) in frames per second. */
export async function sweep(page, x, y, ms) {
  const f0 = Number(await attr(page, 'data-frames'));
  const t0 = Date.now();
  let i = 0;
  while (Date.now() - t0 < ms) {
    i++;
    await page.mouse.move(x + 5 * (i % 100), y + 40 * Math.sin(i / 10));
  }
  // Where the next gesture starts (a press beyond the sheet would start no drag).
  await page.mouse.move(x, y);
  const frames = Number(await attr(page, 'data-frames')) - f0;
  return (1000 * frames) / (Date.now() - t0);
}
