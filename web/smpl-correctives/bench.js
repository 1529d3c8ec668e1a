// Cost of Correctives.update() on synthetic SMPL (24 joints, 207 targets) and
// SMPL-X (55 joints, 486 targets) rigs: microseconds per update, the heap
// growth and the garbage collections during the timed updates (update() must
// allocate nothing, so neither grows).
//
//   node web/smpl-correctives/bench.js [updates]      (npm run bench in web/)
//
// Exits 1 if, in every one of three rounds, a garbage collection ran or the
// heap grew by 4 bytes or more per update (the smallest V8 allocation, a heap
// number, is 12 bytes; what remains is JIT noise).
import { PerformanceObserver } from 'node:perf_hooks';
import v8 from 'node:v8';
import vm from 'node:vm';

import * as THREE from 'three';

import { bindCorrectives } from './index.js';
import { buildRig } from './synthetic-rig.js';

v8.setFlagsFromString('--expose-gc');
const gc = vm.runInNewContext('gc');
const updates = Number(process.argv[2] || 100000);

let collections = 0;
new PerformanceObserver((list) => { collections += list.getEntries().length; }).observe({ entryTypes: ['gc'] });
const settle = () => new Promise((resolve) => setTimeout(resolve, 50));  // gc entries arrive asynchronously

async function bench(kind) {
  const rig = buildRig(THREE, kind);
  rig.bones.forEach((b, k) => b.quaternion.setFromAxisAngle(new THREE.Vector3(1, 2, 3).normalize(), 0.01 * k));
  const correctives = bindCorrectives(rig.root, rig.metadata);
  for (let i = 0; i < 20000; i++) correctives.update();  // warm up the JIT
  // Three timed rounds: the fastest time, the smallest heap growth (a GC-free
  // allocation would show in every round; JIT noise does not).
  let best = Infinity, growth = Infinity, fewestCollections = Infinity;
  for (let round = 0; round < 3; round++) {
    gc();
    await settle();
    const collectionsBefore = collections;
    const heapBefore = process.memoryUsage().heapUsed;
    const start = process.hrtime.bigint();
    for (let i = 0; i < updates; i++) correctives.update();
    const elapsed = Number(process.hrtime.bigint() - start) / 1e3;  // microseconds
    growth = Math.min(growth, (process.memoryUsage().heapUsed - heapBefore) / updates);
    best = Math.min(best, elapsed / updates);
    await settle();
    fewestCollections = Math.min(fewestCollections, collections - collectionsBefore);
  }
  console.log(`${kind}: ${rig.names.length} joints, ${correctives.weights.length} targets: ` +
              `${best.toFixed(2)} us/update (best of 3 x ${updates}), heap growth ${growth.toFixed(3)} bytes/update, ${fewestCollections} garbage collections`);
  return growth >= 4 || fewestCollections > 0;
}

let failed = false;
for (const kind of ['smpl', 'smplx']) {
  if (await bench(kind)) {
    console.error(`${kind}: update() allocates (garbage collections or heap growth in every round of ${updates} updates)`);
    failed = true;
  }
}
process.exit(failed ? 1 : 0);
