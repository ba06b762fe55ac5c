// The playground's service worker: after one visit the app opens and works offline.
//
// `web/precache.sh` (a Trunk post-build hook) fills in BUILD and FILES for each build:
// every file of dist/, and a version made from their names and sizes. Installing caches
// them all; activating deletes the caches of other builds, so a new build replaces the
// old one cleanly. Pages are fetched from the network first (a new build shows at once
// when online) and from the cache when offline; the other files, whose names carry a
// content hash, from the cache first.
const BUILD = '__BUILD__';
const FILES = __FILES__;
const CACHE = `marbling-${BUILD}`;

self.addEventListener('install', (event) => {
  event.waitUntil(caches.open(CACHE).then((c) => c.addAll(FILES)).then(() => self.skipWaiting()));
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
