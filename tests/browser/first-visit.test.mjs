// A first visit as a stranger makes it: a fresh profile with the offline service worker
// allowed, the site served by a plain static server (no compression negotiated) from a
// copy of dist/ that holds the wasm module only in its precompressed forms. What the
// server sends is counted; the gallery must show every card from the prerendered
// thumbnails, with no GPU thumbnail drawn.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { DIST, READY_MS, attr, launch } from './harness.mjs';

/** What a first visit from a plain static server may download, bytes: the module as
 * `.gz` (2.61 MB with phasor noise, the relief view, MIDI, sound, the Stream and the 3D
 * view's styles; Chromium's
 * DecompressionStream has no brotli, and a server that negotiates sends the brotli form
 * instead), the thumbnails (0.40 MB), the page, its script and the icons
 * (docs/BENCHMARKS.md, "The first visit"). */
const FIRST_VISIT_BUDGET = 3.3e6;

/** dist/ without the plain `.wasm` files: only `.wasm.br` and `.wasm.gz` stand for them. */
function compressedOnlyCopy() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'marbling-dist-'));
  fs.cpSync(DIST, dir, { recursive: true, filter: (f) => !f.endsWith('.wasm') });
  assert.ok(fs.readdirSync(dir).some((f) => f.endsWith('.wasm.br')), 'dist/ has no .wasm.br: run make web');
  return dir;
}

describe('a first visit', () => {
  let browser;
  let site;
  before(async () => {
    ({ browser, site } = await launch('webgl2', [], compressedOnlyCopy()));
  });
  after(async () => {
    await browser?.close();
    site?.server.close();
  });

  test('downloads the module once, compressed, and shows every gallery card at once', async () => {
    const context = await browser.newContext({ viewport: { width: 1300, height: 820 }, deviceScaleFactor: 1 });
    const page = await context.newPage();
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    // When the gallery shows all its cards, on the page's clock.
    await page.addInitScript(() => {
      document.addEventListener('DOMContentLoaded', () => { window.marblingLoadingText = document.getElementById('loading')?.textContent; });
      new MutationObserver(() => {
        if (document.body?.dataset.thumbnails?.startsWith('27/') && !window.marblingCardsAt) window.marblingCardsAt = performance.now();
      }).observe(document, { attributes: true, subtree: true, attributeFilter: ['data-thumbnails'] });
    });
    await page.goto(site.url);
    await page.waitForFunction(() => document.body.dataset.landing === '1' && document.body.dataset.thumbnails === '27/27', null, { timeout: READY_MS });
    assert.equal(await attr(page, 'data-thumbnails-from'), 'atlas', 'the cards come from the prerendered thumbnails');
    // The loading note is plain HTML, there before the module starts, gone once it runs.
    assert.match(await page.evaluate(() => window.marblingLoadingText), /Loading the app/);
    assert.equal(await page.$('#loading'), null, 'the loading note is gone once the app runs');
    const timing = await page.evaluate(() => ({
      arrived: performance.getEntriesByName('marbling-wasm-arrived')[0]?.startTime,
      cards: window.marblingCardsAt,
    }));
    assert.ok(timing.arrived > 0, 'the module was fetched through marblingFetchWasm');
    console.log(`first visit: module in at ${timing.arrived.toFixed(0)} ms, all 27 cards at ${timing.cards.toFixed(0)} ms (${(timing.cards - timing.arrived).toFixed(0)} ms after the module)`);
    // The service worker has cached the app for offline use (its install has fetched).
    await page.evaluate(() => navigator.serviceWorker.ready.then(() => undefined));
    await page.waitForFunction(() => navigator.serviceWorker.controller !== null || document.readyState === 'complete', null, { timeout: READY_MS });
    await page.waitForTimeout(500);
    const sent = [...site.sent.entries()].sort((a, b) => b[1] - a[1]);
    const total = sent.reduce((s, [, n]) => s + n, 0);
    console.log(`first visit: ${total} bytes sent; largest: ${sent.slice(0, 4).map(([p, n]) => `${p} ${n}`).join(', ')}`);
    const modules = sent.filter(([p]) => /\.wasm(\.br|\.gz)?$/.test(p));
    assert.equal(modules.length, 1, `one form of the module is fetched, once: ${JSON.stringify(modules)}`);
    const [modulePath, moduleBytes] = modules[0];
    assert.equal(moduleBytes, fs.statSync(path.join(DIST, modulePath)).size, 'the module is sent once (the service worker revalidates)');
    assert.ok(total <= FIRST_VISIT_BUDGET, `a first visit sent ${total} bytes (budget ${FIRST_VISIT_BUDGET})`);
    assert.deepEqual(errors, []);
    await context.close();
  });
});
