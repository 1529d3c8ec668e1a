// The viewer in a real browser: Debian's headless Chromium, driven by
// puppeteer-core, opens web/viewer (served by web/viewer/serve.js), loads an
// export through the page's file input, checks the counts the page shows,
// poses the joints with a pose of the C++ reference and compares the posed
// vertices the page computes (three's skinning in the browser, correctives
// by the driver) with the reference (1e-5 m); with the correctives toggled
// off they must differ. Saves a screenshot. With --anim-asset (an animated
// FBX and its sidecar): the clip list, play (time advances), scrub, and a
// pose slider moving its joint's corrective weights.
//
//   node browser_test.mjs --chromium /usr/bin/chromium --asset body.glb \
//        --reference PREFIX --screenshot out.png [--pose 3] [--anim-asset walk.fbx]
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
    'anim-asset': { type: 'string' },
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
    args: ['--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
           '--window-size=1280,800'],
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
    if (args['anim-asset']) {
      await checkAnimated(page, args['anim-asset']);
      const second = args.screenshot.replace(/(\.png)?$/, '_anim.png');
      await page.screenshot({ path: second });
      console.log(`screenshot: ${second}`);
    }
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

/** Animated FBX + sidecar through the file input: clips, play, scrub, a pose slider. */
async function checkAnimated(page, asset) {
  const input = await page.$('#file');
  await input.uploadFile(asset, asset + '.smpl.json');
  const name = path.basename(asset);
  await page.waitForFunction((n) => document.getElementById('info-file').textContent === n, { timeout: 60000 }, name);
  const shown = await page.evaluate(() => ({
    clips: document.getElementById('clip').options.length,
    driven: document.getElementById('info-driven').textContent,
    encoding: document.getElementById('info-encoding').textContent,
  }));
  console.log(`page shows for ${name}`, JSON.stringify(shown));
  assert.equal(shown.clips, 1, 'one baked clip listed');
  assert.ok(Number(shown.driven) > 0, 'the sidecar bound the correctives');
  assert.equal(shown.encoding, 'unit');
  await page.click('#play');
  await page.waitForFunction(() => parseFloat(document.getElementById('time').textContent) > 0.05, { timeout: 30000 });
  await page.click('#play');  // pause
  await page.evaluate(() => {
    const scrub = document.getElementById('scrub');
    scrub.value = String(Number(scrub.max) / 2);
    scrub.dispatchEvent(new Event('input'));
  });
  const scrubbed = await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r(
    [parseFloat(document.getElementById('time').textContent), Number(document.getElementById('scrub').max)]))));
  assert.ok(Math.abs(scrubbed[0] - scrubbed[1] / 2) < 2e-3, `scrub to the middle: time ${scrubbed[0]} of ${scrubbed[1]}`);
  // Pose mode: bend the left knee with its slider; its correctives follow.
  const knee = await page.evaluate(() => {
    document.getElementById('pose-mode').click();
    const slider = document.querySelector('#sliders input[data-joint="left_knee"]');
    slider.value = '1.5';
    slider.dispatchEvent(new Event('input'));
    return new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => {
      const c = window.smplViewer.correctives;
      r(c.targetNames.filter((t) => t.startsWith('pose_left_knee_')));
    })));
  });
  const f = await page.evaluate(() => Array.from(window.smplViewer.correctives.features.slice(27, 36)));
  console.log('left_knee features after the slider', f.map((v) => v.toFixed(4)).join(' '));
  assert.equal(knee.length, 9, 'left knee targets driven');
  assert.ok(Math.abs(f[4] - (Math.cos(1.5) - 1)) < 1e-6 && Math.abs(f[5] + Math.sin(1.5)) < 1e-6,
            'left_knee slider (x, 1.5 rad) gives R - I of a 1.5 rad turn about x');
}
