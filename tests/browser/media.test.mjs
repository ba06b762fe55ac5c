// Pictures and live video as the background, in headless Chromium (WebGL2 on
// SwiftShader) with its fake camera: a picture dropped on the window is marbled and a
// broken one leaves the design; the webcam's frames change over time under the design's
// ink. One browser launch for the file (cheap: small sheets, few frames).
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import {
  READY_MS, SHOTS, attr, clickControl, dropFile, launch, linkFragment, openPage, shootSheet, twoColourPng,
} from './harness.mjs';

const INK = [200, 30, 40];
/** A 160×120 sheet with one big red drop in the middle (the marbling the video shows through). */
const DESIGN = {
  version: 1, width: 160, height: 120, background: '#ffffff',
  ops: [{ type: 'drop', center: [80, 60], radius: 30, color: '#c81e28' }],
};

const pixel = (img, fx, fy) => {
  const i = (Math.floor(fy * img.height) * img.width + Math.floor(fx * img.width)) * 4;
  return [img.data[i], img.data[i + 1], img.data[i + 2]];
};
const near = (a, b, tol = 24) => a.every((v, k) => Math.abs(v - b[k]) <= tol);

describe('pictures and live video on webgl2', () => {
  let browser;
  let site;
  before(async () => {
    ({ browser, site } = await launch('webgl2', ['--use-fake-device-for-media-stream', '--use-fake-ui-for-media-stream']));
  });
  after(async () => {
    await browser?.close();
    site?.server.close();
  });

  test('a dropped picture is marbled under the ink; a broken one leaves the design', async () => {
    const { page, context, errors } = await openPage(browser, site, linkFragment(DESIGN, 'media-drop'));
    await dropFile(page, 'halves.png', 'image/png', twoColourPng());
    await page.waitForFunction(() => (document.body.dataset.error ?? '') === '' && document.querySelector('body').dataset.ready === '1', null, { timeout: READY_MS });
    await page.waitForTimeout(1500);
    const { img } = await shootSheet(page, DESIGN.width, DESIGN.height);
    // Cover fit: 64×48 scaled ×2.5 covers 160×120; the drop in the middle is ink, the
    // picture's halves show left and right of it.
    assert.ok(near(pixel(img, 0.5, 0.5), INK), `centre ${pixel(img, 0.5, 0.5)}`);
    assert.ok(near(pixel(img, 0.05, 0.5), [30, 60, 220]), `left ${pixel(img, 0.05, 0.5)}`);
    assert.ok(near(pixel(img, 0.95, 0.5), [240, 210, 20]), `right ${pixel(img, 0.95, 0.5)}`);
    fs.mkdirSync(SHOTS, { recursive: true });
    await page.screenshot({ path: path.join(SHOTS, 'image-background.png'), timeout: READY_MS });
    await dropFile(page, 'broken.png', 'image/png', Buffer.from('not a picture'));
    await page.waitForFunction(() => (document.body.dataset.error ?? '').includes('broken.png'), null, { timeout: READY_MS });
    const message = await attr(page, 'data-error');
    assert.match(message, /cannot decode/);
    const after = await shootSheet(page, DESIGN.width, DESIGN.height);
    assert.ok(near(pixel(after.img, 0.05, 0.5), [30, 60, 220]), 'the picture is still there');
    assert.deepEqual(errors, []);
    await context.close();
  });

  test('the fake camera is marbled live: frames change, the ink stays', async () => {
    const { page, context, errors } = await openPage(browser, site, linkFragment(DESIGN, 'media-camera'));
    await clickControl(page, 'video-camera');
    await page.waitForFunction(() => Number(document.body.dataset.videoFrames ?? 0) >= 3, null, { timeout: READY_MS });
    const first = await shootSheet(page, DESIGN.width, DESIGN.height);
    const frames = Number(await attr(page, 'data-video-frames'));
    await page.waitForFunction((n) => Number(document.body.dataset.videoFrames) >= n + 10, frames, { timeout: READY_MS });
    await page.waitForTimeout(500);
    const second = await shootSheet(page, DESIGN.width, DESIGN.height);
    // The ink of the drop covers the centre in both frames…
    for (const s of [first, second]) assert.ok(near(pixel(s.img, 0.5, 0.5), INK), `centre ${pixel(s.img, 0.5, 0.5)}`);
    // …while the camera's picture around it moved on (Chromium's fake camera animates).
    // The fake camera is mostly flat green: its moving parts are the rotating wedge
    // round the middle and the time code, so sample the whole sheet outside the drop.
    let changed = 0;
    for (let y = 0.01; y < 1; y += 0.02) for (let x = 0.01; x < 1; x += 0.02) {
      if (Math.hypot((x - 0.5) * DESIGN.width, (y - 0.5) * DESIGN.height) < 34) continue;
      if (!near(pixel(first.img, x, y), pixel(second.img, x, y), 8)) changed++;
    }
    assert.ok(changed > 10, `only ${changed} sampled pixels changed between frames`);
    // Not the plain white paper: the camera's picture is under the ink.
    assert.ok(!near(pixel(second.img, 0.05, 0.05), [255, 255, 255], 4), `corner ${pixel(second.img, 0.05, 0.05)}`);
    await page.screenshot({ path: path.join(SHOTS, 'video-fake-camera.png'), timeout: READY_MS });
    await clickControl(page, 'video-stop');
    assert.deepEqual(errors, []);
    await context.close();
  });
});
