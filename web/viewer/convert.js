// The viewer's "convert" panel: a model file (or the built-in body) and
// optionally a motion are converted in this page by the WebAssembly build
// (convert-worker.mjs), the result is shown in the viewer and offered as a
// download. Nothing leaves the page: the worker fetches only the .wasm, once,
// when the page opens; the files are read in the browser.
const $ = (id) => document.getElementById(id);

/** Wire the panel; `show(files)` loads [output, sidecar] File objects into the viewer. */
export function setupConvert(show) {
  const worker = new Worker(new URL('./convert-worker.mjs', import.meta.url), { type: 'module' });
  const pending = new Map();
  let nextId = 1, url = null;
  const say = (text) => { $('conv-status').textContent = text; };
  worker.onmessage = ({ data }) => {
    if (data.ready) { $('conv-run').disabled = false; $('convert').dataset.state = 'ready'; say('ready'); return; }
    if (data.unavailable) { $('convert').dataset.state = 'unavailable'; say(data.unavailable); return; }
    const job = pending.get(data.id);
    if (!job) return;
    if (data.line !== undefined) { say(data.line); return; }
    pending.delete(data.id);
    if (data.error !== undefined) job.reject(Object.assign(new Error(data.error), { exitCode: data.exitCode }));
    else job.resolve(data.result);
  };
  const convert = (files, options) => new Promise((resolve, reject) => {
    const id = nextId++;
    pending.set(id, { resolve, reject });
    worker.postMessage({ id, files, options });
  });

  $('conv-builtin').addEventListener('change', (e) => { $('conv-model').disabled = e.target.checked; });
  $('conv-run').addEventListener('click', async () => {
    const model = $('conv-builtin').checked ? 'builtin' : $('conv-model').files[0];
    if (!model) { say('choose a model file (.npz or .pkl from the model\'s authors) or the built-in body'); return; }
    const files = { model };
    if ($('conv-motion').files[0]) files.motion = $('conv-motion').files[0];
    const stem = model === 'builtin' ? 'body' : model.name.replace(/\.[^.]*$/, '');
    const name = `${files.motion ? files.motion.name.replace(/\.[^.]*$/, '') : stem}.${$('conv-format').value}`;
    const options = { out: name, 'max-influences': $('conv-influences').value,
      'skin-weights': $('conv-skin').value, 'corrective-refit': $('conv-refit').checked ? 'on' : 'off' };
    if ($('conv-preset').value) options.preset = $('conv-preset').value;
    if ($('conv-betas').value.trim()) options.betas = $('conv-betas').value.trim();
    $('conv-run').disabled = true;
    $('conv-download').hidden = true;
    $('convert').dataset.state = 'running';
    const started = performance.now();
    try {
      const result = await convert(files, options);
      const output = new File([result.files[result.output]], result.output);
      const sidecar = result.files[`${result.output}.smpl.json`];
      await show(sidecar ? [output, new File([sidecar], `${result.output}.smpl.json`)] : [output]);
      if (url) URL.revokeObjectURL(url);
      url = URL.createObjectURL(output);
      Object.assign($('conv-download'), { href: url, download: result.output, hidden: false,
        textContent: `Download ${result.output} (${(output.size / 1e6).toFixed(2)} MB)` });
      $('convert').dataset.memory = String(result.memoryBytes);
      say(`${result.stdout.split('\n')[0]} (${((performance.now() - started) / 1000).toFixed(1)} s in this page, ` +
          `WebAssembly memory ${(result.memoryBytes / 2 ** 20).toFixed(0)} MiB)`);
      $('convert').dataset.state = 'done';
    } catch (e) {
      say(e.message);
      $('convert').dataset.state = 'failed';
    } finally {
      $('conv-run').disabled = false;
    }
  });
}
