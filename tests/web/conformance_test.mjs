// web/smpl-correctives (the three.js driver) as a loader of the runtime
// conformance kit (docs/conformance.md). Per case of a frame whose root bone
// rests in the model frame (manifest "root_rest_is_axes": the driver takes C
// from the root's rest orientation, as three's loaders deliver smpl-export
// files), a three.js skeleton is built with the kit's local rest rotations,
// a skinned mesh with the sidecar's morph targets, bindCorrectives() reads
// the case's sidecar, and per pose the bones get the kit's local rotations;
// features and weights are compared with the kit's tolerance table. Every bad
// sidecar must make bindCorrectives throw an error naming the kit's field.
//
//   node conformance_test.mjs KIT_DIR
//
// Prints "<case>: pose <i>: <quantity> differ by <e> (> <tol>)" per
// difference and exits 1 if there was any (or no case ran).
import fs from 'node:fs';
import path from 'node:path';

import { THREE, driver } from './harness.mjs';

const kitDir = process.argv[2];
if (!kitDir) {
  console.error('usage: node conformance_test.mjs KIT_DIR');
  process.exit(2);
}
const readJson = (file) => JSON.parse(fs.readFileSync(path.join(kitDir, file), 'utf8'));
const manifest = readJson('manifest.json');
const tolerance = (what) => manifest.tolerances[what].float64;
const usable = new Set(manifest.frames.filter((f) => f.root_rest_is_axes).map((f) => f.name));

/** A skeleton (local rest rotations `restLocal`) and a mesh with `targets`. */
function buildRig(names, parents, restLocal, targets) {
  const bones = names.map((name, k) => {
    const bone = new THREE.Bone();
    bone.name = name;
    bone.position.set(0.01 * k, k === 0 ? 1 : 0.1, 0.02 * (k % 3));
    bone.quaternion.fromArray(restLocal[k]);  // (x, y, z, w), as three stores it
    return bone;
  });
  bones.forEach((bone, k) => { if (parents[k] >= 0) bones[parents[k]].add(bone); });
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(new Float32Array(3), 3));
  geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute(new Uint16Array(4), 4));
  geometry.setAttribute('skinWeight', new THREE.Float32BufferAttribute(new Float32Array([1, 0, 0, 0]), 4));
  geometry.morphAttributes.position = targets.map((t) => {
    const a = new THREE.Float32BufferAttribute(new Float32Array(3), 3);
    a.name = t;
    return a;
  });
  geometry.morphTargetsRelative = true;
  const mesh = new THREE.SkinnedMesh(geometry, new THREE.MeshBasicMaterial());
  mesh.updateMorphTargets();
  const root = new THREE.Group();
  root.add(mesh);
  root.add(bones[0]);
  root.updateMatrixWorld(true);
  mesh.bind(new THREE.Skeleton(bones));
  return { root, bones };
}

function maxDiff(a, b) {
  if (a.length !== b.length) return Infinity;
  let d = 0;
  for (let i = 0; i < a.length; i++) d = Math.max(d, Math.abs(a[i] - b[i]));
  return Number.isNaN(d) ? Infinity : d;
}

const problems = [];
let cases = 0;
for (const entry of manifest.cases) {
  if (!usable.has(entry.frame)) continue;
  const sidecar = readJson(entry.sidecar), data = readJson(entry.data);
  const targets = sidecar.correctives.map((e) => e.target)
    .concat(sidecar.corrective_basis ? sidecar.corrective_basis.targets : []);
  const rig = buildRig(sidecar.joint_names, sidecar.parents, data.rest_local, targets);
  const correctives = driver.bindCorrectives(rig.root, sidecar, { warn: () => {} });
  data.poses.forEach((pose, i) => {
    rig.bones.forEach((bone, k) => bone.quaternion.fromArray(pose.local[k]));
    rig.root.updateMatrixWorld(true);
    correctives.update();
    for (const [what, got] of [['features', correctives.features], ['weights', correctives.weights]]) {
      const e = maxDiff(got, pose[what]);
      if (!(e <= tolerance(what))) problems.push(`${entry.name}: pose ${i}: ${what} differ by ${e} (> ${tolerance(what)})`);
    }
  });
  cases++;
}
// Bad sidecars: refused with an error naming the field the kit names.
const bad = manifest.bad || [];
for (const b of bad) {
  let error = '';
  try {
    const meta = JSON.parse(fs.readFileSync(path.join(kitDir, b.sidecar), 'utf8'));
    if (!meta || typeof meta !== 'object' || Array.isArray(meta)) throw new Error('not a JSON object');
    const rig = buildRig(['a', 'b', 'c'], [-1, 0, 1], [[0, 0, 0, 1], [0, 0, 0, 1], [0, 0, 0, 1]],
      ['pose_b_00', 'pose_c_22', 'pose_basis_0', 'pose_basis_1']);
    driver.bindCorrectives(rig.root, meta, { warn: () => {} });
  } catch (e) {
    error = String(e.message);
  }
  if (!error) problems.push(`${b.sidecar}: accepted (${b.what})`);
  else if (b.error !== 'json' && !error.includes(b.error)) problems.push(`${b.sidecar}: error does not name '${b.error}': ${error}`);
}

for (const p of problems) console.log(p);
console.log(`web conformance: ${cases} cases, ${bad.length} bad sidecars, ${problems.length} problems`);
process.exitCode = problems.length || cases === 0 ? 1 : 0;
