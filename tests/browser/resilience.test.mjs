// Losing the GPU device (WebGPU: the device destroyed; WebGL2: the context lost) restarts
// the renderer on a fresh canvas and keeps the design and its undo history.
import { after, before, describe, test } from 'node:test';
import assert from 'node:assert/strict';
import { BACKENDS, READY_MS, longOnly, attr, differing, example, launch, openPage, sheet, shootSheet, waitOps } from './harness.mjs';

const STONE = example('stone').design;

/** Takes the GPU away the way the platform would. */
async function loseDevice(page, backend) {
  if (backend === 'webgpu') {
    await page.evaluate(() => window.marblingLoseDevice());
  } else {
    await page.evaluate(() => {
      const gl = document.getElementById('marbling_canvas').getContext('webgl2');
      gl.getExtension('WEBGL_lose_context').loseContext();
    });
  }
}

for (const backend of Object.keys(BACKENDS)) {
  describe(`device loss on ${backend}`, backend === 'webgpu' ? longOnly : {}, () => {
    let browser;
    let site;
    before(async () => {
      ({ browser, site } = await launch(backend));
    });
    after(async () => {
      await browser?.close();
      site?.server.close();
    });

    test('a lost device recreates the renderer and keeps the design and its history', async () => {
      const { page, context } = await openPage(browser, site);
      const n = STONE.ops.length;
      const s = await sheet(page);
      await page.mouse.click(s.x + 120, s.y + 90);
      await waitOps(page, n + 1);
      const before = await shootSheet(page, STONE.width, STONE.height);

      await loseDevice(page, backend);
      await page.waitForFunction(() => document.body.dataset.recovered === '1', null, { timeout: READY_MS });
      await waitOps(page, n + 1);
      const after = await shootSheet(page, STONE.width, STONE.height);
      assert.ok(differing(before.img, after.img, 2) < 0.001, 'the design looks different after the restart');
      assert.equal(await attr(page, 'data-backend'), backend);

      // The undo history came along: undo removes the drop made before the loss.
      await page.keyboard.press('Control+z');
      await waitOps(page, n);
      // And the new renderer takes new ops.
      const again = await sheet(page);
      await page.mouse.click(again.x + 200, again.y + 100);
      await waitOps(page, n + 1);
      await context.close();
    });
  });
}
