// A short monkey in `make test` (monkey.mjs: seeded random real input, then no panic, no
// unasked error, the saved design as the CLI renders it, and a reload that restores it).
// The long one: `node monkey.mjs --events 20000`.
import { after, before, describe, test } from 'node:test';
import { launch } from './harness.mjs';
import { run } from './monkey.mjs';

/** Events of the short run, and its seeds (printed with any failure). */
const EVENTS = 250;
const SEEDS = [7];

describe('the monkey on webgl2', () => {
  let browser;
  let site;
  before(async () => {
    ({ browser, site } = await launch('webgl2'));
  });
  after(async () => {
    await browser?.close();
    site?.server.close();
  });

  for (const seed of SEEDS) {
    test(`${EVENTS} random events (seed ${seed}) leave a design that saves, reloads and renders as shown`, async () => {
      const r = await run(browser, site, { seed, events: EVENTS });
      console.log(`monkey seed ${seed}: ${r.ops} ops left, ${(100 * r.off).toFixed(3)} % of the sheet off the CLI render`);
    });
  }
});
