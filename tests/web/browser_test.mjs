// The viewer in a real browser: Debian's headless Chromium, driven by
// puppeteer-core, opens web/viewer (served by web/viewer/serve.js), loads an
// export through the page's file input, checks the counts the page shows,
// poses the joints with a pose of the C++ reference and compares the posed
// vertices the page computes (three's skinning in the browser, correctives
// by the driver) with the reference (1e-5 m); with the correctives toggled
// off they must differ. Saves a screenshot.
//
//   node browser_test.mjs --chromium /usr/bin/chromium --asset body.glb \
//        --reference PREFIX --screenshot out.png [--pose 3]
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { parseArgs } from 'node:util';

import { WEB_DIR, readReference } from './harness.mjs';

const { values: args } = parseArgs({
  options: {
    chromium: { type: 'string', default: '/usr/bin/chromium' }, asset: { type: 'string' },
    reference: { type: 'string' }, screenshot: { type: 'string' }, pose: { type: 'string', default: '3' },
  },
});
for (const key of ['asset', 'reference', 'screenshot']) {
  if (!args[key]) {
    console.error(`browser_test: --${key} is required`);
    process.exit(1);
  }
}
if (!fs.existsSync(args.chromium)) {
  console.error(`browser_test: ${args.chromium} not found (Debian package chromium; scripts/setup-deps.sh installs it)`);
  process.exit(1);
}
const puppeteer = (await import(pathToFileURL(path.join(WEB_DIR, 'node_modules/puppeteer-core/lib/esm/puppeteer/puppeteer-core.js')).href)).default;
const { startServer } = await import(pathToFileURL(path.join(WEB_DIR, 'viewer', 'serve.js')).href);

test(`viewer in headless Chromium: ${path.basename(args.asset)}`, async () => {
  const ref = readReference(args.reference);
  const K = ref.header.num_joints, N = ref.header.num_vertices, p = Number(args.pose);
  const server = await startServer(0);
  const browser = await puppeteer.launch({
    executablePath: args.chromium, headless: true,
    // root in CI needs --no-sandbox; no GPU: WebGL through SwiftShader.
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--window-size=1280,800'],
  });
  try {
    const page = await browser.newPage();
    await page.setViewport({ width: 1280, height: 800 });
    const errors = [], requests = [];
    page.on('pageerror', (e) => errors.push(e.message));
    page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
    page.on('request', (r) => requests.push(r.url()));
    const base = `http://127.0.0.1:${server.address().port}`;
    await page.goto(`${base}/viewer/`, { waitUntil: 'load' });
    await page.waitForSelector('body[data-ready="true"]', { timeout: 60000 });
    const input = await page.$('#file');
    await input.uploadFile(args.asset);
    const name = path.basename(args.asset);
    await page.waitForFunction((n) => document.getElementById('info-file').textContent === n, { timeout: 60000 }, name);
    const shown = await page.evaluate(() => Object.fromEntries(
      ['kind', 'vertices', 'joints', 'targets', 'driven'].map((k) => [k, document.getElementById('info-' + k).textContent])));
    console.log('page shows', JSON.stringify(shown));
    assert.deepEqual(shown, { kind: ref.header.model_kind, vertices: String(N), joints: String(K),
                              targets: String(9 * (K - 1)), driven: String(9 * (K - 1)) });

    const pose = Array.from(ref.arrays.poses.data.subarray(3 * K * p, 3 * K * (p + 1)));
    const expected = ref.arrays.vertices_pruned.data.subarray(3 * N * p, 3 * N * (p + 1));
    const readVertices = () => page.evaluate((n) => {
      const out = [];
      for (let i = 0; i < n; i++) out.push(...window.smplViewer.vertexWorld(i));
      return out;
    }, N);
    const maxError = (got) => got.reduce((m, v, i) => Math.max(m, Math.abs(v - expected[i])), 0);
    await page.evaluate((a) => window.smplViewer.setPose(a), pose);
    const err = maxError(await readVertices());
    // Toggle the correctives off: the page must show plain skinning (wrong by the correctives).
    await page.click('#correctives');
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    const errOff = maxError(await readVertices());
    await page.click('#correctives');
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    console.log(`browser ${name} pose ${p}: max_err_m ${err.toExponential(3)} (correctives off: ${errOff.toExponential(3)})`);
    fs.mkdirSync(path.dirname(args.screenshot), { recursive: true });
    await page.screenshot({ path: args.screenshot });
    console.log(`screenshot: ${args.screenshot}`);
    const foreign = requests.filter((u) => !u.startsWith(base) && !u.startsWith('data:') && !u.startsWith('blob:'));
    assert.deepEqual(foreign, [], 'the viewer fetched something from outside the local server');
    assert.deepEqual(errors, [], 'page errors');
    assert.ok(err <= 1e-5, `posed vertices off by ${err} m (> 1e-5 m)`);
    assert.ok(errOff > 1e-4, `correctives toggle had no visible effect (${errOff} m)`);
  } finally {
    await browser.close();
    server.close();
  }
});
