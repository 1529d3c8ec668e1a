// Babylon.js facts for the README's engine notes and docs/file-contract.md,
// measured by hand, not part of CTest (it predates Babylon in web/'s devDependencies, which
// tests/web/babylon_scene_test.mjs uses; this script still installs its own copy):
// a mesh with JOINTS_1 loads with 8 bone influencers, default morph weights
// become the targets' influences, quantized (KHR_mesh_quantization, normalized
// int16, stored as d_n / s_n) and sparse morph targets decode to the plain
// export's deltas.
//
//   mkdir /tmp/bjs && cd /tmp/bjs && npm init -y && npm i @babylonjs/core@9 @babylonjs/loaders@9
//   cp <repo>/tests/web/babylon_facts.mjs . && node babylon_facts.mjs plain.glb unit.glb quantized.glb sparse.glb m8.glb
// with (smpl_small fixture; m8: smplx_small)
//   smpl-export --model M --out plain.glb;   ... --corrective-weights unit --out unit.glb
//   ... --quantize-morphs --out quantized.glb;  ... --corrective-epsilon 0.005 --out sparse.glb
//   smpl-export --model smplx_small.npz --max-influences 8 --out m8.glb
import fs from 'node:fs';
import { NullEngine, Scene, SceneLoader } from '@babylonjs/core';
import '@babylonjs/loaders/glTF/index.js';

async function load(file) {
  const scene = new Scene(new NullEngine());
  const r = await SceneLoader.ImportMeshAsync('', '', new Uint8Array(fs.readFileSync(file)), scene, undefined, '.glb');
  const mesh = r.meshes.find((m) => m.morphTargetManager);
  const json = JSON.parse(Buffer.from(fs.readFileSync(file)).subarray(20, 20 + fs.readFileSync(file).readUInt32LE(12)).toString());
  const mtm = mesh.morphTargetManager;
  const targets = Array.from({ length: mtm.numTargets }, (_, i) => mtm.getTarget(i));
  const base = mesh.getVerticesData('position');
  return { mesh, json, base, targets, influences: targets.map((t) => t.influence), positions: targets.map((t) => t.getPositions()) };
}

const [plain, unit, quantized, sparse] = await Promise.all(process.argv.slice(2, 6).map(load));
const fileWeights = unit.json.meshes[0].weights || [];
let dw = 0, nonzero = 0;
fileWeights.forEach((w, i) => { dw = Math.max(dw, Math.abs(w - unit.influences[i])); if (w) nonzero++; });
console.log(`default weights: ${fileWeights.length} in the file (${nonzero} non-zero), max |influence - weight| ${dw.toExponential(3)}`);
// Quantized targets store d_n / s_n (s_n = the largest |component| of d_n; docs/file-contract.md):
// Babylon's decoded delta times s_n must give the plain export's delta, within one int16 step of s_n.
for (const [name, other, scaled] of [['quantized', quantized, true], ['sparse', sparse, false]]) {
  let err = 0, worstStep = 0, maxRaw = 0;
  for (let t = 0; t < plain.positions.length; t++) {
    const a = plain.positions[t], b = other.positions[t];
    let s = 0;
    for (let i = 0; i < a.length; i++) s = Math.max(s, Math.abs(a[i] - plain.base[i]));
    for (let i = 0; i < a.length; i++) {
      const raw = b[i] - other.base[i];
      maxRaw = Math.max(maxRaw, Math.abs(raw));
      const e = Math.abs((scaled ? raw * s : raw) - (a[i] - plain.base[i]));
      err = Math.max(err, e);
      if (scaled) worstStep = Math.max(worstStep, e / (s / 32767));
    }
  }
  console.log(`${name}: ${other.targets.length} targets, largest decoded |delta| ${maxRaw.toFixed(4)}, ` +
              `max |delta - plain export's| ${err.toExponential(3)} m` + (scaled ? ` (${worstStep.toFixed(2)} int16 steps)` : ''));
}

{
  const scene = new Scene(new NullEngine());
  const file = process.argv[6];
  const r = await SceneLoader.ImportMeshAsync('', '', new Uint8Array(fs.readFileSync(file)), scene, undefined, '.glb');
  const m = r.meshes.find((x) => x.skeleton);
  const extra = m.getVerticesData('matricesWeightsExtra');
  console.log(`${file}: numBoneInfluencers ${m.numBoneInfluencers}, second weight set ${extra ? 'read' : 'absent'}`);
}
