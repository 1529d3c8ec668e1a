// Serve the viewer offline: web/ over HTTP on localhost (three.js from
// web/node_modules, the driver from web/smpl-correctives; nothing from a CDN).
// /smpl-export-wasm/ is the built npm package of the WebAssembly build, for
// the viewer's "convert" panel: $SMPL_EXPORT_WASM_DIR, else build-wasm/npm of
// this checkout (scripts/build-wasm.sh); without it the panel says so.
//
//   npm start                 (in web/, after npm ci)  -> http://localhost:8080/viewer/
//   node viewer/serve.js [port]
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const ROOT = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const TYPES = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8', '.css': 'text/css; charset=utf-8',
  '.json': 'application/json', '.png': 'image/png', '.wasm': 'application/wasm',
};

const WASM_PREFIX = '/smpl-export-wasm/';
const DEFAULT_WASM_DIR = path.join(ROOT, '..', 'build-wasm', 'npm');

/**
 * Start the server; resolves to the http.Server (port 0: any free port).
 * wasmDir: the folder served at /smpl-export-wasm/ (the built npm package).
 */
export function startServer(port = 8080, host = '127.0.0.1',
                            wasmDir = process.env.SMPL_EXPORT_WASM_DIR || DEFAULT_WASM_DIR) {
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://localhost');
    let base = ROOT, rel = decodeURIComponent(url.pathname);
    if (rel.startsWith(WASM_PREFIX)) {
      base = path.resolve(wasmDir);
      rel = rel.slice(WASM_PREFIX.length - 1);
    }
    let file = path.normalize(path.join(base, rel));
    if (file !== base && !file.startsWith(base + path.sep)) {
      res.writeHead(403).end('forbidden');
      return;
    }
    if (url.pathname === '/') {
      res.writeHead(302, { Location: '/viewer/' }).end();
      return;
    }
    if (fs.existsSync(file) && fs.statSync(file).isDirectory()) file = path.join(file, 'index.html');
    fs.readFile(file, (err, data) => {
      if (err) {
        res.writeHead(404).end('not found');
        return;
      }
      res.writeHead(200, { 'Content-Type': TYPES[path.extname(file)] || 'application/octet-stream' }).end(data);
    });
  });
  return new Promise((resolve, reject) => {
    server.once('error', reject);
    server.listen(port, host, () => resolve(server));
  });
}

if (process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  if (!fs.existsSync(path.join(ROOT, 'node_modules', 'three'))) {
    console.error(`serve: ${path.join(ROOT, 'node_modules', 'three')} is missing: run 'npm ci' in ${ROOT}`);
    process.exit(1);
  }
  const server = await startServer(Number(process.argv[2] || process.env.PORT || 8080));
  console.log(`smpl-export viewer: http://localhost:${server.address().port}/viewer/`);
}
