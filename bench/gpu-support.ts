/*
 * Helpers shared by the GPU benchmarks (gpu-broadphase.ts, gpu-narrowphase.ts, gpu-step.ts): a
 * seeded random generator, medians, number formatting for the tables, and the shapes they build.
 */
import { b2CircleShape } from '../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../src/collision/shapes/b2PolygonShape';
import type { b2Vec2 } from '../src/common/b2Math';

/** mulberry32: a small seeded generator, so every run builds the same scene. */
export function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export function median(values: number[]): number {
  if (values.length === 0) return NaN;
  const v = values.slice().sort((a, b) => a - b);
  return v[Math.floor(v.length / 2)];
}

/** Three significant digits, whole numbers from 100; '–' for a missing value. */
export function fmt(v: number | undefined, digits = 3): string {
  if (v === undefined || !Number.isFinite(v)) return '–';
  return v >= 100 ? v.toFixed(0) : v >= 10 ? v.toFixed(1) : v.toPrecision(digits);
}

export function box(hx: number, hy: number, centre?: b2Vec2): b2PolygonShape {
  const s = new b2PolygonShape();
  if (centre) s.SetAsBox(hx, hy, centre, 0);
  else s.SetAsBox(hx, hy);
  return s;
}

export function circle(r: number): b2CircleShape {
  const s = new b2CircleShape();
  s.m_radius = r;
  return s;
}
