import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { main } from '../../src/cli/main';
import { b2dJsonRead } from '../../src/io/b2dJsonRead';

/*
 * The command line in-process (test/cli spawns it as users run it): bad command lines and bad
 * scene files give one clear line on stderr and the right exit code, never a stack trace.
 */

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
let tmp = '';

beforeAll(() => {
  tmp = mkdtempSync(path.join(tmpdir(), 'webphysics-cli-inprocess-'));
});

afterAll(() => {
  rmSync(tmp, { recursive: true, force: true });
});

async function cli(args: string[]): Promise<{ code: number; out: string; err: string }> {
  let out = '';
  let err = '';
  const code = await main(args, {
    stdout: { write: (text: string) => (out += text), isTTY: false },
    stderr: { write: (text: string) => (err += text) },
    cwd: tmp,
    packageRoot: repoRoot,
  });
  return { code, out, err };
}

function scene(name: string, document: unknown): string {
  const file = path.join(tmp, name);
  writeFileSync(file, typeof document === 'string' ? document : JSON.stringify(document));
  return name;
}

describe('webphysics command line, in-process', () => {
  it('prints the overview, a command help and the version', async () => {
    const overview = await cli([]);
    expect(overview.code).toBe(0);
    expect(overview.out).toMatch(/^usage: webphysics <command>/);
    expect((await cli(['--help'])).out).toBe(overview.out);
    expect((await cli(['help'])).out).toBe(overview.out);
    const help = await cli(['help', 'run']);
    expect(help.out).toMatch(/^usage: webphysics run/);
    expect((await cli(['run', '--help'])).out).toBe(help.out);
    const version = await cli(['--version']);
    expect(version.out).toBe(`${JSON.parse(readFileSync(path.join(repoRoot, 'package.json'), 'utf8')).version}\n`);
  });

  const usage: [string, string[], RegExp][] = [
    ['an unknown command', ['fly'], /^webphysics: unknown command "fly" \(see webphysics --help\)\n$/],
    ['an unknown option before the command', ['--fast'], /^webphysics: unknown option --fast/],
    ['help on an unknown command', ['help', 'fly'], /unknown command "fly"/],
    ['an unknown run option', ['run', '--fast'], /^webphysics run: unknown option --fast \(see webphysics run --help\)\n$/],
    ['a short option with a value', ['run', '-h=1'], /unknown option -h=1/],
    ['a flag given a value', ['run', '--help=yes'], /--help takes no value/],
    ['an option without its value', ['run', '--steps'], /--steps needs a value/],
    ['negative steps', ['run', '--steps', '-1'], /--steps expects a whole number >= 0, got "-1"/],
    ['fractional steps', ['run', '--steps=2.5'], /--steps expects a whole number/],
    ['a zero rate', ['run', '--hz', '0'], /--hz expects a number > 0, got "0"/],
    ['a rate that is not a number', ['run', '--hz', 'fast'], /--hz expects a number > 0, got "fast"/],
    ['negative iterations', ['run', '--velocity-iterations', '-3'], /--velocity-iterations expects a whole number >= 0/],
    ['an empty output name', ['run', '--out='], /--out expects a file name/],
    ['two scene files', ['run', 'a.json', 'b.json'], /expected one scene file, got 2: a.json b.json/],
  ];
  for (const [what, args, message] of usage) {
    it(`rejects ${what} with exit code 2`, async () => {
      const run = await cli(args);
      expect(run.code).toBe(2);
      expect(run.out).toBe('');
      expect(run.err).toMatch(message);
      expect(run.err.trimEnd().split('\n')).toHaveLength(1);
    });
  }

  const failures: [string, () => string, RegExp][] = [
    ['a missing scene file', () => 'missing.json', /^webphysics run: cannot read scene .*missing\.json: /],
    ['a file that is not JSON', () => scene('broken.json', '{"body": ['), /broken\.json: \(root\): not valid JSON/],
    [
      'a scene breaking a rule',
      () => scene('concave.json', { body: [{ type: 2, fixture: [{ density: 1, polygon: { vertices: { x: [0, 2, 1, 2, 0], y: [0, 0, 0.5, 2, 2] } } }] }] }),
      /concave\.json: body\[0\]\.fixture\[0\]\.polygon\.vertices: rejected by b2PolygonShape\.Set: vertices\[2\] makes the polygon non-convex/,
    ],
    [
      'a joint breaking a rule',
      () =>
        scene('rope.json', {
          body: [{}, { type: 2, fixture: [{ density: 1, circle: { radius: 1 } }] }],
          joint: [{ type: 'rope', bodyA: 0, bodyB: 1, maxLength: -1 }],
        }),
      /rope\.json: joint\[0\]\.maxLength: expected a finite number >= 0, got -1/,
    ],
  ];
  for (const [what, file, message] of failures) {
    it(`reports ${what} in one line with exit code 1`, async () => {
      const run = await cli(['run', file(), '--steps', '5']);
      expect(run.code).toBe(1);
      expect(run.err).toMatch(message);
      expect(run.err.trimEnd().split('\n')).toHaveLength(1);
    });
  }

  it('runs a scene with overridden settings and writes it with --out', async () => {
    const file = scene('drop.json', {
      gravity: { x: 0, y: -10 },
      body: [
        { fixture: [{ edge: { vertex1: { x: -5, y: 0 }, vertex2: { x: 5, y: 0 } } }] },
        { type: 2, awake: true, position: { x: 0, y: 2 }, fixture: [{ density: 1, circle: { radius: 0.5 } }] },
      ],
    });
    const run = await cli(['run', file, '--steps', '30', '--hz=120', '--velocity-iterations', '6', '--position-iterations', '2', '--out', 'after.json']);
    expect(run.err).toBe('');
    expect(run.code).toBe(0);
    expect(run.out).toMatch(/^scene {5}.*drop\.json\nsteps {5}30 at 120 Hz, 6 velocity \/ 2 position iterations\n/);
    const written = b2dJsonRead(readFileSync(path.join(tmp, 'after.json'), 'utf8'));
    expect(written.stepSettings).toEqual({ stepsPerSecond: 120, velocityIterations: 6, positionIterations: 2 });
    expect(written.world.GetBodyCount()).toBe(2);
  });

  it('reports an unwritable --out path', async () => {
    const file = scene('tiny.json', { body: [{ type: 2, fixture: [{ density: 1, circle: { radius: 0.5 } }] }] });
    const run = await cli(['run', file, '--steps', '1', '--out', path.join(tmp, 'no-such-dir', 'x.json')]);
    expect(run.code).toBe(1);
    expect(run.err).toMatch(/^webphysics run: cannot write .*x\.json: /);
  });
});
