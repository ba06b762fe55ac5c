// The web build (`make web`): dist/, the static site of the playground.
//   1. `cargo build` of the app for wasm32 in the `web` profile (Cargo.toml: small, no
//      unwinding; .cargo/config.toml: simd128).
//   2. `wasm-bindgen --target web` (the CLI's version must equal the crate's in
//      Cargo.lock: Makefile's WASM_BINDGEN_VERSION), the module and its JS glue named
//      with a hash of their bytes, so hosts may cache them for ever (`_headers`).
//   3. index.html with the module's script where it says `<!-- the module -->` (the
//      module is fetched through its `marblingFetchWasm`; only the small glue is
//      preloaded), and every file of web/ but icon.json (the icons' source).
//   4. tools/build/post_build.mjs on the staging folder (no name section, precompressed
//      `.br`/`.gz`, `_headers`, the service worker's list), which then replaces dist/.
// Set CARGO to use another cargo; arguments are passed to `cargo build`.
import { execFileSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import fs from 'node:fs';
import path from 'node:path';

const ROOT = path.resolve(import.meta.dirname, '../..');
const DIST = path.join(ROOT, 'dist');
const NAME = 'marbling-app';
const MARKER = '<!-- the module -->';
const run = (cmd, args) => execFileSync(cmd, args, { cwd: ROOT, stdio: 'inherit' });

run(process.env.CARGO ?? 'cargo', ['build', '--target', 'wasm32-unknown-unknown', '--profile', 'web', '-p', NAME, '--bin', NAME, ...process.argv.slice(2)]);
const target = path.resolve(ROOT, process.env.CARGO_TARGET_DIR ?? 'target');
const stage = fs.mkdtempSync(path.join(target, 'dist-stage-'));
try {
  const bindgen = path.join(stage, 'bindgen');
  run('wasm-bindgen', ['--target', 'web', '--no-typescript', '--out-dir', bindgen, '--out-name', NAME,
    path.join(target, 'wasm32-unknown-unknown', 'web', `${NAME}.wasm`)]);
  const js = fs.readFileSync(path.join(bindgen, `${NAME}.js`));
  const wasm = fs.readFileSync(path.join(bindgen, `${NAME}_bg.wasm`));
  const hash = createHash('sha256').update(js).update(wasm).digest('hex').slice(0, 16);
  const site = path.join(stage, 'site');
  fs.mkdirSync(site);
  fs.writeFileSync(path.join(site, `${NAME}-${hash}.js`), js);
  fs.writeFileSync(path.join(site, `${NAME}-${hash}_bg.wasm`), wasm);

  const page = fs.readFileSync(path.join(ROOT, 'index.html'), 'utf8');
  if (!page.includes(MARKER)) throw new Error(`index.html lacks ${MARKER}`);
  const script = [
    `<link rel="modulepreload" href="./${NAME}-${hash}.js" crossorigin="anonymous" />`,
    '  <script type="module">',
    `    import init from './${NAME}-${hash}.js';`,
    `    const started = await init({ module_or_path: window.marblingFetchWasm('./${NAME}-${hash}_bg.wasm') });`,
    "    dispatchEvent(new CustomEvent('marbling-started', { detail: { wasm: started } }));",
    '  </script>',
  ].join('\n');
  fs.writeFileSync(path.join(site, 'index.html'), page.replace(MARKER, script));
  for (const f of fs.readdirSync(path.join(ROOT, 'web')).filter((f) => f !== 'icon.json')) {
    fs.copyFileSync(path.join(ROOT, 'web', f), path.join(site, f));
  }

  run(process.execPath, [path.join(ROOT, 'tools/build/post_build.mjs'), site]);
  fs.rmSync(DIST, { recursive: true, force: true });
  // A copy where the target folder lies on another file system than the checkout.
  try {
    fs.renameSync(site, DIST);
  } catch (e) {
    if (e.code !== 'EXDEV') throw e;
    fs.cpSync(site, DIST, { recursive: true });
  }
  console.error(`dist/ built (${NAME}-${hash})`);
} finally {
  fs.rmSync(stage, { recursive: true, force: true });
}
