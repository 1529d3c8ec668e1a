// --pre-js of smpl-export-web.mjs (cli/CMakeLists.txt): emscripten 3.1.6's
// ES-module output reads __dirname when it runs in node, which an ES module
// does not have; this gives it the module's own folder (_scriptDir is
// emscripten's import.meta.url). In a browser or a
// worker it is unused.
var __dirname = (typeof process == 'object' && typeof process.versions == 'object' &&
                 typeof process.versions.node == 'string')
  ? decodeURIComponent(new URL('.', _scriptDir).pathname).replace(/\/$/, '')
  : '';
