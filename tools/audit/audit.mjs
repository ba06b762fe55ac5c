// `make audit`: Lighthouse (pinned in ./package.json) on dist/ as a first visit sees it,
// served on 127.0.0.1 by the browser tests' static server, in Debian's headless Chromium
// (WebGL2 on SwiftShader; desktop form factor, no throttling: the figures measure our
// page, not a simulated phone network). Prints the four category scores, the bytes
// transferred and the largest requests; writes the whole report to out/lighthouse.json.
import fs from 'node:fs';
import path from 'node:path';
import lighthouse from 'lighthouse';
import * as chromeLauncher from 'chrome-launcher';
import { DIST, ROOT, serve } from '../../tests/browser/harness.mjs';

const site = await serve(DIST);
const chrome = await chromeLauncher.launch({
  chromePath: process.env.CHROMIUM || '/usr/bin/chromium',
  chromeFlags: ['--headless=new', '--no-sandbox', '--disable-quic', '--no-first-run',
    '--disable-background-networking', '--disable-component-update', '--disable-sync',
    '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
});
try {
  const result = await lighthouse(site.url, {
    port: chrome.port,
    output: 'json',
    logLevel: 'error',
    onlyCategories: ['performance', 'accessibility', 'best-practices', 'seo'],
    formFactor: 'desktop',
    screenEmulation: { mobile: false, width: 1300, height: 820, deviceScaleFactor: 1, disabled: false },
    throttlingMethod: 'provided',
  });
  const lhr = result.lhr;
  const out = path.join(ROOT, 'out');
  fs.mkdirSync(out, { recursive: true });
  fs.writeFileSync(path.join(out, 'lighthouse.json'), result.report);
  for (const [id, c] of Object.entries(lhr.categories)) console.log(`${id}: ${Math.round(c.score * 100)}`);
  const weight = lhr.audits['total-byte-weight'];
  console.log(`transferred: ${weight.numericValue} bytes`);
  for (const item of (weight.details?.items ?? []).slice(0, 5)) {
    console.log(`  ${item.totalBytes} ${new URL(item.url).pathname}`);
  }
  for (const id of ['first-contentful-paint', 'largest-contentful-paint', 'total-blocking-time', 'cumulative-layout-shift']) {
    console.log(`${id}: ${lhr.audits[id].displayValue}`);
  }
  const flagged = Object.values(lhr.audits)
    .filter((a) => a.score !== null && a.score < 0.9 && a.scoreDisplayMode !== 'informative' && a.scoreDisplayMode !== 'notApplicable');
  for (const a of flagged) console.log(`flagged: ${a.id} (${a.title})`);
} finally {
  await chrome.kill();
  site.server.close();
}
