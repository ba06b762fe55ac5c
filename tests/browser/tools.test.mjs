// The tools schemas v3 and v4 added, as a user meets them in Chromium on WebGL2: a drop
// pattern shows its ghost drops before the click and lays one op cycling the palette, a
// jiggle, a shift, a turn, a comb of five tines as one op and a free-hand stylus with
// three tips — each changes the canvas, each is one undo step, the saved document
// holds the v3 ops, and the app's exact picture of it is `marbling render`'s; the flow
// tool streams the ink along a curl noise as one v4 op, drawn as the CLI draws it. One
// browser, a small sheet.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {
  attr, linkFragment, longOnly, MARBLING, READY_MS, SHOTS, clickControl, crop, decode, differing, download, launch, sheet, shootSheet, waitOps, waitReady,
} from './harness.mjs';

const SMALL = {
  version: 1, width: 300, height: 200, background: '#f4ecd8',
  ops: [
    { type: 'drop', center: [150, 100], radius: 60, color: '#2a9d8f' },
  ],
};

const PREFS = JSON.stringify({
  tool: 'drop',
  palette: 0,
  ink: '#1d3557',
  antialias: 'rgss',
  settings: {
    drop_radius: 9, drop_growth: 0, drop_pattern: 'grid', pattern_rows: 3, pattern_columns: 4,
    pattern_spacing: 40, cycle_colors: true, stylus_wake: 4, stylus_tips: 3, stylus_spacing: 25,
    comb_tines: 5, comb_spacing: 30, jiggle_wavelength: 90, jiggle_along: 6, jiggle_across: 10,
  },
});

describe('v3 tools on webgl2', () => {
  let browser;
  let site;
  before(async () => {
    ({ browser, site } = await launch('webgl2'));
  });
  after(async () => {
    await browser?.close();
    site?.server.close();
  });

  test('drop pattern, stylus, comb, jiggle, shift and turn: one op each, the CLI picture', async () => {
    const context = await browser.newContext({ viewport: { width: 760, height: 480 }, deviceScaleFactor: 1, acceptDownloads: true });
    await context.addInitScript((p) => localStorage.setItem('marbling.prefs.v1', p), PREFS);
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(site.url + linkFragment(SMALL, 'tools'));
    let n = SMALL.ops.length;
    await waitOps(page, n);
    const s = await sheet(page);
    const p = (x, y) => ({ x: s.x + x * s.scale, y: s.y + y * s.scale });
    let last = await shootSheet(page, SMALL.width, SMALL.height);

    // Ghost drops: hovering with a pattern draws its 12 drops before any click.
    const c = p(150, 100);
    await page.mouse.move(c.x, c.y);
    await page.waitForTimeout(400);
    const clip = { x: Math.round(s.x), y: Math.round(s.y), width: Math.floor(SMALL.width * s.scale), height: Math.floor(SMALL.height * s.scale) };
    const hovering = decode(await page.screenshot({ clip, timeout: READY_MS }));
    assert.ok(differing(last.img, hovering, 24) > 0.002, 'no ghost drops before the click');
    await page.mouse.click(c.x, c.y);

    // Each step: draw, wait for its one op, check the canvas changed.
    const t0 = Date.now();
    const step = async (name, draw) => {
      await draw();
      console.log(`tools: ${name} drawn after ${((Date.now() - t0) / 1000).toFixed(1)} s`);
      n += 1;
      await waitOps(page, n);
      const now = await shootSheet(page, SMALL.width, SMALL.height);
      const changed = differing(last.img, now.img, 8);
      console.log(`tools: ${name} changed ${(100 * changed).toFixed(2)} % of the sheet after ${((Date.now() - t0) / 1000).toFixed(1)} s`);
      assert.ok(changed > 0.003, `${name} did not change the canvas`);
      last = now;
    };
    const drag = async (points) => {
      await page.mouse.move(points[0].x, points[0].y);
      await page.mouse.down();
      for (const q of points.slice(1)) await page.mouse.move(q.x, q.y);
      await page.mouse.up();
    };
    await step('drop grid', async () => {});
    await step('jiggle', async () => {
      await clickControl(page, 'tool-jiggle');
      await drag([p(100, 100), p(130, 110), p(160, 120)]);
    });
    await step('shift', async () => {
      await clickControl(page, 'tool-shift');
      await drag([p(150, 100), p(165, 105), p(180, 110)]);
    });
    await step('turn', async () => {
      await clickControl(page, 'tool-turn');
      const pts = [];
      for (let i = 0; i <= 8; i++) pts.push(p(150 + 60 * Math.cos(i / 16), 100 + 60 * Math.sin(i / 16)));
      await drag(pts);
    });
    await step('comb', async () => {
      await clickControl(page, 'tool-comb');
      await drag([p(150, 30), p(150, 60), p(150, 90), p(150, 110)]);
    });
    await step('stylus', async () => {
      await clickControl(page, 'tool-stylus');
      const pts = [];
      for (let i = 0; i <= 10; i++) pts.push(p(40 + 22 * i, 100 + 45 * Math.sin(i / 1.6)));
      await drag(pts);
    });
    await page.screenshot({ path: path.join(SHOTS, 'tools-v3-webgl2.png'), timeout: READY_MS });

    // The saved document: version 3, the six ops in order, the pattern cycling colours.
    const saved = JSON.parse((await download(page, 'save-json')).bytes.toString('utf8'));
    assert.equal(saved.version, 3);
    // Several-record ops (comb, stylus) last: every exact frame after them walks them.
    assert.deepEqual(saved.ops.slice(1).map((o) => o.type), ['drops', 'jiggle', 'shift', 'turn', 'comb', 'stylus']);
    const drops = saved.ops[1];
    assert.equal(drops.centers.length, 12);
    assert.ok(drops.colors.length >= 4, `the pattern did not cycle the palette: ${drops.colors}`);
    assert.deepEqual(saved.ops[5].tines, [-60, -30, 0, 30, 60]);
    assert.deepEqual(saved.ops[6].tips, [-25, 0, 25]);

    // The app's exact picture is the CLI's.
    const file = path.join(os.tmpdir(), `marbling-tools-saved-${process.pid}.json`);
    fs.writeFileSync(file, JSON.stringify(saved));
    const out = path.join(os.tmpdir(), `marbling-tools-${process.pid}.png`);
    execFileSync(MARBLING, ['render', file, '-o', out, '--scale', String(last.scale), '--aa', 'rgss']);
    const cpu = decode(fs.readFileSync(out));
    const w = Math.min(cpu.width, last.img.width);
    const h = Math.min(cpu.height, last.img.height);
    const frac = differing(crop(cpu, w, h), crop(last.img, w, h), 24);
    console.log(`tools: app vs CLI: ${(100 * frac).toFixed(3)} % of ${w}×${h} px differ by > 24/255`);
    assert.ok(frac <= 0.01, `${(100 * frac).toFixed(2)} % of pixels differ from the CLI render`);

    assert.equal(drops.radius, 9, 'a mouse (no pressure) changed the drop size');

    // Each tool was one undo step.
    for (let k = 1; k <= 6; k++) {
      await page.keyboard.press('Control+z');
      await waitOps(page, n - k);
    }
    n -= 6;

    // A pen: its pressure sets the drop size and the stylus wake, kept in the ops.
    // Synthetic pointer events with pressure, as a pen sends them (0.5, a device
    // without pressure, is the set size; 1.0 twice it; 0.2 is 0.4 of it).
    const pen = (type, q, pressure) => page.evaluate(({ type, x, y, pressure }) => {
      const canvas = document.getElementById('marbling_canvas');
      const buttons = type === 'pointerup' || pressure === 0 ? 0 : 1;
      canvas.dispatchEvent(new PointerEvent(type, {
        clientX: x, clientY: y, pressure, pointerType: 'pen', pointerId: 9, isPrimary: true,
        button: type === 'pointermove' ? -1 : 0, buttons, bubbles: true, cancelable: true, composed: true,
      }));
      // A browser follows a pen's pointermove with a compatibility mousemove (egui's).
      if (type === 'pointermove') canvas.dispatchEvent(new MouseEvent('mousemove', { clientX: x, clientY: y, buttons, bubbles: true, cancelable: true, composed: true }));
    }, { type, x: q.x, y: q.y, pressure });
    await clickControl(page, 'tool-drop');
    const at = p(150, 100);
    await pen('pointermove', at, 0);
    await page.waitForTimeout(100);
    await pen('pointerdown', at, 1.0);
    await page.waitForTimeout(100);
    await pen('pointerup', at, 0);
    await waitOps(page, n + 1);
    await clickControl(page, 'tool-stylus');
    const line = [];
    for (let i = 0; i <= 8; i++) line.push(p(40 + 25 * i, 60 + 10 * i));
    await pen('pointermove', line[0], 0);
    await page.waitForTimeout(100);
    await pen('pointerdown', line[0], 0.2);
    for (const q of line.slice(1)) {
      await page.waitForTimeout(60);
      await pen('pointermove', q, 0.2);
    }
    await page.waitForTimeout(60);
    await pen('pointerup', line.at(-1), 0);
    await waitOps(page, n + 2);
    const pressed = JSON.parse((await download(page, 'save-json')).bytes.toString('utf8'));
    const [penDrops, ...strokes] = pressed.ops.slice(n);
    assert.equal(penDrops.type, 'drops');
    assert.equal(penDrops.radius, 18, 'a full press did not double the drop (9 px set)');
    assert.ok(strokes.length >= 1 && strokes.every((o) => o.type === 'stylus' && o.wake === 1.6), `a light pen's wake is not 0.4 × 4 px: ${JSON.stringify(strokes.map((o) => o.wake))}`);

    // MIDI (through the test hook, as Web MIDI delivers it): a note-on is one drop on the
    // line across the middle, placed by pitch and sized by velocity; *Learn* binds a
    // controller to the drop radius; one undo takes the last note's drop away.
    const midi = (bytes) => page.evaluate((b) => window.marblingMidi(b), bytes);
    const k = Number(await (await page.$('body')).getAttribute('data-ops'));
    await midi([0x90, 60, 127]);
    await waitOps(page, k + 1);
    // Learn waits for a controller (data-midi-learning); a click lost to a frame that
    // moved the button is made again.
    for (let tries = 0; (await attr(page, 'data-midi-learning')) !== 'midi-learn-radius'; tries++) {
      assert.ok(tries < 3, 'Learn never waited for a controller');
      await clickControl(page, 'midi-learn-radius');
      const frames = Number(await page.evaluate(() => document.body.dataset.frames));
      await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, frames + 2, { timeout: READY_MS });
    }
    await midi([0xB0, 7, 0]);
    await midi([0xB0, 7, 127]);
    await midi([0x80, 96, 0]);
    await midi([0x90, 96, 64]);
    await waitOps(page, k + 2);
    const played = JSON.parse((await download(page, 'save-json')).bytes.toString('utf8'));
    const [note60, note96] = played.ops.slice(-2);
    // Of the current ink (the pattern's colour cycling has moved it on from the first).
    assert.deepEqual([note60.type, note96.type, note96.color], ['drop', 'drop', note60.color]);
    const near = (a, b) => Math.abs(a - b) < 1e-9;
    assert.ok(near(note60.center[0], 300 * 0.42) && near(note60.center[1], 100), `middle C at ${note60.center}`);
    assert.ok(near(note60.radius, 9 * 1.75), `velocity 127 gave radius ${note60.radius}`);
    assert.ok(near(note96.center[0], 270) && near(note96.radius, 300 * (0.25 + 1.5 * 64 / 127)), `C7 after controller 7 at 127: ${JSON.stringify(note96)}`);
    await page.keyboard.press('Control+z');
    await waitOps(page, k + 1);

    // *Draw line*: the next drag on the sheet is the notes' line (C2 at its start, C7 at
    // its end), and no tool's; the pointer lands on whole CSS pixels.
    await clickControl(page, 'midi-draw-line');
    await page.mouse.move(p(40, 170).x, p(40, 170).y);
    await page.mouse.down();
    for (let y = 150; y >= 30; y -= 20) await page.mouse.move(p(40, y).x, p(40, y).y);
    await page.mouse.up();
    await midi([0xB0, 7, 8]); // the learned controller: radius 1 + 8/127 · 299 → 20
    await midi([0x90, 36, 64]);
    await midi([0x90, 96, 64]);
    await waitOps(page, k + 3);
    const drawn = JSON.parse((await download(page, 'save-json')).bytes.toString('utf8'));
    const [low, high] = drawn.ops.slice(-2);
    const close = (a, [x, y]) => Math.hypot(a[0] - x, a[1] - y) <= 1.5 / s.scale;
    assert.ok(close(low.center, [40, 170]) && close(high.center, [40, 30]), `notes on the drawn line at ${low.center} and ${high.center}`);
    assert.ok(Math.abs(low.radius - 20 * (0.25 + 1.5 * 64 / 127)) < 1e-9, `radius ${low.radius}`);
    await page.screenshot({ path: path.join(SHOTS, 'midi-drawn-line.png'), timeout: READY_MS });
    assert.deepEqual(errors, []);
    await context.close();
  });

  test('flow: a drag streams the ink as one v4 op, the CLI picture, one undo', longOnly, async () => {
    const design = {
      version: 1, width: 160, height: 120, background: '#f4ecd8',
      ops: [
        { type: 'drop', center: [55, 60], radius: 30, color: '#e63946' },
        { type: 'drop', center: [110, 60], radius: 30, color: '#1d3557' },
        { type: 'drop', center: [80, 60], radius: 14, color: '#f1c453' },
      ],
    };
    const prefs = JSON.stringify({
      tool: 'flow', palette: 0, ink: '#1d3557', antialias: 'none',
      settings: { flow_size: 60, flow_octaves: 1, flow_strength: 10, flow_seed: 3 },
    });
    const context = await browser.newContext({ viewport: { width: 760, height: 480 }, deviceScaleFactor: 1, acceptDownloads: true });
    await context.addInitScript((p) => localStorage.setItem('marbling.prefs.v1', p), prefs);
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(site.url + linkFragment(design, 'flow'));
    await waitOps(page, 3);
    const s = await sheet(page);
    const p = (x, y) => ({ x: s.x + x * s.scale, y: s.y + y * s.scale });
    const before = await shootSheet(page, design.width, design.height);
    // A 30-px drag at 10 px per unit time: T = 3.
    let t0 = Date.now();
    await page.mouse.move(p(60, 100).x, p(60, 100).y);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++) await page.mouse.move(p(60 + 5 * i, 100).x, p(60 + 5 * i, 100).y);
    await page.mouse.up();
    await waitOps(page, 4);
    const after = await shootSheet(page, design.width, design.height);
    console.log(`tools: flow drawn exactly ${((Date.now() - t0) / 1000).toFixed(1)} s after the drag began`);
    const changed = differing(before.img, after.img, 8);
    assert.ok(changed > 0.02, `the flow changed only ${(100 * changed).toFixed(2)} % of the sheet`);

    const saved = JSON.parse((await download(page, 'save-json')).bytes.toString('utf8'));
    assert.equal(saved.version, 4);
    const flow = saved.ops[3];
    assert.deepEqual(
      [flow.type, flow.noise.type, flow.noise.octaves, flow.noise.seed, flow.strength],
      ['flow', 'perlin', 1, 3, 10],
    );
    // The pointer lands on whole CSS pixels: the drag is 30 design px within one pixel.
    assert.ok(Math.abs(flow.time - 3) <= 1 / (10 * s.scale), `time ${flow.time}`);
    // 1/60 as the f32 the noise crate keeps.
    assert.ok(Math.abs(flow.noise.frequency - 1 / 60) < 1e-8, `frequency ${flow.noise.frequency}`);
    const file = path.join(os.tmpdir(), `marbling-flow-saved-${process.pid}.json`);
    fs.writeFileSync(file, JSON.stringify(saved));
    const out = path.join(os.tmpdir(), `marbling-flow-${process.pid}.png`);
    execFileSync(MARBLING, ['render', file, '-o', out, '--scale', String(after.scale), '--aa', 'none']);
    const cpu = decode(fs.readFileSync(out));
    const w = Math.min(cpu.width, after.img.width);
    const h = Math.min(cpu.height, after.img.height);
    const frac = differing(crop(cpu, w, h), crop(after.img, w, h), 24);
    console.log(`tools: flow, app vs CLI: ${(100 * frac).toFixed(3)} % of ${w}×${h} px differ by > 24/255`);
    assert.ok(frac <= 0.01, `${(100 * frac).toFixed(2)} % of pixels differ from the CLI render`);
    await page.screenshot({ path: path.join(SHOTS, 'tool-flow-webgl2.png'), timeout: READY_MS });

    await page.keyboard.press('Control+z');
    await waitOps(page, 3);

    // Stream: the design flowing along the tool's noise, a looping turbulence; paused,
    // its frame is the CLI's `render --flow TURB --time t` of the same document.
    const stream = async () => JSON.parse((await attr(page, 'data-stream')) ?? 'null');
    assert.equal(await stream(), null);
    t0 = Date.now();
    // The stream is on from the frame after the click (data-stream); a click lost to a
    // frame that moved the button is made again.
    for (let tries = 0; (await stream()) === null; tries++) {
      assert.ok(tries < 3, 'Stream never started');
      await clickControl(page, 'flow-stream');
      const frames = Number(await attr(page, 'data-frames'));
      await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, frames + 2, { timeout: READY_MS });
    }
    await page.waitForFunction(() => JSON.parse(document.body.dataset.stream ?? '{"frame":0}').frame >= 2, null, { timeout: READY_MS });
    await clickControl(page, 'flow-stream');
    await page.waitForFunction(() => JSON.parse(document.body.dataset.stream).playing === false, null, { timeout: READY_MS });
    await waitReady(page);
    const hook = await stream();
    console.log(`tools: stream, 2 frames and a paused one in ${((Date.now() - t0) / 1000).toFixed(1)} s: ${JSON.stringify(hook)}`);
    assert.ok(hook.time > 0 && hook.time < hook.period, `time ${hook.time}`);
    const streamed = await shootSheet(page, design.width, design.height);
    const turbFile = path.join(os.tmpdir(), `marbling-stream-${process.pid}.json`);
    fs.writeFileSync(turbFile, JSON.stringify({ noise: hook.noise, strength: hook.strength, period: hook.period }));
    const designFile = path.join(os.tmpdir(), `marbling-stream-design-${process.pid}.json`);
    fs.writeFileSync(designFile, JSON.stringify(design));
    const streamOut = path.join(os.tmpdir(), `marbling-stream-${process.pid}.png`);
    execFileSync(MARBLING, ['render', designFile, '--flow', turbFile, '--time', String(hook.time), '-o', streamOut, '--scale', String(streamed.scale), '--aa', 'none']);
    const frame = decode(fs.readFileSync(streamOut));
    const sw = Math.min(frame.width, streamed.img.width);
    const sh = Math.min(frame.height, streamed.img.height);
    const off = differing(crop(frame, sw, sh), crop(streamed.img, sw, sh), 24);
    const moved = differing(crop(before.img, sw, sh), crop(streamed.img, sw, sh), 24);
    console.log(`tools: stream frame vs CLI ${(100 * off).toFixed(3)} %, vs the still design ${(100 * moved).toFixed(1)} % of ${sw}×${sh} px differ by > 24/255`);
    assert.ok(off <= 0.01, `${(100 * off).toFixed(2)} % of pixels differ from the CLI's frame`);
    assert.ok(moved > 0.05, `the stream moved only ${(100 * moved).toFixed(2)} % of the sheet`);
    await page.screenshot({ path: path.join(SHOTS, 'flow-stream-webgl2.png'), timeout: READY_MS });
    // Record films one period (4 at 1 per second) to a WebM.
    const video = await download(page, 'flow-record');
    assert.equal(video.name, 'marbling-flow-loop.webm');
    assert.deepEqual([...video.bytes.subarray(0, 4)], [0x1a, 0x45, 0xdf, 0xa3], 'an EBML (WebM) header');
    await clickControl(page, 'flow-stream-stop');
    await page.waitForFunction(() => !document.body.dataset.stream && document.body.dataset.ready === '1', null, { timeout: READY_MS });
    assert.deepEqual(errors, []);
    await context.close();
  });
});
