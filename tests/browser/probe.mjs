// Shared by the diagnosis scripts (drag-rate, skip-draws, trace, gpu-calls; not run by
// npm test): the gallery design with its live-preview cache built, the tine tool
// chosen, and the pointer wiggled over the sheet.
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
