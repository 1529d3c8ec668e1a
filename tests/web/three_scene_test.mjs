// three.js as a client of a --scene GLB (docs/file-contract.md "Scene files"):
// GLTFLoader loads every body (one SkinnedMesh each, named <body>_mesh),
// AnimationMixer plays the file's one animation, and three's own CPU skinning
// (harness.skinnedPositions) gives each body's vertices at the scene frames
// of the expected file written by tests/cli/scene_check.py (numpy's forward
// pass): within --tol where the body is present, on one point where it is
// hidden (scale 0 on its body node). A camera in the file must load as a
// PerspectiveCamera named "camera"; with an expected camera, its world
// position, view direction (-z) and up (+y) at the expected frames.
//
//   node three_scene_test.mjs --asset scene.glb --expected scene.glb.expected.json [--tol 1e-5]
//
// Prints one line per checked body and frame: "glb <body> frame <f> max_err_m <e>".
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { parseArgs } from 'node:util';

import * as h from './harness.mjs';

const { values: args } = parseArgs({
  options: { asset: { type: 'string' }, expected: { type: 'string' }, tol: { type: 'string', default: '1e-5' } },
});
if (!args.asset || !args.expected) {
  console.error('usage: three_scene_test.mjs --asset SCENE.glb --expected EXPECTED.json [--tol 1e-5]');
  process.exit(1);
}
const tol = Number(args.tol);
const name = path.basename(args.asset);

test(`${name}: every body of the scene played by AnimationMixer vs numpy`, async () => {
  const ref = JSON.parse(fs.readFileSync(args.expected, 'utf8'));
  const gltf = await h.loadGltf(args.asset);
  const root = gltf.scene;
  const meshes = {};
  root.traverse((o) => { if (o.isSkinnedMesh) meshes[o.name.replace(/_mesh$/, '')] = o; });
  const bodies = Object.keys(ref.bodies).sort();
  assert.deepEqual(Object.keys(meshes).sort(), bodies, 'one skinned mesh per body, named <body>_mesh');
  for (const body of bodies) assert.ok(root.getObjectByName(body), `no node ${body}`);
  const cameras = [];
  root.traverse((o) => { if (o.isCamera) cameras.push(o); });
  assert.equal(cameras.length, ref.camera ? 1 : 0, 'cameras');
  if (ref.camera) assert.ok(cameras[0].isPerspectiveCamera && cameras[0].name === 'camera', 'the camera');
  assert.equal(gltf.animations.length, 1, 'one animation for the whole scene');
  const mixer = new h.THREE.AnimationMixer(root);
  const action = mixer.clipAction(gltf.animations[0]);
  action.setLoop(h.THREE.LoopOnce, 1);
  action.clampWhenFinished = true;
  action.play();
  let worst = 0, checked = 0;
  for (const body of bodies) {
    const { frames, vertices } = ref.bodies[body];
    const mesh = meshes[body];
    const map = Int32Array.from({ length: mesh.geometry.attributes.position.count }, (_, i) => i);
    frames.forEach((frame, i) => {
      // A LoopOnce action that reached its end stays paused there: restart it for every time.
      action.reset().play();
      mixer.setTime((frame - ref.first_frame) / ref.fps);
      const got = h.skinnedPositions({ root, mesh });
      if (vertices[i] === 'hidden') {
        let spread = 0;
        for (let a = 0; a < 3; a++) {
          let lo = Infinity, hi = -Infinity;
          for (let v = 0; v < map.length; v++) { lo = Math.min(lo, got[3 * v + a]); hi = Math.max(hi, got[3 * v + a]); }
          spread = Math.max(spread, hi - lo);
        }
        console.log(`glb ${body} frame ${frame} hidden spread_m ${spread.toExponential(3)}`);
        assert.ok(spread <= 1e-6, `${body} frame ${frame}: not hidden (spread ${spread} m)`);
        return;
      }
      const err = h.maxError(got, map, (v, a) => vertices[i][v][a]);
      console.log(`glb ${body} frame ${frame} max_err_m ${err.toExponential(3)}`);
      worst = Math.max(worst, err);
      checked++;
    });
  }
  if (ref.camera) checkCamera(ref, cameras[0], mixer, action);
  console.log(`glb ${name} worst max_err_m ${worst.toExponential(3)} over ${checked} body frames`);
  assert.ok(checked > 0, 'no present frame checked');
  assert.ok(worst <= tol, `${name}: max vertex error ${worst} m > ${tol} m`);
});

// The camera object after AnimationMixer at each expected frame: position, view direction (three's
// cameras look down local -z, as glTF's) and up, against numpy's in the file's axes.
function checkCamera(ref, camera, mixer, action) {
  const { frames, position, direction, up } = ref.camera;
  const p = new h.THREE.Vector3(), d = new h.THREE.Vector3(), u = new h.THREE.Vector3(), q = new h.THREE.Quaternion();
  frames.forEach((frame, i) => {
    action.reset().play();
    mixer.setTime((frame - ref.first_frame) / ref.fps);
    camera.updateMatrixWorld(true);
    camera.getWorldPosition(p);
    camera.getWorldDirection(d);
    u.set(0, 1, 0).applyQuaternion(camera.getWorldQuaternion(q));
    const err = Math.max(...[p, d, u].flatMap((v, k) => {
      const want = [position, direction, up][k][i];
      return [Math.abs(v.x - want[0]), Math.abs(v.y - want[1]), Math.abs(v.z - want[2])];
    }));
    console.log(`glb camera frame ${frame} max_err ${err.toExponential(3)}`);
    assert.ok(err <= 1e-5, `camera frame ${frame}: position/direction/up off by ${err}`);
  });
}
