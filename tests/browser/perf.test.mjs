// Frame rate while dragging a tool over a 1,000-op 1024×768 design, read from the app's
// own frame timings (data-frame-ms: the mean interval of the last 60 frames), in headless
// Chromium on SwiftShader (a CPU-emulated GPU). The numbers go to docs/BENCHMARKS.md.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { BACKENDS, MARBLING, READY_MS, attr, launch, openPage, sheet } from './harness.mjs';

const design = path.join(os.tmpdir(), `marbling-perf-${process.pid}.json`);

for (const backend of Object.keys(BACKENDS)) {
  describe(`drag frame rate on ${backend}`, () => {
    let browser;
    let site;
    before(async () => {
      execFileSync(MARBLING, ['random', '--ops', '1000', '--size', '1024x768', '--seed', '11', '--mix', 'mixed', '-o', design]);
      ({ browser, site } = await launch(backend));
    });
    after(async () => {
      await browser?.close();
      site?.server.close();
      fs.rmSync(design, { force: true });
    });

    test('dragging a tine over a 1,000-op design runs at ≥ 30 frames/s', async () => {
      const link = execFileSync(MARBLING, ['link', design, '--base', site.url]).toString().trim();
      const { page, context, errors } = await openPage(browser, site, link.slice(link.indexOf('#')), { width: 1440, height: 900 });
      assert.equal(await attr(page, 'data-ops'), '1000');
      // The app builds its live-preview cache in the idle frame after the exact one.
      await page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: READY_MS });
      const s = await sheet(page);
      await page.keyboard.press('3'); // tine
      const x = s.x + 100 * s.scale;
      const y = s.y + 384 * s.scale;
      await page.mouse.move(x, y);
      await page.mouse.down();
      // Keep the pointer moving for 6 s so every frame has a new pending op to draw
      // (data-frame-ms averages the last 60 frames).
      const t0 = Date.now();
      let i = 0;
      while (Date.now() - t0 < 6000) {
        i++;
        await page.mouse.move(x + 5 * (i % 160), y + 40 * Math.sin(i / 10));
        await page.waitForTimeout(5);
      }
      const ms = Number(await attr(page, 'data-frame-ms'));
      await page.mouse.up();
      const fps = 1000 / ms;
      console.log(`${backend}: dragging a tine over 1,000 ops at 1024×768 (scale ${s.scale.toFixed(3)}): ${ms.toFixed(2)} ms/frame = ${fps.toFixed(1)} frames/s`);
      assert.ok(fps >= 30, `${fps.toFixed(1)} frames/s while dragging`);
      assert.deepEqual(errors, []);
      await context.close();
    });
  });
}
