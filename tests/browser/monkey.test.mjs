// The short monkey of `make test`: seeded random real input on WebGL2 (monkey.mjs), then
// no panic, no page error, no error no event asked for, the saved design rendered by the
// CLI is what the page shows, and a reload restores it. A failure names its seed and
// last events; `node monkey.mjs --events 20000 --seed N` runs a long one.
import { describe, test } from 'node:test';
import { sharedBrowser } from './harness.mjs';
import { run } from './monkey.mjs';

/** Seeds run in `make test`: fixed, so a failure reproduces (MONKEY_SEEDS=7,11,… runs
 *  others). */
const SEEDS = (process.env.MONKEY_SEEDS ?? '7').split(',').map(Number);
/** Events per seed: about half a minute each on SwiftShader. */
const EVENTS = 40;

describe('the monkey on webgl2', () => {
  const shared = sharedBrowser('webgl2');

  for (const seed of SEEDS) {
    test(`seed ${seed}: ${EVENTS} random events leave a design the CLI renders and a reload restores`, async () => {
      const r = await run(shared.browser, shared.site, { seed, events: EVENTS });
      console.log(`monkey seed ${seed}: ${r.ops} ops left, ${(100 * r.off).toFixed(3)} % off the CLI render`);
    });
  }
});
