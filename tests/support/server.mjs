// A small static file server for the built site (dist/), for the end-to-end tests.
// Serves under any base path (e.g. '/course/demos/') to prove the site is relocatable,
// listens on 127.0.0.1 at a free port, and answers only GET/HEAD inside the folder.
import { createServer } from 'node:http';
import { brotliCompressSync, constants as zlib } from 'node:zlib';
import { readdir, readFile, stat } from 'node:fs/promises';
import { extname, join, normalize, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';

export const DIST = resolve(fileURLToPath(new URL('../../dist', import.meta.url)));

const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.wasm': 'application/wasm',
  '.json': 'application/json',
  '.webmanifest': 'application/manifest+json',
  '.svg': 'image/svg+xml',
  '.png': 'image/png',
  '.ico': 'image/x-icon',
  '.ftl': 'text/plain; charset=utf-8',
};

/** Every file under `dir`, brotli-compressed (quality 11), by path. */
async function precompress(dir, into) {
  for (const entry of await readdir(dir, { withFileTypes: true })) {
    const path = join(dir, entry.name);
    if (entry.isDirectory()) await precompress(path, into);
    else if (entry.isFile()) into.set(path, brotliCompressSync(await readFile(path), { params: { [zlib.BROTLI_PARAM_QUALITY]: 11 } }));
  }
  return into;
}

/**
 * Starts a server for `root` under `base`; resolves to {url, close()}. With `brotli`, a
 * request that accepts `br` gets the body brotli-compressed, as a real static host sends
 * it: compressed before the server starts, as such a host stores it, so no request waits
 * for the compression (at quality 11 a module takes about a second).
 */
export async function serve({ root = DIST, base = '/', headers = {}, brotli = false } = {}) {
  const compressed = brotli ? await precompress(root, new Map()) : new Map();
  const server = createServer(async (req, res) => {
    try {
      const url = new URL(req.url, 'http://localhost');
      if (!url.pathname.startsWith(base) || !['GET', 'HEAD'].includes(req.method)) {
        res.writeHead(404).end('not found');
        return;
      }
      let rel = decodeURIComponent(url.pathname.slice(base.length));
      if (rel === '' || rel.endsWith('/')) rel += 'index.html';
      const file = normalize(join(root, rel));
      if (!file.startsWith(root + sep)) {
        res.writeHead(403).end('forbidden');
        return;
      }
      const info = await stat(file);
      if (!info.isFile()) throw new Error('not a file');
      let body = await readFile(file);
      const extra = {};
      if (brotli && compressed.has(file) && /\bbr\b/.test(req.headers['accept-encoding'] || '')) {
        body = compressed.get(file);
        extra['content-encoding'] = 'br';
      }
      res.writeHead(200, {
        'content-type': TYPES[extname(file)] || 'application/octet-stream',
        'cache-control': 'no-store',
        ...extra,
        ...headers,
      });
      res.end(req.method === 'HEAD' ? undefined : body);
    } catch {
      res.writeHead(404).end('not found');
    }
  });
  await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
  const { port } = server.address();
  return {
    url: `http://127.0.0.1:${port}${base}`,
    close: () => new Promise((ok) => server.close(ok)),
  };
}
