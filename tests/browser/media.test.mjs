// Pictures, live video and sound, in headless Chromium (WebGL2 on SwiftShader) with its
// fake camera and microphone: a picture dropped on the window is marbled and a broken
// one leaves the design; the webcam's frames change over time under the design's ink;
// the microphone's test tones light their own bands and its pulses drop ink on the
// beat. One browser launch for the file (cheap: small sheets, few frames).
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {
  READY_MS, SHOTS, attr, clickControl, download, dropFile, launch, linkFragment, openPage, shootSheet, twoColourPng,
} from './harness.mjs';

/**
 * The fake microphone's sound, a 16-bit mono WAV at 48 kHz that Chromium loops: 440 Hz
 * (band 2) for 2.5 s, 3520 Hz (band 5) for 2.5 s, then 880 Hz (band 3) pulsed 0.5 s on,
 * 0.7 s off, five times; each at half of full scale, faded in and out over 20 ms (no
 * clicks to spill into the other bands).
 */
function toneWav() {
  const rate = 48000;
  const fade = (t, len) => Math.min(1, t / 0.02, (len - t) / 0.02);
  const parts = [
    [440, 2.5, (t) => fade(t, 2.5)],
    [3520, 2.5, (t) => fade(t, 2.5)],
    [880, 6, (t) => (t % 1.2 < 0.5 ? fade(t % 1.2, 0.5) : 0)],
  ];
  const samples = [];
  for (const [hz, seconds, envelope] of parts) {
    for (let i = 0; i < seconds * rate; i++) {
      const t = i / rate;
      samples.push(0.5 * envelope(t) * Math.sin(2 * Math.PI * hz * t));
    }
  }
  const data = Buffer.alloc(44 + 2 * samples.length);
  data.write('RIFF', 0); data.writeUInt32LE(36 + 2 * samples.length, 4); data.write('WAVE', 8);
  data.write('fmt ', 12); data.writeUInt32LE(16, 16); data.writeUInt16LE(1, 20); data.writeUInt16LE(1, 22);
  data.writeUInt32LE(rate, 24); data.writeUInt32LE(2 * rate, 28); data.writeUInt16LE(2, 32); data.writeUInt16LE(16, 34);
  data.write('data', 36); data.writeUInt32LE(2 * samples.length, 40);
  samples.forEach((v, i) => data.writeInt16LE(Math.round(v * 32767), 44 + 2 * i));
  const file = path.join(os.tmpdir(), `marbling-tones-${process.pid}.wav`);
  fs.writeFileSync(file, data);
  return file;
}

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
    ({ browser, site } = await launch('webgl2', [
      '--use-fake-device-for-media-stream', '--use-fake-ui-for-media-stream',
      `--use-file-for-fake-audio-capture=${toneWav()}`, '--autoplay-policy=no-user-gesture-required',
    ]));
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

  test('sound: each tone of the fake microphone leads its band; pulses drop ink on the beat', async () => {
    // A small window: each beat's drop is an exact render, and the analyser is read once
    // a frame (on SwiftShader a large canvas's render would hold frames back past beats).
    const { page, context, errors } = await openPage(browser, site, linkFragment(DESIGN, 'media-sound'), { width: 700, height: 440 });
    await clickControl(page, 'sound-microphone');
    // The loop plays 440 Hz, then 3520 Hz: band 2, then band 5 leads the meter.
    const led = new Set();
    const t0 = Date.now();
    let heard = null;
    while (led.size < 2 && Date.now() - t0 < 60_000) {
      heard = await attr(page, 'data-audio');
      const levels = (heard ?? '').split(',').map(Number);
      if (levels.length === 6) {
        const top = levels.indexOf(Math.max(...levels));
        const rest = Math.max(...levels.filter((_, k) => k !== top));
        if ((top === 1 || top === 4) && levels[top] > 0.6 && rest < 0.3) led.add(top + 1);
      }
      await page.waitForTimeout(100);
    }
    assert.deepEqual([...led].sort(), [2, 5], `bands seen leading: ${[...led]}; last levels ${heard}; error ${await attr(page, 'data-error')}`);
    // Band 3 (the pulsed 880 Hz) drops ink on its beats.
    await clickControl(page, 'sound-target-3');
    // The list opens after egui's sizing pass: a few frames on, its options are placed.
    const frames = Number(await attr(page, 'data-frames'));
    await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n + 3, frames, { timeout: READY_MS });
    await clickControl(page, 'sound-target-3-beat');
    await page.waitForFunction(() => Number(document.body.dataset.ops) >= 3, null, { timeout: READY_MS });
    await page.screenshot({ path: path.join(SHOTS, 'sound-beats.png'), timeout: READY_MS });
    await clickControl(page, 'sound-stop');
    await page.waitForFunction(() => document.body.dataset.audio === undefined && document.body.dataset.ready === '1', null, { timeout: READY_MS });
    const saved = JSON.parse((await download(page, 'save-json')).bytes.toString('utf8'));
    const drops = saved.ops.slice(1);
    assert.ok(drops.length >= 2 && drops.every((op) => op.type === 'drop'), JSON.stringify(drops));
    // Half the drop tool's radius and more, by the level of the beat.
    assert.ok(drops.every((d) => d.radius >= 0.5 * 30 && d.radius <= 1.5 * 30 * 1.0001), JSON.stringify(drops.map((d) => d.radius)));
    const n = saved.ops.length;
    await page.keyboard.press('Control+z');
    await page.waitForFunction((k) => Number(document.body.dataset.ops) === k - 1, n, { timeout: READY_MS });
    assert.deepEqual(errors, []);
    await context.close();
  });
});
