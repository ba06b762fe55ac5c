// The monkey: seeded random real input — clicks anywhere, drags, wheel, keys (tools,
// Ctrl+Z, Ctrl+Shift+Z), the Marbling and Noise tabs, the gallery, New, undo back to the
// start — then checks what a user would: no panic and no page error, no error the events
// did not ask for, the saved design renders in the CLI as the page shows it, and a
// reload restores it. `monkey.test.mjs` runs a short one in `make test`; a long one:
//
//   cd tests/browser && node monkey.mjs --events 20000 [--seed N] [--backend webgl2]
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {
  MARBLING, READY_MS, attr, clickControl, controls, crop, decode, differing, download, launch,
  shootSheet, waitReady,
} from './harness.mjs';

/** A small seeded PRNG (mulberry32): the same seed, the same events. */
export function random(seed) {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Errors that an event may ask for (a camera that is not there, a file not chosen). */
const ASKED_FOR = /Camera not available|the design is unchanged|no file|was not chosen|too large for a link/;

/** Runs `events` random events on `page`; resolves to the events' log (for a failure). */
export async function monkey(page, { seed, events }) {
  const rnd = random(seed);
  const pick = (list) => list[Math.floor(rnd() * list.length)];
  const { width, height } = page.viewportSize();
  const log = [];
  // File dialogs are cancelled as a user closing them would.
  page.on('filechooser', (chooser) => chooser.setFiles([]).catch(() => {}));
  for (let i = 0; i < events; i++) {
    const kind = pick(['click', 'click', 'drag', 'drag', 'wheel', 'key', 'key', 'control']);
    const x = Math.round(rnd() * width), y = Math.round(rnd() * height);
    log.push(`${i} ${kind} ${x},${y}`);
    if (kind === 'click') {
      await page.mouse.click(x, y);
    } else if (kind === 'drag') {
      await page.mouse.move(x, y);
      await page.mouse.down();
      for (let k = 1; k <= 4; k++) await page.mouse.move(x + (rnd() - 0.5) * 200 * k / 4, y + (rnd() - 0.5) * 200 * k / 4);
      await page.mouse.up();
    } else if (kind === 'wheel') {
      await page.mouse.move(x, y);
      await page.mouse.wheel(0, (rnd() - 0.5) * 600);
    } else if (kind === 'key') {
      const key = pick(['1', '2', '3', '4', '5', '6', '7', '8', '9', '0', 'Control+z', 'Control+z', 'Control+Shift+z', 'Escape', 'Tab', 'Enter']);
      log[log.length - 1] += ` ${key}`;
      await page.keyboard.press(key);
    } else {
      const all = await controls(page);
      const safe = Object.keys(all).filter((n) => /^(gallery(-.*)?|mode-(marbling|noise)|new|undo|redo|play|player-(back|forward|close|explain)|rail-(undo|redo|panel)|tool-.*|sheet-.*)$/.test(n));
      if (safe.length) {
        const name = pick(safe);
        log[log.length - 1] += ` ${name}`;
        const c = all[name];
        await page.mouse.click(c.x + c.w / 2, c.y + c.h / 2);
      }
    }
    // Now and then the page is let alone for a moment, as people do.
    if (rnd() < 0.05) await page.waitForTimeout(200);
  }
  return log;
}

/** Opens a fresh page, runs the monkey, and checks what it left behind. */
/**
 * The sheet shot while the exact frame of one view is on screen: ready before the shot,
 * and the view read before it still the view, and still ready, after it (a view that
 * moves during the shot is shot again, and said so).
 */
async function settledShot(page, design) {
  for (let i = 0; i < 3; i++) {
    await waitReady(page);
    const before = await attr(page, 'data-view');
    const shot = await shootSheet(page, design.width, design.height);
    const after = await attr(page, 'data-view');
    if (after === before && (await attr(page, 'data-ready')) === '1') return shot;
    console.log(`monkey: the view moved or was not ready while the sheet was shot (${before} → ${after}); shot again`);
  }
  throw new Error('the view kept moving after the reload');
}

export async function run(browser, site, { seed, events }) {
  const context = await browser.newContext({ viewport: { width: 1100, height: 760 }, deviceScaleFactor: 1, acceptDownloads: true, serviceWorkers: 'block' });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${site.url}?landing=0`);
  await waitReady(page);
  const log = await monkey(page, { seed, events });
  const where = `(seed ${seed}; last events: ${log.slice(-5).join(' | ')})`;
  assert.deepEqual(errors, [], `page errors ${where}`);
  assert.equal(await attr(page, 'data-panic'), null, `a panic ${where}`);
  const error = await attr(page, 'data-error');
  assert.ok(error === null || ASKED_FOR.test(error), `an error no event asked for: ${error} ${where}`);
  // Back to the editor, the design as it is.
  await page.keyboard.press('Escape');
  if ((await attr(page, 'data-landing')) === '1') await clickControl(page, 'gallery-close');
  if ((await attr(page, 'data-mode')) !== 'marbling') await clickControl(page, 'mode-marbling');
  if ((await controls(page))['player-close']) await clickControl(page, 'player-close');
  // The 3D view's window floats over the canvas: closed from the panel.
  if ((await controls(page))['view3d-sphere']) await clickControl(page, 'view3d');
  // clickControl scrolls the side panel back to its File row when the wheel moved it.
  let saved;
  try {
    saved = (await download(page, 'save-json')).bytes.toString('utf8');
  } catch (e) {
    // What the page showed when Save JSON gave nothing: a screenshot and the hooks.
    const shot = path.join(os.tmpdir(), `marbling-monkey-${seed}-save.png`);
    await page.screenshot({ path: shot }).catch(() => {});
    const hooks = await page.evaluate(() => ({ ...document.body.dataset, controls: undefined }));
    throw new Error(`Save JSON gave no file (${e.message.split('\n')[0]}); page: ${JSON.stringify(hooks)}; screenshot ${shot} ${where}`);
  }
  const design = JSON.parse(saved);
  // A reload restores it, fitted to the window: the CLI's render of the saved JSON is
  // what the page shows.
  await page.reload();
  await waitReady(page);
  assert.equal(await attr(page, 'data-ops'), String(design.ops.length), `the reload lost ops ${where}`);
  const again = (await download(page, 'save-json')).bytes.toString('utf8');
  assert.deepEqual(JSON.parse(again), design, `the reload changed the design ${where}`);
  const file = path.join(os.tmpdir(), `marbling-monkey-${process.pid}-${seed}.json`);
  fs.writeFileSync(file, saved);
  const shot = await settledShot(page, design);
  const png = `${file}.png`;
  execFileSync(MARBLING, ['render', file, '-o', png, '--scale', String(shot.scale), '--aa', 'rgss']);
  const cpu = decode(fs.readFileSync(png));
  const w = Math.min(cpu.width, shot.img.width), h = Math.min(cpu.height, shot.img.height);
  const off = differing(crop(cpu, w, h), crop(shot.img, w, h), 24);
  // Random gestures can leave a design so sheared that its slivers are finer than f32
  // can place (the GPU walks in f32): then what no f32 renderer can match is measured,
  // not assumed — the CLI's own render moved by numbers 2e-6 off — and allowed for.
  const chaos = off > 0.01 ? chaosBaseline(design, file, shot.scale, cpu) : 0;
  const budget = 0.01 + 1.5 * chaos;
  assert.ok(off <= budget, `${(100 * off).toFixed(2)} % of the page's picture differs from the CLI's render of its saved JSON (budget ${(100 * budget).toFixed(2)} %: 1 % + 1.5 × the ${(100 * chaos).toFixed(2)} % that numbers 2e-6 off change) ${where}`);
  if (chaos > 0) console.log(`monkey: a chaotic design (numbers 2e-6 off change ${(100 * chaos).toFixed(2)} % of it): ${(100 * off).toFixed(2)} % off, budget ${(100 * budget).toFixed(2)} %`);
  await context.close();
  return { ops: design.ops.length, off };
}

/**
 * The fraction of pixels (by > 24/255) that the CLI's render of `design` changes when
 * every number of its ops is moved by a relative 2e-6 (f32 keeps about 1.2e-7 an
 * operation, and the walk compounds it): how chaotic the design is at the GPU's
 * precision. `cpu` is the CLI's render of the design itself at `scale`.
 */
export function chaosBaseline(design, file, scale, cpu) {
  let k = 0;
  const nudge = (v) => {
    if (typeof v === 'number') {
      k += 1;
      return v * (1 + ((k * 7919) % 3 - 1) * 2e-6);
    }
    if (Array.isArray(v)) return v.map(nudge);
    if (v && typeof v === 'object') return Object.fromEntries(Object.entries(v).map(([key, x]) => [key, key === 'color' || key === 'colors' ? x : nudge(x)]));
    return v;
  };
  const moved = `${file}.moved.json`;
  fs.writeFileSync(moved, JSON.stringify({ ...design, ops: design.ops.map(nudge) }));
  execFileSync(MARBLING, ['render', moved, '-o', `${moved}.png`, '--scale', String(scale), '--aa', 'rgss']);
  const other = decode(fs.readFileSync(`${moved}.png`));
  const w = Math.min(cpu.width, other.width), h = Math.min(cpu.height, other.height);
  return differing(crop(cpu, w, h), crop(other, w, h), 24);
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const arg = (name, fallback) => {
    const i = process.argv.indexOf(`--${name}`);
    return i > 0 ? process.argv[i + 1] : fallback;
  };
  const events = Number(arg('events', '20000'));
  const seed = Number(arg('seed', String(Date.now() % 100000)));
  const { browser, site } = await launch(arg('backend', 'webgl2'));
  const t0 = Date.now();
  try {
    const r = await run(browser, site, { seed, events });
    console.log(`monkey: seed ${seed}, ${events} events in ${((Date.now() - t0) / 1000).toFixed(0)} s: ${r.ops} ops left, ${(100 * r.off).toFixed(3)} % off the CLI render`);
  } catch (e) {
    console.error(`monkey: seed ${seed} failed: ${e.message}`);
    process.exitCode = 1;
  } finally {
    await browser.close();
    site.server.close();
  }
}
