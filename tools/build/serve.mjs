// A static server for dist/ on 127.0.0.1, as a plain host serves it: no compression
// negotiated, a content-length and last-modified on every file, 304 for a revalidation.
// `make run` runs it (`node tools/build/serve.mjs [DIR] [PORT]`: dist/ on 8080); the
// browser tests and `make audit` import `serve` (a free port, and `sent`: the body bytes
// sent per path, which the test of a first visit's weight reads).
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const TYPES = {
  '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.png': 'image/png',
  '.jpg': 'image/jpeg', '.json': 'application/json', '.css': 'text/css', '.svg': 'image/svg+xml',
  '.webmanifest': 'application/manifest+json',
};

/** Serves `dir` on 127.0.0.1:`port` (0: a free one); resolves to `{ server, sent, url }`. */
export function serve(dir, port = 0) {
  const root = path.resolve(dir);
  const sent = new Map();
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://x');
    const file = path.join(root, url.pathname === '/' ? 'index.html' : decodeURIComponent(url.pathname));
    if (!file.startsWith(root) || !fs.existsSync(file) || fs.statSync(file).isDirectory()) {
      res.writeHead(404).end();
      return;
    }
    const { size, mtime } = fs.statSync(file);
    const modified = new Date(Math.floor(mtime.getTime() / 1000) * 1000);
    const since = Date.parse(req.headers['if-modified-since'] ?? '');
    if (since >= modified.getTime()) {
      res.writeHead(304).end();
      return;
    }
    res.writeHead(200, { 'content-type': TYPES[path.extname(file)] || 'application/octet-stream', 'content-length': size, 'last-modified': modified.toUTCString() });
    if (req.method === 'HEAD') {
      res.end();
      return;
    }
    sent.set(url.pathname, (sent.get(url.pathname) ?? 0) + size);
    fs.createReadStream(file).pipe(res);
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, '127.0.0.1', () => resolve({ server, sent, url: `http://127.0.0.1:${server.address().port}/` }));
  });
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) {
  const dir = process.argv[2] ?? path.resolve(import.meta.dirname, '../../dist');
  if (!fs.existsSync(path.join(dir, 'index.html'))) {
    console.error(`${dir} has no index.html: run \`make web\` first`);
    process.exit(1);
  }
  const { url } = await serve(dir, Number(process.argv[3] ?? 8080));
  console.log(`serving ${dir} on ${url} (Ctrl+C stops it)`);
}
