import { describe, expect, it } from 'vitest';
import { b2AABB, b2RayCastInput, b2RayCastOutput } from '../../../src/collision/b2Collision';
import { b2CircleShape } from '../../../src/collision/shapes/b2CircleShape';
import { b2MassData, b2Shape } from '../../../src/collision/shapes/b2Shape';
import { b2Rot, b2Transform, b2Vec2 } from '../../../src/common/b2Math';
import { b2_pi } from '../../../src/common/b2Settings';

function makeCircle(radius: number, x: number, y: number): b2CircleShape {
  const circle = new b2CircleShape();
  circle.m_radius = radius;
  circle.m_p.Set(x, y);
  return circle;
}

describe('b2CircleShape', () => {
  it('starts as a zero-radius circle at the origin with one child', () => {
    const circle = new b2CircleShape();
    expect(circle.GetType()).toBe(b2Shape.e_circle);
    expect(circle.m_radius).toBe(0);
    expect(circle.m_p).toEqual(new b2Vec2(0, 0));
    expect(circle.GetChildCount()).toBe(1);
    expect(circle.GetVertexCount()).toBe(1);
    expect(circle.GetVertex(0)).toBe(circle.m_p);
    expect(circle.GetSupport(new b2Vec2(1, 0))).toBe(0);
    expect(circle.GetSupportVertex(new b2Vec2(0, 1))).toBe(circle.m_p);
  });

  it('ComputeMass gives density * pi * r^2 and the inertia about the shape origin', () => {
    const circle = makeCircle(0.5, 1.0, 2.0);
    const massData = new b2MassData();
    circle.ComputeMass(massData, 2.0);
    const mass = 2.0 * b2_pi * 0.5 * 0.5;
    expect(massData.mass).toBe(mass);
    expect(massData.center).toEqual(new b2Vec2(1.0, 2.0));
    expect(massData.I).toBe(mass * (0.5 * 0.5 * 0.5 + (1.0 * 1.0 + 2.0 * 2.0)));
  });

  it('ComputeAABB is the transformed center plus and minus the radius', () => {
    const circle = makeCircle(0.5, 1.0, 0.0);
    const aabb = new b2AABB();
    const xf = new b2Transform(new b2Vec2(2.0, 3.0), new b2Rot(0.5 * b2_pi));
    circle.ComputeAABB(aabb, xf, 0);
    const q = xf.q;
    const px = 2.0 + (q.c * 1.0 - q.s * 0.0);
    const py = 3.0 + (q.s * 1.0 + q.c * 0.0);
    expect(aabb.lowerBound).toEqual(new b2Vec2(px - 0.5, py - 0.5));
    expect(aabb.upperBound).toEqual(new b2Vec2(px + 0.5, py + 0.5));
  });

  it('TestPoint includes the boundary and excludes points outside', () => {
    const circle = makeCircle(1.0, 0.0, 0.0);
    const xf = new b2Transform(new b2Vec2(5.0, 0.0));
    expect(circle.TestPoint(xf, new b2Vec2(6.0, 0.0))).toBe(true);
    expect(circle.TestPoint(xf, new b2Vec2(5.5, 0.5))).toBe(true);
    expect(circle.TestPoint(xf, new b2Vec2(6.001, 0.0))).toBe(false);
  });

  it('RayCast hits the near surface with the outward normal', () => {
    const circle = makeCircle(1.0, 0.0, 0.0);
    const xf = new b2Transform(new b2Vec2(0.0, 2.0));
    const input = new b2RayCastInput();
    input.p1.Set(-4.0, 2.0);
    input.p2.Set(4.0, 2.0);
    input.maxFraction = 1.0;
    const output = new b2RayCastOutput();
    expect(circle.RayCast(output, input, xf, 0)).toBe(true);
    expect(output.fraction).toBe(3.0 / 8.0);
    expect(output.normal).toEqual(new b2Vec2(-1.0, 0.0));
  });

  it('RayCast misses beyond maxFraction, past the circle, and for degenerate rays', () => {
    const circle = makeCircle(1.0, 0.0, 0.0);
    const xf = new b2Transform();
    const input = new b2RayCastInput();
    const output = new b2RayCastOutput();
    input.p1.Set(-4.0, 0.0);
    input.p2.Set(4.0, 0.0);
    input.maxFraction = 0.3;
    expect(circle.RayCast(output, input, xf, 0)).toBe(false);
    input.maxFraction = 1.0;
    input.p1.Set(-4.0, 1.5);
    input.p2.Set(4.0, 1.5);
    expect(circle.RayCast(output, input, xf, 0)).toBe(false);
    input.p1.Set(-4.0, 0.0);
    input.p2.Set(-4.0, 0.0);
    expect(circle.RayCast(output, input, xf, 0)).toBe(false);
  });

  it('Clone copies radius and center into a separate shape', () => {
    const circle = makeCircle(0.25, -1.0, 0.5);
    const clone = circle.Clone();
    expect(clone).toBeInstanceOf(b2CircleShape);
    expect(clone.m_radius).toBe(0.25);
    expect(clone.m_p).toEqual(circle.m_p);
    clone.m_p.x = 9;
    expect(circle.m_p.x).toBe(-1.0);
  });
});
