// The editor's history as a user meets it, in Chromium on WebGL2 (the history does not
// depend on the GPU path): a gesture is one undo, its preview follows the drag, a
// linked design keeps its edits across a reload, New and the paper colour are undoable,
// editing an earlier step keeps the later ones restorable, replaced designs are in
// Recent designs, and an edit past the op cap is refused without losing anything. One
// browser for all of them; a 5-op design keeps each frame cheap.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {
  linkFragment, MARBLING, READY_MS, SHOTS, attr, clickControl, controls, decode, differing, download, launch, openPage, sheet, shootSheet,
  waitOps,
} from './harness.mjs';

const SMALL = {
  version: 1, width: 300, height: 200, background: '#f4ecd8',
  ops: [
    { type: 'drop', center: [80, 100], radius: 40, color: '#1d3557' },
    { type: 'drop', center: [200, 90], radius: 50, color: '#e63946' },
    { type: 'drop', center: [150, 140], radius: 30, color: '#2a9d8f' },
  ],
};
const N = SMALL.ops.length;

/** Preferences stored before the page loads (the app restores them). */
function prefs(tool, settings) {
  return JSON.stringify({ tool, settings, palette: 0, ink: '#1d3557', antialias: 'rgss' });
}

/** Waits until the design shows more than `n` ops and its exact frame is drawn. */
async function waitMoreOps(page, n) {
  await page.waitForFunction((k) => Number(document.body.dataset.ops) > k && document.body.dataset.ready === '1', n, { timeout: READY_MS });
  return Number(await attr(page, 'data-ops'));
}

/** A screenshot of the sheet while the button is held (no pointer parking). */
async function shootHeld(page, s) {
  await page.waitForTimeout(600);
  const clip = { x: Math.round(s.x), y: Math.round(s.y), width: Math.floor(SMALL.width * s.scale), height: Math.floor(SMALL.height * s.scale) };
  return decode(await page.screenshot({ clip, timeout: READY_MS }));
}

/** Drags from `a` to `b` (page pixels) in `steps`, shooting the preview halfway and at the end. */
async function dragWithShots(page, s, a, b, steps) {
  await page.mouse.move(a.x, a.y);
  await page.mouse.down();
  const at = (t) => ({ x: a.x + (b.x - a.x) * t, y: a.y + (b.y - a.y) * t });
  for (let i = 1; i <= steps / 2; i++) await page.mouse.move(at(i / steps).x, at(i / steps).y);
  const half = await shootHeld(page, s);
  for (let i = steps / 2 + 1; i <= steps; i++) await page.mouse.move(at(i / steps).x, at(i / steps).y);
  const full = await shootHeld(page, s);
  await page.mouse.up();
  return { half, full };
}

describe('history on webgl2', () => {
  let browser;
  let site;
  before(async () => {
    ({ browser, site } = await launch('webgl2'));
  });
  after(async () => {
    await browser?.close();
    site?.server.close();
  });

  test('a spray stroke and a 9-tine rake are one undo each, and their previews follow the drag', async () => {
    // A small window: every drag frame of a multi-op gesture is an exact render.
    const context = await browser.newContext({ viewport: { width: 900, height: 640 }, deviceScaleFactor: 1, acceptDownloads: true });
    await context.addInitScript((p) => localStorage.setItem('marbling.prefs.v1', p), prefs('spray', { comb_tines: 9, spray_density: 2 }));
    const t0 = Date.now();
    const log = (what) => console.log(`history: ${what} after ${((Date.now() - t0) / 1000).toFixed(1)} s`);
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(site.url + linkFragment(SMALL, 'stroke'));
    await waitOps(page, N);
    const s = await sheet(page);
    const p = (x, y) => ({ x: s.x + x * s.scale, y: s.y + y * s.scale });
    const before = await shootSheet(page, SMALL.width, SMALL.height);

    log('loaded');
    const spray = await dragWithShots(page, s, p(30, 40), p(270, 60), 8);
    log('sprayed');
    assert.ok(differing(before.img, spray.half, 8) > 0.001, 'no spray preview halfway');
    assert.ok(differing(spray.half, spray.full, 8) > 0.001, 'the spray preview did not follow the drag');
    const sprayed = await waitMoreOps(page, N + 1);
    const droplets = sprayed - N;
    // The stroke is one gesture in the saved document.
    const saved = JSON.parse((await download(page, 'save-json')).bytes.toString('utf8'));
    assert.deepEqual(saved.gestures, [[N, droplets]]);

    await page.keyboard.press('4'); // rake, 9 tines from the stored preferences
    log('saved');
    const rake = await dragWithShots(page, s, p(150, 20), p(150, 120), 6);
    log('raked');
    assert.ok(differing(rake.half, rake.full, 8) > 0.001, 'the rake preview froze during the drag');
    // A comb of 9 tines is one op.
    await waitOps(page, sprayed + 1);
    await page.screenshot({ path: path.join(SHOTS, 'history-stroke-rake-webgl2.png'), timeout: READY_MS });

    await page.keyboard.press('Control+z');
    await waitOps(page, sprayed);
    await page.keyboard.press('Control+z');
    await waitOps(page, N);
    const undone = await shootSheet(page, SMALL.width, SMALL.height);
    assert.ok(differing(before.img, undone.img, 2) < 0.001, 'two undos did not restore the design');
    await page.keyboard.press('Control+Shift+z');
    await waitOps(page, sprayed);
    log('undone and redone');
    assert.deepEqual(errors, []);
    await context.close();
  });

  test('a linked design keeps its edits across a reload; New, paper and an earlier-step edit are all recoverable', async () => {
    // Tall enough that the whole side panel (history, recent designs) is on screen.
    const fragment = linkFragment(SMALL, 'link');
    const { page, context, errors } = await openPage(browser, site, fragment, { width: 1300, height: 1300 });
    await waitOps(page, N);
    // *Show QR*: the link's QR code in a window (`data-qr` = version and characters; the
    // Rust and CLI tests read codes back), the link being this page's with the fragment.
    await clickControl(page, 'show-qr');
    await page.waitForFunction(() => document.body.dataset.qr !== undefined, null, { timeout: READY_MS });
    const base = await page.evaluate(() => location.origin + location.pathname);
    const [version, chars] = (await attr(page, 'data-qr')).slice(1).split(' ').map(Number);
    assert.equal(chars, base.length + fragment.length, 'the QR code holds another link');
    assert.ok(version >= 1 && version <= 40, `version ${version}`);
    const code = (await controls(page))['qr-code'];
    assert.ok(code && Math.abs(code.w - code.h) <= 1 && code.w >= 96, `the code is drawn ${JSON.stringify(code)}`);
    // A new window is sized in an unseen first pass: two more frames show it.
    const shown = Number(await attr(page, 'data-frames')) + 2;
    await page.mouse.move(code.x + code.w / 2, code.y + code.h / 2);
    await page.waitForFunction((n) => Number(document.body.dataset.frames) >= n, shown, { timeout: READY_MS });
    await page.screenshot({ path: path.join(SHOTS, 'link-qr.png'), timeout: READY_MS });
    await clickControl(page, 'show-qr');
    await page.waitForFunction(() => document.body.dataset.qr === undefined, null, { timeout: READY_MS });
    const s = await sheet(page);
    await page.mouse.click(s.x + 60 * s.scale, s.y + 40 * s.scale);
    await waitOps(page, N + 1);
    assert.equal(await page.evaluate(() => location.hash), '', 'the edited link is still in the address bar');
    const edited = await shootSheet(page, SMALL.width, SMALL.height);
    await page.reload();
    await waitOps(page, N + 1);
    const reloaded = await shootSheet(page, SMALL.width, SMALL.height);
    assert.ok(differing(edited.img, reloaded.img, 2) < 0.001, 'the reload lost the edit');

    // Show an earlier step, draw: the later steps become a branch that can be restored.
    const rows = Object.keys(await controls(page)).filter((k) => k.startsWith('history-')).map((k) => Number(k.slice(8)));
    const last = Math.max(...rows);
    await clickControl(page, `history-${last - 2}`);
    await waitOps(page, N - 1);
    await page.mouse.click(s.x + 250 * s.scale, s.y + 170 * s.scale);
    await waitOps(page, N);
    await clickControl(page, 'restore-0');
    await waitOps(page, N + 1);
    const restored = await shootSheet(page, SMALL.width, SMALL.height);
    assert.ok(differing(edited.img, restored.img, 2) < 0.001, 'the restored branch differs from the edited design');

    // New, then Undo: the design is back.
    await clickControl(page, 'new');
    await waitOps(page, 0);
    await page.keyboard.press('Control+z');
    await waitOps(page, N + 1);

    // The paper colour: a pick in the picker is a step that Undo takes back.
    const c = (await controls(page))['paper-color'];
    await page.mouse.click(c.x + c.w / 2, c.y + c.h / 2);
    // The picker opens below the button: a saturation/value square, about 275 px wide.
    await page.waitForTimeout(1500);
    // A press held over a few frames (egui's picker follows the held pointer).
    await page.mouse.move(c.x + 200, c.y + 250);
    await page.mouse.down();
    await page.waitForTimeout(400);
    await page.mouse.move(c.x + 205, c.y + 255);
    await page.waitForTimeout(400);
    await page.mouse.up();
    await page.waitForTimeout(1000);
    await page.screenshot({ path: path.join(SHOTS, 'history-paper-picker-webgl2.png'), timeout: READY_MS });
    // A click on the status bar's empty end closes the picker (Escape does not).
    await page.mouse.click(1290, 1292);
    await page.waitForTimeout(300);
    await page.waitForFunction(() => document.body.dataset.ready === '1', null, { timeout: READY_MS });
    const painted = await shootSheet(page, SMALL.width, SMALL.height);
    assert.ok(differing(restored.img, painted.img, 8) > 0.2, 'the paper colour did not change the sheet');
    await page.keyboard.press('Control+z');
    await page.waitForTimeout(300);
    await waitOps(page, N + 1);
    const unpainted = await shootSheet(page, SMALL.width, SMALL.height);
    assert.ok(differing(restored.img, unpainted.img, 2) < 0.001, 'undo did not restore the paper');

    // The design New replaced is in Recent designs; restoring it is one more step.
    await clickControl(page, 'recent');
    await page.waitForFunction(() => (document.body.dataset.controls ?? '').includes('recent-0='), null, { timeout: READY_MS });
    await clickControl(page, 'new');
    await waitOps(page, 0);
    await clickControl(page, 'recent-0');
    await waitOps(page, N + 1);
    await page.screenshot({ path: path.join(SHOTS, 'history-recent-webgl2.png'), timeout: READY_MS });
    assert.deepEqual(errors, []);
    await context.close();
  });

  test('at the op cap a stroke is refused with a message; the design and its autosave stay', async () => {
    // 99,995 spray droplets, opened as a file (too long for a link): a stroke of more
    // than 5 droplets would pass the 100,000-op cap. The exact frame of so many ops never
    // completes on SwiftShader, so only data-ops is awaited, never data-ready.
    const CAP = 100000;
    const have = CAP - 5;
    let seed = 1;
    const rnd = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
    const inks = ['#1d3557', '#e63946', '#2a9d8f'];
    const ops = Array.from({ length: have }, (_, i) => ({
      type: 'spray', center: [Math.round(rnd() * 30000) / 100, Math.round(rnd() * 20000) / 100], radius: 1, color: inks[i % 3],
    }));
    const file = path.join(os.tmpdir(), `marbling-cap-${process.pid}.json`);
    fs.writeFileSync(file, JSON.stringify({ ...SMALL, ops }));
    const context = await browser.newContext({ viewport: { width: 900, height: 640 }, deviceScaleFactor: 1 });
    await context.addInitScript((p) => localStorage.setItem('marbling.prefs.v1', p), prefs('spray', { spray_density: 2 }));
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(site.url);
    await page.waitForFunction(() => document.body.dataset.ops !== undefined, null, { timeout: READY_MS });
    const [chooser] = await Promise.all([page.waitForEvent('filechooser', { timeout: READY_MS }), clickControl(page, 'open')]);
    await chooser.setFiles(file);
    const opsAre = (n) => page.waitForFunction((k) => document.body.dataset.ops === String(k), n, { timeout: READY_MS });
    await opsAre(have);
    // The autosave of so big a design fits in the page's storage (it is compressed).
    const autosaved = () => page.evaluate(() => ['a', 'b'].map((k) => localStorage.getItem(`marbling.autosave.${k}`) ?? '').sort((x, y) => y.length - x.length)[0].length);
    await page.waitForFunction(() => ['a', 'b'].some((k) => (localStorage.getItem(`marbling.autosave.${k}`) ?? '').length > 500000), null, { timeout: READY_MS });
    console.log(`history: the ${have}-op design autosaved in ${await autosaved()} characters (its JSON: ${fs.statSync(file).size} bytes)`);
    assert.equal(await attr(page, 'data-error'), null);

    const s = await sheet(page);
    const p = (x, y) => ({ x: s.x + x * s.scale, y: s.y + y * s.scale });
    await page.mouse.move(p(30, 40).x, p(30, 40).y);
    await page.mouse.down();
    for (let i = 1; i <= 6; i++) await page.mouse.move(p(30 + 40 * i, 40 + 10 * i).x, p(30 + 40 * i, 40 + 10 * i).y);
    await page.mouse.up();
    await page.waitForFunction(() => document.body.dataset.error !== undefined, null, { timeout: READY_MS });
    const error = await attr(page, 'data-error');
    console.log(`history: at the cap: ${error}`);
    assert.match(error, new RegExp(`^the design has ${have} ops and this adds \\d+: more than ${CAP} cannot be saved or shared, so nothing was added$`));
    assert.equal(await attr(page, 'data-ops'), String(have));

    // Nothing was overwritten: a reload restores the design from its autosave.
    await page.reload();
    await opsAre(have);
    assert.equal(await attr(page, 'data-error'), null);
    assert.deepEqual(errors, []);
    fs.rmSync(file, { force: true });
    await context.close();
  });
});
