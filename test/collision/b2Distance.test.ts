import { describe, expect, it } from 'vitest';
import {
  b2Distance,
  b2DistanceInput,
  b2DistanceOutput,
  b2DistanceProxy,
  b2ResetGjkCounters,
  b2SimplexCache,
  b2_gjkCalls,
  b2_gjkIters,
  b2_gjkMaxIters,
} from '../../src/collision/b2Distance';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import type { b2Shape } from '../../src/collision/shapes/b2Shape';
import { b2Rot, b2Transform, b2Vec2 } from '../../src/common/b2Math';
import {
  checkVectorFamily,
  collisionVectors,
  compareDouble,
  compareVec2,
  describeFamilyResult,
  makeShape,
  makeTransform,
  type DistanceCase,
} from '../support/collisionVectors';

function circle(radius: number, x: number, y: number): b2CircleShape {
  const shape = new b2CircleShape();
  shape.m_radius = radius;
  shape.m_p.Set(x, y);
  return shape;
}

function box(hx: number, hy: number): b2PolygonShape {
  const shape = new b2PolygonShape();
  shape.SetAsBox(hx, hy);
  return shape;
}

function transform(x: number, y: number, angle: number): b2Transform {
  return new b2Transform(new b2Vec2(x, y), new b2Rot(angle));
}

function distance(shapeA: b2Shape, xfA: b2Transform, shapeB: b2Shape, xfB: b2Transform, useRadii: boolean, cache = new b2SimplexCache()): b2DistanceOutput {
  const input = new b2DistanceInput();
  input.proxyA.Set(shapeA, 0);
  input.proxyB.Set(shapeB, 0);
  input.transformA.Assign(xfA);
  input.transformB.Assign(xfB);
  input.useRadii = useRadii;
  const output = new b2DistanceOutput();
  b2Distance(output, cache, input);
  return output;
}

function compareCase(testCase: DistanceCase, xfA: b2Transform, xfB: b2Transform): string | null {
  const output = distance(makeShape(testCase.shapeA), xfA, makeShape(testCase.shapeB), xfB, testCase.useRadii);
  const expected = testCase.output;
  if (output.iterations !== expected.iterations) {
    return `iterations: expected ${expected.iterations}, got ${output.iterations}`;
  }
  return (
    compareVec2('pointA', output.pointA, expected.pointA) ??
    compareVec2('pointB', output.pointB, expected.pointB) ??
    compareDouble('distance', output.distance, expected.distance)
  );
}

describe('b2Distance', () => {
  it('reproduces all 300 reference distance cases bit for bit (documented reference-rotation outliers aside)', () => {
    const cases = collisionVectors.distance;
    expect(cases.length).toBe(300);
    const result = checkVectorFamily(cases, (testCase) => {
      const xfA = makeTransform(testCase.xfA);
      const xfB = makeTransform(testCase.xfB);
      return { transforms: [xfA, xfB], check: () => compareCase(testCase, xfA, xfB) };
    });
    expect(describeFamilyResult('distance', result)).toBeNull();
  });

  it('measures two circles centre to centre, or surface to surface with radii', () => {
    const a = circle(0.5, 0.0, 0.0);
    const b = circle(0.25, 1.0, 0.0);
    const xfA = transform(0.0, 0.0, 0.0);
    const xfB = transform(2.0, 0.0, 0.0);

    const centres = distance(a, xfA, b, xfB, false);
    expect(centres.distance).toBe(3.0);
    expect([centres.pointA.x, centres.pointA.y, centres.pointB.x, centres.pointB.y]).toEqual([0.0, 0.0, 3.0, 0.0]);
    expect(centres.iterations).toBe(1);

    const surfaces = distance(a, xfA, b, xfB, true);
    expect(surfaces.distance).toBe(2.25);
    expect([surfaces.pointA.x, surfaces.pointA.y, surfaces.pointB.x, surfaces.pointB.y]).toEqual([0.5, 0.0, 2.75, 0.0]);
  });

  it('puts both witness points at the midpoint when circles overlap with radii', () => {
    const output = distance(circle(1.0, 0.0, 0.0), transform(0, 0, 0), circle(1.0, 0.0, 0.0), transform(1.5, 0, 0), true);
    expect(output.distance).toBe(0.0);
    expect([output.pointA.x, output.pointA.y, output.pointB.x, output.pointB.y]).toEqual([0.75, 0.0, 0.75, 0.0]);
  });

  it('measures face to face and corner to face between two boxes', () => {
    // Unit boxes 5 apart along x, offset in y: the gap between the facing sides is 3.
    const faces = distance(box(1.0, 1.0), transform(0, 0, 0), box(1.0, 1.0), transform(5.0, 0.5, 0), false);
    expect(faces.distance).toBeCloseTo(3.0, 14);
    expect(faces.pointA.x).toBeCloseTo(1.0, 14);
    expect(faces.pointB.x).toBeCloseTo(4.0, 14);
    expect(faces.pointA.y).toBeCloseTo(faces.pointB.y, 14);
    expect(faces.pointA.y).toBeGreaterThanOrEqual(-0.5 - 1e-14);
    expect(faces.pointA.y).toBeLessThanOrEqual(1.0 + 1e-14);

    // Box B turned 45 degrees: its corner points at A's face, sqrt(2) from its centre.
    const corner = distance(box(1.0, 1.0), transform(0, 0, 0), box(1.0, 1.0), transform(5.0, 0.0, 0.25 * Math.PI), false);
    expect(corner.distance).toBeCloseTo(4.0 - Math.SQRT2, 14);
    expect(corner.pointB.x).toBeCloseTo(5.0 - Math.SQRT2, 14);
    expect(corner.pointB.y).toBeCloseTo(0.0, 14);
    expect(corner.pointA.x).toBeCloseTo(1.0, 14);
    expect(corner.pointA.y).toBeCloseTo(0.0, 14);

    // Overlapping boxes report zero distance.
    const overlap = distance(box(1.0, 1.0), transform(0, 0, 0), box(1.0, 1.0), transform(1.0, 0.3, 0.2), false);
    expect(overlap.distance).toBe(0.0);
  });

  it('gives the same answer when warm started from its own cache', () => {
    const shapeA = box(0.7, 0.3);
    const shapeB = box(0.4, 0.9);
    const xfA = transform(-0.2, 0.1, 0.4);
    const xfB = transform(2.1, -0.7, -1.1);
    const cache = new b2SimplexCache();
    const cold = distance(shapeA, xfA, shapeB, xfB, true, cache);
    expect(cache.count).toBeGreaterThan(0);
    const saved = cache.Clone();

    const warm = distance(shapeA, xfA, shapeB, xfB, true, cache);
    expect(Object.is(warm.distance, cold.distance)).toBe(true);
    expect([warm.pointA.x, warm.pointA.y, warm.pointB.x, warm.pointB.y]).toEqual([cold.pointA.x, cold.pointA.y, cold.pointB.x, cold.pointB.y]);
    // The warm start begins from the converged simplex, so it needs no more support calls.
    expect(warm.iterations).toBeLessThanOrEqual(cold.iterations);
    expect(cache.count).toBe(saved.count);
    expect(cache.indexA.slice(0, cache.count)).toEqual(saved.indexA.slice(0, saved.count));
    expect(cache.indexB.slice(0, cache.count)).toEqual(saved.indexB.slice(0, saved.count));
  });

  it('counts calls, iterations and the maximum iterations', () => {
    b2ResetGjkCounters();
    expect([b2_gjkCalls, b2_gjkIters, b2_gjkMaxIters]).toEqual([0, 0, 0]);
    const first = distance(box(1, 1), transform(0, 0, 0), box(1, 1), transform(4, 1, 0.3), false);
    const second = distance(circle(1, 0, 0), transform(0, 0, 0), circle(1, 0, 0), transform(4, 0, 0), false);
    expect(b2_gjkCalls).toBe(2);
    expect(b2_gjkIters).toBe(first.iterations + second.iterations);
    expect(b2_gjkMaxIters).toBe(Math.max(first.iterations, second.iterations));
  });
});

describe('b2DistanceProxy', () => {
  it('copies a chain child edge into its buffer, wrapping the last child to vertex 0', () => {
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(0, 0), new b2Vec2(1, 0), new b2Vec2(1, 1)], 3);
    const proxy = new b2DistanceProxy();

    proxy.Set(chain, 1);
    expect(proxy.GetVertexCount()).toBe(2);
    expect(proxy.m_vertices).toBe(proxy.m_buffer);
    expect([proxy.GetVertex(0).x, proxy.GetVertex(0).y, proxy.GetVertex(1).x, proxy.GetVertex(1).y]).toEqual([1, 0, 1, 1]);
    expect(proxy.GetVertex(0)).not.toBe(chain.m_vertices[1]);
    expect(proxy.m_radius).toBe(chain.m_radius);

    proxy.Set(chain, 2);
    expect([proxy.GetVertex(0).x, proxy.GetVertex(0).y, proxy.GetVertex(1).x, proxy.GetVertex(1).y]).toEqual([1, 1, 0, 0]);
  });

  it('references the vertices of circles, edges and polygons rather than copying them', () => {
    const proxy = new b2DistanceProxy();

    const c = circle(0.3, 1, 2);
    proxy.Set(c, 0);
    expect(proxy.GetVertexCount()).toBe(1);
    expect(proxy.GetVertex(0)).toBe(c.m_p);
    expect(proxy.m_radius).toBe(0.3);

    const edge = new b2EdgeShape();
    edge.Set(new b2Vec2(-1, 0), new b2Vec2(2, 0));
    proxy.Set(edge, 0);
    expect(proxy.GetVertexCount()).toBe(2);
    expect(proxy.GetVertex(0)).toBe(edge.m_vertex1);
    expect(proxy.GetVertex(1)).toBe(edge.m_vertex2);

    const polygon = box(1, 2);
    proxy.Set(polygon, 0);
    expect(proxy.GetVertexCount()).toBe(4);
    expect(proxy.m_vertices).toBe(polygon.m_vertices);
  });

  it('finds the support vertex farthest along a direction', () => {
    const proxy = new b2DistanceProxy();
    proxy.Set(box(1, 2), 0);
    const d = new b2Vec2(-1, 0.1);
    const index = proxy.GetSupport(d);
    expect([proxy.GetVertex(index).x, proxy.GetVertex(index).y]).toEqual([-1, 2]);
    expect(proxy.GetSupportVertex(d)).toBe(proxy.GetVertex(index));
  });

  it('keeps pointing at the shape it copied after the source proxy is reused', () => {
    const a = circle(0.1, 5, 6);
    const source = new b2DistanceProxy();
    source.Set(a, 0);
    const copy = new b2DistanceProxy().Assign(source);
    source.Set(circle(0.2, -1, -1), 0);
    expect(copy.GetVertex(0)).toBe(a.m_p);
    expect(copy.m_radius).toBe(0.1);
  });
});
