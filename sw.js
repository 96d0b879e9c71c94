// Zeta Lab service worker: after the first visit the app works offline.
// The cache is versioned by the build (the post-build hook writes BUILD and FILES), so a
// new deployment installs a fresh cache and deletes the old one.
const BUILD = '__ZETA_BUILD__';
const FILES = ['./'];
const CACHE = `zeta-lab-${BUILD}`;
// Language catalogues are not installed up front: a visitor downloads only the one the
// page asks for, and the fetch handler below keeps it for the next (or an offline) visit.
// Nor are the demos' first modules (zeta-first-<demo>): they serve a first visit, and a
// page this worker serves starts from the full module, which it installs (web/preload.js).
const CATALOGUE = /\/locales\/[^/]+\.ftl$/;
const INSTALL = FILES.filter((f) => !/^locales\//.test(f) && !/^zeta-first-/.test(f));

self.addEventListener('install', (event) => {
  event.waitUntil(
    caches.open(CACHE).then((cache) => cache.addAll(INSTALL)).then(() => self.skipWaiting()),
  );
});

self.addEventListener('activate', (event) => {
  event.waitUntil(
    caches.keys()
      .then((keys) => Promise.all(keys.filter((k) => k.startsWith('zeta-lab-') && k !== CACHE).map((k) => caches.delete(k))))
      .then(() => self.clients.claim()),
  );
});

// Network first for pages and catalogues (so a new build or translation shows at once when
// online), cache first for the versioned assets; either way the cache answers when the
// network does not.
self.addEventListener('fetch', (event) => {
  const req = event.request;
  const url = new URL(req.url);
  if (req.method !== 'GET' || url.origin !== self.location.origin) return;
  if (CATALOGUE.test(url.pathname)) {
    event.respondWith(
      fetch(req)
        .then((res) => {
          if (res.ok) {
            const copy = res.clone();
            caches.open(CACHE).then((c) => c.put(req, copy));
          }
          return res;
        })
        .catch(() => caches.match(req, { ignoreSearch: true }).then((hit) => hit || Response.error())),
    );
    return;
  }
  if (req.mode === 'navigate') {
    event.respondWith(
      fetch(req)
        .then((res) => {
          const copy = res.clone();
          caches.open(CACHE).then((c) => c.put('./', copy));
          return res;
        })
        .catch(() => caches.match('./', { ignoreSearch: true })),
    );
    return;
  }
  event.respondWith(
    caches.match(req, { ignoreSearch: true }).then((hit) => hit || fetch(req).then((res) => {
      if (res.ok) {
        const copy = res.clone();
        caches.open(CACHE).then((c) => c.put(req, copy));
      }
      return res;
    })),
  );
});
