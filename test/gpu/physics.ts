/*
 * Physical measures the GPU solver tests share: penetration at the bodies' transforms (from the
 * engine's contacts or the GPU's), kinetic energy.
 */

import type { b2Manifold } from '../../src/collision/b2Collision';
import { b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2World } from '../../src/dynamics/b2World';
import type { GpuStepper } from '../../src-gpu/stepper';

interface Geometry {
  type: number;
  pointCount: number;
  localNormal: { x: number; y: number };
  localPoint: { x: number; y: number };
  points: { x: number; y: number }[];
}

/** The separations of a manifold's points at the bodies' transforms (b2PositionSolverManifold). */
function separations(m: Geometry, a: b2Body, radiusA: number, b: b2Body, radiusB: number): number[] {
  const mul = (body: b2Body, v: { x: number; y: number }) => ({
    x: body.m_xf.q.c * v.x - body.m_xf.q.s * v.y + body.m_xf.p.x,
    y: body.m_xf.q.s * v.x + body.m_xf.q.c * v.y + body.m_xf.p.y,
  });
  const rotate = (body: b2Body, v: { x: number; y: number }) => ({
    x: body.m_xf.q.c * v.x - body.m_xf.q.s * v.y,
    y: body.m_xf.q.s * v.x + body.m_xf.q.c * v.y,
  });
  const out: number[] = [];
  if (m.type === 0) {
    const pA = mul(a, m.localPoint);
    const pB = mul(b, m.points[0]);
    out.push(Math.hypot(pB.x - pA.x, pB.y - pA.y) - radiusA - radiusB);
    return out;
  }
  const [plane, clip] = m.type === 1 ? [a, b] : [b, a];
  const normal = rotate(plane, m.localNormal);
  const planePoint = mul(plane, m.localPoint);
  for (let j = 0; j < m.pointCount; ++j) {
    const c = mul(clip, m.points[j]);
    out.push((c.x - planePoint.x) * normal.x + (c.y - planePoint.y) * normal.y - radiusA - radiusB);
  }
  return out;
}

/** The deepest penetration over the engine's touching, solid contacts (after a collide). */
export function engineDeepest(world: b2World): number {
  let deepest = 0;
  for (let c = world.m_contactManager.m_contactList; c; c = c.m_next) {
    if ((c.m_flags & 0x0002) === 0 || c.m_fixtureA.m_isSensor || c.m_fixtureB.m_isSensor) continue;
    const m: b2Manifold = c.m_manifold;
    const g: Geometry = {
      type: m.type,
      pointCount: m.pointCount,
      localNormal: m.localNormal,
      localPoint: m.localPoint,
      points: m.points.slice(0, m.pointCount).map((p) => p.localPoint),
    };
    for (const s of separations(g, c.m_fixtureA.m_body, c.m_fixtureA.m_shape.m_radius, c.m_fixtureB.m_body, c.m_fixtureB.m_shape.m_radius))
      deepest = Math.max(deepest, -s);
  }
  return deepest;
}

/**
 * The deepest penetration over the GPU's touching, solid contacts, at the bodies' transforms in the
 * world (call after a collision-only step, stepper.step(0, ...), and readBodies()).
 */
export async function gpuDeepestPenetration(stepper: GpuStepper): Promise<number> {
  let deepest = 0;
  for (const contact of await stepper.narrowPhase.readContacts()) {
    if (!contact.touching || contact.sensor) continue;
    const fa = stepper.mirror.fixtureAt(contact.fixtureA)!;
    const fb = stepper.mirror.fixtureAt(contact.fixtureB)!;
    const g: Geometry = {
      type: contact.type,
      pointCount: contact.pointCount,
      localNormal: contact.localNormal,
      localPoint: contact.localPoint,
      points: contact.points.map((p) => p.localPoint),
    };
    for (const sep of separations(g, fa.m_body, fa.m_shape.m_radius, fb.m_body, fb.m_shape.m_radius)) deepest = Math.max(deepest, -sep);
  }
  return deepest;
}

export function kineticEnergy(world: b2World): number {
  let e = 0;
  for (let b = world.m_bodyList; b; b = b.m_next) {
    if (b.m_type !== b2_dynamicBody) continue;
    const v = b.m_linearVelocity;
    e += 0.5 * b.m_mass * (v.x * v.x + v.y * v.y) + 0.5 * b.m_I * b.m_angularVelocity * b.m_angularVelocity;
  }
  return e;
}
