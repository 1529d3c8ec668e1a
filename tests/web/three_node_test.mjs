// three.js as a second real client of our GLB and FBX: three's
// GLTFLoader / FBXLoader load an export, the joints are posed, the
// smpl-correctives driver sets the morph weights, three's own CPU skinning
// gives the vertices, and they are compared with the C++ reference forward
// pass (tools/reference, same pruned weights) or, for a baked motion played
// by three's AnimationMixer, numpy's forward pass (anim_reference.py).
//
//   node three_node_test.mjs --asset body.glb --reference PREFIX [--tol 1e-5]
//   node three_node_test.mjs --asset walk.fbx --anim-reference PREFIX.json --faces-from walk.glb
//   node three_node_test.mjs --asset packed.glb --same-as plain.glb   (--meshopt: the same data)
//
// FBX needs --faces-from: a GLB of the same model, whose triangle list maps
// FBXLoader's per-corner vertices back to model vertices. Prints one line per
// checked pose: "<format> <asset> pose|time <i> max_err_m <e>".
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { parseArgs } from 'node:util';

import * as h from './harness.mjs';

const { values: args } = parseArgs({
  options: {
    asset: { type: 'string' }, reference: { type: 'string' }, 'anim-reference': { type: 'string' },
    'faces-from': { type: 'string' }, tol: { type: 'string', default: '1e-5' },
    'same-as': { type: 'string' },
  },
});
if (!args.asset || !(args.reference || args['anim-reference'] || args['same-as'])) {
  console.error('usage: three_node_test.mjs --asset FILE (--reference PREFIX | --anim-reference FILE | --same-as GLB) [--faces-from GLB]');
  process.exit(1);
}
const tol = Number(args.tol);
const name = path.basename(args.asset);

async function prepare() {
  const asset = await h.loadAsset(args.asset);
  const facesFrom = asset.format === 'fbx' ? await h.loadAsset(args['faces-from']) : null;
  const warnings = [];
  const correctives = h.driver.bindCorrectives(asset.root, asset.metadata, { warn: (m) => warnings.push(m) });
  return { asset, map: h.vertexMap(asset, facesFrom), correctives, warnings };
}

if (args.reference) {
  test(`${name}: posed by the reference poses, correctives by the driver, vs smpl-reference`, async () => {
    const { asset, map, correctives, warnings } = await prepare();
    const ref = h.readReference(args.reference);
    const names = ref.header.joint_names, parents = ref.header.parents;
    const K = names.length, P = ref.arrays.poses.shape[0], N = ref.header.num_vertices;
    assert.equal(ref.header.max_influences, 4, 'compare exports with 4 influences (what three.js skins)');
    assert.equal(warnings.length, 0, `unexpected warnings: ${warnings}`);
    assert.equal(asset.metadata.joint_names.join(), names.join(), 'joint names of file and reference');
    assert.ok(correctives.weights.length > 0, 'the driver bound no target');
    const bones = h.jointBones(asset.mesh, asset.metadata.bone_names || names);  // --skeleton-names
    const rest = h.restWorldRotations(bones);
    const features = ref.arrays.features.data, verts = ref.arrays.vertices_pruned.data;
    let worst = 0, worstFeature = 0;
    for (let p = 0; p < P; p++) {
      h.poseJoints(bones, parents, ref.arrays.poses.data.subarray(3 * K * p, 3 * K * (p + 1)), rest);
      correctives.update();
      let featureError = 0;
      for (let n = 0; n < 9 * (K - 1); n++) {
        featureError = Math.max(featureError, Math.abs(correctives.features[n] - features[9 * (K - 1) * p + n]));
      }
      const err = h.maxError(h.skinnedPositions(asset), map, (v, a) => verts[3 * (N * p + v) + a]);
      console.log(`${asset.format} ${name} pose ${p} max_err_m ${err.toExponential(3)} feature_err ${featureError.toExponential(3)}`);
      worst = Math.max(worst, err);
      worstFeature = Math.max(worstFeature, featureError);
    }
    console.log(`${asset.format} ${name} worst max_err_m ${worst.toExponential(3)} over ${P} poses`);
    assert.ok(worstFeature < 1e-6, `${name}: driver's pose features off by ${worstFeature}`);
    assert.ok(worst <= tol, `${name}: max vertex error ${worst} m > ${tol} m`);
  });
}

// Plays `clip` at each reference time and returns the worst vertex error;
// `drive` runs the correctives driver after the mixer.
function playAndCompare(asset, map, clip, ref, correctives, tag) {
  const mixer = new h.THREE.AnimationMixer(asset.root);
  const action = mixer.clipAction(clip);
  action.setLoop(h.THREE.LoopOnce, 1);
  action.clampWhenFinished = true;  // the last key, not a wrap to the first
  action.play();
  let worst = 0;
  ref.frames.forEach((frame, i) => {
    const time = frame / ref.fps;
    mixer.setTime(time);
    if (correctives) correctives.update();
    const expected = ref.vertices[i];
    const err = h.maxError(h.skinnedPositions(asset), map, (v, a) => expected[v][a]);
    console.log(`${asset.format} ${name} ${tag} time ${time.toFixed(4)}s (frame ${frame}) max_err_m ${err.toExponential(3)}`);
    worst = Math.max(worst, err);
  });
  action.stop();
  mixer.uncacheRoot(asset.root);
  return worst;
}

// The clip without the corrective weights the driver makes: their values are
// zeroed (their tracks dropped), the other targets' weights (expr_<i>, dmpl_<i>: the motion's
// coefficients, not a function of the bones) are kept; a morph track with
// nothing left is dropped. `baked`: some corrective weight was non-zero.
function withoutCorrectiveWeights(clip, mesh, drivenNames) {
  const names = [];
  for (const [n, i] of Object.entries(mesh.morphTargetDictionary)) names[i] = n;
  const driven = names.map((n) => drivenNames.has(n));
  let baked = false;
  const tracks = [];
  for (const t of clip.tracks) {
    if (!/morphTargetInfluences/.test(t.name)) {
      tracks.push(t);
      continue;
    }
    const one = /morphTargetInfluences\[(.+)\]$/.exec(t.name);  // FBXLoader: a track per target
    if (one) {
      const index = /^\d+$/.test(one[1]) ? Number(one[1]) : mesh.morphTargetDictionary[one[1]];
      if (!driven[index]) tracks.push(t);
      else if (t.values.some((v) => v !== 0)) baked = true;
      continue;
    }
    const stride = t.values.length / t.times.length;  // GLTFLoader: all targets in one track
    assert.equal(stride, names.length, `${t.name}: one weight per morph target and key`);
    const copy = t.clone();
    let kept = false;
    for (let k = 0; k < copy.values.length; k++) {
      if (!driven[k % stride]) {
        kept = true;
        continue;
      }
      if (copy.values[k] !== 0) baked = true;
      copy.values[k] = 0;
    }
    if (kept) tracks.push(copy);
  }
  const out = clip.clone();
  out.tracks = tracks;
  return { clip: out, baked };
}

if (args['anim-reference']) {
  test(`${name}: baked motion played by AnimationMixer vs numpy (baked weights; bone tracks + driver)`, async () => {
    const { asset, map, correctives } = await prepare();
    const ref = JSON.parse(fs.readFileSync(args['anim-reference'], 'utf8'));
    assert.equal(asset.animations.length, 1, 'one baked animation');
    assert.equal(ref.frames.length, 3, 'three times');
    const clip = asset.animations[0];
    assert.ok(ref.frames[2] / ref.fps <= clip.duration + 1e-6, `clip duration ${clip.duration} s`);
    // 1. The file as baked: bone tracks and the corrective weight tracks, no driver.
    const baked = playAndCompare(asset, map, clip, ref, null, 'baked-weights');
    // 2. Bone tracks only (what a retargeted or procedural pose gives): the
    //    driver must produce every corrective weight from the bones.
    const { clip: bonesOnly, baked: bakesCorrectives } = withoutCorrectiveWeights(
      clip, asset.mesh, new Set(correctives.targetNames));
    assert.ok(bakesCorrectives, 'the clip bakes corrective weights');
    asset.mesh.morphTargetInfluences.fill(0);
    const driven = playAndCompare(asset, map, bonesOnly, ref, correctives, 'bones+driver');
    assert.ok(baked <= tol, `${name}: baked weights: max vertex error ${baked} m > ${tol} m`);
    assert.ok(driven <= tol, `${name}: bone tracks + driver: max vertex error ${driven} m > ${tol} m`);
  });
}

// Every vertex attribute and morph target of two loads, element by element:
// a --meshopt file must give three.js exactly the arrays of the same export
// without it (meshopt's codecs are lossless; the quantisation is the same).
if (args['same-as']) {
  test(`${name}: three.js reads the same vertex and morph arrays as ${path.basename(args['same-as'])}`, async () => {
    const a = await h.loadAsset(args.asset), b = await h.loadAsset(args['same-as']);
    const ga = a.mesh.geometry, gb = b.mesh.geometry;
    const pairs = Object.keys(gb.attributes).map((k) => [k, ga.attributes[k], gb.attributes[k]]);
    (gb.morphAttributes.position || []).forEach((t, i) => pairs.push([`morph ${i}`, ga.morphAttributes.position[i], t]));
    pairs.push(['index', ga.index, gb.index]);
    assert.ok(pairs.length > 5, 'attributes to compare');
    for (const [key, x, y] of pairs) {
      assert.ok(x, `${name} lacks ${key}`);
      assert.equal(x.count, y.count, `${key}: count`);
      assert.equal(x.itemSize, y.itemSize, `${key}: itemSize`);
      assert.equal(Boolean(x.normalized), Boolean(y.normalized), `${key}: normalized`);
      for (let i = 0; i < y.count; i++) {
        for (let c = 0; c < y.itemSize; c++) {
          const u = x.getComponent ? x.getComponent(i, c) : x.array[i * x.itemSize + c];
          const v = y.getComponent ? y.getComponent(i, c) : y.array[i * y.itemSize + c];
          if (u !== v) assert.fail(`${key}[${i}][${c}]: ${u} != ${v}`);
        }
      }
    }
    console.log(`glb ${name} same as ${path.basename(args['same-as'])}: ${pairs.length} arrays equal`);
  });
}
