/*
 * Golden scenes: loading them, the per-step state digest of the trajectory files, and a runner
 * that reports the first divergence from the C++ reference in a form that locates the bug.
 */

import { readdirSync } from 'node:fs';
import path from 'node:path';
import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2World } from '../../src/dynamics/b2World';
import { b2dJsonRead } from '../../src/io/b2dJsonRead';
import type { b2dJsonScene } from '../../src/io/b2dJsonScene';
import { bodyState, stateDigest } from '../../demos/determinism';
import { goldenDir, readGoldenJson } from './golden';

/** The digest and the body state it hashes are the testbed's, so Node and every browser hash alike. */
export { bodyState, stateDigest };

/** One entry of a trajectory's `samples`: six values per body plus world counts. */
export interface GoldenSample {
  step: number;
  contacts: number;
  touching: number;
  awake: number;
  bodies: number[][];
}

export interface GoldenTrajectory {
  scene: string;
  testbedName: string;
  steps: number;
  digests: string[];
  samples: GoldenSample[];
}

/** The six quantities of the digest, in digest order. */
export const kBodyQuantities = ['x', 'y', 'angle', 'vx', 'vy', 'w'] as const;

/** Scene names (file names without `.scene.json`), sorted. */
export function goldenSceneNames(): string[] {
  return readdirSync(path.join(goldenDir, 'scenes'))
    .filter((f) => f.endsWith('.scene.json'))
    .map((f) => f.slice(0, -'.scene.json'.length))
    .sort();
}

export function readGoldenScene(name: string): unknown {
  return readGoldenJson(`scenes/${name}.scene.json`);
}

/** Load a golden scene with the b2dJson reader (which applies the world flags of the file). */
export function loadGoldenScene(name: string): b2dJsonScene {
  return b2dJsonRead(readGoldenScene(name));
}

export function readTrajectory(name: string): GoldenTrajectory {
  return readGoldenJson<GoldenTrajectory>(`trajectories/${name}.trajectory.json`);
}

/** Contact count, touching contacts and awake bodies, as in the trajectory samples. */
export function worldCounts(world: b2World, bodies: readonly b2Body[]): { contacts: number; touching: number; awake: number } {
  let touching = 0;
  for (let c = world.GetContactList(); c !== null; c = c.GetNext()) {
    if (c.IsTouching()) ++touching;
  }
  const awake = bodies.filter((b) => b.IsAwake()).length;
  return { contacts: world.GetContactCount(), touching, awake };
}

/** Distance in units in the last place between two doubles of the same sign (Infinity otherwise). */
export function ulpDistance(a: number, b: number): number {
  if (Object.is(a, b)) return 0;
  if (Math.sign(a) !== Math.sign(b) || !Number.isFinite(a) || !Number.isFinite(b)) return Infinity;
  const bits = new BigInt64Array(new Float64Array([Math.abs(a), Math.abs(b)]).buffer);
  const d = bits[0] - bits[1];
  return Number(d < 0n ? -d : d);
}

function formatNumber(x: number): string {
  return Object.is(x, -0) ? '-0' : String(x);
}

/** Compare the world to a sample: the first differing body and quantity, and the counts. */
export function describeSampleDifference(scene: b2dJsonScene, sample: GoldenSample): string {
  const lines: string[] = [];
  let differing = 0;
  let first = '';
  for (let i = 0; i < scene.bodies.length; ++i) {
    const got = bodyState(scene.bodies[i]);
    const expected = sample.bodies[i];
    for (let q = 0; q < kBodyQuantities.length; ++q) {
      if (Object.is(got[q], expected[q])) continue;
      if (first === '') {
        const diff = got[q] - expected[q];
        const ulps = ulpDistance(got[q], expected[q]);
        first =
          `first difference: body[${i}].${kBodyQuantities[q]} = ${formatNumber(got[q])}, ` +
          `expected ${formatNumber(expected[q])} (diff ${diff}${Number.isFinite(ulps) ? `, ${ulps} ulp` : ''})`;
      }
      ++differing;
    }
  }
  lines.push(first === '' ? 'all body values equal the sample' : first);
  if (differing > 1) lines.push(`${differing} body values differ in all`);
  const counts = worldCounts(scene.world, scene.bodies);
  lines.push(
    `counts (got/expected): contacts ${counts.contacts}/${sample.contacts}, ` +
      `touching ${counts.touching}/${sample.touching}, awake ${counts.awake}/${sample.awake}`,
  );
  return lines.join('\n');
}

/**
 * Load the scene, step it `steps` times (default: the trajectory's length) and compare each digest
 * with the reference. Returns null when every digest matches; otherwise a report naming the scene,
 * the first differing step and, stepping on to the next sample, the first differing body value
 * and the world counts.
 */
export function runGoldenScene(name: string, steps?: number): string | null {
  const trajectory = readTrajectory(name);
  const lastStep = steps ?? trajectory.steps;
  const scene = loadGoldenScene(name);
  let step = 0;
  try {
    for (; step <= lastStep; ++step) {
      if (step > 0) scene.step();
      const digest = stateDigest(scene.bodies);
      if (digest === trajectory.digests[step]) continue;

      const report = [
        `${name}: the digest first differs at step ${step} (got ${digest}, expected ${trajectory.digests[step]})` +
          (step === 0 ? ', before any step: the loaded scene differs' : ''),
      ];
      const sample = trajectory.samples.find((s) => s.step >= step);
      if (sample !== undefined) {
        for (; step < sample.step; ++step) scene.step();
        report.push(`at sample step ${sample.step}:`, describeSampleDifference(scene, sample));
      }
      return report.join('\n');
    }
  } catch (e) {
    const message = e instanceof Error ? (e.stack ?? e.message) : String(e);
    return `${name}: threw at step ${step}: ${message}`;
  }
  return null;
}
