/*
 * The API reference (npm run docs, typedoc.config.mjs): TypeDoc builds it from the TSDoc comments
 * of the package's entries with no warning (treatWarningsAsErrors makes one fail the build), and
 * it documents the public names of `webphysics` and `webphysics/gpu` but not @internal ones.
 * Built into a temporary folder, not docs/api.
 */

import { spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readdirSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { repoRoot } from '../support/bundles';

let out = '';
let result: { status: number | null; output: string };

beforeAll(() => {
  out = mkdtempSync(path.join(tmpdir(), 'webphysics-docs-'));
  const run = spawnSync('npm', ['run', 'docs', '--', '--out', out], {
    cwd: repoRoot,
    encoding: 'utf8',
    env: { ...process.env, NO_COLOR: '1', FORCE_COLOR: '0' },
  });
  result = { status: run.status, output: `${run.stdout}\n${run.stderr}` };
}, 180_000);

afterAll(() => {
  if (out !== '') rmSync(out, { recursive: true, force: true });
});

/** The names a page of the reference links to, by their link text. */
function linkedNames(page: string): string[] {
  return [...readFileSync(path.join(out, page), 'utf8').matchAll(/<a href="[^"]*"[^>]*>([A-Za-z_$][\w$]*)<\/a>/g)].map((m) => m[1]);
}

describe('npm run docs', () => {
  it('builds the reference with no warning and no error', () => {
    expect(result.output).not.toMatch(/\[warning\]|\[error\]/);
    expect(result.status).toBe(0);
    expect(existsSync(path.join(out, 'index.html'))).toBe(true);
  });

  it('has a module per package entry, webphysics and webphysics/gpu', () => {
    const index = readFileSync(path.join(out, 'index.html'), 'utf8');
    expect(index).toContain('>webphysics<');
    expect(index).toContain('>webphysics/gpu<');
  });

  it("lists the engine's classes under webphysics: b2World documented as the class", () => {
    const names = linkedNames('modules/webphysics.html');
    for (const name of ['b2World', 'b2Body', 'b2PolygonShape', 'b2CircleShape', 'b2RevoluteJoint', 'b2Vec2', 'Box2D']) expect(names).toContain(name);
    expect(existsSync(path.join(out, 'classes/webphysics.b2World.html'))).toBe(true);
    const world = readFileSync(path.join(out, 'classes/webphysics.b2World.html'), 'utf8');
    for (const method of ['CreateBody', 'Step', 'SetBackend']) expect(world).toContain(`>${method}<`);
  });

  it('lists the GPU backend under webphysics/gpu, without its @internal parts', () => {
    const names = linkedNames('modules/webphysics_gpu.html');
    for (const name of ['WebGPUBackend', 'AutoBackend', 'GpuRenderer', 'requestGpu']) expect(names).toContain(name);
    for (const name of ['GpuPipeline', 'GpuWorld', 'GpuStepper', 'GpuSolver', 'GpuBroadPhase', 'GpuNarrowPhase', 'GpuProxySet'])
      expect(names).not.toContain(name);
    const classes = readdirSync(path.join(out, 'classes'));
    expect(classes).toContain('webphysics_gpu.WebGPUBackend.html');
    expect(classes.filter((file) => /\.Gpu(Pipeline|World|Stepper|Solver|BroadPhase|NarrowPhase|ProxySet)\.html$/.test(file))).toEqual([]);
  });
});
