#!/usr/bin/env node
// `npx smpl-export ...`: the WebAssembly build (../smpl-export.js + .wasm,
// made by scripts/build-wasm.sh) with the native command line; it reads and
// writes the machine's files directly (emscripten's NODERAWFS) and exits
// with the native exit codes.
require("../smpl-export.js");
