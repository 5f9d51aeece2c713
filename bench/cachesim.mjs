#!/usr/bin/env node
// Counts the instructions and cache misses of one engine's steps on one benchmark scene under
// valgrind's cache simulator, which unlike a timing does not move with the machine's load:
//   node bench/cachesim.mjs [--scene bench2d] [--engine webphysics] [--ours FILE] [--preroll 300]
//                           [--steps 200] [--ll BYTES] [--functions] [--top 25] [--sort ll|ir]
// It runs the scene twice under `valgrind --tool=cachegrind` (preroll steps, then preroll + steps)
// with V8 on one thread (--single-threaded: no background compiler or GC threads, so the two runs
// differ only by the measured steps) and prints the difference per step: instructions (Ir), first
// level data misses (D1) and last level data misses (LL, a BYTES cache, 4 MiB by default; the
// machine's own caches are shared with its neighbours). With --functions both are callgrind runs
// instead, and V8's code map (--perf-basic-prof) names the JavaScript functions and builtins the
// difference falls in, listed by last level read misses or (--sort ir) by instructions.
// Needs valgrind on the PATH (Debian: apt-get install valgrind); a step under valgrind takes about
// fifty times as long as without.
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { parseArgs } from 'node:util';
import { ENGINES, buildOurs } from './harness.mjs';
import { costsByCodeObject, eventTotals } from './valgrind.mjs';
import { makeScene, sceneStepper } from './scenes.mjs';

const { values } = parseArgs({
  options: {
    scene: { type: 'string', default: 'bench2d' },
    engine: { type: 'string', default: 'webphysics' },
    ours: { type: 'string' },
    preroll: { type: 'string', default: '300' },
    steps: { type: 'string', default: '200' },
    ll: { type: 'string', default: String(4 * 1024 * 1024) },
    functions: { type: 'boolean', default: false },
    top: { type: 'string', default: '25' },
    sort: { type: 'string', default: 'll' },
    child: { type: 'string' },
  },
});

const engine = ENGINES.find((e) => e.id === values.engine);
if (!engine) throw new Error(`unknown engine ${values.engine}`);

if (values.child !== undefined) {
  // Inside valgrind: build the scene and step it, nothing else.
  const scene = makeScene(values.scene);
  const api = await engine.load({ oursBundle: values.ours });
  const { step } = sceneStepper(engine.create(api, scene, { sleep: false }), scene);
  for (let i = 0; i < Number(values.child); i++) step();
  process.exit(0);
}

const preroll = Number(values.preroll);
const steps = Number(values.steps);
if (!(Number.isInteger(preroll) && preroll >= 0)) throw new Error('--preroll must be a whole number of steps');
if (!(Number.isInteger(steps) && steps > 0)) throw new Error('--steps must be a positive whole number of steps');
if (values.sort !== 'll' && values.sort !== 'ir') throw new Error(`--sort must be ll or ir, not ${values.sort}`);
const built = engine.id === 'webphysics' && !values.ours ? buildOurs(() => {}) : null;
const bundle = values.ours ?? built?.bundle;
const work = mkdtempSync(path.join(os.tmpdir(), 'webphysics-cachesim-'));
const self = fileURLToPath(import.meta.url);
const cacheArgs = ['--cache-sim=yes', `--LL=${values.ll},16,64`];

/** Runs the scene for `total` steps under the valgrind tool: its output file and the process id. */
function run(total, tool, extraNodeArgs = []) {
  const out = path.join(work, `${tool}-${total}.out`);
  const args = [
    `--tool=${tool}`,
    ...cacheArgs,
    ...(tool === 'callgrind' ? ['--dump-instr=yes', `--callgrind-out-file=${out}`] : [`--cachegrind-out-file=${out}`]),
    process.execPath,
    '--single-threaded',
    ...extraNodeArgs,
    self,
    '--scene',
    values.scene,
    '--engine',
    values.engine,
    ...(bundle ? ['--ours', bundle] : []),
    '--child',
    String(total),
  ];
  const r = spawnSync('valgrind', args, { stdio: ['ignore', 'ignore', 'pipe'], cwd: work, maxBuffer: 1 << 26 });
  if (r.error) throw new Error(`valgrind did not run (${r.error.message}); Debian: apt-get install valgrind`);
  if (r.status !== 0) throw new Error(`valgrind exited with ${r.status}:\n${r.stderr.toString().slice(-2000)}`);
  return { out, pid: r.pid };
}

const label = `${engine.name} on ${makeScene(values.scene).title}`;
console.log(`${label}: ${steps} steps after ${preroll} under valgrind (last level ${(Number(values.ll) / 2 ** 20).toFixed(1)} MiB)...`);
// Both runs under the same tool; callgrind (--functions) also records where each instruction ran.
const tool = values.functions ? 'callgrind' : 'cachegrind';
const nodeArgs = values.functions ? ['--perf-basic-prof', '--no-compact-code-space'] : [];
/** A run's event totals and, with --functions, its costs by code object (V8's /tmp/perf-<pid>.map). */
function measure(total) {
  const { out, pid } = run(total, tool, nodeArgs);
  const text = readFileSync(out, 'utf8');
  if (!values.functions) return { totals: eventTotals(text), byCode: null };
  const mapFile = `/tmp/perf-${pid}.map`;
  const byCode = costsByCodeObject(text, readFileSync(mapFile, 'utf8'));
  rmSync(mapFile, { force: true });
  return { totals: eventTotals(text), byCode };
}
const base = measure(preroll);
const measured = measure(preroll + steps);
const per = (event) => (measured.totals[event] - base.totals[event]) / steps;
console.log(
  `per step: Ir ${(per('Ir') / 1e6).toFixed(2)} M, D1 data misses ${((per('D1mr') + per('D1mw')) / 1e3).toFixed(1)} K ` +
    `(reads ${(per('D1mr') / 1e3).toFixed(1)} K), last level data misses ${((per('DLmr') + per('DLmw')) / 1e3).toFixed(1)} K ` +
    `(reads ${(per('DLmr') / 1e3).toFixed(1)} K)`,
);

if (base.byCode && measured.byCode) {
  // Per code object: the second run's costs less the first's (code objects match by name: the
  // function, its tier mark (* optimised, ^ baseline, ~ interpreted) and its source position).
  const { events, costs } = measured.byCode;
  const ir = events.indexOf('Ir');
  const d1 = events.indexOf('D1mr');
  const ll = events.indexOf('DLmr');
  const rows = [...costs].map(([name, v]) => {
    const b = base.byCode.costs.get(name) ?? [];
    return { name, ir: (v[ir] - (b[ir] ?? 0)) / steps, d1: (v[d1] - (b[d1] ?? 0)) / steps, ll: (v[ll] - (b[ll] ?? 0)) / steps };
  });
  const total = rows.reduce((sum, r) => sum + r.ll, 0);
  const by = values.sort;
  console.log(`\nper step by code object, most ${by === 'ir' ? 'instructions' : 'last level read misses'} first:`);
  console.log('  LL reads %   LL reads   D1 reads      Ir (K)  code');
  for (const r of rows.sort((x, y) => y[by] - x[by]).slice(0, Number(values.top))) {
    console.log(
      `${((100 * r.ll) / total).toFixed(1).padStart(11)}  ${r.ll.toFixed(0).padStart(9)}  ${r.d1.toFixed(0).padStart(9)}  ${(r.ir / 1e3).toFixed(0).padStart(10)}  ${r.name.slice(0, 100)}`,
    );
  }
}
rmSync(work, { recursive: true, force: true });
if (built) rmSync(built.dir, { recursive: true, force: true });
