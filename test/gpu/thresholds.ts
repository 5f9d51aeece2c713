/*
 * Telling a float32 threshold case from a wrong GPU kernel, on the CPU in float64.
 *
 * The GPU collides float32 copies of a case's inputs in float32. Where the reference (float64,
 * exact inputs) and the GPU disagree on a discrete outcome (manifold type, point count, feature
 * ids), the disagreement is legitimate only if the case sits within float32 rounding of one of the
 * algorithm's decision thresholds. classifyThreshold checks that in two ways, both with the
 * engine's own float64 collide function:
 *   - flip distance: the smallest perturbation of the inputs, in float32 ulps of each input
 *     (shape coordinates, normals, centroid, radii; transform positions and rotation), under
 *     which the float64 engine gives the GPU's discrete answer (searched over the float32
 *     rounding itself, then random perturbations of 1, 2, 4, ... THRESHOLD_ULPS ulps);
 *   - separation margin: the decisive quantity at the exact inputs (see `margins`), relative to
 *     the case's scale, must be below MARGIN_TOLERANCE.
 * A case is a threshold case when the flip distance is at most THRESHOLD_ULPS and the margin is
 * below MARGIN_TOLERANCE; anything else is reported as a failure with both numbers.
 */

import { b2Manifold, b2TestOverlapShapes } from '../../src/collision/b2Collision';
import { b2CollideCircles, b2CollidePolygonAndCircle } from '../../src/collision/b2CollideCircle';
import { b2CollideEdgeAndCircle, b2CollideEdgeAndPolygon } from '../../src/collision/b2CollideEdge';
import { b2CollidePolygons } from '../../src/collision/b2CollidePolygon';
import type { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import type { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import type { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import type { b2Shape } from '../../src/collision/shapes/b2Shape';
import type { b2Transform, b2Vec2 } from '../../src/common/b2Math';
import { makeShape, makeTransform } from '../support/collisionVectors';
import type { CollideCase, ShapeJson } from '../support/collisionVectors';
import { rng } from './support';

export type Family =
  | 'collideCircles'
  | 'collidePolygonAndCircle'
  | 'collidePolygons'
  | 'collideEdgeAndCircle'
  | 'collideEdgeAndPolygon'
  /** b2TestOverlap (sensors): the discrete answer is touching or not. */
  | 'overlap';

/** A case as engine objects (chain children given as their b2EdgeShape). */
export interface CaseObjects {
  a: b2Shape;
  xfA: b2Transform;
  b: b2Shape;
  xfB: b2Transform;
}

function fromJson(tc: CollideCase<ShapeJson, ShapeJson>): CaseObjects {
  return { a: makeShape(tc.shapeA), xfA: makeTransform(tc.xfA), b: makeShape(tc.shapeB), xfB: makeTransform(tc.xfB) };
}

function cloneCase(c: CaseObjects): CaseObjects {
  return { a: c.a.Clone(), xfA: c.xfA.Clone(), b: c.b.Clone(), xfB: c.xfB.Clone() };
}

/** Largest input perturbation, in float32 ulps, that may explain a GPU/reference disagreement. */
export const THRESHOLD_ULPS = 16;
/** Largest |margin| / scale of a threshold case (float32 rounding of the inputs and arithmetic). */
export const MARGIN_TOLERANCE = 1e-5;

function collide(family: Family, m: b2Manifold, a: b2Shape, xfA: b2Transform, b: b2Shape, xfB: b2Transform): void {
  switch (family) {
    case 'collideCircles':
      return b2CollideCircles(m, a as b2CircleShape, xfA, b as b2CircleShape, xfB);
    case 'collidePolygonAndCircle':
      return b2CollidePolygonAndCircle(m, a as b2PolygonShape, xfA, b as b2CircleShape, xfB);
    case 'collidePolygons':
      return b2CollidePolygons(m, a as b2PolygonShape, xfA, b as b2PolygonShape, xfB);
    case 'collideEdgeAndCircle':
      return b2CollideEdgeAndCircle(m, a as b2EdgeShape, xfA, b as b2CircleShape, xfB);
    case 'collideEdgeAndPolygon':
      return b2CollideEdgeAndPolygon(m, a as b2EdgeShape, xfA, b as b2PolygonShape, xfB);
    case 'overlap':
      m.pointCount = b2TestOverlapShapes(a, 0, b, 0, xfA, xfB) ? 1 : 0;
      m.type = 0;
      m.points[0].id.key = 0;
      return;
  }
}

/** The engine's manifold (float64) for a case. */
export function engineManifold(family: Family, c: CaseObjects): b2Manifold {
  return run(family, c.a, c.xfA, c.b, c.xfB);
}

export function discrete(m: b2Manifold): string {
  if (m.pointCount === 0) return '0';
  const ids: number[] = [];
  for (let i = 0; i < m.pointCount; ++i) ids.push(m.points[i].id.key);
  return `${m.type}/${m.pointCount}/${ids.join(',')}`;
}

/** Every float input of a shape and a transform, as (get, set) over the live objects. */
function inputsOf(shape: b2Shape, xf: b2Transform): { get: () => number; set: (v: number) => void }[] {
  const out: { get: () => number; set: (v: number) => void }[] = [];
  const vec = (v: b2Vec2) => {
    out.push({ get: () => v.x, set: (x) => (v.x = x) });
    out.push({ get: () => v.y, set: (y) => (v.y = y) });
  };
  out.push({ get: () => shape.m_radius, set: (r) => (shape.m_radius = r) });
  if (shape.m_type === 0) vec((shape as b2CircleShape).m_p);
  else if (shape.m_type === 1) {
    const e = shape as b2EdgeShape;
    [e.m_vertex0, e.m_vertex1, e.m_vertex2, e.m_vertex3].forEach(vec);
  } else if (shape.m_type === 2) {
    const p = shape as b2PolygonShape;
    for (let i = 0; i < p.m_vertexCount; ++i) {
      vec(p.m_vertices[i]);
      vec(p.m_normals[i]);
    }
    vec(p.m_centroid);
  }
  vec(xf.p);
  out.push({ get: () => xf.q.c, set: (c) => (xf.q.c = c) });
  out.push({ get: () => xf.q.s, set: (s) => (xf.q.s = s) });
  return out;
}

const f32 = new Float32Array(1);
const u32 = new Uint32Array(f32.buffer);

/** x moved by k float32 ulps (of fround(x)), as a float64. */
function stepF32(x: number, k: number): number {
  f32[0] = x;
  if (k === 0 || x === 0) return k === 0 ? f32[0] : k * 1.4e-45;
  const bits = u32[0];
  const sign = bits & 0x80000000;
  let mag = bits & 0x7fffffff;
  // Moving "up" in magnitude for positive x means k > 0 increases x.
  mag = sign ? mag - k : mag + k;
  if (mag < 0) mag = 0;
  u32[0] = (sign | mag) >>> 0;
  return f32[0];
}

export interface ThresholdVerdict {
  explained: boolean;
  /** Smallest perturbation (float32 ulps) found that reproduces the GPU's answer, or Infinity. */
  flipUlps: number;
  /** |margin| / scale of the decisive quantity at the exact inputs. */
  margin: number;
  why: string;
}

/** The largest coordinate magnitude of a case's inputs (shapes and transforms), at least 1. */
export function caseScale(tc: CollideCase<ShapeJson, ShapeJson> | CaseObjects): number {
  const c = 'shapeA' in tc ? fromJson(tc) : tc;
  let s = 1;
  for (const x of [...inputsOf(c.a, c.xfA), ...inputsOf(c.b, c.xfB)]) s = Math.max(s, Math.abs(x.get()));
  return s;
}

/**
 * The case's decision margin, in float64: the smallest change of its inputs, as a fraction of
 * its scale S, that changes the engine's discrete answer (type, point count, ids). Each input x
 * becomes x + eps * d * S for random directions d in [-1, 1]^n (64 of them, fixed seed), and eps
 * is bisected to 1e-12 relative between "same answer" and "different answer". A decision at
 * distance m from its threshold (a separation against a radius, a clip distance against 0, a
 * region test, the hysteresis) flips at eps of about m / S, so this is the distance to the nearest
 * threshold; Infinity when no change up to 1e-3 flips it.
 */
export function margins(family: Family, tc: CollideCase<ShapeJson, ShapeJson> | CaseObjects): number {
  const { a, xfA, b, xfB } = 'shapeA' in tc ? fromJson(tc) : cloneCase(tc);
  const S = caseScale({ a, xfA, b, xfB });
  const base = discrete(run(family, a, xfA, b, xfB));
  const inputs = [...inputsOf(a, xfA), ...inputsOf(b, xfB)];
  const original = inputs.map((x) => x.get());
  let best = Infinity;
  const random = rng(7);
  for (let trial = 0; trial < 64; ++trial) {
    const dir = inputs.map(() => 2 * random() - 1);
    const flips = (eps: number) => {
      inputs.forEach((x, i) => x.set(original[i] + eps * dir[i] * S));
      const out = discrete(run(family, a, xfA, b, xfB));
      inputs.forEach((x, i) => x.set(original[i]));
      return out !== base;
    };
    let lo = 0;
    let hi = Math.min(best, 1e-3);
    if (!flips(hi)) continue;
    while (hi - lo > 1e-12 * Math.max(1, hi)) {
      const mid = 0.5 * (lo + hi);
      if (flips(mid)) hi = mid;
      else lo = mid;
    }
    best = Math.min(best, hi);
  }
  return best;
}

function run(family: Family, a: b2Shape, xfA: b2Transform, b: b2Shape, xfB: b2Transform): b2Manifold {
  const m = new b2Manifold();
  collide(family, m, a, xfA, b, xfB);
  return m;
}

/** Is the GPU's discrete answer `gpu` for this case a float32 threshold flip? */
export function classifyThreshold(family: Family, tc: CollideCase<ShapeJson, ShapeJson> | CaseObjects, gpu: string): ThresholdVerdict {
  const { a, xfA, b, xfB } = 'shapeA' in tc ? fromJson(tc) : cloneCase(tc);
  const inputs = [...inputsOf(a, xfA), ...inputsOf(b, xfB)];
  const original = inputs.map((x) => x.get());
  let flipUlps = Infinity;
  const random = rng(12345);
  const tryUlps = (range: number, trials: number) => {
    for (let t = 0; t < trials; ++t) {
      inputs.forEach((x, i) => x.set(stepF32(original[i], range === 0 ? 0 : Math.round((2 * random() - 1) * range))));
      const out = discrete(run(family, a, xfA, b, xfB));
      inputs.forEach((x, i) => x.set(original[i]));
      if (out === gpu) return true;
    }
    return false;
  };
  if (tryUlps(0, 1)) flipUlps = 0;
  else {
    for (let range = 1; range <= THRESHOLD_ULPS; range *= 2) {
      if (tryUlps(range, 400)) {
        flipUlps = range;
        break;
      }
    }
  }
  const margin = margins(family, tc);
  const explained = flipUlps <= THRESHOLD_ULPS && margin <= MARGIN_TOLERANCE;
  return {
    explained,
    flipUlps,
    margin,
    why: `flip distance ${flipUlps} float32 ulps (at most ${THRESHOLD_ULPS}), margin ${margin.toExponential(2)} of the scale (at most ${MARGIN_TOLERANCE})`,
  };
}
