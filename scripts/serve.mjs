// A plain static server for a folder (default site/, the page as ./scripts/build-site.sh writes
// it): what any static host does, with the content types the page needs and the two headers
// that make the page cross-origin isolated, so that its worker runs the threaded module
// (`isolated: false`, or --not-isolated, serves without them). No dependencies.
// Run directly (`node scripts/serve.mjs [port] [folder] [--not-isolated]`) or import
// `startServer` from tests.
import { createServer } from 'node:http';
import { readFile, stat } from 'node:fs/promises';
import { extname, join, normalize, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = resolve(fileURLToPath(import.meta.url), '../..');
export const SITE = join(ROOT, 'site');
const TYPES = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.wasm': 'application/wasm',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.svg': 'image/svg+xml',
  '.md': 'text/markdown; charset=utf-8',
};

function filePath(root, urlPath) {
  const path = normalize(decodeURIComponent(urlPath.split('?')[0]));
  if (path.includes('..')) return null;
  return join(root, path.endsWith('/') ? path + 'index.html' : path);
}

/** The headers that make a page cross-origin isolated (site/_headers says the same to hosts). */
export const ISOLATION = {
  'cross-origin-opener-policy': 'same-origin',
  'cross-origin-embedder-policy': 'require-corp',
};

export function startServer({ port = 8080, host = '127.0.0.1', root = SITE, isolated = true } = {}) {
  const server = createServer(async (req, res) => {
    const path = filePath(root, req.url);
    try {
      if (!path || !(await stat(path)).isFile()) throw new Error('not a file');
      const body = await readFile(path);
      res.writeHead(200, {
        'content-type': TYPES[extname(path)] ?? 'application/octet-stream',
        'cache-control': 'no-store',
        ...(isolated ? ISOLATION : {}),
      });
      res.end(body);
    } catch {
      res.writeHead(404, { 'content-type': 'text/plain' });
      res.end(`not found: ${req.url}\n`);
    }
  });
  return new Promise((done, fail) => {
    server.once('error', fail);
    server.listen(port, host, () => done(server));
  });
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const args = process.argv.slice(2).filter((a) => a !== '--not-isolated');
  const port = Number(args[0] ?? process.env.PORT ?? 8080);
  const root = resolve(args[1] ?? SITE);
  const isolated = !process.argv.includes('--not-isolated');
  const server = await startServer({ port, root, isolated });
  const { address, port: bound } = server.address();
  console.log(`serving ${root} at http://${address}:${bound}/  (Ctrl-C to stop)`);
}
