// The viewer's "convert" panel runs smpl-export here, off the page's thread:
// the WebAssembly build's JS API (/smpl-export-wasm/index.mjs, served from the
// built npm package) on the File objects the page posts. Nothing is sent
// anywhere: the files are read in this worker and the outputs posted back.
//
// Messages in:  { id, files: {model: File|'builtin', motion?: File}, options }
// Messages out: { ready: true } | { unavailable: reason } once at start;
//               { id, line } per printed line; { id, result } | { id, error, exitCode }.
let api = null;
try {
  api = await import('../smpl-export-wasm/index.mjs');
  await api.preload();  // the .wasm is fetched and compiled now, before any file is chosen
  postMessage({ ready: true });
} catch (e) {
  api = null;
  postMessage({ unavailable: `the WebAssembly build is not there (${e.message || e}); ` +
                             'run scripts/build-wasm.sh, then serve this page again' });
}

self.onmessage = async ({ data: { id, files, options } }) => {
  if (!api) {
    postMessage({ id, error: 'the WebAssembly build is not available', exitCode: 1 });
    return;
  }
  try {
    const line = (text) => postMessage({ id, line: text });
    const result = await api.exportAsset(files, options, { stdout: line, stderr: line });
    const buffers = Object.values(result.files).map((b) => b.buffer);
    postMessage({ id, result }, buffers);
  } catch (e) {
    postMessage({ id, error: e.message, exitCode: e.exitCode ?? 1 });
  }
};
