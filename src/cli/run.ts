/*
 * `webphysics run [scene.json] [options]`: load a b2dJson scene, step it, print the time per step
 * and the final world's counts, and optionally write the final world as b2dJson.
 */

import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { b2dJsonRead } from '../io/b2dJsonRead';
import { b2dJsonError } from '../io/b2dJsonScene';
import type { b2dJsonScene } from '../io/b2dJsonScene';
import { b2dJsonWriteString } from '../io/b2dJsonWrite';
import { CliError, EXIT_USAGE } from './command';
import type { CliCommand, CliContext } from './command';
import { parseOptions } from './options';
import type { OptionSpec } from './options';
import { ProgressBar } from './progress';
import { percentile } from './stats';

/** The scene `webphysics run` loads when given none (in the package's scenes/ folder). */
export const DEFAULT_SCENE = 'scenes/pyramid.scene.json';
/** Steps run when --steps is not given: ten seconds at 60 Hz. */
export const DEFAULT_STEPS = 600;

const HELP = `usage: webphysics run [scene.json] [options]

Load a b2dJson scene (R.U.B.E. / b2dJson format), step it, and print the milliseconds per step
(median and 95th percentile), the bodies, the awake bodies and the contacts of the final world.
Without a scene file it runs the packaged ${DEFAULT_SCENE} (a 20-row pyramid of 210 boxes,
with sleeping off so every step solves the whole stack).
The step settings default to the scene's stepsPerSecond, velocityIterations and positionIterations.

options:
  --steps N                  steps to run (default ${DEFAULT_STEPS})
  --hz H                     steps per second: each step is 1/H seconds
  --velocity-iterations V    velocity iterations per step
  --position-iterations P    position iterations per step
  --out FILE                 write the final world to FILE as b2dJson (with the step settings used)
  -h, --help                 this text
`;

interface RunOptions {
  scenePath: string;
  steps: number;
  hz: number | undefined;
  velocityIterations: number | undefined;
  positionIterations: number | undefined;
  out: string | undefined;
}

function usageError(message: string): CliError {
  return new CliError(`${message} (see webphysics run --help)`, EXIT_USAGE);
}

/** A whole number in [min, 0x7fffffff], as given to option `name`. */
function parseInteger(name: string, text: string, min: number): number {
  const value = Number(text);
  if (!/^\s*[+-]?\d+\s*$/.test(text) || !Number.isSafeInteger(value) || value < min || value > 0x7fffffff) {
    throw usageError(`--${name} expects a whole number >= ${min}, got ${JSON.stringify(text)}`);
  }
  return value;
}

/** A finite number > 0, as given to option `name`. */
function parsePositive(name: string, text: string): number {
  const value = Number(text);
  if (text.trim() === '' || !Number.isFinite(value) || !(value > 0)) {
    throw usageError(`--${name} expects a number > 0, got ${JSON.stringify(text)}`);
  }
  return value;
}

const OPTIONS: readonly OptionSpec[] = [
  { name: 'steps', takesValue: true },
  { name: 'hz', takesValue: true },
  { name: 'velocity-iterations', takesValue: true },
  { name: 'position-iterations', takesValue: true },
  { name: 'out', takesValue: true },
  { name: 'help', takesValue: false, short: 'h' },
];

function parseRunArgs(args: string[], context: CliContext): RunOptions | null {
  const { values, positionals } = parseOptions(args, OPTIONS, 'see webphysics run --help');
  if (values.has('help')) return null;
  if (positionals.length > 1) {
    throw usageError(`expected one scene file, got ${positionals.length}: ${positionals.join(' ')}`);
  }
  const text = (name: string): string | undefined => values.get(name) as string | undefined;
  const steps = text('steps');
  const hz = text('hz');
  const velocityIterations = text('velocity-iterations');
  const positionIterations = text('position-iterations');
  const out = text('out');
  if (out === '') throw usageError('--out expects a file name');
  return {
    scenePath: positionals.length === 1 ? path.resolve(context.cwd, positionals[0]) : path.join(context.packageRoot, DEFAULT_SCENE),
    steps: steps === undefined ? DEFAULT_STEPS : parseInteger('steps', steps, 0),
    hz: hz === undefined ? undefined : parsePositive('hz', hz),
    velocityIterations: velocityIterations === undefined ? undefined : parseInteger('velocity-iterations', velocityIterations, 0),
    positionIterations: positionIterations === undefined ? undefined : parseInteger('position-iterations', positionIterations, 0),
    out: out === undefined ? undefined : path.resolve(context.cwd, out),
  };
}

/** The reason a file system call failed, in a few words. */
function describeFsError(e: unknown): string {
  const code = (e as { code?: unknown }).code;
  switch (code) {
    case 'ENOENT':
      return 'no such file';
    case 'EISDIR':
      return 'it is a folder';
    case 'EACCES':
    case 'EPERM':
      return 'permission denied';
    default:
      return e instanceof Error ? e.message : String(e);
  }
}

/**
 * What makes a JSON object a b2dJson scene: its `body` array or one of the world's fields. b2dJson
 * gives every field a default, so any other JSON object (a package.json, a settings file) would
 * otherwise load as an empty world and run.
 */
const kSceneKeys = [
  'body',
  'gravity',
  'allowSleep',
  'autoClearForces',
  'continuousPhysics',
  'subStepping',
  'warmStarting',
  'stepsPerSecond',
  'velocityIterations',
  'positionIterations',
] as const;

function loadScene(scenePath: string): b2dJsonScene {
  let text: string;
  try {
    text = readFileSync(scenePath, 'utf8');
  } catch (e) {
    throw new CliError(`cannot read scene ${scenePath}: ${describeFsError(e)}`);
  }
  // b2dJsonRead reports where text that is not JSON breaks, so such text goes to it as it is.
  let document: unknown;
  try {
    document = JSON.parse(text);
  } catch {
    document = text;
  }
  if (typeof document === 'object' && document !== null && !Array.isArray(document) && !kSceneKeys.some((key) => key in document)) {
    throw new CliError(
      `${scenePath}: not a b2dJson scene: a scene has a "body" array or the world's fields (${kSceneKeys.slice(1).join(', ')}), and this JSON has none of them`,
    );
  }
  try {
    return b2dJsonRead(document);
  } catch (e) {
    if (e instanceof b2dJsonError) {
      throw new CliError(`${scenePath}: ${e.message}`);
    }
    throw e;
  }
}

function formatMs(ms: number): string {
  return ms.toFixed(3);
}

function runScene(options: RunOptions, context: CliContext): number {
  const scene = loadScene(options.scenePath);
  const world = scene.world;
  const settings = scene.stepSettings;
  if (options.hz !== undefined) settings.stepsPerSecond = options.hz;
  if (options.velocityIterations !== undefined) settings.velocityIterations = options.velocityIterations;
  if (options.positionIterations !== undefined) settings.positionIterations = options.positionIterations;

  const dt = 1 / settings.stepsPerSecond;
  const velocityIterations = settings.velocityIterations;
  const positionIterations = settings.positionIterations;
  const steps = options.steps;
  const times = new Float64Array(steps);
  const progress = context.stdout.isTTY ? new ProgressBar(context.stdout, steps) : null;

  for (let i = 0; i < steps; ++i) {
    const start = performance.now();
    world.Step(dt, velocityIterations, positionIterations);
    times[i] = performance.now() - start;
    progress?.update(i + 1);
  }
  progress?.done();

  let awake = 0;
  for (let b = world.GetBodyList(); b !== null; b = b.GetNext()) {
    if (b.IsAwake()) ++awake;
  }
  let touching = 0;
  for (let c = world.GetContactList(); c !== null; c = c.GetNext()) {
    if (c.IsTouching()) ++touching;
  }

  if (options.out !== undefined) {
    try {
      writeFileSync(options.out, b2dJsonWriteString(scene, 2) + '\n');
    } catch (e) {
      throw new CliError(`cannot write ${options.out}: ${describeFsError(e)}`);
    }
  }

  let total = 0;
  for (let i = 0; i < steps; ++i) total += times[i];
  const sorted = times.slice().sort();
  const median = formatMs(percentile(sorted, 0.5));
  const p95 = formatMs(percentile(sorted, 0.95));
  const timing = steps === 0 ? 'no steps run' : `median ${median}  p95 ${p95}  total ${total.toFixed(1)} ms`;
  const iterations = `${velocityIterations} velocity / ${positionIterations} position iterations`;
  const lines = [
    `scene     ${options.scenePath}`,
    `steps     ${steps} at ${settings.stepsPerSecond} Hz, ${iterations}`,
    `ms/step   ${timing}`,
    `bodies    ${world.GetBodyCount()}`,
    `awake     ${awake}`,
    `contacts  ${world.GetContactCount()} (${touching} touching)`,
  ];
  if (options.out !== undefined) lines.push(`wrote     ${options.out}`);
  context.stdout.write(lines.join('\n') + '\n');
  return 0;
}

export const runCommand: CliCommand = {
  name: 'run',
  summary: 'step a b2dJson scene and report the time per step',
  help: HELP,
  run(args, context) {
    const options = parseRunArgs(args, context);
    if (options === null) {
      context.stdout.write(HELP);
      return 0;
    }
    return runScene(options, context);
  },
};
