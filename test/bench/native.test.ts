// The native reference (bench/native.mjs, bench/native/scene.cpp): the float64 rewrite of Box2D's
// source, the scenes as the C++ runner's records, and the checks on --box2d. Building and running
// the runner needs Box2D 2.2.1's C++ source, which this package does not ship: set
// WEBPHYSICS_BOX2D to a checkout to run that test too.
import { mkdirSync, mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { afterAll, describe, expect, it } from 'vitest';
import { box2dIncludeDir, float64Source, nativeSceneText } from '../../bench/native.mjs';
import { resolveProcessesOptions, runProcesses } from '../../bench/processes.mjs';
import { makeScene } from '../../bench/scenes.mjs';
import type { Scene } from '../../bench/scenes.mjs';

const temp = mkdtempSync(path.join(os.tmpdir(), 'webphysics-native-test-'));
afterAll(() => rmSync(temp, { recursive: true, force: true }));

function scene(id: string): Scene {
  const s = makeScene(id, { quick: true });
  if (!s) throw new Error(`scene ${id} has no data`);
  return s;
}

function lines(id: string, steps: number): string[] {
  return nativeSceneText(scene(id), steps).trimEnd().split('\n');
}

describe('float64Source', () => {
  it('makes float32 a double and every f-suffixed literal the double it spells', () => {
    expect(float64Source('typedef float float32;\n#define b2_pi 3.14159265359f\n')).toBe('typedef double float32;\n#define b2_pi 3.14159265359\n');
    expect(float64Source('x = 0.5f * y + .25f - 1e-3f + 2.f + 10.0f;')).toBe('x = 0.5 * y + .25 - 1e-3 + 2. + 10.0;');
    expect(float64Source('b2Vec2(0.0f, -10.0f)')).toBe('b2Vec2(0.0, -10.0)');
  });

  it("computes b2Rot's sine and cosine in double, and leaves names ending in f alone", () => {
    expect(float64Source('s = sinf(angle); c = cosf(angle);')).toBe('s = sin(angle); c = cos(angle);');
    expect(float64Source('b2Vec2 v1f = m_v1f; float32 halfF = 1;')).toBe('b2Vec2 v1f = m_v1f; float32 halfF = 1;');
  });
});

describe('nativeSceneText', () => {
  it('writes the world, then each body followed by its shapes with their materials, in creation order', () => {
    const t = lines('bench2d', 40);
    expect(t[0]).toBe(`world 0 -10 ${1 / 60} 3 3`);
    expect(t.slice(1, 5)).toEqual([
      'body 0 0 0 0 0 0 0 0 1',
      'edge -40 0 40 0 0 0.2 0 1 65535',
      'body 2 -7 0.75 0 0 0 0 0 1',
      'box 0.5 0.5 0 0 0 5 0.2 0 1 65535',
    ]);
    expect(t.filter((l) => l.startsWith('body ')).length).toBe(211);
  });

  it('writes revolute joints after the bodies, with their motor, and the spawned bodies after the step that spawns them', () => {
    const t = lines('tumbler', 40);
    const joint = t.findIndex((l) => l.startsWith('revolute '));
    expect(t[joint]).toBe('revolute 0 1 0 10 0 0 0 0 1 0.1570796326795 100000000');
    expect(t.slice(0, joint).filter((l) => l.startsWith('body ')).length).toBe(2);
    expect(t[joint + 1]).toBe('spawn 1');
    const spawns = t.filter((l) => l.startsWith('spawn '));
    expect(spawns).toEqual(Array.from({ length: 12 }, (_, i) => `spawn ${i + 1}`));
    expect(t.filter((l) => l.startsWith('body ')).length).toBe(2 + 96);
    // Only the spawns up to the run's last step are written.
    expect(lines('tumbler', 5).filter((l) => l.startsWith('spawn ')).length).toBe(5);

    const grid = lines('joint-grid', 40);
    expect(grid.filter((l) => l.startsWith('revolute ')).length).toBe(2 * 20 * 19);
    expect(grid[2]).toBe('circle 0.4 0 0 1 0.2 0 2 65533');
  });

  it('writes chains with their loop flag, points and neighbour vertices', () => {
    const s = scene('bench2d');
    const ground = s.bodies[0];
    s.bodies = [
      {
        ...ground,
        shapes: [
          {
            ...ground.shapes[0],
            kind: 'chain',
            vertices: [
              [0, 0],
              [1, 0],
              [2, 1],
            ],
            loop: false,
            prev: [-1, 0],
            next: null,
          },
          {
            ...ground.shapes[0],
            kind: 'polygon',
            vertices: [
              [0, 0],
              [1, 0],
              [0, 1],
            ],
          },
        ],
      },
    ];
    const t = nativeSceneText(s, 10).trimEnd().split('\n');
    expect(t.slice(2)).toEqual(['chain 0 3 0 0 1 0 2 1 1 -1 0 0 0 0 0 0.2 0 1 65535', 'polygon 3 0 0 1 0 0 1 0 0.2 0 1 65535']);
  });

  it('rejects a shape or joint kind the runner cannot build, by name', () => {
    const s = scene('bench2d');
    s.bodies[0].shapes[0] = { ...s.bodies[0].shapes[0], kind: 'capsule' as 'box' };
    expect(() => nativeSceneText(s, 10)).toThrow('shape kind "capsule" has no native record');
    const grid = scene('joint-grid');
    grid.joints[0].kind = 'weld';
    expect(() => nativeSceneText(grid, 10)).toThrow('joint kind "weld" has no native record');
  });
});

describe('--box2d', () => {
  it('takes a repository checkout or its Box2D folder, and names the folder it cannot use', () => {
    const repo = path.join(temp, 'repo');
    mkdirSync(path.join(repo, 'Box2D', 'Box2D'), { recursive: true });
    writeFileSync(path.join(repo, 'Box2D', 'Box2D', 'Box2D.h'), '');
    expect(box2dIncludeDir(repo)).toBe(path.join(repo, 'Box2D'));
    expect(box2dIncludeDir(path.join(repo, 'Box2D'))).toBe(path.join(repo, 'Box2D'));
    expect(() => box2dIncludeDir(temp)).toThrow(`--box2d ${temp}: no Box2D/Box2D.h there or in its Box2D folder`);
  });

  it('is needed by the native engines and checked before anything runs', () => {
    expect(() => resolveProcessesOptions({ engines: 'webphysics,box2d-native-f64' })).toThrow('box2d-native-f64 needs --box2d DIR');
    expect(() => resolveProcessesOptions({ engines: 'box2d-native', box2d: temp })).toThrow('no Box2D/Box2D.h');
  });

  it.runIf(process.env.WEBPHYSICS_BOX2D)(
    'builds Box2D 2.2.1 twice and times both builds on a scene',
    async () => {
      const result = await runProcesses({ engines: 'box2d-native,box2d-native-f64', box2d: process.env.WEBPHYSICS_BOX2D, quick: true, runs: 1, log: null });
      expect(result.engines.map((e: { name: string }) => e.name)).toEqual(['Box2D 2.2.1 C++ float32', 'Box2D 2.2.1 C++ float64']);
      for (const e of result.engines) for (const ms of e.windowMs) expect(ms).toBeGreaterThan(0);
    },
    600_000,
  );
});
