// The last step of the web build (tools/build/build.mjs), run on its staging folder (the
// argument), which then becomes dist/:
//   1. The module's `name` and `producers` sections are dropped (function names for
//      debuggers: 1.3 MB raw, 0.26 MB of the brotli form).
//   2. `.br` (brotli, quality 11) and `.gz` (gzip -9) beside the module: index.html's
//      `marblingFetchWasm` fetches one of them, so any static server sends the small form.
//   3. `_headers`: cache advice for static hosts (hashed files immutable, the page
//      revalidated).
//   4. web/sw.js's BUILD (a hash of every file's name and size) and FILES (every file but
//      the plain module, whose compressed forms stand for it).
// Prints the module's sizes, bytes, as `wasm raw … gzip … brotli …` (docs/BENCHMARKS.md,
// "The first visit", which also says why binaryen's wasm-opt is not run).
import { createHash } from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';

const staging = process.argv[2];
if (!staging) throw new Error('usage: node tools/build/post_build.mjs STAGING_DIR');

/** Every file below `dir`, as paths relative to it with `/` separators, sorted. */
function files(dir, prefix = '') {
  return fs.readdirSync(dir, { withFileTypes: true }).flatMap((e) => e.isDirectory()
    ? files(path.join(dir, e.name), `${prefix}${e.name}/`)
    : [`${prefix}${e.name}`]).sort();
}

/** `wasm` without the custom sections named in `drop` (the module's meaning is unchanged). */
function withoutSections(wasm, drop) {
  const MAGIC = '0061736d01000000';
  if (wasm.subarray(0, 8).toString('hex') !== MAGIC) throw new Error('not a wasm module (version 1)');
  const kept = [wasm.subarray(0, 8)];
  let i = 8;
  const leb = () => {
    let value = 0;
    for (let shift = 0; ; shift += 7) {
      const byte = wasm[i++];
      value += (byte & 0x7f) * 2 ** shift;
      if (!(byte & 0x80)) return value;
    }
  };
  while (i < wasm.length) {
    const start = i;
    const id = wasm[i++];
    const size = leb();
    const body = i;
    i = body + size;
    if (i > wasm.length) throw new Error(`section at byte ${start} runs past the end`);
    if (id === 0) {
      const saved = i;
      i = body;
      const nameLength = leb();
      const name = wasm.subarray(i, i + nameLength).toString('utf8');
      i = saved;
      if (drop.includes(name)) continue;
    }
    kept.push(wasm.subarray(start, i));
  }
  return Buffer.concat(kept);
}

const modules = files(staging).filter((f) => f.endsWith('.wasm'));
if (modules.length === 0) throw new Error(`no .wasm file in ${staging}`);

// 1. No names.
for (const m of modules) {
  const file = path.join(staging, m);
  fs.writeFileSync(file, withoutSections(fs.readFileSync(file), ['name', 'producers']));
}

// 2. Precompressed forms of the module.
for (const m of modules) {
  const file = path.join(staging, m);
  const raw = fs.readFileSync(file);
  const gz = zlib.gzipSync(raw, { level: 9 });
  const br = zlib.brotliCompressSync(raw, {
    params: {
      [zlib.constants.BROTLI_PARAM_QUALITY]: 11,
      [zlib.constants.BROTLI_PARAM_LGWIN]: 24,
      [zlib.constants.BROTLI_PARAM_SIZE_HINT]: raw.length,
    },
  });
  fs.writeFileSync(`${file}.gz`, gz);
  fs.writeFileSync(`${file}.br`, br);
  console.error(`wasm raw ${raw.length} gzip ${gz.length} brotli ${br.length} (${m})`);
}

// 3. Cache advice for static hosts that read a `_headers` file (Netlify, Cloudflare
// Pages; others take the same rules from their own configuration): the files whose names
// carry a content hash never change; the page and the service worker are revalidated.
fs.writeFileSync(path.join(staging, '_headers'), [
  '/*', '  Cache-Control: no-cache',
  ...modules.flatMap((m) => [m, `${m}.br`, `${m}.gz`, m.replace(/_bg\.wasm$/, '.js')])
    .flatMap((f) => [`/${f}`, '  Cache-Control: public, max-age=31536000, immutable']),
  '',
].join('\n'));

// 4. The service worker's build version and file list.
const all = files(staging).filter((f) => f !== 'sw.js' && f !== '_headers');
const build = createHash('sha256')
  .update(all.map((f) => `${f} ${fs.statSync(path.join(staging, f)).size}\n`).join(''))
  .digest('hex').slice(0, 16);
const precached = ['./', ...all.filter((f) => !f.endsWith('.wasm'))];
const sw = path.join(staging, 'sw.js');
const text = fs.readFileSync(sw, 'utf8');
if (!text.includes('__BUILD__') || !text.includes('__FILES__')) throw new Error('web/sw.js lacks __BUILD__ or __FILES__');
fs.writeFileSync(sw, text.replace('__BUILD__', build).replace('__FILES__', JSON.stringify(precached)));
