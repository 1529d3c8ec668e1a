// The JS API of the npm package (web/smpl-export-wasm/index.mjs: exportAsset
// on in-memory files, the in-memory module smpl-export-web.mjs/.wasm) in node,
// against the native binary run on the same files with the same options, every
// output and sidecar byte-identical: an SMPL-H model + an AMASS motion to GLB
// (skin fit and refit, and without them) and to FBX, a Python 2 pickle model
// with betas, a BVH, the built-in body's default GLB;
//   the same call twice gives the same bytes (a fresh instance per call);
//   errors: a bad model rejects with the CLI's one line naming the file and its
//   exit code (2) and returns no file; inputs given as options, batch options
//   and a missing model are refused before anything runs.
//
//   node wasm_api_test.mjs NPM_DIR NATIVE_EXE FIXTURES WORK
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const [npmDir, native, fixtures, work] = process.argv.slice(2).map((p) => path.resolve(p));
if (!fs.existsSync(path.join(npmDir, 'index.mjs')) || !fs.existsSync(path.join(npmDir, 'smpl-export-web.wasm'))) {
  console.error(`FAIL: no npm package with the JS API in ${npmDir} (scripts/build-wasm.sh makes build-wasm/npm)`);
  process.exit(1);
}
const { exportAsset } = await import(pathToFileURL(path.join(npmDir, 'index.mjs')).href);
fs.rmSync(work, { recursive: true, force: true });
fs.mkdirSync(path.join(work, 'native'), { recursive: true });

const fixture = (rel) => ({ name: path.basename(rel), data: fs.readFileSync(path.join(fixtures, rel)) });
/** The native CLI on copies of the same files (same base names), in WORK/native/<case>/. */
function runNative(name, files, args) {
  const dir = path.join(work, 'native', name);
  fs.mkdirSync(dir, { recursive: true });
  const cli = [];
  for (const [key, f] of Object.entries(files)) {
    if (f === 'builtin') { cli.push(`--${key}`, 'builtin'); continue; }
    fs.writeFileSync(path.join(dir, f.name), f.data);
    cli.push(`--${key}`, f.name);
  }
  execFileSync(native, [...cli, ...args], { cwd: dir, stdio: ['ignore', 'ignore', 'inherit'] });
  return dir;
}
const words = (options) => Object.entries(options).filter(([k]) => k !== 'out')
  .flatMap(([k, v]) => (v === true ? [`--${k}`] : [`--${k}`, String(v)]));

const plain = { 'skin-weights': 'truncated', 'corrective-refit': 'off' };
const exact = [
  ['amass_glb', { model: fixture('models/smplh_small.npz'), motion: fixture('motions/amass_smplh.npz') },
    { out: 'walk.glb', ...plain }],
  ['amass_fit', { model: fixture('models/smplh_small.npz'), motion: fixture('motions/amass_smplh.npz') },
    { out: 'fit.glb' }],
  ['amass_fbx', { model: fixture('models/smplh_small.npz'), motion: fixture('motions/amass_smplh.npz') },
    { out: 'walk.fbx' }],
  ['builtin', { model: 'builtin' }, { out: 'body.glb' }],
  ['pickle', { model: fixture('models/smpl_small_p2.pkl') }, { out: 'body.glb', ...plain, betas: '0.5,-1.2,0.3' }],
  ['bvh', { model: fixture('models/smplh_small.npz'), motion: fixture('motions/amass_smplh.npz') }, { out: 'walk.bvh' }],
];
let compared = 0;
for (const [name, files, options] of exact) {
  const result = await exportAsset(files, { ...options, quiet: true });
  assert.equal(result.exitCode, 0);
  const dir = runNative(name, files, ['--out', options.out, ...words(options), '--quiet']);
  const expected = fs.readdirSync(dir).filter((f) => f.startsWith(options.out)).sort();
  assert.deepEqual(Object.keys(result.files).sort(), expected, `${name}: the files written`);
  for (const f of expected) {
    assert.ok(Buffer.from(result.files[f]).equals(fs.readFileSync(path.join(dir, f))),
              `${name}: ${f} differs from the native CLI's`);
    compared++;
  }
}
assert.ok(compared >= 12, `only ${compared} files compared`);

// The summary names the output as given; a second call gives the same bytes.
const body = await exportAsset({ model: 'builtin' }, { out: 'body.glb' });
assert.match(body.stdout, /^body\.glb: 4644 vertices, 24 joints/, 'the summary names the output as given');
const again = await exportAsset({ model: 'builtin' }, { out: 'body.glb', quiet: true });
assert.ok(Buffer.from(again.files['body.glb']).equals(Buffer.from(body.files['body.glb'])), 'a second call differs');

// Errors: the CLI's line, its exit code, no file.
await assert.rejects(exportAsset({ model: { name: 'broken.npz', data: new Uint8Array(64) } }, { out: 'x.glb' }),
  (e) => {
    assert.match(e.message, /^Error loading broken\.npz: /);
    assert.equal(e.exitCode, 2);
    assert.equal(e.files, undefined);
    return true;
  });
await assert.rejects(exportAsset({ model: 'builtin' }, { out: 'x.glb', 'max-influences': 0 }), (e) => e.exitCode === 1);
await assert.rejects(exportAsset({ motion: fixture('motions/smpl_72.npz') }), /files\.model is required/);
await assert.rejects(exportAsset({ model: 'builtin' }, { motion: 'walk.npz' }), /give it in files\.motion/);
await assert.rejects(exportAsset({ model: 'builtin' }, { 'motion-dir': 'x' }), /batch mode/);
await assert.rejects(exportAsset({ model: 'builtin', poses: new Uint8Array(1) }), /files\.poses: not an input/);
console.log(`PASS: exportAsset: ${compared} files byte-identical to the native CLI's, ` +
            `repeatable; errors (memory of the built-in export: ${(body.memoryBytes / 2 ** 20).toFixed(0)} MiB)`);
