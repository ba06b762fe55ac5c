// Diagnosis: where the CPU goes while a tine is dragged over the gallery design on WebGPU
// (SwiftShader), by `perf record` of every Chromium process for 6 s, with the draws of
// pipelines whose "LABEL COUNT" matches SKIP skipped (as skip-draws.mjs):
// node jit-profile.mjs [SKIP] [flags…]. Needs `perf` (linux-perf) and
// kernel.perf_event_paranoid ≤ 2. Prints CPU milliseconds per frame: all, each
// SwiftShader JIT routine (one per shader stage and pipeline state; named by its index
// among the JIT mappings and its code size, so compare runs by skipping draws), and the
// rest by thread. Results: docs/BENCHMARKS.md, "eighth session".
import { execFileSync, spawn } from 'node:child_process';
import { launch } from '../harness.mjs';
import { skipDraws, tineOverSheet, wiggle } from '../probe.mjs';

const SECONDS = 6;
const HZ = 999;
const [skip = '^$', ...extra] = process.argv.slice(2);
const { browser, site } = await launch('webgpu', extra);
const context = await browser.newContext({ viewport: { width: 1024, height: 768 }, deviceScaleFactor: 1 });
await skipDraws(context, skip);
const page = await context.newPage();
await page.goto(site.url);
await page.waitForFunction(() => document.body.dataset.previewReady === '1', null, { timeout: 240_000 });
const at = await tineOverSheet(page);
await page.mouse.down();
await wiggle(page, at, 2000); // the preview settles on its sample count
const pids = execFileSync('pgrep', ['-f', 'lib/chromium/chromium']).toString().trim().split('\n').join(',');
const data = `/tmp/marbling-jit-${process.pid}.data`;
const perf = spawn('perf', ['record', '-q', '-F', String(HZ), '-p', pids, '-o', data, '--', 'sleep', String(SECONDS)], { stdio: 'inherit' });
const fps = await wiggle(page, at, SECONDS * 1000);
await new Promise((r) => perf.on('exit', r));
await page.mouse.up();
await browser.close();
site.server.close();

const script = (args) => execFileSync('perf', ['script', '-i', data, ...args], { maxBuffer: 1 << 28, stdio: ['ignore', 'pipe', 'ignore'] }).toString();
const maps = [...script(['--show-mmap-events']).matchAll(/\[(0x[0-9a-f]+)\((0x[0-9a-f]+)\).*swiftshader_jit/g)]
  .map((m) => [BigInt(m[1]), BigInt(m[2])])
  .sort((a, b) => (a[0] < b[0] ? -1 : 1));
const routines = new Map();
const threads = new Map();
let samples = 0;
for (const line of script(['-F', 'comm,ip,dso']).split('\n')) {
  const m = line.match(/^\s*(.+?)\s+([0-9a-f]+) \((.*)\)$/);
  if (!m) continue;
  samples++;
  const [, comm, ip, dso] = m;
  if (dso.includes('swiftshader_jit')) {
    const a = BigInt(`0x${ip}`);
    const i = maps.findIndex(([base, size]) => a >= base && a < base + size);
    const key = i < 0 ? '?' : `#${i} (${Number(maps[i][1]) / 1024} KiB of code)`;
    routines.set(key, (routines.get(key) ?? 0) + 1);
  } else {
    const key = dso.includes('kernel') ? 'kernel' : comm;
    threads.set(key, (threads.get(key) ?? 0) + 1);
  }
}
const ms = (n) => `${((n / HZ) * 1000 / (SECONDS * fps)).toFixed(2)} ms/frame`;
console.log(`skip /${skip}/ ${extra.join(' ')}: drag ${fps.toFixed(1)} frames/s; CPU ${ms(samples)}`);
for (const [k, n] of [...routines].sort()) if (n > 20) console.log(`  JIT routine ${k}: ${ms(n)}`);
for (const [k, n] of [...threads].sort((a, b) => b[1] - a[1]).slice(0, 8)) console.log(`  ${k}: ${ms(n)}`);
execFileSync('rm', ['-f', data]);
