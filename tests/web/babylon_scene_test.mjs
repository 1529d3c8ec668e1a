// Babylon.js as a client of a --scene GLB (docs/file-contract.md "Scene files"):
// the glTF loader (NullEngine, no GPU) loads every body (one skinned mesh each,
// named <body>_mesh, and a transform node <body>), the file's one animation
// becomes one AnimationGroup, and Babylon's own CPU skinning
// (AbstractMesh.getPositionData(applySkeleton, applyMorph): the morph targets'
// influences, then the skeleton's matrices) gives each body's vertices at the
// scene frames of the expected file written by tests/cli/scene_check.py
// (numpy's forward pass): within --tol where the body is present, on one point
// where it is hidden (scale 0 on its body node). A camera in the file must load
// as a camera named "camera"; with an expected camera, its world position, view
// direction and up at the expected frames.
//
//   node babylon_scene_test.mjs --asset scene.glb --expected scene.glb.expected.json [--tol 1e-5]
//
// Prints one line per checked body and frame: "babylon <body> frame <f> max_err_m <e>".
//
// Axes: the file is glTF's right-handed Y-up; Babylon's scene is left-handed and
// the loader converts with a root node "__root__" (rotation 180 degrees about Y,
// scaling (1, 1, -1): together x -> -x). Every world-space point and direction
// read from Babylon is mapped back into the file's axes by the inverse of
// __root__'s world matrix (checked below to be diag(-1, 1, 1)), so nothing here
// assumes the sign flip. Vertex order: the loader keeps glTF's vertex order
// (the identity map, as in three_scene_test.mjs; the vertex count is checked).
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { test } from 'node:test';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { parseArgs } from 'node:util';

// Babylon from web/node_modules (devDependencies of web/package.json), like three in harness.mjs.
const WEB_DIR = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', 'web');
const modules = path.join(WEB_DIR, 'node_modules', '@babylonjs');
if (!fs.existsSync(path.join(modules, 'core')) || !fs.existsSync(path.join(modules, 'loaders'))) {
  throw new Error(`${modules}/core and loaders are missing: run 'npm ci' in ${WEB_DIR} (scripts/test.sh does)`);
}
const B = await import(pathToFileURL(path.join(modules, 'core', 'index.js')).href);
await import(pathToFileURL(path.join(modules, 'loaders', 'glTF', 'index.js')).href);
const babylonVersion = JSON.parse(fs.readFileSync(path.join(modules, 'core', 'package.json'), 'utf8')).version;

const { values: args } = parseArgs({
  options: { asset: { type: 'string' }, expected: { type: 'string' }, tol: { type: 'string', default: '1e-5' } },
});
if (!args.asset || !args.expected) {
  console.error('usage: babylon_scene_test.mjs --asset SCENE.glb --expected EXPECTED.json [--tol 1e-5]');
  process.exit(1);
}
const tol = Number(args.tol);
const name = path.basename(args.asset);

// Bring every node's world matrix and every skeleton up to date after the animation group moved
// them, without rendering (no camera or GPU needed; culling cannot skip a hidden body).
function update(scene) {
  for (const n of [...scene.transformNodes, ...scene.meshes, ...scene.cameras]) n.computeWorldMatrix(true);
  // prepare(true): recompute now (not once per render id) from the bones' linked transform nodes.
  for (const s of scene.skeletons) s.prepare(true);
}

test(`${name}: every body of the scene played by Babylon's AnimationGroup vs numpy`, async () => {
  const ref = JSON.parse(fs.readFileSync(args.expected, 'utf8'));
  const engine = new B.NullEngine();
  const scene = new B.Scene(engine);
  // LoadAssetContainerAsync/ImportMeshAsync leave cameras out of their results: append the whole file.
  await B.SceneLoader.AppendAsync('', new Uint8Array(fs.readFileSync(args.asset)), scene, undefined, '.glb');
  console.log(`babylon ${babylonVersion}: ${scene.meshes.length} meshes, ${scene.transformNodes.length} transform nodes, ` +
              `${scene.skeletons.length} skeletons, ${scene.animationGroups.length} animation groups, ${scene.cameras.length} cameras`);
  const root = scene.getMeshByName('__root__');
  assert.ok(root, 'no __root__ node');
  root.computeWorldMatrix(true);
  const toFile = root.getWorldMatrix().clone().invert(); // Babylon's left-handed world -> the file's axes
  const flip = root.getWorldMatrix().m;
  const flipErr = Math.max(...[-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1].map((v, i) => Math.abs(flip[i] - v)));
  console.log(`babylon __root__ world matrix vs diag(-1, 1, 1) max_err ${flipErr.toExponential(3)}`);

  const meshes = {};
  for (const m of scene.meshes) if (m.skeleton) meshes[m.name.replace(/_mesh$/, '')] = m;
  const bodies = Object.keys(ref.bodies).sort();
  assert.deepEqual(Object.keys(meshes).sort(), bodies, 'one skinned mesh per body, named <body>_mesh');
  for (const body of bodies) {
    assert.ok(scene.getTransformNodeByName(body), `no transform node ${body}`);
    assert.equal(meshes[body].getTotalVertices(), ref.bodies[body].rest.length, `${body}: vertex count`);
  }
  const cameras = scene.cameras;
  assert.equal(cameras.length, ref.camera ? 1 : 0, 'cameras');
  if (ref.camera) assert.equal(cameras[0].name, 'camera', 'the camera');
  assert.equal(scene.animationGroups.length, 1, 'one animation group for the whole scene');
  const group = scene.animationGroups[0];
  // The loader keys glTF seconds as frames at its animations' framePerSecond (60 in Babylon 9):
  // scene time t seconds is group frame t * fps.
  const fpsSet = new Set(group.targetedAnimations.map((ta) => ta.animation.framePerSecond));
  assert.equal(fpsSet.size, 1, `animations at several frame rates ${[...fpsSet]}`);
  const groupFps = [...fpsSet][0];
  console.log(`babylon animation group "${group.name}": ${group.targetedAnimations.length} animations at ` +
              `${groupFps} frames/s, frames ${group.from}-${group.to}`);
  group.start(false, 1, group.from, group.to);
  group.pause();
  const goTo = (frame) => {
    group.goToFrame(((frame - ref.first_frame) / ref.fps) * groupFps);
    update(scene);
  };

  const v = new B.Vector3();
  const worldInFile = (mesh, local) => {
    const w = mesh.getWorldMatrix().multiplyToRef(toFile, new B.Matrix()); // local -> world -> file axes
    const out = new Float64Array(local.length);
    for (let i = 0; i < local.length; i += 3) {
      B.Vector3.TransformCoordinatesFromFloatsToRef(local[i], local[i + 1], local[i + 2], w, v);
      out[i] = v.x; out[i + 1] = v.y; out[i + 2] = v.z;
    }
    return out;
  };

  let worst = 0, checked = 0, moved = 0;
  for (const body of bodies) {
    const { frames, vertices } = ref.bodies[body];
    const mesh = meshes[body];
    frames.forEach((frame, i) => {
      goTo(frame);
      // Babylon skins on the GPU; getPositionData(applySkeleton, applyMorph) is its own CPU path
      // (morph influences, then the skeleton's transform matrices for this mesh).
      const got = worldInFile(mesh, mesh.getPositionData(true, true));
      if (vertices[i] === 'hidden') {
        let spread = 0;
        for (let a = 0; a < 3; a++) {
          let lo = Infinity, hi = -Infinity;
          for (let k = a; k < got.length; k += 3) { lo = Math.min(lo, got[k]); hi = Math.max(hi, got[k]); }
          spread = Math.max(spread, hi - lo);
        }
        console.log(`babylon ${body} frame ${frame} hidden spread_m ${spread.toExponential(3)}`);
        assert.ok(spread <= 1e-6, `${body} frame ${frame}: not hidden (spread ${spread} m)`);
        return;
      }
      let err = 0;
      for (let k = 0; k < vertices[i].length; k++) {
        for (let a = 0; a < 3; a++) err = Math.max(err, Math.abs(got[3 * k + a] - vertices[i][k][a]));
      }
      // The same vertices one scene frame later: how far the body moves there (the time conversion
      // above must pick the frame, not a neighbour). Only the largest is asserted: a held frame repeats.
      let later = NaN;
      if (frame + 1 < ref.end_frame) {
        goTo(frame + 1);
        const next = worldInFile(mesh, mesh.getPositionData(true, true));
        later = 0;
        for (let k = 0; k < vertices[i].length; k++) {
          for (let a = 0; a < 3; a++) later = Math.max(later, Math.abs(next[3 * k + a] - vertices[i][k][a]));
        }
        moved = Math.max(moved, later);
      }
      console.log(`babylon ${body} frame ${frame} max_err_m ${err.toExponential(3)} (one frame later ${Number.isNaN(later) ? "n/a" : later.toExponential(3) + " m away"})`);
      worst = Math.max(worst, err);
      checked++;
    });
  }
  if (ref.camera) checkCamera(ref, cameras[0], goTo, toFile);
  console.log(`babylon ${name} worst max_err_m ${worst.toExponential(3)} over ${checked} body frames`);
  assert.ok(flipErr <= 1e-12, `__root__ is not the x -> -x handedness flip`);
  assert.ok(checked > 0, 'no present frame checked');
  assert.ok(moved >= 1e-3, `no body moves by 1 mm in one frame (largest ${moved} m): the time conversion is not checked`);
  assert.ok(worst <= tol, `${name}: max vertex error ${worst} m > ${tol} m`);
  engine.dispose();
});

// The camera after the animation group at each expected frame: position, view direction and up,
// against numpy's in the file's axes. Babylon cameras look down their local +z with +y up; the loader
// turns the camera 180 degrees about y inside the glTF node (setTarget(0, 0, -1)) and gives that node
// scaling.x = -1 (cancelling __root__'s flip in the view matrix), so getDirection(+z) is the glTF
// node's -z and getDirection(+y) its +y, both then mapped to the file's axes by __root__'s inverse.
function checkCamera(ref, camera, goTo, toFile) {
  const { frames, position, direction, up } = ref.camera;
  frames.forEach((frame, i) => {
    goTo(frame);
    const p = B.Vector3.TransformCoordinates(camera.globalPosition, toFile);
    const d = B.Vector3.TransformNormal(camera.getDirection(B.Vector3.Forward()), toFile).normalize();
    const u = B.Vector3.TransformNormal(camera.getDirection(B.Vector3.Up()), toFile).normalize();
    const err = Math.max(...[p, d, u].flatMap((vec, k) => {
      const want = [position, direction, up][k][i];
      return [Math.abs(vec.x - want[0]), Math.abs(vec.y - want[1]), Math.abs(vec.z - want[2])];
    }));
    console.log(`babylon camera frame ${frame} max_err ${err.toExponential(3)}`);
    assert.ok(err <= 1e-5, `camera frame ${frame}: position/direction/up off by ${err}`);
  });
}
