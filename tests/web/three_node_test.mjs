// three.js as a second real client of our GLB and FBX (issue 12): three's
// GLTFLoader / FBXLoader load an export, the joints are posed, the
// smpl-correctives driver sets the morph weights, three's own CPU skinning
// gives the vertices, and they are compared with the C++ reference forward
// pass (tools/reference, same pruned weights) or, for a baked motion played
// by three's AnimationMixer, numpy's forward pass (anim_reference.py).
//
//   node three_node_test.mjs --asset body.glb --reference PREFIX [--tol 1e-5]
//   node three_node_test.mjs --asset walk.fbx --anim-reference PREFIX.json --faces-from walk.glb
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
  },
});
if (!args.asset || !(args.reference || args['anim-reference'])) {
  console.error('usage: three_node_test.mjs --asset FILE (--reference PREFIX | --anim-reference FILE) [--faces-from GLB]');
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
    const bones = h.jointBones(asset.mesh, names);
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
    //    driver must produce every corrective weight from the bones. Weights of
    //    other targets (an animated expression, expr_<i>) stay in the clip with
    //    the corrective columns zeroed.
    const bonesOnly = clip.clone();
    const names = asset.metadata.morph_targets || [];
    const kept = names.map((n, i) => (n.startsWith('pose_') ? -1 : i)).filter((i) => i >= 0);
    assert.ok(clip.tracks.some((t) => /morphTargetInfluences/.test(t.name)), 'the clip bakes corrective weights');
    bonesOnly.tracks = clip.tracks.flatMap((t) => {
      if (!/morphTargetInfluences/.test(t.name)) return [t];
      const one = /morphTargetInfluences\[(.+)\]$/.exec(t.name);  // FBXLoader: a track per target
      if (one) return one[1].startsWith('pose_') ? [] : [t];
      if (kept.length === 0) return [];
      const u = t.clone(), n = names.length;
      assert.equal(u.values.length % n, 0, `${t.name}: ${u.values.length} values for ${n} targets`);
      for (let k = 0; k < u.values.length; k += n) {
        for (let i = 0; i < n; i++) if (names[i].startsWith('pose_')) u.values[k + i] = 0;
      }
      return [u];
    });
    asset.mesh.morphTargetInfluences.fill(0);
    const driven = playAndCompare(asset, map, bonesOnly, ref, correctives, 'bones+driver');
    assert.ok(baked <= tol, `${name}: baked weights: max vertex error ${baked} m > ${tol} m`);
    assert.ok(driven <= tol, `${name}: bone tracks + driver: max vertex error ${driven} m > ${tol} m`);
  });
}
