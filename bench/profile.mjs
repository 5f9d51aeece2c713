#!/usr/bin/env node
// Profiles one engine on one benchmark scene through node:inspector, no flags needed:
//   node bench/profile.mjs [--scene bench2d] [--engine webphysics] [--steps 300] [--preroll 64]
//                          [--sleep] [--top 25] [--alloc] [--out file.cpuprofile]
// Prints the functions with the most self time (CPU profile, sampled every 100 us) and, with
// --alloc, the functions that allocate the most bytes (V8's sampling heap profiler, counting objects
// a GC has already freed too). --out saves the .cpuprofile for Chrome DevTools or speedscope.
import { writeFileSync } from 'node:fs';
import { Session } from 'node:inspector/promises';
import { parseArgs } from 'node:util';
import { ENGINES, buildOurs } from './harness.mjs';
import { makeScene, sceneStepper } from './scenes.mjs';

const { values } = parseArgs({
  options: {
    scene: { type: 'string', default: 'bench2d' },
    engine: { type: 'string', default: 'webphysics' },
    steps: { type: 'string', default: '300' },
    preroll: { type: 'string', default: '64' },
    sleep: { type: 'boolean', default: false },
    top: { type: 'string', default: '25' },
    alloc: { type: 'boolean', default: false },
    out: { type: 'string' },
    ours: { type: 'string' },
  },
});

const engine = ENGINES.find((e) => e.id === values.engine);
if (!engine) throw new Error(`unknown engine ${values.engine}`);
const scene = makeScene(values.scene);
const built = engine.id === 'webphysics' && !values.ours ? buildOurs(() => {}) : null;
const api = await engine.load({ oursBundle: values.ours ?? built?.bundle });
const w = engine.create(api, scene, { sleep: values.sleep });
const { step } = sceneStepper(w, scene);
for (let i = 0; i < Number(values.preroll); i++) step();

const session = new Session();
session.connect();
const top = Number(values.top);
const steps = Number(values.steps);
const label = (f) => `${f.functionName || '(anonymous)'} ${f.url ? f.url.replace(/^.*\//, '') : ''}:${f.lineNumber + 1}`;

await session.post('Profiler.enable');
await session.post('Profiler.setSamplingInterval', { interval: 100 });
await session.post('Profiler.start');
const t0 = performance.now();
for (let i = 0; i < steps; i++) step();
const ms = performance.now() - t0;
const { profile } = await session.post('Profiler.stop');
if (values.out) writeFileSync(values.out, JSON.stringify(profile));

const self = new Map();
const dt = new Map();
for (let i = 0; i < profile.samples.length; i++) dt.set(i, profile.timeDeltas[i] ?? 0);
const byId = new Map(profile.nodes.map((n) => [n.id, n]));
const hits = new Map();
profile.samples.forEach((id, i) => hits.set(id, (hits.get(id) ?? 0) + (profile.timeDeltas[i + 1] ?? profile.timeDeltas[i] ?? 0)));
let total = 0;
for (const [id, us] of hits) {
  const key = label(byId.get(id).callFrame);
  self.set(key, (self.get(key) ?? 0) + us);
  total += us;
}
console.log(
  `${engine.name} on ${scene.title}, sleeping ${values.sleep ? 'on' : 'off'}: ${steps} steps in ${ms.toFixed(0)} ms (${(ms / steps).toFixed(2)} ms/step)`,
);
console.log(`top ${top} functions by self time:`);
for (const [k, us] of [...self].sort((a, b) => b[1] - a[1]).slice(0, top)) {
  console.log(`${((100 * us) / total).toFixed(1).padStart(6)}%  ${(us / 1000 / steps).toFixed(3).padStart(7)} ms/step  ${k}`);
}

if (values.alloc) {
  await session.post('HeapProfiler.enable');
  await session.post('HeapProfiler.startSampling', {
    samplingInterval: 1024,
    includeObjectsCollectedByMajorGC: true,
    includeObjectsCollectedByMinorGC: true,
  });
  for (let i = 0; i < steps; i++) step();
  const { profile: heap } = await session.post('HeapProfiler.stopSampling');
  const bytes = new Map();
  let sum = 0;
  const walk = (n) => {
    if (n.selfSize) {
      const key = label(n.callFrame);
      bytes.set(key, (bytes.get(key) ?? 0) + n.selfSize);
      sum += n.selfSize;
    }
    for (const c of n.children) walk(c);
  };
  walk(heap.head);
  console.log(`\nallocation (sampled): ${(sum / steps / 1024).toFixed(1)} KiB per step; top ${top} allocating functions:`);
  for (const [k, b] of [...bytes].sort((a, c) => c[1] - a[1]).slice(0, top)) {
    console.log(`${((100 * b) / sum).toFixed(1).padStart(6)}%  ${(b / steps / 1024).toFixed(1).padStart(8)} KiB/step  ${k}`);
  }
}
session.disconnect();
w.destroy();
