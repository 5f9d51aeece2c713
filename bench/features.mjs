#!/usr/bin/env node
// What the JavaScript engine pays for the features a scene may not need, measured instead of
// assumed: continuous physics (b2World.SolveTOI) in scenes without fast bodies, and sleeping
// turned off in scenes that come to rest. Each of the benchmark's scenes (bench/scenes.mjs) is
// stepped with Box2D's defaults (continuous physics on, sleeping on), with continuous physics off
// and with sleeping off, in one process, one configuration after another:
//   node bench/features.mjs [--scenes a,b] [--steps N] [--quick] [--out DIR] [--ours FILE]
// writes features.json and features.md into bench/results, or --out. For programs:
// measureFeatures(b2, options) resolves to the rows.

import { mkdirSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { parseArgs } from 'node:util';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { createBox2D221World } from './engines/box2d221.mjs';
import { makeScene, sceneStepper } from './scenes.mjs';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

/** The configurations: Box2D's defaults, then one feature changed each. */
export const FEATURE_CONFIGS = [
  { id: 'defaults', label: 'continuous physics and sleeping on (Box2D defaults)', continuous: true, sleep: true },
  { id: 'no-continuous', label: 'continuous physics off', continuous: false, sleep: true },
  { id: 'no-sleep', label: 'sleeping off', continuous: true, sleep: false },
];

/** The scenes by default: a pile coming to rest, bodies raining on the ground, a rotating box full of boxes. */
const SCENES = ['many-pyramids', 'mixed-rain', 'tumbler'];

/** Median of an array of numbers. */
function median(values) {
  const s = [...values].sort((a, b) => a - b);
  return s.length === 0 ? NaN : s[Math.floor(s.length / 2)];
}

/**
 * Scene `id` under each configuration: the median milliseconds of a step over the steps after the
 * first `settle` (the pile comes to rest, the rain lands), and how many bodies are awake at the end.
 */
async function measureScene(b2, id, { steps, settle, quick }) {
  const scene = makeScene(id, { quick });
  if (scene === null) return null;
  const out = { scene: id, title: scene.title, bodies: scene.bodies.length, configs: [] };
  // Untimed: the scene's code paths compiled before the first configuration is timed.
  const warm = sceneStepper(createBox2D221World(b2, scene, { sleep: true }), scene);
  for (let i = 0; i < settle; ++i) warm.step();
  for (const config of FEATURE_CONFIGS) {
    const built = createBox2D221World(b2, scene, { sleep: config.sleep });
    built.world.SetContinuousPhysics(config.continuous);
    const stepper = sceneStepper(built, scene);
    const times = [];
    for (let i = 0; i < settle + steps; ++i) {
      const t0 = performance.now();
      stepper.step();
      if (i >= settle) times.push(performance.now() - t0);
    }
    let awake = 0;
    for (let b = built.world.GetBodyList(); b !== null; b = b.GetNext()) if (b.GetType() !== b2.b2_staticBody && b.IsAwake()) awake++;
    out.configs.push({ id: config.id, ms: median(times), awake, bodies: built.world.GetBodyCount() });
  }
  return out;
}

/** Every scene's rows (see measureScene); `quick` builds them small and steps them less. */
export async function measureFeatures(b2, options = {}) {
  const quick = options.quick === true;
  const steps = options.steps ?? (quick ? 20 : 240);
  const settle = options.settle ?? (quick ? 20 : 240);
  const rows = [];
  for (const id of options.scenes ?? SCENES) {
    const row = await measureScene(b2, id, { steps, settle, quick });
    if (row !== null) rows.push(row);
    options.log?.(row === null ? `${id}: its data is missing` : `${id}: ${row.configs.map((c) => `${c.id} ${c.ms.toFixed(3)} ms`).join(', ')}`);
  }
  const cpus = os.cpus();
  return {
    date: new Date().toISOString(),
    quick,
    steps,
    settle,
    machine: { cpus: cpus.length, cpuModel: cpus[0]?.model ?? 'unknown', node: process.version },
    rows,
  };
}

const fmt = (v) => (v >= 10 ? v.toFixed(1) : v >= 1 ? v.toFixed(2) : v.toFixed(3));

/** The rows as a Markdown table: each configuration's step time and its ratio to the defaults'. */
export function featuresMarkdown(run) {
  const lines = [
    "# The JavaScript engine's features: what each costs",
    '',
    `Node ${run.machine.node}, ${run.machine.cpus} x ${run.machine.cpuModel}, ${run.date}${run.quick ? ' (quick)' : ''}. Median ms a step over ${run.steps} steps after the first ${run.settle}; awake bodies at the end.`,
    '',
    `| scene | bodies | ${FEATURE_CONFIGS.map((c) => c.label).join(' | ')} |`,
    `| --- | ---: |${' ---: |'.repeat(FEATURE_CONFIGS.length)}`,
  ];
  for (const r of run.rows) {
    const base = r.configs[0].ms;
    const cells = r.configs.map((c, i) => `${fmt(c.ms)} ms${i === 0 ? '' : ` (${fmt(c.ms / base)}x)`}, ${c.awake} awake`);
    lines.push(`| ${r.title} | ${r.configs[0].bodies} | ${cells.join(' | ')} |`);
  }
  return lines.join('\n') + '\n';
}

async function main() {
  const { values } = parseArgs({
    options: {
      scenes: { type: 'string' },
      steps: { type: 'string' },
      quick: { type: 'boolean', default: false },
      out: { type: 'string' },
      ours: { type: 'string' },
    },
  });
  let bundle = values.ours;
  if (!bundle) {
    const { buildOurs } = await import('./harness.mjs');
    bundle = buildOurs((s) => process.stderr.write(s + '\n')).bundle;
  }
  const b2 = await import(pathToFileURL(path.resolve(bundle)).href);
  const steps = values.steps === undefined ? undefined : Number(values.steps);
  if (steps !== undefined && !(Number.isInteger(steps) && steps > 0)) throw new RangeError(`--steps must be a positive integer, got ${values.steps}`);
  const run = await measureFeatures(b2, { scenes: values.scenes?.split(','), steps, quick: values.quick, log: (s) => process.stderr.write(s + '\n') });
  const dir = values.out ?? path.join(repoRoot, 'bench', 'results');
  mkdirSync(dir, { recursive: true });
  writeFileSync(path.join(dir, 'features.json'), JSON.stringify(run, null, 2) + '\n');
  writeFileSync(path.join(dir, 'features.md'), featuresMarkdown(run));
  process.stdout.write(featuresMarkdown(run));
}

if (import.meta.url === pathToFileURL(process.argv[1] ?? '').href) {
  main().catch((e) => {
    process.stderr.write(`${e instanceof Error ? e.message : e}\n`);
    process.exit(1);
  });
}
