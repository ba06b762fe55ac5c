// Diagnosis: frames/s while hovering and dragging a tine over the gallery design on WebGPU
// when the draws of the render pipelines whose label matches SKIP (a regex) are skipped,
// which bounds what each pipeline costs: node skip-draws.mjs SKIP [flags…]. SKIP is
// matched against "LABEL COUNT" (COUNT: the draw's vertex or index count).
import { launch } from '../harness.mjs';
import { skipDraws, tineOverSheet, wiggle } from '../probe.mjs';
const [skip = '^$', ...extra] = process.argv.slice(2);
const { browser, site } = await launch('webgpu', extra);
const context = await browser.newContext({ viewport: { width: 1024, height: 768 }, deviceScaleFactor: 1 });
await skipDraws(context, skip);
const page = await context.newPage();
await page.goto(site.url);
const at = await tineOverSheet(page);
const hover = await wiggle(page, at, 4000);
await page.mouse.down();
const drag = await wiggle(page, at, 4000);
await page.mouse.up();
console.log(`skip /${skip}/ ${extra.join(' ')}: hover ${hover.toFixed(1)} frames/s, drag ${drag.toFixed(1)} frames/s; draws ${JSON.stringify(await page.evaluate(() => window.drawn))}`);
await browser.close(); site.server.close();
