/*
 * `webphysics bench [options]`: the benchmark suite (bench/run.mjs, the same as `npm run bench`).
 * The suite measures WebPhysics against peer engines that are dev dependencies, so it runs from a
 * checkout after `npm ci`; the published package has no bench/ and says so.
 */

import { existsSync } from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { CliError, EXIT_FAILURE } from './command';
import type { CliCommand, CliContext } from './command';

const HELP = `usage: webphysics bench [options]

Run the benchmark suite: WebPhysics against planck, @box2d/core, Box2DWeb 2.1a, box2d-wasm,
box2d3-wasm, phaser-box2d, Rapier and matter-js on six scenes, in one process. The same as
\`npm run bench -- [options]\`; it needs a checkout of the repository with its dev dependencies
(\`npm ci\`). \`webphysics bench --help\` in a checkout lists every option; the common ones:

  --scenes a,b      bench2d, large-pyramid, many-pyramids, mixed-rain, joint-grid, tumbler
  --engines a,b     the engines to run (webphysics always first)
  --sleep on|off|both
  --quick           small scenes, a few steps, print only
  --out DIR         where the JSON and SVG results go (default bench/results)
`;

/** The suite's entry point, bench/run.mjs's main(argv) resolving to an exit code. */
type BenchMain = (argv: string[]) => Promise<number>;

async function loadBench(context: CliContext): Promise<BenchMain> {
  const runner = path.join(context.packageRoot, 'bench', 'run.mjs');
  if (!existsSync(runner)) {
    throw new CliError('the benchmark suite is not part of the published package: run it from a checkout of the repository after `npm ci`', EXIT_FAILURE);
  }
  const module = (await import(pathToFileURL(runner).href)) as { main: BenchMain };
  return module.main;
}

export const benchCommand: CliCommand = {
  name: 'bench',
  summary: 'benchmark WebPhysics against peer engines (from a checkout)',
  help: HELP,
  async run(args: string[], context: CliContext): Promise<number> {
    const main = await loadBench(context);
    return main(args);
  },
};
