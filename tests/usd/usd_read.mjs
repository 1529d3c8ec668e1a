// An independent reading of a UsdSkel export (.usda or .usdz) through tinyusdz
// (npm `tinyusdz`, Light Transport's C++ USD library compiled to WebAssembly),
// never through our writer's code: what this prints is what a third-party USD
// reader makes of the file.
//
//   node tests/usd/usd_read.mjs FILE.usda|FILE.usdz OUT.json
//
// Two tinyusdz APIs read the file:
//  - Tydra (TinyUSDZLoaderNative.loadFromBinary -> RenderScene): tinyusdz's
//    scene conversion. It checks the UsdSkel binding (skel:skeleton, joints vs
//    bind/rest transform counts, the single-rooted joint tree, jointIndices /
//    jointWeights elementSize and `vertex` interpolation, SkelAnimation array
//    lengths at every time code, blendShapes vs blendShapeTargets) and rejects
//    the file when one is wrong. Its JavaScript binding (0.9.0-rc10) hands out
//    the mesh only: points, normals, faceVertexCounts, faceVertexIndices.
//  - The parsed layer (loadAsLayerFromBinary -> layerToString): tinyusdz's own
//    re-serialisation of the layer after parsing and type-checking every
//    attribute (float values printed shortest-round-trip). Everything Tydra's
//    binding does not hand out (skeleton, animation, skin primvars, blend
//    shapes, stage metadata) is read from that text by the small parser below;
//    the mesh arrays read both ways must agree exactly (checked here).
//
// OUT.json (numbers as read; float32 values as the float64 nearest their text):
//   {stage: {metersPerUnit, upAxis, timeCodesPerSecond, startTimeCode, endTimeCode,
//            defaultPrim},
//    mesh: {path, points [N][3], normals [N][3], faceVertexCounts [F],
//           faceVertexIndices [3F], jointIndices [N*M], jointWeights [N*M], elementSize M,
//           geomBindTransform [4][4] (row-major as written), blendShapes [B],
//           blendShapeTargets [B] (paths), skeleton (path)},
//    blendShapes: {name: {offsets [K][3], pointIndices [K]}},
//    skeleton: {path, joints [J], bindTransforms [J][4][4], restTransforms [J][4][4],
//               animationSource},
//    animation: {path, joints [J], blendShapes [B], timeCodes [T],
//                translations/rotations/scales/blendShapeWeights: {default, samples: {t: [...]}}},
//    readBy: {tydra: [...], layer: [...]}}
// Rotations are kept as written, (real, i, j, k), and matrices as their text
// rows: usdskel_eval.py interprets them (USD's conventions are cited there).
//
// Tydra (0.9.0-rc10, src/tydra/render-data.cc ConvertSkelAnimation) rejects a
// SkelAnimation whose blendShapeWeights has timeSamples but no default value
// ("`blendShapeWeights` attribute of SkelAnimation is invalid"), although USD
// allows that; a file that authors both (the default is unused at numeric time
// codes) loads.
// Errors: exit 1 with one line `FILE: ...` when tinyusdz cannot load the file.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const HERE = path.dirname(fileURLToPath(import.meta.url));
const TINYUSDZ = path.join(HERE, '..', '..', 'web', 'node_modules', 'tinyusdz');

function fail(file, message) {
  process.stdout.write(`${file}: ${message.split('\n').find((l) => l.trim()) || message}\n`);
  process.exit(1);
}

// tinyusdz.js is an Emscripten build for the web only: it looks for `window`
// and refuses to start when it sees node's `process`; with the wasm bytes
// given it needs neither fetch nor the file system.
async function loadTinyUsdz() {
  const entry = path.join(TINYUSDZ, 'tinyusdz.js');
  if (!fs.existsSync(entry)) {
    throw new Error(`${entry} missing: run npm ci in web/`);
  }
  globalThis.window = globalThis;
  const create = (await import(entry)).default;
  const saved = globalThis.process;
  globalThis.process = undefined;
  try {
    // print/printErr: tinyusdz's own log lines stay out of our one-line errors.
    return await create({
      wasmBinary: fs.readFileSync(path.join(TINYUSDZ, 'tinyusdz.wasm')),
      print: () => {},
      printErr: () => {},
    });
  } finally {
    globalThis.process = saved;
  }
}

// ---------------------------------------------------------------------------
// A parser for the USDA text tinyusdz prints (prims, attributes with default
// values and timeSamples, relationships, metadata), from the USDA grammar.

const TOKEN = new RegExp([
  String.raw`(?<space>\s+|#[^\n]*)`,
  String.raw`(?<string>"""[\s\S]*?"""|'''[\s\S]*?'''|"(?:[^"\\\n]|\\.)*"|'(?:[^'\\\n]|\\.)*')`,
  String.raw`(?<path><[^>]*>)`,
  String.raw`(?<number>[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|[-+]?inf\b|nan\b)`,
  String.raw`(?<ident>[A-Za-z_][\w:.]*(?:\[\])?)`,
  String.raw`(?<punct>[()[\]{}=,:])`,
].join('|'), 'y');

function tokenize(text) {
  const out = [];
  TOKEN.lastIndex = 0;
  while (TOKEN.lastIndex < text.length) {
    const at = TOKEN.lastIndex;
    const m = TOKEN.exec(text);
    if (!m) throw new Error(`layer text: unexpected character at offset ${at}: '${text.slice(at, at + 20)}'`);
    const kind = Object.keys(m.groups).find((k) => m.groups[k] !== undefined);
    if (kind !== 'space') out.push({ kind, text: m[0] });
  }
  return out;
}

// A USDA string token's text: "..." or '...' (or tripled) with backslash escapes.
function unquote(text) {
  const q = text.startsWith('"""') || text.startsWith("'''") ? 3 : 1;
  const escapes = { n: '\n', t: '\t', r: '\r' };
  return text.slice(q, -q).replace(/\\(.)/gs, (_, c) => escapes[c] ?? c);
}

class Parser {
  constructor(tokens) { this.t = tokens; this.i = 0; }
  peek(k = 0) { return this.t[this.i + k]; }
  next() {
    if (this.i >= this.t.length) throw new Error('layer text: unexpected end');
    return this.t[this.i++];
  }
  is(text, k = 0) { const t = this.peek(k); return t !== undefined && t.kind !== 'string' && t.text === text; }
  expect(text) {
    const t = this.next();
    if (t.text !== text) throw new Error(`layer text: expected '${text}', got '${t.text}'`);
  }

  value() {
    const t = this.next();
    if (t.kind === 'number') return Number(t.text.replace(/inf$/, 'Infinity').replace(/^nan$/, 'NaN'));
    if (t.kind === 'string') return unquote(t.text);
    if (t.kind === 'path') return t.text.slice(1, -1);
    if (t.kind === 'ident') return t.text === 'true' ? true : t.text === 'false' ? false : t.text;
    if (t.text === '[' || t.text === '(') {
      const close = t.text === '[' ? ']' : ')';
      const items = [];
      while (!this.is(close)) {
        items.push(this.value());
        if (this.is(',')) this.next();
      }
      this.next();
      return items;
    }
    if (t.text === '{') return this.peek().kind === 'number' || this.is('}') ? this.timeSamples() : this.dictionary();
    throw new Error(`layer text: unexpected '${t.text}' in a value`);
  }

  // { time: value, ... }
  timeSamples() {
    const samples = {};
    while (!this.is('}')) {
      const time = this.next();
      if (time.kind !== 'number') throw new Error(`layer text: time code expected, got '${time.text}'`);
      this.expect(':');
      samples[Number(time.text)] = this.value();
      if (this.is(',')) this.next();
    }
    this.next();
    return samples;
  }

  // { type key = value ... } (customData, customLayerData), after its '{'.
  dictionary() {
    const dict = {};
    while (!this.is('}')) {
      this.next();  // the value's type (string, int, double[], dictionary, ...)
      const key = this.value();
      this.expect('=');
      dict[key] = this.value();
      if (this.is(';') || this.is(',')) this.next();
    }
    this.next();
    return dict;
  }

  // ( key = value ... ), with list-op keywords (prepend/append/...) and bare strings (doc).
  metadata() {
    const meta = {};
    this.expect('(');
    while (!this.is(')')) {
      if (this.peek().kind === 'string') { meta.doc = this.value(); continue; }
      let key = this.next().text;
      if (['prepend', 'append', 'add', 'delete', 'reorder'].includes(key)) key = this.next().text;
      this.expect('=');
      meta[key] = this.value();
      if (this.is(';') || this.is(',')) this.next();
    }
    this.next();
    return meta;
  }

  prim(specifier) {
    let type = '';
    if (this.peek().kind === 'ident') type = this.next().text;
    const name = this.value();
    const prim = { specifier, type, name, meta: {}, attrs: {}, rels: {}, children: [] };
    if (this.is('(')) prim.meta = this.metadata();
    this.expect('{');
    this.body(prim);
    this.expect('}');
    return prim;
  }

  body(prim) {
    while (this.peek() && !this.is('}')) {
      const word = this.peek().text;
      if (['def', 'over', 'class'].includes(word)) {
        this.next();
        prim.children.push(this.prim(word));
      } else if (word === 'rel') {
        this.next();
        const name = this.next().text;
        prim.rels[name] = this.is('=') ? (this.next(), this.value()) : null;
        if (this.is('(')) this.metadata();
      } else {
        this.attribute(prim);
      }
    }
  }

  attribute(prim) {
    let uniform = false;
    while (['uniform', 'custom', 'varying', 'config'].includes(this.peek().text)) {
      uniform ||= this.next().text === 'uniform';
    }
    const type = this.next().text;
    let name = this.next().text;
    let field = 'default';
    for (const suffix of ['.timeSamples', '.connect', '.spline']) {
      if (name.endsWith(suffix)) { field = suffix.slice(1); name = name.slice(0, -suffix.length); }
    }
    const attr = prim.attrs[name] || (prim.attrs[name] = { type, uniform, meta: {} });
    if (this.is('=')) {
      this.next();
      attr[field] = this.value();
    }
    if (this.is('(')) Object.assign(attr.meta, this.metadata());
  }
}

function parseLayer(text) {
  const p = new Parser(tokenize(text));
  const root = { name: '', meta: {}, attrs: {}, rels: {}, children: [] };
  if (p.is('(')) root.meta = p.metadata();
  p.body(root);
  if (p.peek()) throw new Error(`layer text: unexpected '${p.peek().text}' after the prims`);
  return root;
}

function primsByPath(node, prefix = '', out = new Map()) {
  for (const child of node.children) {
    const p = `${prefix}/${child.name}`;
    out.set(p, child);
    primsByPath(child, p, out);
  }
  return out;
}

// ---------------------------------------------------------------------------

function attrValue(prim, name, { required = true } = {}) {
  const a = prim.attrs[name];
  if (!a || a.default === undefined) {
    if (required) throw new Error(`${prim.type} ${prim.name}: no value for '${name}'`);
    return undefined;
  }
  return a.default;
}

// {default, samples: {t: value}} of a possibly time-sampled attribute.
function animated(prim, name) {
  const a = prim.attrs[name];
  if (!a) return null;
  return { type: a.type, default: a.default === undefined ? null : a.default, samples: a.timeSamples || {} };
}

function relTargets(prim, name) {
  const r = prim.rels[name];
  if (r === undefined || r === null) return [];
  return Array.isArray(r) ? r : [r];
}

function readLayer(M, bytes, file) {
  const loader = new M.TinyUSDZLoaderNative();
  if (!loader.loadAsLayerFromBinary(bytes, path.basename(file))) {
    throw new Error(`tinyusdz could not parse the layer: ${loader.error()}`);
  }
  const text = loader.layerToString();
  const root = parseLayer(text);
  const prims = primsByPath(root);
  const byType = (type) => [...prims].filter(([, p]) => p.type === type);
  const one = (type) => {
    const found = byType(type);
    if (found.length !== 1) throw new Error(`expected one ${type} prim, found ${found.length}`);
    return found[0];
  };
  const [meshPath, mesh] = one('Mesh');
  const [skelPath, skel] = one('Skeleton');
  const [animPath, anim] = one('SkelAnimation');
  const ji = mesh.attrs['primvars:skel:jointIndices'];
  const jw = mesh.attrs['primvars:skel:jointWeights'];
  if (!ji || !jw) throw new Error(`${meshPath}: primvars:skel:jointIndices/jointWeights missing`);
  const out = {
    stage: root.meta,
    mesh: {
      path: meshPath,
      points: attrValue(mesh, 'points'),
      normals: attrValue(mesh, 'normals', { required: false }) ?? null,
      normalsInterpolation: mesh.attrs.normals?.meta.interpolation ?? null,
      faceVertexCounts: attrValue(mesh, 'faceVertexCounts'),
      faceVertexIndices: attrValue(mesh, 'faceVertexIndices'),
      jointIndices: ji.default,
      jointWeights: jw.default,
      elementSize: ji.meta.elementSize,
      jointWeightsElementSize: jw.meta.elementSize,
      jointIndicesInterpolation: ji.meta.interpolation,
      jointWeightsInterpolation: jw.meta.interpolation,
      geomBindTransform: attrValue(mesh, 'primvars:skel:geomBindTransform', { required: false }) ?? null,
      blendShapes: attrValue(mesh, 'skel:blendShapes', { required: false }) ?? [],
      blendShapeTargets: relTargets(mesh, 'skel:blendShapeTargets'),
      skeleton: relTargets(mesh, 'skel:skeleton')[0] ?? null,
    },
    blendShapes: {},
    skeleton: {
      path: skelPath,
      joints: attrValue(skel, 'joints'),
      bindTransforms: attrValue(skel, 'bindTransforms'),
      restTransforms: attrValue(skel, 'restTransforms'),
      animationSource: relTargets(skel, 'skel:animationSource')[0] ?? null,
    },
    animation: {
      path: animPath,
      joints: attrValue(anim, 'joints'),
      blendShapes: attrValue(anim, 'blendShapes', { required: false }) ?? [],
      translations: animated(anim, 'translations'),
      rotations: animated(anim, 'rotations'),
      scales: animated(anim, 'scales'),
      blendShapeWeights: animated(anim, 'blendShapeWeights'),
    },
  };
  // The targets by relationship path, named as the mesh's skel:blendShapes (UsdSkelBindingAPI:
  // skel:blendShapes[i] names the target skel:blendShapeTargets[i]).
  out.mesh.blendShapeTargets.forEach((target, i) => {
    const prim = prims.get(target);
    if (!prim || prim.type !== 'BlendShape') throw new Error(`${meshPath}: blend shape target ${target} is no BlendShape`);
    out.blendShapes[out.mesh.blendShapes[i]] = {
      path: target,
      offsets: attrValue(prim, 'offsets'),
      pointIndices: attrValue(prim, 'pointIndices', { required: false }) ?? null,
    };
  });
  const times = new Set();
  for (const key of ['translations', 'rotations', 'scales', 'blendShapeWeights']) {
    for (const t of Object.keys(out.animation[key]?.samples || {})) times.add(Number(t));
  }
  out.animation.timeCodes = [...times].sort((a, b) => a - b);
  return out;
}

// Tydra's RenderScene: the UsdSkel checks above, and the mesh arrays it hands out.
function readTydra(M, bytes, file) {
  const loader = new M.TinyUSDZLoaderNative();
  if (!loader.loadFromBinary(bytes, path.basename(file))) {
    throw new Error(`tinyusdz Tydra rejected the file: ${loader.error()}`);
  }
  if (loader.numMeshes() !== 1) throw new Error(`Tydra found ${loader.numMeshes()} meshes, expected 1`);
  const m = loader.getMesh(0);
  return {
    path: m.absPath,
    points: Array.from(m.points),
    normals: m.normals ? Array.from(m.normals) : null,
    faceVertexCounts: Array.from(m.faceVertexCounts),
    faceVertexIndices: Array.from(m.faceVertexIndices),
  };
}

// Tydra's float32 arrays must be the layer's values rounded to float32, exactly.
function sameAsTydra(name, layerValues, tydraValues) {
  const flat = layerValues.flat(Infinity);
  if (flat.length !== tydraValues.length) {
    throw new Error(`${name}: the layer has ${flat.length} values, Tydra ${tydraValues.length}`);
  }
  for (let i = 0; i < flat.length; i++) {
    if (Math.fround(flat[i]) !== tydraValues[i]) {
      throw new Error(`${name}[${i}]: layer ${flat[i]}, Tydra ${tydraValues[i]}`);
    }
  }
}

async function main() {
  const [file, outPath] = process.argv.slice(2);
  if (!file || !outPath) {
    process.stdout.write('usage: node usd_read.mjs FILE.usda|FILE.usdz OUT.json\n');
    process.exit(2);
  }
  let bytes;
  try {
    bytes = new Uint8Array(fs.readFileSync(file));
  } catch (e) {
    fail(file, e.message);
  }
  try {
    const M = await loadTinyUsdz();
    const tydra = readTydra(M, bytes, file);
    const out = readLayer(M, bytes, file);
    if (tydra.path !== out.mesh.path) throw new Error(`Tydra's mesh is ${tydra.path}, the layer's ${out.mesh.path}`);
    sameAsTydra('points', out.mesh.points, tydra.points);
    sameAsTydra('faceVertexCounts', out.mesh.faceVertexCounts, tydra.faceVertexCounts);
    sameAsTydra('faceVertexIndices', out.mesh.faceVertexIndices, tydra.faceVertexIndices);
    if (out.mesh.normals && tydra.normals) sameAsTydra('normals', out.mesh.normals, tydra.normals);
    out.readBy = {
      tydra: ['UsdSkel binding checks', 'points', 'normals', 'faceVertexCounts', 'faceVertexIndices'],
      layer: ['stage metadata', 'skin primvars', 'geomBindTransform', 'blend shapes', 'skeleton', 'animation'],
    };
    fs.writeFileSync(outPath, JSON.stringify(out));
  } catch (e) {
    fail(file, e.message);
  }
}

await main();
