// The smpl-export viewer: load a .glb / .fbx (+ sidecar), orbit, play the
// baked animations, toggle the pose correctives, pose joints with sliders,
// and show the counts and the per-frame corrective weights; convert a model
// file (+ a motion) in the page with the WebAssembly build (convert.js).
//
// The floor grid is at the body's lowest point over its clip (the rest
// pose's for a file without one), so a body exported with --origin floor or
// an AMASS clip (feet at y = 0 in its world) stands on it; the camera frames
// the box the body sweeps over the whole clip, so it stays in view while
// playing.
//
// window.smplViewer (for scripts and the browser test): {load(files),
// info(), setPose(axisAngles), vertexWorld(i), framing(), camera, correctives}.
import * as THREE from 'three';
import { FBXLoader } from 'three/addons/loaders/FBXLoader.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { applyFbxUnitScale, bindCorrectives, metadataFromGltf } from 'smpl-correctives';
import { setupConvert } from './convert.js';

const $ = (id) => document.getElementById(id);
const MAX_BOUND_SAMPLES = 300;  // clip times skinned on the CPU for the animated bounds
const SLIDER_JOINTS = [  // joint, axis (model space), range in radians
  ['spine1', 'x', 1.0], ['left_shoulder', 'z', 1.5], ['right_shoulder', 'z', 1.5], ['left_elbow', 'y', 2.0],
  ['right_elbow', 'y', 2.0], ['left_hip', 'x', 1.5], ['left_knee', 'x', 2.2], ['right_knee', 'x', 2.2],
];

const view = $('view');
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x30363d);
scene.add(new THREE.HemisphereLight(0xffffff, 0x444455, 2.0));
const sun = new THREE.DirectionalLight(0xffffff, 2.0);
sun.position.set(2, 4, 3);
const grid = new THREE.GridHelper(4, 20, 0x666666, 0x444444);
scene.add(sun, grid);
const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
camera.position.set(0, 1.2, 3.2);
const controls = new OrbitControls(camera, renderer.domElement);
controls.target.set(0, 0.9, 0);
controls.update();
const clock = new THREE.Clock();

const state = { root: null, mesh: null, correctives: null, mixer: null, action: null, playing: false,
  bones: {}, restQuaternions: {}, metadata: null, info: {}, lastWeightsDraw: 0, bounds: null, floorY: 0 };

function resize() {
  const w = view.clientWidth, h = view.clientHeight;
  renderer.setSize(w, h);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
}
window.addEventListener('resize', resize);
resize();

function status(text) { $('status').textContent = text; }

/** Load from File objects: one .glb/.fbx and, for FBX, its .smpl.json sidecar. */
async function load(files) {
  files = [...files];
  const asset = files.find((f) => /\.(glb|gltf|fbx)$/i.test(f.name));
  if (!asset) throw new Error('no .glb or .fbx among the files');
  const sidecar = files.find((f) => f.name.toLowerCase() === asset.name.toLowerCase() + '.smpl.json') ||
                  files.find((f) => /\.smpl\.json$/i.test(f.name));
  const buffer = await asset.arrayBuffer();
  let root, metadata, animations;
  if (/\.fbx$/i.test(asset.name)) {
    root = new FBXLoader().parse(buffer, '');
    applyFbxUnitScale(root);
    animations = root.animations;
    metadata = sidecar ? JSON.parse(await sidecar.text()) : null;
  } else {
    const gltf = await new GLTFLoader().parseAsync(buffer, '');
    root = gltf.scene;
    animations = gltf.animations;
    metadata = metadataFromGltf(gltf) || (sidecar ? JSON.parse(await sidecar.text()) : null);
  }
  show(root, metadata, animations, asset.name);
  return { ...state.info };
}

function show(root, metadata, animations, name) {
  if (state.root) scene.remove(state.root);
  if (state.mixer) state.mixer.stopAllAction();
  let mesh = null;
  root.traverse((o) => {
    if (o.isSkinnedMesh && !mesh) mesh = o;
    if (o.isMesh && o.material && !Array.isArray(o.material)) o.material.side = THREE.DoubleSide;
    o.frustumCulled = false;  // three culls skinned meshes by their rest bounds
  });
  if (!mesh) throw new Error(`${name}: no skinned mesh`);
  scene.add(root);
  root.updateMatrixWorld(true);
  const warnings = [];
  let correctives = null;
  try {
    correctives = bindCorrectives(root, metadata, { warn: (m) => warnings.push(m) });
  } catch (e) {
    warnings.push(e.message);
  }
  Object.assign(state, { root, mesh, metadata, correctives, mixer: new THREE.AnimationMixer(root), action: null,
    playing: false, bones: {}, restQuaternions: {} });
  for (const b of mesh.skeleton.bones) {
    state.bones[b.name] = b;
    state.restQuaternions[b.name] = b.quaternion.clone();
  }
  state.animations = animations;
  $('pose-mode').checked = false;  // a new file starts in animation mode
  fillInfo(name, mesh, metadata, correctives);
  fillClips(animations);
  fillSliders();
  status(warnings.join('\n'));
  frameCamera(animatedBounds(mesh));
}

function modelVertexCount(mesh, format) {
  const pos = mesh.geometry.attributes.position;
  if (format !== 'fbx') return pos.count;
  const seen = new Set();  // FBXLoader splits vertices per triangle corner: count distinct positions
  for (let i = 0; i < pos.count; i++) seen.add(`${pos.getX(i)},${pos.getY(i)},${pos.getZ(i)}`);
  return seen.size;
}

function fillInfo(name, mesh, metadata, correctives) {
  const format = name.split('.').pop().toLowerCase();
  state.info = {
    file: name, format,
    modelKind: metadata ? String(metadata.model_kind) : 'unknown (no metadata)',
    vertices: modelVertexCount(mesh, format),
    threeVertices: mesh.geometry.attributes.position.count,
    joints: metadata && metadata.joint_names ? metadata.joint_names.length : mesh.skeleton.bones.length,
    morphTargets: mesh.morphTargetInfluences ? mesh.morphTargetInfluences.length : 0,
    driven: correctives ? correctives.weights.length : 0,
    encoding: metadata ? String(metadata.corrective_encoding || encodingOf(metadata)) : '-',
  };
  const i = state.info;
  $('info-file').textContent = i.file;
  $('info-kind').textContent = i.modelKind;
  $('info-vertices').textContent = (format === 'fbx' ? '~' : '') + i.vertices;
  $('info-gpu-vertices').textContent = i.threeVertices;
  $('info-joints').textContent = i.joints;
  $('info-targets').textContent = i.morphTargets;
  $('info-driven').textContent = i.driven;
  $('info-encoding').textContent = i.encoding;
}

function encodingOf(metadata) {
  if (metadata.corrective_basis) return 'basis';
  const c = metadata.correctives || [];
  if (c.some((e) => e.rectified)) return 'split';
  return c.some((e) => e.offset) ? 'unit' : 'signed';
}

function fillClips(animations) {
  const select = $('clip');
  select.innerHTML = '';
  animations.forEach((clip, i) => select.add(new Option(`${clip.name || 'clip ' + i} (${clip.duration.toFixed(2)} s)`, i)));
  select.disabled = animations.length === 0;
  $('play').disabled = animations.length === 0;
  $('scrub').disabled = animations.length === 0;
  if (animations.length) {
    selectClip(0);
  } else {  // a file without clips: nothing to play, scrub back at 0
    $('scrub').max = 1;
    $('scrub').value = 0;
    setPlaying(false);
  }
}

function selectClip(index) {
  state.mixer.stopAllAction();
  const clip = state.animations[index];
  state.action = state.mixer.clipAction(clip);
  state.action.setLoop(THREE.LoopRepeat, Infinity);
  state.action.play();
  state.mixer.setTime(0);
  $('scrub').max = clip.duration;
  setPlaying(false);
}

function setPlaying(on) {
  state.playing = on && !!state.action && !$('pose-mode').checked;
  $('play').textContent = state.playing ? 'Pause' : 'Play';
}

function fillSliders() {
  const box = $('sliders');
  box.innerHTML = '';
  for (const [joint, axis, range] of SLIDER_JOINTS) {
    if (!state.bones[joint]) continue;
    const label = document.createElement('label');
    label.textContent = `${joint} (${axis})`;
    const input = Object.assign(document.createElement('input'), { type: 'range', min: -range, max: range, step: 0.01, value: 0 });
    input.dataset.joint = joint;
    input.dataset.axis = axis;
    input.addEventListener('input', applySliders);
    label.appendChild(input);
    box.appendChild(label);
  }
}

/** Slider rotations are model-space axis-angle rotations local to the parent (rest: identity). */
function applySliders() {
  if (!$('pose-mode').checked) return;
  const axes = { x: new THREE.Vector3(1, 0, 0), y: new THREE.Vector3(0, 1, 0), z: new THREE.Vector3(0, 0, 1) };
  for (const name in state.bones) state.bones[name].quaternion.copy(state.restQuaternions[name]);
  for (const input of $('sliders').querySelectorAll('input')) {
    const q = new THREE.Quaternion().setFromAxisAngle(axes[input.dataset.axis], Number(input.value));
    state.bones[input.dataset.joint].quaternion.multiply(q);
  }
}

/**
 * Pose every joint: axisAngles (K*3, model axes, local to the parent, the
 * metadata's joint order). Switches to pose mode.
 */
function setPose(axisAngles) {
  $('pose-mode').checked = true;
  setPlaying(false);
  if (state.mixer) state.mixer.stopAllAction();
  const names = state.metadata.joint_names;
  names.forEach((name, k) => {
    const v = new THREE.Vector3(axisAngles[3 * k], axisAngles[3 * k + 1], axisAngles[3 * k + 2]);
    const angle = v.length();
    const q = angle > 0 ? new THREE.Quaternion().setFromAxisAngle(v.divideScalar(angle), angle) : new THREE.Quaternion();
    state.bones[name].quaternion.copy(state.restQuaternions[name]).multiply(q);
  });
  step(0);
}

/** Skinned position of three.js vertex i in the scene (three's CPU skinning). */
function vertexWorld(i) {
  state.root.updateMatrixWorld(true);
  const v = state.mesh.getVertexPosition(i, new THREE.Vector3()).applyMatrix4(state.mesh.matrixWorld);
  return [v.x, v.y, v.z];
}

/** World box of the skinned mesh in its current pose (three's CPU skinning of every vertex). */
function posedBox(mesh) {
  state.root.updateMatrixWorld(true);
  mesh.computeBoundingBox();  // SkinnedMesh: the posed vertices, in the mesh's space
  return mesh.boundingBox.clone().applyMatrix4(mesh.matrixWorld);
}

/**
 * The box (scene units, metres) the body sweeps over the selected clip: the
 * union of its posed boxes at the clip's key times (at most
 * MAX_BOUND_SAMPLES of them, evenly spread, first and last included), or the
 * current pose's box without a clip. Leaves the clip at time 0.
 */
function animatedBounds(mesh) {
  if (!state.action) return posedBox(mesh);
  const clip = state.action.getClip();
  const times = new Set([0, clip.duration]);
  for (const track of clip.tracks) for (const t of track.times) times.add(t);
  let sorted = [...times].filter((t) => t >= 0 && t <= clip.duration).sort((a, b) => a - b);
  if (sorted.length > MAX_BOUND_SAMPLES) {
    const n = MAX_BOUND_SAMPLES - 1;
    sorted = [...new Set(Array.from({ length: n + 1 }, (_, i) => sorted[Math.round((i * (sorted.length - 1)) / n)]))];
  }
  const box = new THREE.Box3();
  for (const t of sorted) {
    state.mixer.setTime(t);
    box.union(posedBox(mesh));
  }
  state.mixer.setTime(0);
  return box;
}

/** Floor grid at the box's lowest point, camera on the box's centre, far enough to see all of it. */
function frameCamera(box) {
  const center = box.getCenter(new THREE.Vector3()), extent = box.getSize(new THREE.Vector3());
  const size = Math.max(extent.length(), 0.1);
  state.bounds = box.clone();
  state.floorY = box.min.y;
  grid.scale.setScalar(Math.max(extent.x, extent.z, size / 2) / 2 * 1.5);
  grid.position.set(center.x, box.min.y, center.z);
  // Distance so the box's bounding sphere fits the vertical and horizontal field of view.
  const vfov = THREE.MathUtils.degToRad(camera.fov) / 2;
  const hfov = Math.atan(Math.tan(vfov) * camera.aspect);
  const distance = (size / 2) * 1.1 / Math.sin(Math.min(vfov, hfov));
  const direction = new THREE.Vector3(0, 0.15, 1).normalize();
  controls.target.copy(center);
  camera.position.copy(center).addScaledVector(direction, distance);
  camera.near = size / 100;
  camera.far = size * 100 + distance;
  camera.updateProjectionMatrix();
  controls.update();
}

function drawWeights(now) {
  const c = state.correctives;
  if (!c || now - state.lastWeightsDraw < 100) return;
  state.lastWeightsDraw = now;
  const influences = state.mesh.morphTargetInfluences;
  const dict = state.mesh.morphTargetDictionary;
  const rows = c.targetNames.map((t, i) => [t, influences[dict[t]] ?? c.weights[i]]);
  const rest = c.enabled ? null : rows;
  rows.sort((a, b) => Math.abs(b[1]) - Math.abs(a[1]));
  $('weights').textContent = (rest ? '(correctives off: rest weights)\n' : '') +
    rows.slice(0, 16).map(([t, w]) => `${w.toFixed(4).padStart(8)}  ${t}`).join('\n');
}

function step(dt) {
  if (!state.root) return;
  if (state.playing && state.mixer) {
    state.mixer.update(dt);
    $('scrub').value = state.action.time;
  }
  if (state.correctives) {
    state.correctives.enabled = $('correctives').checked;
    if (state.correctives.enabled) state.correctives.update();
    else state.correctives.rest();  // also overrides any baked weight tracks
  }
  $('time').textContent = `${(state.action ? state.action.time : 0).toFixed(3)} s`;
}

function animate() {
  requestAnimationFrame(animate);
  step(clock.getDelta());
  drawWeights(performance.now());
  renderer.render(scene, camera);
}
animate();

// ------------------------------------------------------------------ UI events
$('file').addEventListener('change', (e) => load(e.target.files).catch((err) => status(err.message)));
const drop = $('drop');
for (const target of [drop, view]) {
  target.addEventListener('dragover', (e) => { e.preventDefault(); drop.classList.add('over'); });
  target.addEventListener('dragleave', () => drop.classList.remove('over'));
  target.addEventListener('drop', (e) => {
    e.preventDefault();
    drop.classList.remove('over');
    load(e.dataTransfer.files).catch((err) => status(err.message));
  });
}
$('play').addEventListener('click', () => setPlaying(!state.playing));
$('clip').addEventListener('change', (e) => {
  selectClip(Number(e.target.value));
  frameCamera(animatedBounds(state.mesh));
});
$('scrub').addEventListener('input', (e) => {
  if (!state.mixer || !state.action) return;
  $('pose-mode').checked = false;
  setPlaying(false);
  state.mixer.setTime(Number(e.target.value));
});
$('pose-mode').addEventListener('change', (e) => {
  if (e.target.checked) {
    setPlaying(false);
    if (state.mixer) state.mixer.stopAllAction();
    applySliders();
  } else if (state.animations && state.animations.length) {
    selectClip(Number($('clip').value) || 0);
  }
});

/** Where the view is: floor height, the animated bounds (min, max), play state. */
function framing() {
  const b = state.bounds;
  return { floorY: state.floorY, gridY: grid.position.y, playing: state.playing,
    time: state.action ? state.action.time : 0, hasClip: !!state.action,
    bounds: b ? { min: b.min.toArray(), max: b.max.toArray() } : null };
}

window.smplViewer = {
  load, setPose, vertexWorld, framing, camera, grid,
  /** Sets the clip's time (seconds), paused; for scripts and tests. */
  setTime: (t) => { if (state.action) { setPlaying(false); state.mixer.setTime(t); step(0); } },
  info: () => ({ ...state.info }),
  get correctives() { return state.correctives; },
};
setupConvert(load);
document.body.dataset.ready = 'true';
