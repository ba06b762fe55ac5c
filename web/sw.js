// The playground's service worker: after one visit the app opens and works offline.
//
// `tools/build/post_build.mjs` (a Trunk post-build hook) fills in BUILD and FILES for each
// build: every file of dist/ but the plain wasm module, and a version made from their
// names and sizes. The module is there twice, as `.br` and `.gz` (index.html fetches the
// first this browser can decompress); installing caches that one and every other file,
// so a first visit downloads the module once, compressed. Activating deletes the caches of other builds, so a new build replaces the
// old one cleanly. Pages are fetched from the network first (a new build shows at once
// when online) and from the cache when offline; the other files, whose names carry a
// content hash, from the cache first.
const BUILD = '__BUILD__';
const FILES = __FILES__;
const CACHE = `marbling-${BUILD}`;

/** Whether this browser's DecompressionStream reads `format`. */
function canDecompress(format) {
  try { new DecompressionStream(format); return true; } catch { return false; }
}

/** FILES less the compressed forms that index.html's `marblingFetchWasm` will not ask for. */
function wanted() {
  const brotli = canDecompress('brotli');
  return FILES.filter((f) => !(brotli ? f.endsWith('.wasm.gz') : f.endsWith('.wasm.br')));
}

self.addEventListener('install', (event) => {
  event.waitUntil(caches.open(CACHE).then((c) => c.addAll(wanted())).then(() => self.skipWaiting()));
});

self.addEventListener('activate', (event) => {
  event.waitUntil(caches.keys()
    .then((keys) => Promise.all(keys.filter((k) => k.startsWith('marbling-') && k !== CACHE).map((k) => caches.delete(k))))
    .then(() => self.clients.claim()));
});

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) return;
  if (request.mode === 'navigate') {
    // The page with any query (`?landing=0`); its fragment never reaches the server.
    event.respondWith(fetch(request).catch(() => caches.match('./', { cacheName: CACHE })));
    return;
  }
  event.respondWith(caches.match(request, { cacheName: CACHE, ignoreSearch: true })
    .then((hit) => hit || fetch(request)));
});
