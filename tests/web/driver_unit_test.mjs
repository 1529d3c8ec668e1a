// web/smpl-correctives on synthetic rigs built in code (synthetic-rig.js):
// the robust formula under re-oriented bones and a moved character, the
// "rectified" (split) and basis mappings, names-only binding, the one-time
// warning for more than 4 influences, and errors that name the problem.
import assert from 'node:assert/strict';
import path from 'node:path';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';

import { THREE, WEB_DIR, driver } from './harness.mjs';

const { buildRig, targetNames } = await import(pathToFileURL(path.join(WEB_DIR, 'smpl-correctives', 'synthetic-rig.js')).href);
const { bindCorrectives } = driver;

// Deterministic pseudo-random numbers (LCG), no Math.random in tests.
function random(seed) {
  let s = seed >>> 0;
  return () => ((s = (Math.imul(s, 1664525) + 1013904223) >>> 0) / 2 ** 32) * 2 - 1;
}

function randomQuaternion(rand, maxAngle) {
  const axis = new THREE.Vector3(rand(), rand(), rand()).normalize();
  return new THREE.Quaternion().setFromAxisAngle(axis, maxAngle * rand());
}

/**
 * Pose with model-space local rotations `rot` (THREE.Quaternion per joint)
 * through world rotations only: bone k's world rotation becomes
 * C G_k C^-1 Wrest_k with C the root bone's rest orientation (the model frame).
 */
function poseModelSpace(rig, rot, restWorld) {
  const C = restWorld[0].clone(), Cinv = C.clone().invert();
  const global = [];
  rig.bones.forEach((bone, k) => {
    const p = rig.parents[k];
    global.push(p >= 0 ? global[p].clone().multiply(rot[k]) : rot[k].clone());
    const world = C.clone().multiply(global[k]).multiply(Cinv).multiply(restWorld[k]);
    const parentWorld = bone.parent.getWorldQuaternion(new THREE.Quaternion());
    bone.quaternion.copy(parentWorld.invert().multiply(world));
    bone.updateMatrixWorld(true);
  });
}

function expectedFeatures(rot) {
  const f = [];
  for (let k = 1; k < rot.length; k++) {
    const m = new THREE.Matrix4().makeRotationFromQuaternion(rot[k]).elements;  // column-major
    for (let r = 0; r < 3; r++) for (let c = 0; c < 3; c++) f.push(m[4 * c + r] - (r === c ? 1 : 0));
  }
  return f;
}

function maxDiff(a, b) {
  assert.equal(a.length, b.length);
  let d = 0;
  for (let i = 0; i < a.length; i++) d = Math.max(d, Math.abs(a[i] - b[i]));
  return d;
}

for (const kind of ['smpl', 'smplx']) {
  test(`${kind}: features from re-oriented bones, an extra node in a chain, a moved character`, () => {
    const rand = random(kind === 'smpl' ? 1 : 2);
    // Bones rest at arbitrary local orientations (as an importer that rolls or
    // pre-rotates bones leaves them); the model's rest is still "identity".
    const rig = buildRig(THREE, kind, { restRotation: () => randomQuaternion(rand, Math.PI) });
    // A non-joint node between left_knee and left_ankle (helpers some tools insert).
    const knee = rig.bones[4], ankle = rig.bones[7], helper = new THREE.Object3D();
    helper.quaternion.copy(randomQuaternion(rand, 1));
    knee.add(helper); helper.add(ankle);
    ankle.quaternion.premultiply(helper.quaternion.clone().invert());  // same rest world rotation
    const outer = new THREE.Group();
    outer.add(rig.root);
    outer.updateMatrixWorld(true);
    rig.mesh.bind(rig.mesh.skeleton, rig.mesh.matrixWorld);
    rig.mesh.skeleton.calculateInverses();
    const restWorld = rig.bones.map((b) => b.getWorldQuaternion(new THREE.Quaternion()));
    const correctives = bindCorrectives(rig.root, rig.metadata);
    // Move and turn the whole character after binding: features must not change.
    outer.position.set(3, -1, 2);
    outer.quaternion.copy(randomQuaternion(rand, 2));
    outer.scale.setScalar(2.5);
    outer.updateMatrixWorld(true);
    for (let trial = 0; trial < 5; trial++) {
      const rot = rig.bones.map(() => randomQuaternion(rand, 1.2));
      poseModelSpace(rig, rot, rig.bones.map((b, k) => {
        // rest world rotation in the moved frame
        return outer.quaternion.clone().multiply(restWorld[k]);
      }));
      const weights = correctives.update();
      const f = expectedFeatures(rot);
      assert.ok(maxDiff(correctives.features, f) < 1e-12, `trial ${trial}: features off by ${maxDiff(correctives.features, f)}`);
      const dict = rig.mesh.morphTargetDictionary, influences = rig.mesh.morphTargetInfluences;
      targetNames(rig.names).forEach((t, n) => assert.equal(influences[dict[t]], correctives.features[n]));
      assert.equal(weights.length, f.length);
    }
  });
}

test('split encoding: "rectified" entries give max(0, scale f + offset); others keep the signed formula', () => {
  const base = buildRig(THREE, 'smpl');
  const names = ['pose_left_hip_00', 'pose_left_hip_01_pos', 'pose_left_hip_01_neg', 'pose_left_hip_10'];
  const rig = buildRig(THREE, 'smpl', { targets: names });
  rig.metadata.corrective_encoding = 'split';
  rig.metadata.correctives = [
    { feature: 0, target: names[0], scale: -0.5, offset: 0, rectified: true },
    { feature: 1, target: names[1], scale: 1, offset: 0, rectified: true },
    { feature: 1, target: names[2], scale: -1, offset: 0, rectified: true },
    { feature: 3, target: names[3], scale: 1, offset: 0 },  // no "rectified": may go negative
  ];
  const correctives = bindCorrectives(rig.root, rig.metadata);
  const influences = rig.mesh.morphTargetInfluences, dict = rig.mesh.morphTargetDictionary;
  for (const angle of [0.7, -0.7]) {
    rig.bones[1].quaternion.setFromAxisAngle(new THREE.Vector3(0, 0, 1), angle);  // f[1] = -sin, f[3] = sin
    correctives.update();
    const f = correctives.features;
    assert.ok(Math.abs(f[1] + Math.sin(angle)) < 1e-12 && Math.abs(f[3] - Math.sin(angle)) < 1e-12);
    assert.ok(Math.abs(influences[dict[names[0]]] - -f[0] / 2) < 1e-15 && influences[dict[names[0]]] > 0);
    assert.equal(influences[dict[names[1]]], Math.max(f[1], 0));
    assert.equal(influences[dict[names[2]]], Math.max(-f[1], 0));
    assert.equal(influences[dict[names[3]]], f[3]);
  }
  assert.equal(base.mesh.morphTargetInfluences.length, 207);
});

test('corrective basis: target b gets scale_b (C f)_b + offset_b', () => {
  const rand = random(3);
  const rig = buildRig(THREE, 'smpl', { targets: ['pose_basis_0', 'pose_basis_1'] });
  const P = 207;
  const matrix = Array.from({ length: 2 * P }, () => rand());
  rig.metadata.correctives = [];
  rig.metadata.corrective_basis = { targets: ['pose_basis_0', 'pose_basis_1'], features: P, matrix,
                                    scale: [0.5, -2], offset: [0.25, 1] };
  const correctives = bindCorrectives(rig.root, rig.metadata);
  rig.bones.forEach((b) => b.quaternion.copy(randomQuaternion(rand, 1)));
  correctives.update();
  const f = correctives.features, influences = rig.mesh.morphTargetInfluences;
  for (let b = 0; b < 2; b++) {
    let s = 0;
    for (let n = 0; n < P; n++) s += matrix[b * P + n] * f[n];
    const expected = rig.metadata.corrective_basis.scale[b] * s + rig.metadata.corrective_basis.offset[b];
    assert.ok(Math.abs(influences[rig.mesh.morphTargetDictionary[`pose_basis_${b}`]] - expected) < 1e-12);
  }
  rig.metadata.corrective_basis.matrix = matrix.slice(1);
  assert.throws(() => bindCorrectives(rig.root, rig.metadata), /corrective_basis is malformed \(expected 2 x 207/);
});

test('the unit mapping (scale, offset) is applied; rest() gives the rest weights', () => {
  const rig = buildRig(THREE, 'smpl');
  rig.metadata.correctives.forEach((e) => { e.scale = 0.5; e.offset = e.feature % 9 % 4 === 0 ? 1 : 0.5; });
  const correctives = bindCorrectives(rig.root, rig.metadata);
  rig.bones[5].quaternion.setFromAxisAngle(new THREE.Vector3(1, 0, 0), 0.9);
  correctives.update();
  const f = correctives.features, influences = rig.mesh.morphTargetInfluences;
  rig.metadata.correctives.forEach((e) => {
    assert.ok(Math.abs(influences[e.feature] - (0.5 * f[e.feature] + e.offset)) < 1e-15);
  });
  correctives.rest();
  rig.metadata.correctives.forEach((e) => assert.equal(influences[e.feature], e.offset));
});

test('without metadata: targets pose_<joint>_<rc> are driven with weight = f', () => {
  const rig = buildRig(THREE, 'smpl');
  const correctives = bindCorrectives(rig.root, null);
  rig.bones[18].quaternion.setFromAxisAngle(new THREE.Vector3(0, 1, 0), 0.5);
  correctives.update();
  const names = targetNames(rig.names), dict = rig.mesh.morphTargetDictionary;
  const n = names.indexOf('pose_left_elbow_02');
  assert.ok(Math.abs(rig.mesh.morphTargetInfluences[dict[names[n]]] - Math.sin(0.5)) < 1e-12);
  assert.equal(correctives.weights.length, 207);
});

test('more than 4 influences: one warning, once', () => {
  const warnings = [];
  const rig = buildRig(THREE, 'smpl', { maxInfluences: 8 });
  const correctives = bindCorrectives(rig.root, rig.metadata, { warn: (m) => warnings.push(m) });
  for (let i = 0; i < 10; i++) correctives.update();
  assert.equal(warnings.length, 1);
  assert.match(warnings[0], /8 skin influences per vertex; three\.js skins with JOINTS_0\/WEIGHTS_0 only/);
  const quiet = [];
  const rig4 = buildRig(THREE, 'smpl');
  bindCorrectives(rig4.root, rig4.metadata, { warn: (m) => quiet.push(m) }).update();
  assert.equal(quiet.length, 0);
});

test('errors name the problem', () => {
  const rig = buildRig(THREE, 'smpl');
  rig.metadata.joint_names = rig.metadata.joint_names.map((n) => (n === 'left_knee' ? 'left_knee_x' : n));
  assert.throws(() => bindCorrectives(rig.root, rig.metadata), /joint 'left_knee_x' of the metadata has no bone/);
  assert.throws(() => bindCorrectives(new THREE.Group(), null), /no skinned mesh/);
  const bare = buildRig(THREE, 'smpl', { targets: ['shape_0'] });
  bare.metadata.correctives = [{ feature: 0, target: 'pose_left_hip_00', scale: 1, offset: 0 }];
  assert.throws(() => bindCorrectives(bare.root, bare.metadata), /no skinned mesh has a corrective morph target/);
});

test('--skeleton-names: bones found through the metadata\'s bone_names, as a loader names them', () => {
  const rand = random(7);
  const rig = buildRig(THREE, 'smplx');
  // mixamo-like names with a colon; the loaders keep "mixamorigLeftUpLeg" (PropertyBinding)
  const boneNames = rig.names.map((n) => 'mixamorig:' + n.split('_').map((w) => w[0].toUpperCase() + w.slice(1)).join(''));
  rig.bones.forEach((b, k) => { b.name = boneNames[k].replace(':', ''); });
  const plain = { ...rig.metadata };
  assert.throws(() => bindCorrectives(rig.root, plain), /joint 'pelvis' of the metadata has no bone/);
  assert.throws(() => bindCorrectives(rig.root, { ...plain, bone_names: boneNames.slice(1) }),
                /'bone_names' must be a list of distinct strings/);
  const meta = { ...plain, skeleton_names: 'mixamo', bone_names: boneNames };
  const restWorld = rig.bones.map((b) => b.getWorldQuaternion(new THREE.Quaternion()));
  const correctives = bindCorrectives(rig.root, meta);
  const rot = rig.bones.map(() => randomQuaternion(rand, 1.2));
  poseModelSpace(rig, rot, restWorld);
  correctives.update();
  const f = expectedFeatures(rot);
  assert.ok(maxDiff(correctives.features, f) < 1e-12, `features off by ${maxDiff(correctives.features, f)}`);
  const dict = rig.mesh.morphTargetDictionary, influences = rig.mesh.morphTargetInfluences;
  targetNames(rig.names).forEach((t, n) => assert.equal(influences[dict[t]], correctives.features[n]));
});
