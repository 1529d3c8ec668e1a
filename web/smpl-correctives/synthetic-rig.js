// A synthetic SMPL / SMPL-X rig built in code, for the benchmark and the
// driver's tests (no model file needed): K joint bones (the authors' joint
// names and parents), a small skinned mesh whose morph targets are the
// corrective targets `pose_<joint>_<r><c>` (zero deltas: only the weights
// matter here), and matching metadata (signed encoding).

const BODY = ['pelvis', 'left_hip', 'right_hip', 'spine1', 'left_knee', 'right_knee', 'spine2',
  'left_ankle', 'right_ankle', 'spine3', 'left_foot', 'right_foot', 'neck', 'left_collar',
  'right_collar', 'head', 'left_shoulder', 'right_shoulder', 'left_elbow', 'right_elbow',
  'left_wrist', 'right_wrist'];
const BODY_PARENTS = [-1, 0, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 9, 9, 12, 13, 14, 16, 17, 18, 19];
const FINGERS = ['index', 'middle', 'pinky', 'ring', 'thumb'];

/** Joint names and parents of SMPL (24 joints) or SMPL-X (55 joints). */
export function layout(kind) {
  if (kind === 'smpl') {
    return { names: BODY.concat(['left_hand', 'right_hand']), parents: BODY_PARENTS.concat([20, 21]) };
  }
  if (kind !== 'smplx') throw new Error(`unknown layout ${kind}`);
  const names = BODY.concat(['jaw', 'left_eye_smplhf', 'right_eye_smplhf']);
  const parents = BODY_PARENTS.concat([15, 15, 15]);
  for (const [side, wrist] of [['left', 20], ['right', 21]]) {
    for (const finger of FINGERS) {
      for (let i = 1; i <= 3; i++) {
        names.push(`${side}_${finger}${i}`);
        parents.push(i === 1 ? wrist : names.length - 2);
      }
    }
  }
  return { names, parents };
}

/** Corrective target names in feature order. */
export function targetNames(names) {
  const out = [];
  for (let k = 1; k < names.length; k++) {
    for (let r = 0; r < 3; r++) for (let c = 0; c < 3; c++) out.push(`pose_${names[k]}_${r}${c}`);
  }
  return out;
}

/**
 * Build the rig. options: restRotation(k) -> THREE.Quaternion, a bone's local
 * rest rotation (default identity: the exporter's convention; anything else
 * mimics a loader that re-orients bones); targets (default targetNames);
 * maxInfluences (metadata, default 4).
 * @returns {{root, mesh, bones, names, parents, metadata}}
 */
export function buildRig(THREE, kind, options = {}) {
  const { names, parents } = layout(kind);
  const targets = options.targets || targetNames(names);
  const bones = names.map((name, k) => {
    const bone = new THREE.Bone();
    bone.name = name;
    bone.position.set(0.01 * k, k === 0 ? 1 : 0.1, 0.02 * (k % 3));
    if (options.restRotation) bone.quaternion.copy(options.restRotation(k));
    return bone;
  });
  bones.forEach((bone, k) => { if (parents[k] >= 0) bones[parents[k]].add(bone); });
  const geometry = new THREE.BufferGeometry();
  const count = 4;
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(new Float32Array(3 * count), 3));
  geometry.setAttribute('skinIndex', new THREE.Uint16BufferAttribute(new Uint16Array(4 * count), 4));
  const weights = new Float32Array(4 * count);
  for (let i = 0; i < count; i++) weights[4 * i] = 1;
  geometry.setAttribute('skinWeight', new THREE.Float32BufferAttribute(weights, 4));
  geometry.morphAttributes.position = targets.map((t) => {
    const a = new THREE.Float32BufferAttribute(new Float32Array(3 * count), 3);
    a.name = t;
    return a;
  });
  geometry.morphTargetsRelative = true;
  const mesh = new THREE.SkinnedMesh(geometry, new THREE.MeshBasicMaterial());
  mesh.name = 'body';
  const root = new THREE.Group();
  root.add(mesh);
  root.add(bones[0]);
  root.updateMatrixWorld(true);
  mesh.bind(new THREE.Skeleton(bones));
  const metadata = {
    model_kind: kind, joint_names: names, parents, max_influences: options.maxInfluences || 4,
    units: 'meters', up_axis: '+Y',
    correctives: targets.map((t, n) => ({ feature: n, target: t, scale: 1, offset: 0 })),
  };
  return { root, mesh, bones, names, parents, metadata };
}
