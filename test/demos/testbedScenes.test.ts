/*
 * The testbed's ports of the Box2D 2.2.1 Testbed tests (demos/tests) build the worlds the C++
 * Testbed builds: the golden trajectories were recorded from worlds dumped out of the C++ Testbed
 * (framework ground body first, RandomFloat from glibc's rand() after srand(1)), so each test
 * built here, stepped like the trajectories (listeners removed, 1/60 s, 8/3 iterations), must give
 * the same digest after every step.
 */

import { describe, expect, it } from 'vitest';
import { existsSync, readdirSync } from 'node:fs';
import path from 'node:path';
import type { b2Body } from '../../src/dynamics/b2Body';
import { rand, RandomFloat, srand } from '../../demos/framework/random';
import { sprintf } from '../../demos/framework/printf';
import { g_testEntries } from '../../demos/tests/index';
import { goldenDir } from '../support/golden';
import { readTrajectory, stateDigest } from '../support/scene';

const kSteps = 300;

function trajectoriesByTestbedName(): Map<string, string> {
  const byName = new Map<string, string>();
  const dir = path.join(goldenDir, 'trajectories');
  if (!existsSync(dir)) return byName;
  for (const file of readdirSync(dir)) {
    if (!file.endsWith('.trajectory.json')) continue;
    const name = file.slice(0, -'.trajectory.json'.length);
    byName.set(readTrajectory(name).testbedName, name);
  }
  return byName;
}

describe('glibc rand() (the testbed RandomFloat generator)', () => {
  it('gives glibc’s first numbers after srand(1) and srand(888)', () => {
    srand(1);
    expect([rand(), rand(), rand(), rand(), rand()]).toEqual([1804289383, 846930886, 1681692777, 1714636915, 1957747793]);
    srand(888);
    const a = rand();
    srand(888);
    expect(rand()).toBe(a);
  });

  it('RandomFloat(lo, hi) maps the low 15 bits onto [lo, hi]', () => {
    srand(1);
    expect(RandomFloat(-1, 1)).toBe(2 * ((1804289383 & 32767) / 32767) - 1);
    expect(RandomFloat()).toBe(2 * ((846930886 & 32767) / 32767) - 1);
  });
});

describe('printf subset of DrawString', () => {
  it('formats %d, %f with width and precision, and %g as C does', () => {
    expect(sprintf('%d/%d', 3, 4.7)).toBe('3/4');
    expect(sprintf('step [ave] (max) = %5.2f [%6.2f] (%6.2f)', 1.234, 2.5, 10)).toBe('step [ave] (max) =  1.23 [  2.50] ( 10.00)');
    expect(sprintf('%4.0f', 12.5)).toBe('  13');
    expect(sprintf('%g', 4)).toBe('4');
    expect(sprintf('%g', 0.7)).toBe('0.7');
    expect(sprintf('%g', 1234567)).toBe('1.23457e+06');
    expect(sprintf('%g', 0.0001234)).toBe('0.0001234');
    expect(sprintf('%g', 0.00001234)).toBe('1.234e-05');
    expect(sprintf('%3.1f%%', 99.95)).toBe('100.0%');
  });
});

describe('testbed tests build the C++ Testbed worlds (golden trajectories)', () => {
  const trajectories = trajectoriesByTestbedName();
  const covered = g_testEntries.filter((e) => trajectories.has(e.name));

  it('covers the Testbed tests that have a golden trajectory', () => {
    expect(covered.length).toBeGreaterThanOrEqual(30);
  });

  for (const entry of covered) {
    const name = trajectories.get(entry.name)!;
    it(`${entry.name} matches ${name} for ${kSteps} steps`, () => {
      const trajectory = readTrajectory(name);
      srand(1);
      const test = entry.createFcn();
      const world = test.m_world;
      world.SetContactListener(null);
      world.SetDestructionListener(null);
      const bodies: b2Body[] = [];
      for (let b = world.GetBodyList(); b !== null; b = b.GetNext()) bodies.unshift(b);
      for (let step = 0; step <= kSteps; ++step) {
        if (step > 0) world.Step(1 / 60, 8, 3);
        const digest = stateDigest(bodies);
        if (digest !== trajectory.digests[step]) {
          expect.fail(`${entry.name}: digest ${digest} at step ${step}, expected ${trajectory.digests[step]} (${bodies.length} bodies)`);
        }
      }
    });
  }
});
