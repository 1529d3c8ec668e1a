// The JS API of smpl-export-wasm: exportAsset(files, options) runs the
// smpl-export command line (the WebAssembly build smpl-export-web.mjs/.wasm
// beside this file) on files held in memory, in a browser, a worker or node.
// Nothing is fetched but the .wasm beside this file, once; the inputs never
// leave the page or the process.
//
//   import { exportAsset } from 'smpl-export-wasm';
//   const { files, output } = await exportAsset(
//     { model: modelFile, motion: motionFile },          // File, Blob, bytes or {name, data}
//     { out: 'walk.glb', 'max-influences': 4, preset: 'web' });
//   files[output]                                       // Uint8Array: the GLB
//   files[output + '.smpl.json']                         // the metadata sidecar
//
// Each call runs in a fresh WebAssembly instance (the compiled module is
// reused), so its memory is returned when the call ends.

/** Options that name an input file: they are given in `files`, not in `options`. */
export const FILE_OPTIONS = ['model', 'motion', 'betas-file', 'dmpl', 'uv'];
/** Options of the command line's batch mode, which the API does not run (one export per call). */
const BATCH_OPTIONS = ['motion-dir', 'motion-sequence', 'out-dir', 'manifest', 'shard', 'force', 'threads'];
const REPEATABLE = new Set(['motion']);
const IN_DIR = '/in', OUT_DIR = '/out';

const isNode = typeof process === 'object' && typeof process.versions === 'object' &&
               typeof process.versions.node === 'string';
let compiled = null;  // Promise<WebAssembly.Module>

/** The compiled smpl-export-web.wasm beside this file (compiled once per page or process). */
function wasmModule() {
  if (!compiled) {
    const url = new URL('./smpl-export-web.wasm', import.meta.url);
    compiled = isNode
      ? import('node:fs').then((fs) => WebAssembly.compile(fs.readFileSync(url)))
      : (typeof WebAssembly.compileStreaming === 'function'
          ? WebAssembly.compileStreaming(fetch(url))
          : fetch(url).then((r) => r.arrayBuffer()).then((b) => WebAssembly.compile(b)));
    compiled.catch(() => { compiled = null; });
  }
  return compiled;
}

/** Load the module now (e.g. when a page opens), so that a later exportAsset() makes no request. */
export async function preload() {
  await Promise.all([wasmModule(), emscriptenFactory()]);
}

/** A file-like value -> { name, bytes: Uint8Array }. Accepts File, Blob (+ name), {name, data}, bytes + name. */
async function readInput(value, key, index) {
  if (value && typeof value === 'object' && 'data' in value && !(value instanceof Uint8Array)) {
    return { name: value.name, bytes: await toBytes(value.data, key) };
  }
  const name = value && typeof value.name === 'string' ? value.name : undefined;
  return { name: name ?? `${key}${index || ''}`, bytes: await toBytes(value, key) };
}

async function toBytes(data, key) {
  if (data instanceof Uint8Array) return data;
  if (data instanceof ArrayBuffer) return new Uint8Array(data);
  if (ArrayBuffer.isView(data)) return new Uint8Array(data.buffer, data.byteOffset, data.byteLength);
  if (data && typeof data.arrayBuffer === 'function') return new Uint8Array(await data.arrayBuffer());
  throw new TypeError(`exportAsset: files.${key}: expected a File, Blob, ArrayBuffer, typed array or {name, data}`);
}

/** A file name without folders, as the file is stored in the instance ("a/b.npz" -> "b.npz"). */
function plainName(name, key) {
  const base = String(name).split(/[\\/]/).pop();
  if (!base || base === '.' || base === '..') throw new Error(`exportAsset: files.${key}: the file has no name`);
  return base;
}

/** options -> command-line words: {a: 1, b: true, c: [x, y]} -> --a 1 --b --c x --c y (false/null omitted). */
export function optionArgs(options) {
  const args = [];
  for (const [key, value] of Object.entries(options)) {
    if (key === 'out' || value === false || value === null || value === undefined) continue;
    if (FILE_OPTIONS.includes(key)) {
      throw new Error(`exportAsset: --${key} names a file: give it in files.${key}, not in options`);
    }
    if (BATCH_OPTIONS.includes(key)) {
      throw new Error(`exportAsset: --${key} is batch mode, which exportAsset does not run (one export per call)`);
    }
    for (const v of Array.isArray(value) ? value : [value]) {
      args.push(`--${key}`);
      if (v !== true) args.push(String(v));
    }
  }
  return args;
}

/** Every file under `dir` in the instance's memory file system -> {relative name: Uint8Array}. */
function collect(FS, dir, prefix = '') {
  const found = {};
  for (const entry of FS.readdir(dir)) {
    if (entry === '.' || entry === '..') continue;
    const path = `${dir}/${entry}`;
    if (FS.isDir(FS.stat(path).mode)) Object.assign(found, collect(FS, path, `${prefix}${entry}/`));
    else found[prefix + entry] = FS.readFile(path);
  }
  return found;
}

/**
 * Export one body (and its motions) as the smpl-export command line does.
 *
 * @param files    { model: File|Blob|Uint8Array|ArrayBuffer|{name, data}|'builtin',
 *                   motion?: one or an array (each baked as an animation),
 *                   'betas-file'?, dmpl?, uv?: one or an array (a .npy pair: both) }.
 *                   The file names matter as on the command line (.npz/.pkl/.json
 *                   /.smpl pick the reader); a bare typed array is named after its key.
 * @param options  the command line's options by their long names without "--":
 *                 { out: 'body.glb' (a file name; its extension picks glb|gltf|fbx|bvh),
 *                   'max-influences': 4, betas: '0.5,-1', preset: 'web', quiet: true, ... }.
 *                 true gives a flag, false/null omit it, an array repeats it.
 * @param io       { stdout(line), stderr(line) }: each printed line as it is printed
 *                 (the summary, notes, warnings); default: kept in the result only.
 * @returns Promise<{ output: the out name, files: {name: Uint8Array} (the output,
 *          its .smpl.json sidecar, a .gltf's .bin), stdout: string, stderr: string,
 *          exitCode: 0, memoryBytes: the instance's WebAssembly memory at the end
 *          (its peak: it only grows) }>.
 * @throws Error whose message is the command line's one-line error, with
 *          .exitCode (1 usage, 2 cannot load input, 3 cannot export, 4 cannot write
 *          output, as the CLI) and .stderr; no files.
 */
export async function exportAsset(files, options = {}, io = {}) {
  if (!files || typeof files !== 'object') throw new TypeError('exportAsset: files must be an object');
  if (files.model === undefined) throw new Error('exportAsset: files.model is required (a model file or \'builtin\')');
  const out = options.out === undefined ? 'body.glb' : plainName(options.out, 'out');
  const inputs = [];  // [key, name, bytes]
  for (const [key, value] of Object.entries(files)) {
    if (!FILE_OPTIONS.includes(key)) throw new Error(`exportAsset: files.${key}: not an input (${FILE_OPTIONS.join(', ')})`);
    if (key === 'model' && value === 'builtin') continue;
    const list = Array.isArray(value) ? value : [value];
    if (list.length > 1 && !REPEATABLE.has(key) && key !== 'uv') {
      throw new Error(`exportAsset: files.${key}: one file only`);
    }
    for (let i = 0; i < list.length; i++) {
      const { name, bytes } = await readInput(list[i], key, i);
      inputs.push([key, plainName(name, key), bytes]);
    }
  }
  const args = [];
  if (files.model === 'builtin') args.push('--model', 'builtin');
  const seen = new Set();
  for (const [key, name] of inputs) {
    const path = `${IN_DIR}/${key}/${name}`;
    if (seen.has(path)) throw new Error(`exportAsset: files.${key}: two files named ${name}`);
    // uv: the first file names the option; a .npy pair's partner is found beside it.
    if (key !== 'uv' || !args.includes('--uv')) args.push(`--${key}`, path);
    seen.add(path);
  }
  args.push('--out', out, ...optionArgs(options));  // relative to OUT_DIR, the working folder

  const stdout = [], stderr = [];
  const module = await wasmModule();
  const Module = await createSmplExport({
    thisProgram: 'smpl-export',
    noInitialRun: true,
    print: (line) => { stdout.push(line); io.stdout?.(line); },
    printErr: (line) => { stderr.push(line); io.stderr?.(line); },
    quit: (status, toThrow) => { throw toThrow; },  // never node's process.exit
    instantiateWasm: (imports, receive) => {
      WebAssembly.instantiate(module, imports).then((instance) => receive(instance, module));
      return {};
    },
  });
  Module.FS.mkdir(IN_DIR);
  Module.FS.mkdir(OUT_DIR);
  for (const key of new Set(inputs.map(([k]) => k))) Module.FS.mkdir(`${IN_DIR}/${key}`);
  for (const [key, name, bytes] of inputs) Module.FS.writeFile(`${IN_DIR}/${key}/${name}`, bytes);
  Module.FS.chdir(OUT_DIR);  // the summary names the output as given: "walk.glb: ..."
  const exitCode = Module.callMain(args);
  const memoryBytes = Module.HEAPU8.length;
  const result = { stdout: stdout.join('\n'), stderr: stderr.join('\n'), exitCode, memoryBytes };
  if (exitCode !== 0) {
    const line = [...stderr].reverse().find((l) => /error/i.test(l)) || stderr[stderr.length - 1] ||
                 `smpl-export exited with ${exitCode}`;
    const error = new Error(line.replace(new RegExp(`${IN_DIR}/[a-z-]+/`, 'g'), ''));
    Object.assign(error, result);
    throw error;
  }
  return { output: out, files: collect(Module.FS, OUT_DIR), ...result };
}

// The emscripten factory (smpl-export-web.mjs), imported lazily so that
// importing this file costs nothing until the first export.
let factory = null;
function emscriptenFactory() {
  factory ??= import('./smpl-export-web.mjs').then((m) => m.default);
  return factory;
}
async function createSmplExport(settings) {
  return (await emscriptenFactory())(settings);
}
