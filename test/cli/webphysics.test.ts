/*
 * The `webphysics` command, spawned as a user runs it: from this checkout (bin/webphysics.mjs
 * bundles src/cli in memory) and from a published-package layout (bin/ and scenes/ beside a
 * built dist/, no src/). A golden scene run through it must land exactly on the C++ reference.
 */

import { execFileSync, spawnSync } from 'node:child_process';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { main } from '../../src/cli/main';
import { b2dJsonRead } from '../../src/io/b2dJsonRead';
import { goldenDir } from '../support/golden';
import { readTrajectory, stateDigest } from '../support/scene';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
let tmp = '';

beforeAll(() => {
  tmp = mkdtempSync(path.join(tmpdir(), 'webphysics-cli-'));
});

afterAll(() => {
  rmSync(tmp, { recursive: true, force: true });
});

interface Run {
  status: number | null;
  stdout: string;
  stderr: string;
}

function webphysics(args: string[], bin = path.join(repoRoot, 'bin/webphysics.mjs')): Run {
  const result = spawnSync(process.execPath, [bin, ...args], { cwd: tmp, encoding: 'utf8' });
  return { status: result.status, stdout: result.stdout, stderr: result.stderr };
}

/** The report's `name  value` lines as a map. */
function report(stdout: string): Map<string, string> {
  return new Map(
    stdout
      .trimEnd()
      .split('\n')
      .map((line) => [line.slice(0, 10).trim(), line.slice(10)]),
  );
}

const kNumber = String.raw`\d+\.\d{3}`;

describe('webphysics run', () => {
  it('runs the packaged pyramid for 600 steps when given no scene, and reports the time per step', () => {
    const run = webphysics(['run']);
    expect(run.stderr).toBe('');
    expect(run.status).toBe(0);
    const lines = report(run.stdout);
    expect([...lines.keys()]).toEqual(['scene', 'steps', 'ms/step', 'bodies', 'awake', 'contacts']);
    expect(lines.get('scene')).toBe(path.join(repoRoot, 'scenes/pyramid.scene.json'));
    expect(lines.get('steps')).toBe('600 at 60 Hz, 8 velocity / 3 position iterations');
    expect(lines.get('ms/step')).toMatch(new RegExp(`^median ${kNumber}  p95 ${kNumber}  total \\d+\\.\\d ms$`));
    expect(lines.get('bodies')).toBe('211');
    expect(lines.get('awake')).toBe('211');
    expect(lines.get('contacts')).toMatch(/^\d+ \(\d+ touching\)$/);
  });

  it('steps a golden scene exactly as the C++ reference, and --out writes that state as b2dJson', () => {
    const scene = path.join(goldenDir, 'scenes/bridge.scene.json');
    const trajectory = readTrajectory('bridge');
    const sample = trajectory.samples.find((s) => s.step === 300)!;
    const run = webphysics(['run', scene, '--steps', '300', '--out', 'bridge-300.json']);
    expect(run.stderr).toBe('');
    expect(run.status).toBe(0);
    const lines = report(run.stdout);
    const settings = b2dJsonRead(readFileSync(scene, 'utf8')).stepSettings;
    expect(lines.get('steps')).toBe(`300 at 60 Hz, ${settings.velocityIterations} velocity / ${settings.positionIterations} position iterations`);
    expect(settings.stepsPerSecond).toBe(60);
    expect(lines.get('bodies')).toBe(String(sample.bodies.length));
    expect(lines.get('awake')).toBe(String(sample.awake));
    expect(lines.get('contacts')).toBe(`${sample.contacts} (${sample.touching} touching)`);
    expect(lines.get('wrote')).toBe(path.join(tmp, 'bridge-300.json'));

    const written = b2dJsonRead(readFileSync(path.join(tmp, 'bridge-300.json'), 'utf8'));
    expect(stateDigest(written.bodies)).toBe(trajectory.digests[300]);
    expect(written.joints).toHaveLength(b2dJsonRead(readFileSync(scene, 'utf8')).joints.length);
  });

  it('--hz and the iteration options override the scene, and are written with the world', () => {
    const run = webphysics(['run', '--steps=20', '--hz', '120', '--velocity-iterations', '4', '--position-iterations=2', '--out', 'fast.json']);
    expect(run.status).toBe(0);
    expect(report(run.stdout).get('steps')).toBe('20 at 120 Hz, 4 velocity / 2 position iterations');
    const written = JSON.parse(readFileSync(path.join(tmp, 'fast.json'), 'utf8'));
    expect([written.stepsPerSecond, written.velocityIterations, written.positionIterations]).toEqual([120, 4, 2]);
    const reloaded = b2dJsonRead(written);
    expect(reloaded.world.GetBodyCount()).toBe(211);
    // Twenty steps of 1/120 s: the top box has started to fall.
    expect(reloaded.bodies[1].GetPosition().y).toBeLessThan(0.75);
  });

  it("runs a scene that has the world's fields and no bodies", () => {
    writeFileSync(path.join(tmp, 'world-only.json'), '{"gravity": {"x": 0, "y": -10}, "allowSleep": true}');
    const run = webphysics(['run', 'world-only.json', '--steps', '5']);
    expect(run.stderr).toBe('');
    expect(run.status).toBe(0);
    expect(report(run.stdout).get('bodies')).toBe('0');
  });

  it('--steps 0 only loads the scene (and can convert it)', () => {
    const run = webphysics(['run', '--steps', '0', '--out', 'copy.json']);
    expect(run.status).toBe(0);
    expect(report(run.stdout).get('ms/step')).toBe('no steps run');
    const copy = b2dJsonRead(readFileSync(path.join(tmp, 'copy.json'), 'utf8'));
    const original = b2dJsonRead(readFileSync(path.join(repoRoot, 'scenes/pyramid.scene.json'), 'utf8'));
    expect(stateDigest(copy.bodies)).toBe(stateDigest(original.bodies));
  });

  /** The refusal of a JSON file with neither bodies nor world fields, which would run an empty world. */
  const kNotAScene = (file: string) =>
    new RegExp(
      `^webphysics run: .*${file.replace('.', '\\.')}: not a b2dJson scene: a scene has a "body" array or the world's fields ` +
        String.raw`\(gravity, allowSleep, autoClearForces, continuousPhysics, subStepping, warmStarting, stepsPerSecond, velocityIterations, positionIterations\), and this JSON has none of them$`,
    );

  const errors: [string, string[], number, RegExp][] = [
    ['a missing scene file', ['run', 'missing.json'], 1, /^webphysics run: cannot read scene .*missing\.json: no such file$/],
    ['a folder as the scene', ['run', '.'], 1, /^webphysics run: cannot read scene .*: it is a folder$/],
    ['a file that is not JSON', ['run', 'bad.json'], 1, /^webphysics run: .*bad\.json: \(root\): not valid JSON \(.*\)$/],
    [
      'a scene with a bad field',
      ['run', 'bad-field.json'],
      1,
      /^webphysics run: .*bad-field\.json: body\[0\]\.type: expected an integer in \[0, 2\], got number 7$/,
    ],
    ['a JSON file that is not a scene', ['run', 'package.json'], 1, kNotAScene('package.json')],
    ['an empty JSON object', ['run', 'empty.json'], 1, kNotAScene('empty.json')],
    ['an unknown option', ['run', '--fast'], 2, /^webphysics run: unknown option --fast \(see webphysics run --help\)$/],
    ['a bad --steps', ['run', '--steps', 'ten'], 2, /^webphysics run: --steps expects a whole number >= 0, got "ten" \(see webphysics run --help\)$/],
    ['a negative --steps', ['run', '--steps', '-5'], 2, /^webphysics run: --steps expects a whole number >= 0, got "-5"/],
    ['a zero --hz', ['run', '--hz', '0'], 2, /^webphysics run: --hz expects a number > 0, got "0"/],
    ['a fractional --velocity-iterations', ['run', '--velocity-iterations', '2.5'], 2, /expects a whole number >= 0, got "2\.5"/],
    ['an option without its value', ['run', '--out'], 2, /^webphysics run: --out needs a value/],
    ['two scene files', ['run', 'a.json', 'b.json'], 2, /^webphysics run: expected one scene file, got 2: a\.json b\.json/],
    ['an unwritable --out', ['run', '--steps', '1', '--out', 'no/such/dir/out.json'], 1, /^webphysics run: cannot write .*out\.json: no such file$/],
    ['an unknown command', ['fly'], 2, /^webphysics: unknown command "fly" \(see webphysics --help\)$/],
    ['an unknown top-level option', ['--fly'], 2, /^webphysics: unknown option --fly \(see webphysics --help\)$/],
  ];

  for (const [what, args, status, message] of errors) {
    it(`reports ${what} in one line on stderr and exits with ${status}`, () => {
      writeFileSync(path.join(tmp, 'bad.json'), '{"body": [}');
      writeFileSync(path.join(tmp, 'bad-field.json'), '{"body": [{"type": 7}]}');
      writeFileSync(path.join(tmp, 'package.json'), '{"name": "app", "version": "1.0.0", "dependencies": {}}');
      writeFileSync(path.join(tmp, 'empty.json'), '{}');
      const run = webphysics(args);
      expect(run.status).toBe(status);
      expect(run.stdout).toBe('');
      expect(run.stderr.endsWith('\n')).toBe(true);
      expect(run.stderr.split('\n')).toHaveLength(2);
      expect(run.stderr.trimEnd()).toMatch(message);
    });
  }

  it('prints help for the command and for run, and the version', () => {
    const help = webphysics(['--help']);
    expect(help.status).toBe(0);
    expect(help.stdout).toMatch(/^usage: webphysics <command> \[arguments\]/);
    expect(help.stdout).toMatch(/\n {2}run {4}step a b2dJson scene/);
    expect(webphysics([]).stdout).toBe(help.stdout);
    expect(webphysics(['help']).stdout).toBe(help.stdout);
    const runHelp = webphysics(['run', '--help']);
    expect(runHelp.status).toBe(0);
    expect(runHelp.stdout).toMatch(/^usage: webphysics run \[scene\.json\] \[options\]/);
    for (const option of ['--steps N', '--hz H', '--velocity-iterations V', '--position-iterations P', '--out FILE']) {
      expect(runHelp.stdout).toContain(option);
    }
    expect(webphysics(['help', 'run']).stdout).toBe(runHelp.stdout);
    const version = webphysics(['--version']);
    expect(version.stdout).toBe(`${JSON.parse(readFileSync(path.join(repoRoot, 'package.json'), 'utf8')).version}\n`);
  });

  it('bench runs the benchmark suite (npm run bench) from the checkout', () => {
    const bench = webphysics(['bench', '--quick', '--scenes', 'bench2d', '--engines', 'webphysics,planck', '--sleep', 'off']);
    expect(bench.status).toBe(0);
    expect(bench.stdout).toMatch(/bench2d pyramid — sleeping off/);
    expect(bench.stdout).toMatch(/\nWebPhysics [^\n]* ok/);
    expect(bench.stdout).toMatch(/\nplanck [^\n]* ok/);
    expect(webphysics(['help', 'bench']).stdout).toMatch(/^usage: webphysics bench \[options\]/);
    expect(webphysics(['--help']).stdout).toMatch(/\n {2}bench {2}benchmark WebPhysics against peer engines/);
  });

  it('draws a progress bar when stdout is a terminal, and erases it before the report', async () => {
    let out = '';
    const code = await main(['run', '--steps', '50'], {
      stdout: { isTTY: true, write: (text: string) => (out += text) },
      stderr: { write: () => true },
      cwd: tmp,
      packageRoot: repoRoot,
    });
    expect(code).toBe(0);
    const [bar, rest] = out.split('\r\x1b[K');
    expect(bar.startsWith('\r[')).toBe(true);
    expect(bar).toContain('\r[##############################] 100% 50/50 steps');
    expect(bar.split('\r').length - 1).toBe(50);
    expect(rest.startsWith('scene     ')).toBe(true);
  });
});

describe('the published package layout', () => {
  it('runs the built dist/cli.mjs when there is no src/ folder', () => {
    const pkg = path.join(tmp, 'package');
    mkdirSync(pkg);
    for (const entry of ['bin', 'scenes', 'package.json']) {
      cpSync(path.join(repoRoot, entry), path.join(pkg, entry), { recursive: true });
    }
    execFileSync(process.execPath, [path.join(repoRoot, 'scripts/build.mjs'), path.join(pkg, 'dist')], { cwd: repoRoot });
    const bin = path.join(pkg, 'bin/webphysics.mjs');
    const run = webphysics(['run', '--steps', '30'], bin);
    expect(run.stderr).toBe('');
    expect(run.status).toBe(0);
    const lines = report(run.stdout);
    expect(lines.get('scene')).toBe(path.join(pkg, 'scenes/pyramid.scene.json'));
    expect(lines.get('bodies')).toBe('211');
    const fromSource = report(webphysics(['run', '--steps', '30']).stdout);
    expect(lines.get('contacts')).toBe(fromSource.get('contacts'));
    const missing = webphysics(['run', 'nothing.json'], bin);
    expect(missing.status).toBe(1);
    expect(missing.stderr).toMatch(/^webphysics run: cannot read scene .*nothing\.json: no such file\n$/);
    const bench = webphysics(['bench'], bin);
    expect(bench.status).toBe(1);
    expect(bench.stderr).toMatch(/^webphysics bench: the benchmark suite is not part of the published package: run it from a checkout/);
  });
});
