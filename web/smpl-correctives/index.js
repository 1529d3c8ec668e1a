// smpl-correctives: drive the pose-corrective morph targets of an smpl-export
// asset (GLB or FBX) in three.js from the current bone rotations.
//
// The "robust runtime formula" of docs/file-contract.md. For joint k with
// parent joint p, world rotations Q taken in the scene at bind time:
//
//     D_k = Q_k(now) Q_k(rest)^-1        rotation change since the bind pose
//     L_k = D_p^-1 D_k                   the joint's own rotation (world axes)
//     R_k = C^-1 L_k C                   C: model axes -> scene axes
//     f[9(k-1) + 3r + c] = R_k[r][c] - delta_rc
//
// Because the exporter's rest pose has identity local rotations in model
// space, C is the root joint's rest orientation, and the formula reduces to
// quantities that three.js already keeps (no matrixWorld needed):
//
//     Q_rest_k = X inv(boneInverse_k)            (X: the same for every bone)
//     R_k = B_k (M_k(now) Rr_k^-1) B_k^-1,
//     B_k = rot(boneInverse_root) rot(boneInverse_p)^-1   (fixed at bind)
//     Rr_k = rot(boneInverse_p inv(boneInverse_k))         (rest p -> k, fixed)
//     M_k  = product of the local rotations (node.quaternion) from bone p
//            (exclusive) down to bone k (inclusive): usually bone k's alone.
//
// So it does not care how a loader oriented the bones (pre-rotations, rolls)
// nor where the character stands. Weights: per target
// weight = scale * f[feature] + offset from the metadata ("rectified": true
// entries: max(0, that)); with a corrective basis, target b gets
// scale_b * (C f)_b + offset_b.
//
// update() allocates nothing: every buffer is made by bindCorrectives().
//
//     import { bindCorrectives, metadataFromGltf } from 'smpl-correctives';
//     const gltf = await new GLTFLoader().loadAsync('body.glb');
//     const correctives = bindCorrectives(gltf.scene, metadataFromGltf(gltf));
//     // each frame, after the mixer / your posing code:
//     mixer.update(dt); correctives.update(); renderer.render(scene, camera);

const TARGET_NAME = /pose_(.+)_([0-2])([0-2])$/;

/**
 * The smpl-export metadata of a GLTFLoader result: `asset.extras.smpl`, else
 * the scene's extras (`scene.userData.smpl`), else null.
 * @param {{asset?: object, scene?: object, parser?: object}} gltf
 * @returns {object|null}
 */
export function metadataFromGltf(gltf) {
  const fromAsset = gltf && gltf.asset && gltf.asset.extras && gltf.asset.extras.smpl;
  if (isObject(fromAsset)) return fromAsset;
  const json = gltf && gltf.parser && gltf.parser.json;
  const fromJson = json && json.asset && json.asset.extras && json.asset.extras.smpl;
  if (isObject(fromJson)) return fromJson;
  const fromScene = gltf && gltf.scene && gltf.scene.userData && gltf.scene.userData.smpl;
  return isObject(fromScene) ? fromScene : null;
}

/**
 * FBXLoader leaves the file's UnitScaleFactor (cm per unit) to the
 * application: a centimetre FBX (`--fbx-units cm`) is 100x too large in a
 * metre scene. This scales the loaded group to metres (factor
 * UnitScaleFactor / 100; 1 for smpl-export's default `--fbx-units m`).
 * @param {object} fbxGroup  the Group returned by FBXLoader
 * @returns {number} the factor applied
 */
export function applyFbxUnitScale(fbxGroup) {
  const unit = fbxGroup && fbxGroup.userData ? Number(fbxGroup.userData.unitScaleFactor) : NaN;
  const factor = Number.isFinite(unit) && unit > 0 ? unit / 100 : 1;
  fbxGroup.scale.multiplyScalar(factor);
  return factor;
}

/**
 * Bind the correctives of every skinned mesh under `root` that carries them.
 *
 * @param {object} root  a three.js Object3D (gltf.scene, the FBXLoader group)
 * @param {object|null} metadata  the smpl-export metadata (glTF
 *   `asset.extras.smpl`, see metadataFromGltf, or the `<file>.smpl.json`
 *   sidecar for FBX). Without it, targets named `pose_<joint>_<r><c>` are
 *   driven with scale 1 and offset 0 and parents come from the bone tree.
 * @param {{warn?: (message: string) => void}} [options]  warn: where the
 *   one-time warnings go (default console.warn)
 * @returns {import('./index').Correctives}
 * @throws {Error} when no skinned mesh has a corrective target, a joint of
 *   the metadata has no bone (message names the joint), or the metadata's
 *   joint_names, parents, correctives or corrective_basis are malformed
 *   (message names the field)
 */
export function bindCorrectives(root, metadata, options = {}) {
  const warn = options.warn || ((m) => console.warn(m));
  const meta = isObject(metadata) ? metadata : null;
  if (meta) checkMetadata(meta);
  const meshes = skinnedMeshes(root);
  if (meshes.length === 0) throw new Error('smpl-correctives: no skinned mesh under the given root');
  const skeleton = meshes[0].skeleton;
  const joints = resolveJoints(skeleton, meta);
  const layout = readLayout(meta, joints, meshes);
  const bound = bindTargets(meshes, layout);
  if (bound.meshes.length === 0) {
    throw new Error('smpl-correctives: no skinned mesh has a corrective morph target (pose_<joint>_<rc> or a basis target)');
  }
  const maxInfluences = meta && Number.isFinite(meta.max_influences) ? meta.max_influences : 0;
  if (maxInfluences > 4) {
    warn(`smpl-correctives: the file has ${maxInfluences} skin influences per vertex; three.js skins with ` +
         'JOINTS_0/WEIGHTS_0 only (4): export with --max-influences 4 for an exact body');
  }
  const rig = buildRig(skeleton, joints);
  return new Correctives(rig, layout, bound);
}

/**
 * Throws on metadata that is present but malformed (files are untrusted):
 * joint_names/parents (strings, one length, parents[0] = -1, 0 <= parents[k] < k)
 * and correctives (a list of entries with an integer feature < 9(K-1), a
 * string target, numeric scale and offset). The message names the field.
 */
function checkMetadata(meta) {
  const fail = (m) => { throw new Error(`smpl-correctives: metadata ${m}`); };
  const names = meta.joint_names, parents = meta.parents;
  if (names !== undefined || parents !== undefined) {
    if (!Array.isArray(names) || !names.every((n) => typeof n === 'string')) fail("'joint_names' must be a list of strings");
    if (!Array.isArray(parents) || parents.length !== names.length) fail("'parents' must be a list as long as 'joint_names'");
    parents.forEach((p, k) => {
      if (!Number.isInteger(p) || (k === 0 ? p !== -1 : p < 0 || p >= k)) {
        fail(`'parents'[${k}] = ${JSON.stringify(p)}; expected ${k === 0 ? '-1 (the root)' : `0 <= parent < ${k}`}`);
      }
    });
  }
  const bones = meta.bone_names;  // --skeleton-names mixamo|ue5: the bone of each joint
  if (bones !== undefined) {
    if (!Array.isArray(bones) || !bones.every((n) => typeof n === 'string') ||
        !Array.isArray(names) || bones.length !== names.length || new Set(bones).size !== bones.length) {
      fail("'bone_names' must be a list of distinct strings as long as 'joint_names'");
    }
  }
  if (meta.correctives === undefined) return;
  if (!Array.isArray(meta.correctives)) fail("'correctives' must be a list");
  const count = Array.isArray(names) ? 9 * (names.length - 1) : Infinity;
  meta.correctives.forEach((e, i) => {
    const ok = isObject(e) && Number.isInteger(e.feature) && e.feature >= 0 && e.feature < count &&
               typeof e.target === 'string' && (e.scale === undefined || Number.isFinite(e.scale)) &&
               (e.offset === undefined || Number.isFinite(e.offset));
    if (!ok) fail(`'correctives'[${i}] is malformed (feature 0..${count - 1}, target, numeric scale and offset)`);
  });
}

function isObject(v) {
  return v !== null && typeof v === 'object' && !Array.isArray(v);
}

function skinnedMeshes(root) {
  const out = [];
  root.traverse((o) => { if (o.isSkinnedMesh && o.morphTargetDictionary) out.push(o); });
  return out;
}

function sanitize(name) {  // PropertyBinding.sanitizeNodeName, as both loaders apply it
  return String(name).replace(/\s/g, '_').replace(/[[\]\.:\/]/g, '');
}

function findBone(bones, name) {
  const wanted = sanitize(name);
  for (let i = 0; i < bones.length; i++) {
    const b = bones[i];
    if (b.name === name || b.name === wanted || (b.userData && b.userData.originalName === name)) return i;
  }
  // SMPL-X eyes: older files name them left_eye / right_eye.
  const alias = { left_eye_smplhf: 'left_eye', right_eye_smplhf: 'right_eye' }[name];
  return alias ? findBone(bones, alias) : -1;
}

/**
 * Joint names, parents and bone indices: metadata first, else the bone tree.
 * The bones are found by the metadata's bone_names when it has them (an export
 * with --skeleton-names mixamo|ue5 renames the bones; the morph targets keep
 * the model's joint names), else by joint_names.
 */
function resolveJoints(skeleton, meta) {
  const bones = skeleton.bones;
  const names = meta && Array.isArray(meta.joint_names) ? meta.joint_names.map(String) : null;
  const parents = meta && Array.isArray(meta.parents) ? meta.parents : null;
  if (names && parents && names.length === parents.length && names.length > 0) {
    const boneNames = Array.isArray(meta.bone_names) && meta.bone_names.length === names.length
      ? meta.bone_names.map(String) : names;
    const bone = boneNames.map((n) => findBone(bones, n));
    const missing = boneNames.filter((n, k) => bone[k] < 0);
    if (missing.length) {
      throw new Error(`smpl-correctives: joint '${missing[0]}' of the metadata has no bone ` +
                      `(${missing.length} missing of ${names.length})`);
    }
    const parent = parents.map((p, k) => (Number.isInteger(p) && p >= 0 && p < k ? p : -1));
    return { names, parent, bone };
  }
  const index = new Map(bones.map((b, i) => [b, i]));
  const parent = bones.map((b) => {  // nearest ancestor that is a bone of the skeleton
    for (let a = b.parent; a; a = a.parent) if (index.has(a)) return index.get(a);
    return -1;
  });
  return { names: bones.map((b) => b.name), parent, bone: bones.map((_, i) => i) };
}

/**
 * Corrective entries (feature, target, scale, offset, rectified) and the
 * basis, from the metadata; without a corrective layout in the metadata, the
 * meshes' targets named pose_<joint>_<r><c> with scale 1 and offset 0.
 */
function readLayout(meta, joints, meshes) {
  const featureCount = 9 * Math.max(0, joints.names.length - 1);
  const list = meta && Array.isArray(meta.correctives) ? meta.correctives : null;
  const basis = readBasis(meta, joints);
  const entries = list || basis ? entriesFromMetadata(list || []) : entriesFromNames(meshes, joints.names);
  for (const e of entries) if (e.feature < 0 || e.feature >= featureCount) e.feature = -1;
  return { entries, basis, featureCount };
}

function entriesFromMetadata(list) {
  const entries = [];
  for (const e of list) {
    if (!isObject(e) || !Number.isInteger(e.feature) || typeof e.target !== 'string') continue;
    const scale = Number.isFinite(e.scale) ? e.scale : 1;
    const offset = Number.isFinite(e.offset) ? e.offset : 0;
    entries.push({ feature: e.feature, target: e.target, scale, offset, rectified: e.rectified === true });
  }
  return entries;
}

function entriesFromNames(meshes, names) {
  const seen = new Map();
  for (const mesh of meshes) {
    for (const key in mesh.morphTargetDictionary) {
      const m = TARGET_NAME.exec(key.slice(Math.max(0, key.indexOf('pose_'))));
      const k = m ? names.indexOf(m[1]) : -1;
      if (k >= 1 && !seen.has(m[0])) {
        seen.set(m[0], { feature: 9 * (k - 1) + 3 * Number(m[2]) + Number(m[3]), target: m[0], scale: 1, offset: 0,
                         rectified: false });
      }
    }
  }
  return [...seen.values()];
}

function readBasis(meta, joints) {
  const b = meta && meta.corrective_basis;
  if (!isObject(b) || !Array.isArray(b.targets)) return null;
  const rows = b.targets.length, cols = 9 * (joints.names.length - 1);
  const flat = Array.isArray(b.matrix) ? b.matrix.flat() : [];
  const ok = flat.length === rows * cols && Array.isArray(b.scale) && b.scale.length === rows &&
             Array.isArray(b.offset) && b.offset.length === rows &&
             flat.concat(b.scale, b.offset).every(Number.isFinite);
  if (!ok) throw new Error(`smpl-correctives: corrective_basis is malformed (expected ${rows} x ${cols} matrix, ` +
                           `${rows} scales and offsets)`);
  return { targets: b.targets.map(String), matrix: Float64Array.from(flat), scale: b.scale, offset: b.offset, cols };
}

function morphIndex(dictionary, name) {
  if (name in dictionary) return dictionary[name];
  for (const key in dictionary) {  // importer prefixes ("Key|", "body.")
    if (key.endsWith(name) && /[|.:]$/.test(key.slice(0, key.length - name.length))) return dictionary[key];
  }
  return -1;
}

/** Per mesh: morph index of each entry and each basis target (-1 = absent). */
function bindTargets(meshes, layout) {
  const out = { meshes: [], entryIndex: [], basisIndex: [] };
  for (const mesh of meshes) {
    const dict = mesh.morphTargetDictionary;
    const entryIndex = Int32Array.from(layout.entries, (e) => morphIndex(dict, e.target));
    const basisIndex = Int32Array.from(layout.basis ? layout.basis.targets : [], (t) => morphIndex(dict, t));
    if (entryIndex.some((i) => i >= 0) || basisIndex.some((i) => i >= 0)) {
      out.meshes.push(mesh);
      out.entryIndex.push(entryIndex);
      out.basisIndex.push(basisIndex);
    }
  }
  return out;
}

// ------------------------------------------------------------------ rotations
// Quaternions as [x, y, z, w] in Float64Array slots; matrices 3x3 row-major.

function matrixRotation(m4, out, o) {  // rotation of a three Matrix4 (scale removed) as a quaternion
  const e = m4.elements;  // column-major
  const sx = Math.hypot(e[0], e[1], e[2]), sy = Math.hypot(e[4], e[5], e[6]), sz = Math.hypot(e[8], e[9], e[10]);
  const r00 = e[0] / sx, r10 = e[1] / sx, r20 = e[2] / sx;
  const r01 = e[4] / sy, r11 = e[5] / sy, r21 = e[6] / sy;
  const r02 = e[8] / sz, r12 = e[9] / sz, r22 = e[10] / sz;
  const trace = r00 + r11 + r22;
  let x, y, z, w;
  if (trace > 0) {
    const s = 0.5 / Math.sqrt(trace + 1);
    w = 0.25 / s; x = (r21 - r12) * s; y = (r02 - r20) * s; z = (r10 - r01) * s;
  } else if (r00 > r11 && r00 > r22) {
    const s = 2 * Math.sqrt(1 + r00 - r11 - r22);
    w = (r21 - r12) / s; x = 0.25 * s; y = (r01 + r10) / s; z = (r02 + r20) / s;
  } else if (r11 > r22) {
    const s = 2 * Math.sqrt(1 + r11 - r00 - r22);
    w = (r02 - r20) / s; x = (r01 + r10) / s; y = 0.25 * s; z = (r12 + r21) / s;
  } else {
    const s = 2 * Math.sqrt(1 + r22 - r00 - r11);
    w = (r10 - r01) / s; x = (r02 + r20) / s; y = (r12 + r21) / s; z = 0.25 * s;
  }
  const n = Math.hypot(x, y, z, w);
  out[o] = x / n; out[o + 1] = y / n; out[o + 2] = z / n; out[o + 3] = w / n;
}

function quatMultiply(a, ao, b, bo, out, oo) {  // out = a * b (may alias)
  const ax = a[ao], ay = a[ao + 1], az = a[ao + 2], aw = a[ao + 3];
  const bx = b[bo], by = b[bo + 1], bz = b[bo + 2], bw = b[bo + 3];
  out[oo] = ax * bw + aw * bx + ay * bz - az * by;
  out[oo + 1] = ay * bw + aw * by + az * bx - ax * bz;
  out[oo + 2] = az * bw + aw * bz + ax * by - ay * bx;
  out[oo + 3] = aw * bw - ax * bx - ay * by - az * bz;
}

function quatConjugate(q, o) { q[o] = -q[o]; q[o + 1] = -q[o + 1]; q[o + 2] = -q[o + 2]; }

/**
 * Per driven joint k (1..K-1): the chain of nodes from bone k up to its
 * parent joint's bone, Rr_k^-1 and B_k (see the header).
 */
function buildRig(skeleton, joints) {
  const { bone, parent } = joints;
  const K = bone.length;
  const bones = skeleton.bones, inverses = skeleton.boneInverses;
  const inverseRot = new Float64Array(4 * K);
  for (let k = 0; k < K; k++) matrixRotation(inverses[bone[k]], inverseRot, 4 * k);
  const restInv = new Float64Array(4 * K), basis = new Float64Array(4 * K), basisInv = new Float64Array(4 * K);
  const chains = [], tmp = new Float64Array(4);
  const root = 0;  // joint 0: its rest orientation is the model frame C
  for (let k = 1; k < K; k++) {
    const p = parent[k] >= 0 ? parent[k] : root;
    // Rr_k = rot(bi_p) rot(bi_k)^-1  ->  Rr_k^-1 = rot(bi_k) rot(bi_p)^-1
    tmp.set(inverseRot.subarray(4 * p, 4 * p + 4)); quatConjugate(tmp, 0);
    quatMultiply(inverseRot, 4 * k, tmp, 0, restInv, 4 * k);
    // B_k = rot(bi_root) rot(bi_p)^-1
    quatMultiply(inverseRot, 4 * root, tmp, 0, basis, 4 * k);
    basisInv.set(basis.subarray(4 * k, 4 * k + 4), 4 * k); quatConjugate(basisInv, 4 * k);
    const chain = [];
    const stop = parent[k] >= 0 ? bones[bone[p]] : null;
    for (let node = bones[bone[k]]; node && node !== stop; node = node.parent) chain.push(node);
    if (stop && chain[chain.length - 1].parent !== stop) {
      throw new Error(`smpl-correctives: bone '${bones[bone[k]].name}' is not below the bone of its parent joint`);
    }
    chains.push(chain.reverse());  // top-down: M = q_top * ... * q_k
  }
  return { K, chains, restInv, basis, basisInv };
}

// ------------------------------------------------------------------ runtime

/** The object bindCorrectives returns; see index.d.ts. */
class Correctives {
  constructor(rig, layout, bound) {
    const { entries, basis } = layout;
    this.rig = rig;
    this.meshes = bound.meshes;
    this.enabled = true;
    this.features = new Float64Array(layout.featureCount);
    this.targetNames = entries.map((e) => e.target).concat(basis ? basis.targets : []);
    this.weights = new Float64Array(this.targetNames.length);
    this._q = new Float64Array(4);
    this._entryIndex = bound.entryIndex;
    this._basisIndex = bound.basisIndex;
    this._feature = Int32Array.from(entries, (e) => e.feature);
    this._scale = Float64Array.from(entries, (e) => e.scale);
    this._offset = Float64Array.from(entries, (e) => e.offset);
    this._rectified = Uint8Array.from(entries, (e) => (e.rectified ? 1 : 0));
    this._basisCount = basis ? basis.targets.length : 0;
    this._basisMatrix = basis ? basis.matrix : new Float64Array(0);
    this._basisScale = Float64Array.from(basis ? basis.scale : []);
    this._basisOffset = Float64Array.from(basis ? basis.offset : []);
  }

  /** f (9(K-1)) from the bones' current local rotations. */
  computeFeatures() {
    const { K, chains, restInv, basis, basisInv } = this.rig;
    const f = this.features, q = this._q;
    for (let k = 1; k < K; k++) {
      const chain = chains[k - 1];
      const first = chain[0].quaternion;
      q[0] = first.x; q[1] = first.y; q[2] = first.z; q[3] = first.w;
      for (let i = 1; i < chain.length; i++) {
        const n = chain[i].quaternion;
        const ax = q[0], ay = q[1], az = q[2], aw = q[3];
        q[0] = ax * n.w + aw * n.x + ay * n.z - az * n.y;
        q[1] = ay * n.w + aw * n.y + az * n.x - ax * n.z;
        q[2] = az * n.w + aw * n.z + ax * n.y - ay * n.x;
        q[3] = aw * n.w - ax * n.x - ay * n.y - az * n.z;
      }
      const o = 4 * k;
      quatMultiply(q, 0, restInv, o, q, 0);   // M Rr^-1
      quatMultiply(basis, o, q, 0, q, 0);     // B (..)
      quatMultiply(q, 0, basisInv, o, q, 0);  // (..) B^-1
      writeFeatures(q, f, 9 * (k - 1));
    }
    return f;
  }

  /** Set morphTargetInfluences of every bound mesh from the current pose. */
  update() {
    if (!this.enabled) return this.weights;
    const f = this.computeFeatures();
    const w = this.weights, n = this._feature.length;
    for (let i = 0; i < n; i++) {
      const j = this._feature[i];
      let v = this._scale[i] * (j >= 0 ? f[j] : 0) + this._offset[i];
      if (this._rectified[i] && v < 0) v = 0;
      w[i] = v;
    }
    const cols = this.features.length, m = this._basisMatrix;
    for (let b = 0; b < this._basisCount; b++) {
      let s = 0;
      for (let c = 0, row = b * cols; c < cols; c++) s += m[row + c] * f[c];
      w[n + b] = this._basisScale[b] * s + this._basisOffset[b];
    }
    this._write();
    return w;
  }

  /** Weights of the rest pose (f = 0): what the file looks like without the driver's work. */
  rest() {
    const w = this.weights, n = this._feature.length;
    for (let i = 0; i < n; i++) w[i] = this._rectified[i] ? Math.max(0, this._offset[i]) : this._offset[i];
    for (let b = 0; b < this._basisCount; b++) w[n + b] = this._basisOffset[b];
    this._write();
    return w;
  }

  _write() {
    const w = this.weights, n = this._feature.length;
    for (let m = 0; m < this.meshes.length; m++) {
      const influences = this.meshes[m].morphTargetInfluences;
      const ei = this._entryIndex[m], bi = this._basisIndex[m];
      for (let i = 0; i < ei.length; i++) if (ei[i] >= 0) influences[ei[i]] = w[i];
      for (let b = 0; b < bi.length; b++) if (bi[b] >= 0) influences[bi[b]] = w[n + b];
    }
  }
}

function writeFeatures(q, f, o) {  // R(q) - I, row-major
  const x = q[0], y = q[1], z = q[2], w = q[3];
  f[o] = -2 * (y * y + z * z);    f[o + 1] = 2 * (x * y - z * w); f[o + 2] = 2 * (x * z + y * w);
  f[o + 3] = 2 * (x * y + z * w); f[o + 4] = -2 * (x * x + z * z); f[o + 5] = 2 * (y * z - x * w);
  f[o + 6] = 2 * (x * z - y * w); f[o + 7] = 2 * (y * z + x * w); f[o + 8] = -2 * (x * x + y * y);
}
