import { describe, expect, it } from 'vitest';
import {
  b2_addState,
  b2_nullState,
  b2_persistState,
  b2_removeState,
  b2AABB,
  b2ClipSegmentToLine,
  b2ClipVertex,
  b2ContactFeature,
  b2ContactID,
  b2GetPointStates,
  b2Manifold,
  b2PointState,
  b2RayCastInput,
  b2RayCastOutput,
  b2TestOverlap,
  b2TestOverlapShapes,
  b2WorldManifold,
} from '../../src/collision/b2Collision';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Transform, b2Vec2 } from '../../src/common/b2Math';
import { b2_epsilon, b2_maxManifoldPoints } from '../../src/common/b2Settings';

function aabb(lx: number, ly: number, ux: number, uy: number): b2AABB {
  const box = new b2AABB();
  box.lowerBound.Set(lx, ly);
  box.upperBound.Set(ux, uy);
  return box;
}

describe('b2ContactID', () => {
  it('packs indexA, indexB, typeA, typeB into the little-endian uint32 key', () => {
    const id = new b2ContactID();
    id.cf.indexA = 3;
    id.cf.indexB = 0;
    id.cf.typeA = b2ContactFeature.e_vertex;
    id.cf.typeB = b2ContactFeature.e_face;
    expect(id.key).toBe(16777219);
    id.cf.indexA = 255;
    id.cf.indexB = 255;
    id.cf.typeA = 255;
    id.cf.typeB = 255;
    expect(id.key).toBe(0xffffffff);
  });

  it('writing key writes the four feature bytes, and key = 0 clears them', () => {
    const id = new b2ContactID();
    id.key = 66307;
    expect(id.cf).toMatchObject({ indexA: 3, indexB: 3, typeA: 1, typeB: 0 });
    id.key = 0;
    expect(id.cf).toMatchObject({ indexA: 0, indexB: 0, typeA: 0, typeB: 0 });
  });

  it('Assign and Clone copy the features by value', () => {
    const id = new b2ContactID();
    id.key = 0x01020304;
    const copy = id.Clone();
    id.key = 0;
    expect(copy.key).toBe(0x01020304);
    expect(new b2ContactID().Assign(copy).cf.indexA).toBe(4);
  });

  it('is one record under both views, as the C++ union: cf is the id, and a copy of cf is its own', () => {
    const id = new b2ContactID();
    expect(id.cf).toBe(id);
    expect(id).toBeInstanceOf(b2ContactFeature);
    id.cf.Assign(Object.assign(new b2ContactFeature(), { indexA: 7, indexB: 1, typeA: 1, typeB: 0 }));
    expect(id.key).toBe(0x00010107);
    const features = id.cf.Clone();
    id.key = 0;
    expect(features).toMatchObject({ indexA: 7, indexB: 1, typeA: 1, typeB: 0 });
  });
});

describe('b2Manifold', () => {
  it('preallocates b2_maxManifoldPoints points', () => {
    const manifold = new b2Manifold();
    expect(manifold.points.length).toBe(b2_maxManifoldPoints);
    expect(manifold.points[0]).not.toBe(manifold.points[1]);
    expect(manifold.pointCount).toBe(0);
  });

  it('Assign is a deep copy, as the C++ struct copy', () => {
    const a = new b2Manifold();
    a.type = b2Manifold.e_faceB;
    a.pointCount = 2;
    a.localNormal.Set(0, 1);
    a.localPoint.Set(2, 3);
    a.points[1].localPoint.Set(4, 5);
    a.points[1].normalImpulse = 6;
    a.points[1].tangentImpulse = 7;
    a.points[1].id.key = 0x01000200;
    const b = a.Clone();
    a.points[1].localPoint.x = -1;
    a.points[1].id.key = 0;
    a.localNormal.x = -1;
    expect(b.type).toBe(b2Manifold.e_faceB);
    expect(b.pointCount).toBe(2);
    expect(b.localNormal.Clone()).toEqual(new b2Vec2(0, 1));
    expect(b.localPoint.Clone()).toEqual(new b2Vec2(2, 3));
    expect(b.points[1].localPoint.Clone()).toEqual(new b2Vec2(4, 5));
    expect(b.points[1].normalImpulse).toBe(6);
    expect(b.points[1].tangentImpulse).toBe(7);
    expect(b.points[1].id.key).toBe(0x01000200);
  });
});

describe('b2WorldManifold.Initialize', () => {
  it('leaves the outputs untouched when there are no points', () => {
    const world = new b2WorldManifold();
    world.normal.Set(7, 7);
    world.Initialize(new b2Manifold(), new b2Transform(), 1, new b2Transform(), 1);
    expect(world.normal).toEqual(new b2Vec2(7, 7));
  });

  it('e_circles: the normal joins the centers and the point is midway between the surfaces', () => {
    const manifold = new b2Manifold();
    manifold.type = b2Manifold.e_circles;
    manifold.pointCount = 1;
    manifold.localPoint.Set(0, 0);
    manifold.points[0].localPoint.Set(0, 0);
    const world = new b2WorldManifold();
    world.Initialize(manifold, new b2Transform(), 1.0, new b2Transform(new b2Vec2(0, 1.5)), 1.0);
    expect(world.normal).toEqual(new b2Vec2(0, 1));
    expect(world.points[0]).toEqual(new b2Vec2(0, 0.5 * (1.0 + 0.5)));
  });

  it('e_circles with coincident centers keeps the default normal (1, 0)', () => {
    const manifold = new b2Manifold();
    manifold.type = b2Manifold.e_circles;
    manifold.pointCount = 1;
    const world = new b2WorldManifold();
    world.Initialize(manifold, new b2Transform(), 0.5, new b2Transform(new b2Vec2(0.5 * b2_epsilon, 0)), 0.5);
    expect(world.normal).toEqual(new b2Vec2(1, 0));
  });

  it('e_faceA: rotates the normal by xfA and projects each clip point onto both surfaces', () => {
    const manifold = new b2Manifold();
    manifold.type = b2Manifold.e_faceA;
    manifold.pointCount = 2;
    manifold.localNormal.Set(0, 1);
    manifold.localPoint.Set(0, 0.5);
    manifold.points[0].localPoint.Set(-0.5, -0.5);
    manifold.points[1].localPoint.Set(0.5, -0.5);
    const xfA = new b2Transform();
    const xfB = new b2Transform(new b2Vec2(0, 0.9));
    const world = new b2WorldManifold();
    world.Initialize(manifold, xfA, 0.01, xfB, 0.01);
    expect(world.normal).toEqual(new b2Vec2(0, 1));
    // clip point y = 0.4, plane y = 0.5: cA.y = 0.4 + (0.01 - (-0.1)) = 0.51, cB.y = 0.39.
    const cAy = 0.4 + (0.01 - (0.4 - 0.5) * 1);
    const cBy = 0.4 - 0.01 * 1;
    expect(world.points[0].x).toBe(-0.5);
    expect(world.points[0].y).toBe(0.5 * (cAy + cBy));
    expect(world.points[1].x).toBe(0.5);
  });

  it('e_faceB: uses xfB for the reference face and flips the normal to point from A to B', () => {
    const manifold = new b2Manifold();
    manifold.type = b2Manifold.e_faceB;
    manifold.pointCount = 1;
    manifold.localNormal.Set(1, 0);
    manifold.localPoint.Set(0.5, 0);
    manifold.points[0].localPoint.Set(0, 0);
    const world = new b2WorldManifold();
    world.Initialize(manifold, new b2Transform(new b2Vec2(3, 0)), 0.25, new b2Transform(new b2Vec2(2.4, 0)), 0.0);
    expect(world.normal).toEqual(new b2Vec2(-1, -0));
    // Face B's plane is at x = 2.9 and A's clip point at x = 3: cB = 2.9, cA = 3 - 0.25.
    const planeX = 0.5 + 2.4;
    const cB = 3 + (0.0 - (3 - planeX) * 1) * 1;
    const cA = 3 - 0.25 * 1;
    expect(world.points[0].x).toBe(0.5 * (cA + cB));
    expect(world.points[0].x).toBeCloseTo(2.825, 15);
  });
});

describe('b2GetPointStates', () => {
  it('classifies points as removed, persisted and added by contact id key', () => {
    const m1 = new b2Manifold();
    m1.pointCount = 2;
    m1.points[0].id.key = 1;
    m1.points[1].id.key = 2;
    const m2 = new b2Manifold();
    m2.pointCount = 1;
    m2.points[0].id.key = 2;
    const state1: b2PointState[] = [];
    const state2: b2PointState[] = [];
    b2GetPointStates(state1, state2, m1, m2);
    expect(state1).toEqual([b2_removeState, b2_persistState]);
    expect(state2).toEqual([b2_persistState, b2_nullState]);

    m2.points[0].id.key = 3;
    b2GetPointStates(state1, state2, m1, m2);
    expect(state1).toEqual([b2_removeState, b2_removeState]);
    expect(state2).toEqual([b2_addState, b2_nullState]);
    expect(b2PointState.b2_addState).toBe(1);
  });
});

describe('b2ClipSegmentToLine', () => {
  function segment(x0: number, y0: number, x1: number, y1: number): b2ClipVertex[] {
    const vIn = [new b2ClipVertex(), new b2ClipVertex()];
    vIn[0].v.Set(x0, y0);
    vIn[1].v.Set(x1, y1);
    vIn[0].id.key = 0x01000102;
    vIn[1].id.key = 0x01000203;
    return vIn;
  }

  it('keeps both points behind the plane unchanged', () => {
    const vOut = [new b2ClipVertex(), new b2ClipVertex()];
    const n = b2ClipSegmentToLine(vOut, segment(-1, 0, 1, 0), new b2Vec2(1, 0), 2, 7);
    expect(n).toBe(2);
    expect(vOut[0].v).toEqual(new b2Vec2(-1, 0));
    expect(vOut[1].id.key).toBe(0x01000203);
  });

  it('replaces the point in front with the intersection, tagged as vertexA hitting edgeB', () => {
    const vOut = [new b2ClipVertex(), new b2ClipVertex()];
    const n = b2ClipSegmentToLine(vOut, segment(-1, 0, 3, 2), new b2Vec2(1, 0), 1, 7);
    expect(n).toBe(2);
    expect(vOut[0].v).toEqual(new b2Vec2(-1, 0));
    const interp = -2 / (-2 - 2);
    expect(vOut[1].v).toEqual(new b2Vec2(-1 + interp * 4, 0 + interp * 2));
    expect(vOut[1].id.cf).toMatchObject({ indexA: 7, indexB: 1, typeA: b2ContactFeature.e_vertex, typeB: b2ContactFeature.e_face });
  });

  it('returns no points when both are in front of the plane', () => {
    const vOut = [new b2ClipVertex(), new b2ClipVertex()];
    expect(b2ClipSegmentToLine(vOut, segment(2, 0, 3, 0), new b2Vec2(1, 0), 1, 0)).toBe(0);
  });
});

describe('b2AABB', () => {
  it('computes center, extents and perimeter', () => {
    const box = aabb(-1, 2, 3, 8);
    expect(box.GetCenter(new b2Vec2())).toEqual(new b2Vec2(1, 5));
    expect(box.GetExtents(new b2Vec2())).toEqual(new b2Vec2(2, 3));
    expect(box.GetPerimeter()).toBe(20);
  });

  it('IsValid rejects inverted and non-finite bounds', () => {
    expect(aabb(0, 0, 1, 1).IsValid()).toBe(true);
    expect(aabb(0, 0, 0, 0).IsValid()).toBe(true);
    expect(aabb(1, 0, 0, 1).IsValid()).toBe(false);
    expect(aabb(0, 0, Infinity, 1).IsValid()).toBe(false);
    expect(aabb(0, NaN, 1, 1).IsValid()).toBe(false);
  });

  it('Combine and Combine2 take the union', () => {
    const box = aabb(0, 0, 1, 1);
    box.Combine(aabb(-1, 0.5, 0.5, 2));
    expect(box).toEqual(aabb(-1, 0, 1, 2));
    const out = new b2AABB();
    out.Combine2(aabb(0, 0, 1, 1), aabb(2, -3, 4, 0));
    expect(out).toEqual(aabb(0, -3, 4, 1));
  });

  it('Contains is inclusive on every side', () => {
    const box = aabb(0, 0, 2, 2);
    expect(box.Contains(aabb(0, 0, 2, 2))).toBe(true);
    expect(box.Contains(aabb(0.5, 0.5, 1, 1))).toBe(true);
    expect(box.Contains(aabb(-0.1, 0.5, 1, 1))).toBe(false);
    expect(box.Contains(aabb(0.5, 0.5, 1, 2.1))).toBe(false);
  });

  it('RayCast reports the entry fraction and the slab normal', () => {
    const box = aabb(0, 0, 2, 2);
    const input = new b2RayCastInput();
    input.p1.Set(-2, 1);
    input.p2.Set(2, 1);
    input.maxFraction = 1;
    const output = new b2RayCastOutput();
    expect(box.RayCast(output, input)).toBe(true);
    expect(output.fraction).toBe(0.5);
    expect(output.normal).toEqual(new b2Vec2(-1, 0));

    input.p1.Set(1, 5);
    input.p2.Set(1, 1);
    expect(box.RayCast(output, input)).toBe(true);
    expect(output.fraction).toBe(0.75);
    expect(output.normal).toEqual(new b2Vec2(0, 1));
  });

  it('RayCast misses parallel rays outside, rays starting inside and hits beyond maxFraction', () => {
    const box = aabb(0, 0, 2, 2);
    const input = new b2RayCastInput();
    const output = new b2RayCastOutput();
    input.maxFraction = 1;
    input.p1.Set(-2, 3);
    input.p2.Set(2, 3);
    expect(box.RayCast(output, input)).toBe(false);
    input.p1.Set(1, 1);
    input.p2.Set(3, 1);
    expect(box.RayCast(output, input)).toBe(false);
    input.p1.Set(-2, 1);
    input.p2.Set(2, 1);
    input.maxFraction = 0.4;
    expect(box.RayCast(output, input)).toBe(false);
  });

  it('b2TestOverlap counts touching boxes as overlapping', () => {
    expect(b2TestOverlap(aabb(0, 0, 1, 1), aabb(1, 0, 2, 1))).toBe(true);
    expect(b2TestOverlap(aabb(0, 0, 1, 1), aabb(0.5, 0.5, 0.6, 0.6))).toBe(true);
    expect(b2TestOverlap(aabb(0, 0, 1, 1), aabb(1.001, 0, 2, 1))).toBe(false);
    expect(b2TestOverlap(aabb(0, 0, 1, 1), aabb(0, -2, 1, -0.001))).toBe(false);
  });
});

describe('b2TestOverlapShapes', () => {
  it('reports overlap when GJK distance with radii is below 10 * b2_epsilon', () => {
    const circle = new b2CircleShape();
    circle.m_radius = 0.5;
    const box = new b2PolygonShape().SetAsBox(1, 1);
    const xfBox = new b2Transform();
    expect(b2TestOverlapShapes(circle, 0, box, 0, new b2Transform(new b2Vec2(1.4, 0)), xfBox)).toBe(true);
    expect(b2TestOverlapShapes(circle, 0, box, 0, new b2Transform(new b2Vec2(1.6, 0)), xfBox)).toBe(false);
    expect(b2TestOverlapShapes(box, 0, box, 0, xfBox, new b2Transform(new b2Vec2(2.01, 0)))).toBe(true);
    expect(b2TestOverlapShapes(box, 0, box, 0, xfBox, new b2Transform(new b2Vec2(2.03, 0)))).toBe(false);
  });
});
