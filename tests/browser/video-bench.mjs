// Benchmark (not part of `npm test`): live video frames marbled per second in the app,
// Chromium's fake camera (640×480) through a 200-op design of 640×480 on WebGL2 or
// WebGPU (SwiftShader here). A frame counts when the canvas has drawn it whole.
//   cd tests/browser && MARBLING_BIN=…/marbling node video-bench.mjs [webgl2|webgpu] [ops]
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { MARBLING, READY_MS, attr, clickControl, launch, openPage } from './harness.mjs';

const backend = process.argv[2] ?? 'webgl2';
const ops = Number(process.argv[3] ?? 200);
const file = path.join(os.tmpdir(), `marbling-video-bench-${process.pid}.json`);
execFileSync(MARBLING, ['random', '--ops', String(ops), '--size', '640x480', '--seed', '3', '-o', file]);
const link = execFileSync(MARBLING, ['link', file, '--base', 'http://x/']).toString().trim();
const { browser, site } = await launch(backend, ['--use-fake-device-for-media-stream', '--use-fake-ui-for-media-stream']);
// A window whose sheet shows the 640×480 design at about 1:1.
const { page } = await openPage(browser, site, link.slice(link.indexOf('#')), { width: 1000, height: 560 });
await clickControl(page, 'video-camera');
await page.waitForFunction(() => Number(document.body.dataset.videoFrames ?? 0) >= 2, null, { timeout: READY_MS });
const seconds = 20;
const f0 = Number(await attr(page, 'data-video-frames'));
const t0 = Date.now();
await page.waitForTimeout(seconds * 1000);
const f1 = Number(await attr(page, 'data-video-frames'));
const dt = (Date.now() - t0) / 1000;
const view = await attr(page, 'data-view');
console.log(`${backend}: ${ops} ops, camera 640×480, view ${view}: ${f1 - f0} frames in ${dt.toFixed(1)} s = ${((f1 - f0) / dt).toFixed(2)} frames/s`);
fs.rmSync(file, { force: true });
await browser.close();
site.server.close();
process.exit(0);
