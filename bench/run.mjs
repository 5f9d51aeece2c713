#!/usr/bin/env node
// `npm run bench` / `node bench/run.mjs [options]`: WebPhysics against the engines a web developer
// would pick instead, on the same scenes, in one process. See bench/README.md.
//
// For programs (the `webphysics bench` CLI subcommand): `runBench(options)` runs it and returns the
// results object; `main(argv)` is this command line (returns the exit code).
import { parseArgs } from 'node:util';
import { pathToFileURL } from 'node:url';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { runBench, SCENE_IDS, ENGINE_IDS, ENGINES, cpuCaches } from './harness.mjs';
import { worldHeapBytes } from './heap.mjs';
import { makeScene } from './scenes.mjs';
import { markdownSummary, compactSummary, describeCaches } from './report.mjs';
import { repoRoot } from './engines/common.mjs';

export { runBench, SCENE_IDS, ENGINE_IDS, cpuCaches, describeCaches, worldHeapBytes };

export const USAGE = `usage: node bench/run.mjs [options]   (npm run bench -- [options])

  --scenes a,b     scenes to run (default all): ${SCENE_IDS.join(', ')}
  --engines a,b    engines to run (default all): ${ENGINE_IDS.join(', ')}
  --sleep MODE     on, off or both (default both)
  --steps N        timed steps per round (default: per scene)
  --rounds N       rounds, each on a fresh world (default: per scene, 3)
  --preroll N      untimed steps before timing (default: per scene)
  --alloc-steps N  steps in the allocation-counting window (default: min(steps, 32))
  --alloc-preroll N  untimed steps between the timed rounds and that window (default 0)
  --quick          tiny protocol for smoke tests (prints only, unless --out is given)
  --out DIR        folder for the JSON and SVG files (default bench/results)
  --no-write       print the tables only
  --ours FILE      use this webphysics.mjs bundle instead of building the working tree
  --baseline FILE  also run this webphysics.mjs bundle (e.g. built from git HEAD) as the engine
                   webphysics-baseline, side by side with ours
  --json           print the results JSON to stdout (tables go to stderr)
  --list           list scenes and engines
  --markdown [F]   print README tables from results file F (default bench/results/latest.json)
  -h, --help       this text`;

/** Runs the command line `argv` (without node and script); resolves to the exit code. */
export async function main(argv = process.argv.slice(2)) {
  let values;
  let positionals;
  try {
    ({ values, positionals } = parseArgs({
      args: argv,
      allowPositionals: true,
      options: {
        scenes: { type: 'string' },
        engines: { type: 'string' },
        sleep: { type: 'string' },
        steps: { type: 'string' },
        rounds: { type: 'string' },
        preroll: { type: 'string' },
        'alloc-steps': { type: 'string' },
        'alloc-preroll': { type: 'string' },
        quick: { type: 'boolean' },
        out: { type: 'string' },
        'no-write': { type: 'boolean' },
        ours: { type: 'string' },
        baseline: { type: 'string' },
        json: { type: 'boolean' },
        list: { type: 'boolean' },
        markdown: { type: 'boolean' },
        help: { type: 'boolean', short: 'h' },
      },
    }));
  } catch (err) {
    process.stderr.write(`${err.message}\n${USAGE}\n`);
    return 2;
  }
  if (values.help) {
    process.stdout.write(USAGE + '\n');
    return 0;
  }
  if (positionals.length && !values.markdown) {
    process.stderr.write(`unexpected argument ${positionals[0]}\n${USAGE}\n`);
    return 2;
  }
  if (values.markdown) {
    const file = positionals[0] ?? path.join(repoRoot, 'bench', 'results', 'latest.json');
    const run = JSON.parse(readFileSync(file, 'utf8'));
    const compact = [false, true].map((sleep) => `Sleeping ${sleep ? 'on' : 'off'}: best-round median ms per step (x ours)\n\n${compactSummary(run, sleep)}`);
    process.stdout.write(`${compact.join('\n\n')}\n\n${markdownSummary(run)}\n`);
    return 0;
  }
  if (values.list) {
    for (const id of SCENE_IDS) {
      const s = makeScene(id);
      process.stdout.write(`scene  ${id.padEnd(14)} ${s ? s.description : '(data file missing)'}\n`);
    }
    for (const e of ENGINES) process.stdout.write(`engine ${e.id.padEnd(14)} ${e.name} ${e.version ?? ''} — ${e.family}\n`);
    return 0;
  }
  const int = (v, name) => {
    if (v === undefined) return undefined;
    const n = Number(v);
    if (!Number.isInteger(n) || n < 1) throw new Error(`--${name} must be a positive integer`);
    return n;
  };
  try {
    const out = await runBench({
      scenes: values.scenes,
      engines: values.engines,
      sleep: values.sleep,
      steps: int(values.steps, 'steps'),
      rounds: int(values.rounds, 'rounds'),
      preroll: values.preroll === '0' ? 0 : int(values.preroll, 'preroll'),
      allocSteps: int(values['alloc-steps'], 'alloc-steps'),
      allocPreroll: values['alloc-preroll'] === '0' ? 0 : int(values['alloc-preroll'], 'alloc-preroll'),
      quick: values.quick,
      outDir: values.out,
      write: values['no-write'] ? false : undefined,
      ours: values.ours,
      baseline: values.baseline,
      print: values.json ? (s) => process.stderr.write(s + '\n') : undefined,
    });
    if (values.json) process.stdout.write(JSON.stringify(out, null, 1) + '\n');
    const failed = out.scenes.flatMap((s) => s.results ?? []).filter((r) => r.status === 'error' || (r.check && !r.check.ok));
    return failed.length ? 1 : 0;
  } catch (err) {
    process.stderr.write(`${err.stack ?? err}\n`);
    return 2;
  }
}

if (process.argv[1] && import.meta.url === pathToFileURL(process.argv[1]).href) {
  process.exitCode = await main();
}
