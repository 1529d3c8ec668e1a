// The viewer's "convert" panel in Debian's headless Chromium (puppeteer-core),
// with the WebAssembly npm package (scripts/build-wasm.sh: build-wasm/npm)
// served at /smpl-export-wasm/:
//   - the panel's worker loads the converter (state "ready"); from then on
//     no request leaves the page: none reaches the page's own server, and
//     Chromium reports none (blob: URLs of the download excepted);
//   - an SMPL-H model file and an AMASS motion chosen in the file inputs,
//     truncated weights, refit off, GLB: the viewer shows the body (the model's
//     vertex and joint counts, a clip), and the downloaded file (Chromium's
//     own download) is byte-identical to the native CLI's export of the same
//     files with the same options; then FBX from a Python 2 pickle model
//     with betas (default skin fit and refit), shown by the viewer, the
//     download byte-identical to the native CLI's;
//   - a broken model: the panel shows the CLI's one-line error naming the
//     file, and offers no download.
// With --measure-model M [--measure-motion X]: also converts those (default
// options) and prints the WebAssembly memory and the time (a benchmark).
//
//   node wasm_browser_test.mjs --chromium /usr/bin/chromium --npm build-wasm/npm \
//        --native build/cli/smpl-export --fixtures build/fixtures --work /tmp/w
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { parseArgs } from 'node:util';

const WEB_DIR = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', 'web');
const { values: args } = parseArgs({ options: {
  chromium: { type: 'string', default: '/usr/bin/chromium' }, npm: { type: 'string' }, native: { type: 'string' },
  fixtures: { type: 'string' }, work: { type: 'string' }, 'measure-model': { type: 'string' },
  'measure-motion': { type: 'string' } } });
for (const key of ['npm', 'native', 'fixtures', 'work']) {
  if (!args[key]) { console.error(`wasm_browser_test: --${key} is required`); process.exit(1); }
}
const fail = (msg) => { console.error(`FAIL: ${msg}`); process.exit(1); };
if (!fs.existsSync(args.chromium)) fail(`${args.chromium} not found (Debian package chromium)`);
if (!fs.existsSync(path.join(args.npm, 'smpl-export-web.wasm'))) fail(`no WebAssembly npm package in ${args.npm} (scripts/build-wasm.sh)`);
const puppeteer = (await import(pathToFileURL(path.join(WEB_DIR, 'node_modules/puppeteer-core/lib/esm/puppeteer/puppeteer-core.js')).href)).default;
const { startServer } = await import(pathToFileURL(path.join(WEB_DIR, 'viewer', 'serve.js')).href);

const work = path.resolve(args.work), downloads = path.join(work, 'downloads');
fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(downloads, { recursive: true });
const fixture = (rel) => path.join(path.resolve(args.fixtures), rel);

/** The native CLI on copies of the inputs (the same base names) in WORK/native/<name>; returns the output's path. */
function native(name, inputs, cliArgs, out) {
  const dir = path.join(work, 'native', name);
  fs.mkdirSync(dir, { recursive: true });
  const words = [];
  for (const [key, file] of Object.entries(inputs)) {
    fs.copyFileSync(file, path.join(dir, path.basename(file)));
    words.push(`--${key}`, path.basename(file));
  }
  execFileSync(path.resolve(args.native), [...words, '--out', out, ...cliArgs, '--quiet'], { cwd: dir, stdio: 'inherit' });
  return path.join(dir, out);
}

const served = [];
const server = await startServer(0, '127.0.0.1', path.resolve(args.npm));
server.on('request', (req) => served.push(req.url));
const base = `http://127.0.0.1:${server.address().port}`;
const browser = await puppeteer.launch({ executablePath: args.chromium, headless: true,
  args: ['--no-sandbox', '--disable-dev-shm-usage', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
         '--window-size=1280,900'] });
let failed = false;
try {
  const page = await browser.newPage();
  await page.setViewport({ width: 1280, height: 900 });
  const errors = [], requests = [];
  page.on('pageerror', (e) => errors.push(e.message));
  page.on('request', (r) => requests.push(r.url()));
  const cdp = await browser.target().createCDPSession();
  await cdp.send('Browser.setDownloadBehavior', { behavior: 'allow', downloadPath: downloads, eventsEnabled: true });

  await page.goto(`${base}/viewer/`, { waitUntil: 'load' });
  await page.waitForFunction(() => ['ready', 'unavailable'].includes(document.getElementById('convert').dataset.state),
                             { timeout: 120000 });
  const loaded = await page.$eval('#convert', (e) => e.dataset.state);
  assert.equal(loaded, 'ready', `the converter did not load: ${await page.$eval('#conv-status', (e) => e.textContent)}`);
  assert.ok(served.some((u) => u.endsWith('/smpl-export-wasm/smpl-export-web.wasm')), 'the .wasm was not fetched');
  served.length = 0;
  requests.length = 0;

  /** Fill the panel, convert; resolves to the panel's final state and status line. */
  async function convert({ model, motion, format = 'glb', skin = 'optimized', refit = true, betas = '' }) {
    const files = (id, file) => page.$(id).then((h) => (file ? h.uploadFile(file) : h.evaluate((e) => { e.value = ''; })));
    await files('#conv-model', model);
    await files('#conv-motion', motion);
    await page.select('#conv-format', format);
    await page.select('#conv-skin', skin);
    await page.$eval('#conv-refit', (e, on) => { e.checked = on; }, refit);
    await page.$eval('#conv-betas', (e, v) => { e.value = v; }, betas);
    await page.click('#conv-run');
    await page.waitForFunction(() => ['done', 'failed'].includes(document.getElementById('convert').dataset.state) &&
                               !document.getElementById('conv-run').disabled, { timeout: 600000 });
    return page.$eval('#convert', (e) => ({ state: e.dataset.state, memory: Number(e.dataset.memory || 0),
      status: document.getElementById('conv-status').textContent }));
  }
  /** Click the download link; resolves to the downloaded file's bytes (Chromium writes it to WORK/downloads). */
  async function download(name) {
    const target = path.join(downloads, name);
    fs.rmSync(target, { force: true });
    await page.click('#conv-download');
    for (let i = 0; i < 600 && !fs.existsSync(target); i++) await new Promise((r) => setTimeout(r, 100));
    assert.ok(fs.existsSync(target), `no download of ${name}`);
    return fs.readFileSync(target);
  }

  // 1. SMPL-H model + AMASS motion -> GLB, byte-identical to the native CLI.
  const model = fixture('models/smplh_small.npz'), motion = fixture('motions/amass_smplh.npz');
  const glb = await convert({ model, motion, skin: 'truncated', refit: false });
  assert.equal(glb.state, 'done', glb.status);
  const info = await page.evaluate(() => window.smplViewer.info());
  assert.equal(info.file, 'amass_smplh.glb');
  assert.equal(info.modelKind, 'smplh');
  const clips = await page.$$eval('#clip option', (o) => o.length);
  assert.ok(clips >= 1, 'the converted motion has no clip in the viewer');
  const downloaded = await download('amass_smplh.glb');
  const expected = native('glb', { model, motion }, ['--max-influences', '4', '--skin-weights', 'truncated',
    '--corrective-refit', 'off'], 'amass_smplh.glb');
  assert.ok(downloaded.equals(fs.readFileSync(expected)), 'the downloaded GLB differs from the native CLI\'s');
  console.log(`GLB: ${downloaded.length} bytes, identical to the native CLI's; ${info.vertices} vertices, ` +
              `${info.joints} joints, ${info.morphTargets} morph targets shown; ${glb.status}`);

  // 2. A Python 2 pickle model with betas -> FBX (default fit and refit).
  const pickle = fixture('models/smpl_small_p2.pkl');
  const fbx = await convert({ model: pickle, format: 'fbx', betas: '0.5,-1.2,0.3' });
  assert.equal(fbx.state, 'done', fbx.status);
  const fbxBytes = await download('smpl_small_p2.fbx');
  const fbxNative = native('fbx', { model: pickle }, ['--betas', '0.5,-1.2,0.3'], 'smpl_small_p2.fbx');
  assert.ok(fbxBytes.equals(fs.readFileSync(fbxNative)), 'the downloaded FBX differs from the native CLI\'s');
  assert.equal((await page.evaluate(() => window.smplViewer.info())).format, 'fbx');
  console.log(`FBX: ${fbxBytes.length} bytes, identical to the native CLI's; ${fbx.status}`);

  // 3. A broken model: the CLI's one line, no download.
  const broken = path.join(work, 'broken.npz');
  fs.writeFileSync(broken, Buffer.alloc(64));
  const bad = await convert({ model: broken });
  assert.equal(bad.state, 'failed');
  assert.match(bad.status, /^Error loading broken\.npz: /);
  assert.equal(await page.$eval('#conv-download', (e) => e.hidden), true, 'a failed conversion offers a download');

  // Measurement (optional): a large model and motion with the panel's defaults.
  if (args['measure-model']) {
    const t0 = Date.now();
    const m = await convert({ model: path.resolve(args['measure-model']),
                              motion: args['measure-motion'] && path.resolve(args['measure-motion']) });
    assert.equal(m.state, 'done', m.status);
    console.log(`MEASURE: ${path.basename(args['measure-model'])} + ${args['measure-motion'] ? path.basename(args['measure-motion']) : '-'}: ` +
                `WebAssembly memory ${(m.memory / 2 ** 20).toFixed(0)} MiB, ${((Date.now() - t0) / 1000).toFixed(1)} s; ${m.status}`);
  }

  const outgoing = requests.filter((u) => !u.startsWith('blob:') && !u.startsWith('data:'));
  assert.deepEqual(outgoing, [], 'the page made requests while converting');
  assert.deepEqual(served, [], 'the server saw requests while converting');
  assert.deepEqual(errors, [], 'page errors');
  console.log('PASS: convert panel: no request after the converter loaded; GLB and FBX byte-identical to the native CLI; error line');
} catch (e) {
  failed = true;
  console.error(`FAIL: ${e.message}`);
} finally {
  await browser.close();
  server.close();
}
process.exit(failed ? 1 : 0);
