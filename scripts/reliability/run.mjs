#!/usr/bin/env node
// Runs the long reliability checks on the working tree's sources (bundled in memory with esbuild,
// as bin/webphysics.mjs does), under `node --expose-gc` so heap measurements follow a full GC:
//
//   node --expose-gc scripts/reliability/run.mjs soak [--steps 100000] [--seed 1] [--json]
//   node --expose-gc scripts/reliability/run.mjs leak [--cycles 10000] [--json]
//
// `npm run soak` runs the first. The leak check is what test/reliability/leak.test.ts spawns.
// Each prints a summary (or, with --json, one JSON report on stdout) and exits 1 if a check failed.
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const repoRoot = path.resolve(here, '../..');
process.env.WEBPHYSICS_GOLDEN ??= path.resolve(repoRoot, '../shared/golden');

/** Bundle a TypeScript entry into a temporary .mjs file (file: URLs keep stack traces short) and import it. */
async function loadTs(entry) {
  const esbuild = await import('esbuild');
  const dir = mkdtempSync(path.join(tmpdir(), 'webphysics-reliability-'));
  const outfile = path.join(dir, `${path.basename(entry, '.ts')}.mjs`);
  await esbuild.build({
    entryPoints: [entry],
    outfile,
    bundle: true,
    platform: 'node',
    format: 'esm',
    target: 'node20',
    sourcemap: 'inline',
    logLevel: 'silent',
  });
  try {
    return await import(pathToFileURL(outfile).href);
  } finally {
    rmSync(dir, { recursive: true, force: true });
  }
}

function option(args, name, fallback) {
  const i = args.indexOf(`--${name}`);
  return i >= 0 && i + 1 < args.length ? Number(args[i + 1]) : fallback;
}

const [command, ...args] = process.argv.slice(2);
const json = args.includes('--json');
const log = json ? () => {} : (line) => process.stderr.write(`${line}\n`);

if (typeof globalThis.gc !== 'function') {
  process.stderr.write('run with node --expose-gc (heap figures need a full collection)\n');
  process.exit(2);
}

let report;
if (command === 'soak') {
  const { runSoak } = await loadTs(path.join(here, 'soak.ts'));
  report = runSoak({ steps: option(args, 'steps', 100_000), seed: option(args, 'seed', 1), log });
} else if (command === 'leak') {
  const { runLeakChecks } = await loadTs(path.join(here, 'leak.ts'));
  report = await runLeakChecks({ cycles: option(args, 'cycles', 10_000), log });
} else {
  process.stderr.write('usage: node --expose-gc scripts/reliability/run.mjs soak|leak [--steps N | --cycles N] [--seed S] [--json]\n');
  process.exit(2);
}

if (json) process.stdout.write(`${JSON.stringify(report)}\n`);
else {
  for (const line of report.summary) process.stdout.write(`${line}\n`);
  for (const failure of report.failures) process.stdout.write(`FAILED: ${failure}\n`);
}
process.exitCode = report.failures.length === 0 ? 0 : 1;
