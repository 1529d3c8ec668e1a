// Shared pieces of the three.js tests: load an smpl-export asset with three's
// own loaders (from web/node_modules), pose its joints, skin it on the CPU
// with three's own code (SkinnedMesh.getVertexPosition: morph targets, then
// applyBoneTransform), read the C++ reference (tools/reference) and map
// three's vertices back to model vertices.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

export const WEB_DIR = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..', '..', 'web');
const modules = path.join(WEB_DIR, 'node_modules', 'three');
if (!fs.existsSync(modules)) {
  throw new Error(`${modules} is missing: run 'npm ci' in ${WEB_DIR} (scripts/test.sh does)`);
}
// The same module instances the loaders import as 'three'.
export const THREE = await import(pathToFileURL(path.join(modules, 'build', 'three.module.js')).href);
const { GLTFLoader } = await import(pathToFileURL(path.join(modules, 'examples/jsm/loaders/GLTFLoader.js')).href);
const { FBXLoader } = await import(pathToFileURL(path.join(modules, 'examples/jsm/loaders/FBXLoader.js')).href);
// EXT_meshopt_compression (--meshopt): three's own decoder (WebAssembly, runs in node).
const { MeshoptDecoder } = await import(pathToFileURL(path.join(modules, 'examples/jsm/libs/meshopt_decoder.module.js')).href);
export const driver = await import(pathToFileURL(path.join(WEB_DIR, 'smpl-correctives', 'index.js')).href);

function arrayBuffer(file) {
  const b = fs.readFileSync(file);
  return b.buffer.slice(b.byteOffset, b.byteOffset + b.byteLength);
}

/** three's GLTFLoader on a .glb (meshopt decoder set): the loader's result {scene, animations, ...}. */
export function loadGltf(file) {
  return new Promise((resolve, reject) => new GLTFLoader().setMeshoptDecoder(MeshoptDecoder).parse(arrayBuffer(file), '', resolve, reject));
}

/**
 * Load a .glb or .fbx: {format, root, mesh, metadata, animations, unitFactor}.
 * FBX metadata comes from the sidecar <file>.smpl.json and the group is
 * scaled to metres by applyFbxUnitScale.
 */
export async function loadAsset(file) {
  const format = path.extname(file).slice(1).toLowerCase();
  let root, metadata, animations, unitFactor = 1;
  if (format === 'glb') {
    const gltf = await loadGltf(file);
    root = gltf.scene;
    metadata = driver.metadataFromGltf(gltf);
    animations = gltf.animations;
  } else if (format === 'fbx') {
    root = new FBXLoader().parse(arrayBuffer(file), '');
    metadata = JSON.parse(fs.readFileSync(file + '.smpl.json', 'utf8'));
    animations = root.animations;
    unitFactor = driver.applyFbxUnitScale(root);
  } else {
    throw new Error(`${file}: expected a .glb or .fbx`);
  }
  root.updateMatrixWorld(true);
  const meshes = [];
  root.traverse((o) => { if (o.isSkinnedMesh) meshes.push(o); });
  if (meshes.length !== 1) throw new Error(`${file}: ${meshes.length} skinned meshes, expected 1`);
  return { format, root, mesh: meshes[0], metadata, animations, unitFactor };
}

/** smpl-reference output (PREFIX.json + PREFIX.bin float64): header and name -> {shape, data}. */
export function readReference(prefix) {
  const header = JSON.parse(fs.readFileSync(prefix + '.json', 'utf8'));
  const raw = fs.readFileSync(prefix + '.bin');
  const all = new Float64Array(raw.buffer.slice(raw.byteOffset, raw.byteOffset + raw.byteLength));
  const arrays = {};
  for (const [name, spec] of Object.entries(header.arrays)) {
    const count = spec.shape.reduce((a, b) => a * b, 1);
    arrays[name] = { shape: spec.shape, data: all.subarray(spec.offset, spec.offset + count) };
  }
  return { header, arrays };
}

/**
 * three vertex -> model vertex. GLB: the identity (the writer keeps the
 * model's order). FBX: FBXLoader splits every triangle corner into its own
 * vertex, in polygon order, so vertex j is corner j of the faces, which we
 * take from the GLB of the same model (its index buffer).
 */
export function vertexMap(asset, facesFrom) {
  const count = asset.mesh.geometry.attributes.position.count;
  if (asset.format === 'glb') return Int32Array.from({ length: count }, (_, i) => i);
  const index = facesFrom.mesh.geometry.index;
  if (!index || index.count !== count) {
    throw new Error(`FBX has ${count} vertices, the GLB's index ${index ? index.count : 0} corners: cannot map`);
  }
  return Int32Array.from(index.array);
}

/**
 * Bone of each joint name (as the driver finds them): `names` are the file's
 * bone names (the metadata's bone_names with --skeleton-names), which the
 * loaders may have sanitised ("mixamorig:Hips" -> "mixamorigHips").
 */
export function jointBones(mesh, names) {
  return names.map((n) => {
    const wanted = THREE.PropertyBinding.sanitizeNodeName(n);
    const b = mesh.skeleton.bones.find((bone) => bone.name === n || bone.name === wanted);
    if (!b) throw new Error(`no bone named ${n}`);
    return b;
  });
}

function quatFromAxisAngle(x, y, z) {
  const angle = Math.hypot(x, y, z);
  const q = new THREE.Quaternion();
  if (angle > 0) q.setFromAxisAngle(new THREE.Vector3(x / angle, y / angle, z / angle), angle);
  return q;
}

/**
 * Pose the joints with axis-angle rotations (K*3, model axes, local to the
 * parent) without assuming how the loader oriented the bones: bone k's world
 * rotation becomes G_k * Wrest_k (G_k the model's world rotation, model axes =
 * scene axes for these Y-up files), written back as a local quaternion.
 * restWorld: the bones' world quaternions at rest (captured before posing).
 */
export function poseJoints(bones, parents, axisAngles, restWorld) {
  const global = [];
  for (let k = 0; k < bones.length; k++) {
    const r = quatFromAxisAngle(axisAngles[3 * k], axisAngles[3 * k + 1], axisAngles[3 * k + 2]);
    global.push(parents[k] >= 0 ? global[parents[k]].clone().multiply(r) : r);
    const world = global[k].clone().multiply(restWorld[k]);
    const parentWorld = new THREE.Quaternion();
    if (bones[k].parent) bones[k].parent.getWorldQuaternion(parentWorld);
    bones[k].quaternion.copy(parentWorld.invert().multiply(world));
    bones[k].updateMatrixWorld(true);
  }
}

export function restWorldRotations(bones) {
  return bones.map((b) => b.getWorldQuaternion(new THREE.Quaternion()));
}

/**
 * Skinned vertex positions in the scene (metres for our files), by three's
 * own CPU path: Mesh.getVertexPosition (morphs) + applyBoneTransform, then
 * the mesh's world matrix.
 */
export function skinnedPositions(asset) {
  asset.root.updateMatrixWorld(true);
  const mesh = asset.mesh, count = mesh.geometry.attributes.position.count;
  const out = new Float64Array(3 * count), v = new THREE.Vector3();
  for (let i = 0; i < count; i++) {
    mesh.getVertexPosition(i, v).applyMatrix4(mesh.matrixWorld);
    out[3 * i] = v.x; out[3 * i + 1] = v.y; out[3 * i + 2] = v.z;
  }
  return out;
}

/** Max |three - expected| over vertices; expected(modelVertex, axis). */
export function maxError(positions, map, expected) {
  let worst = 0;
  for (let j = 0; j < map.length; j++) {
    for (let a = 0; a < 3; a++) worst = Math.max(worst, Math.abs(positions[3 * j + a] - expected(map[j], a)));
  }
  return worst;
}
