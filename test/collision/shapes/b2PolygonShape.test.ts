import { describe, expect, it } from 'vitest';
import { b2AABB, b2RayCastInput, b2RayCastOutput } from '../../../src/collision/b2Collision';
import { b2PolygonShape } from '../../../src/collision/shapes/b2PolygonShape';
import { b2MassData } from '../../../src/collision/shapes/b2Shape';
import { b2Rot, b2Transform, b2Vec2 } from '../../../src/common/b2Math';
import { b2_pi, b2_polygonRadius } from '../../../src/common/b2Settings';
import {
  checkVectorFamily,
  collisionVectors,
  compareDouble,
  compareVec2,
  describeFamilyResult,
  makePolygon,
  makeTransform,
  type PolygonMassAndRayCastCase,
} from '../../support/collisionVectors';

/** null when ComputeMass, ComputeAABB and RayCast (with transform xf) all match the reference case. */
function checkCase(c: PolygonMassAndRayCastCase, xf: b2Transform): string | null {
  const polygon = makePolygon(c.polygon);
  const massData = new b2MassData();
  polygon.ComputeMass(massData, c.density);
  const mass =
    compareDouble('mass.mass', massData.mass, c.mass.mass) ??
    compareVec2('mass.center', massData.center, c.mass.center) ??
    compareDouble('mass.I', massData.I, c.mass.I);
  if (mass !== null) return mass;

  const aabb = new b2AABB();
  polygon.ComputeAABB(aabb, xf, 0);
  const box = compareVec2('aabb.lowerBound', aabb.lowerBound, c.aabb.lowerBound) ?? compareVec2('aabb.upperBound', aabb.upperBound, c.aabb.upperBound);
  if (box !== null) return box;

  const input = new b2RayCastInput();
  input.p1.Set(c.ray.p1.x, c.ray.p1.y);
  input.p2.Set(c.ray.p2.x, c.ray.p2.y);
  input.maxFraction = c.ray.maxFraction;
  const output = new b2RayCastOutput();
  const hit = polygon.RayCast(output, input, xf, 0);
  if (hit !== c.hit) return `hit: expected ${c.hit}, got ${hit}`;
  if (hit) {
    if (c.fraction === undefined || c.normal === undefined) return 'reference hit has no fraction/normal';
    return compareDouble('fraction', output.fraction, c.fraction) ?? compareVec2('normal', output.normal, c.normal);
  }
  return null;
}

describe('b2PolygonShape reference vectors', () => {
  it('reproduces ComputeMass, ComputeAABB and RayCast for all 300 reference polygons bit for bit (documented reference-rotation outliers aside)', () => {
    const cases = collisionVectors.polygonMassAndRayCast;
    expect(cases.length).toBe(300);
    const result = checkVectorFamily(cases, (testCase) => {
      const xf = makeTransform(testCase.xf);
      return { transforms: [xf], check: () => checkCase(testCase, xf) };
    });
    expect(describeFamilyResult('polygonMassAndRayCast', result)).toBeNull();
  });

  it('covers boxes, vertex polygons, hits and misses', () => {
    const cases = collisionVectors.polygonMassAndRayCast;
    expect(cases.some((c) => c.polygon.box !== undefined)).toBe(true);
    expect(cases.some((c) => c.polygon.vertices !== undefined)).toBe(true);
    expect(cases.some((c) => c.hit)).toBe(true);
    expect(cases.some((c) => !c.hit)).toBe(true);
  });
});

describe('b2PolygonShape', () => {
  it('SetAsBox(hx, hy) builds a CCW box with axis normals and a zero centroid', () => {
    const box = new b2PolygonShape().SetAsBox(2.0, 1.0);
    expect(box.GetVertexCount()).toBe(4);
    expect(box.m_radius).toBe(b2_polygonRadius);
    expect(box.m_vertices.slice(0, 4).map((v) => [v.x, v.y])).toEqual([
      [-2, -1],
      [2, -1],
      [2, 1],
      [-2, 1],
    ]);
    expect(box.m_normals.slice(0, 4).map((v) => [v.x, v.y])).toEqual([
      [0, -1],
      [1, 0],
      [0, 1],
      [-1, 0],
    ]);
    expect(box.m_centroid).toEqual(new b2Vec2(0, 0));
    expect(box.m_vertices.length).toBe(4);
  });

  it('SetAsBox(hx, hy, center, angle) rotates then translates vertices and rotates normals', () => {
    const angle = 0.3;
    const center = new b2Vec2(1.5, -0.5);
    const box = new b2PolygonShape().SetAsBox(2.0, 1.0, center, angle);
    const q = new b2Rot(angle);
    expect(box.m_centroid).toEqual(center);
    // Vertex 1 is (hx, -hy) = (2, -1).
    expect(box.m_vertices[1].x).toBe(q.c * 2.0 - q.s * -1.0 + 1.5);
    expect(box.m_vertices[1].y).toBe(q.s * 2.0 + q.c * -1.0 + -0.5);
    // Normal 1 is (1, 0).
    expect(box.m_normals[1].x).toBe(q.c * 1.0 - q.s * 0.0);
    expect(box.m_normals[1].y).toBe(q.s * 1.0 + q.c * 0.0);
  });

  it('Set computes unit outward normals and the area centroid without reordering vertices', () => {
    const triangle = new b2PolygonShape().Set([new b2Vec2(0, 0), new b2Vec2(3, 0), new b2Vec2(0, 3)], 3);
    expect(triangle.GetVertex(2)).toEqual(new b2Vec2(0, 3));
    expect(triangle.m_normals[0]).toEqual(new b2Vec2(0, -1));
    // b2Cross((0, -3), 1) is (-3, -0): the C++ sign of zero survives normalization.
    expect(triangle.m_normals[2]).toEqual(new b2Vec2(-1, -0));
    expect(triangle.m_normals[1].x).toBeCloseTo(Math.SQRT1_2, 15);
    expect(triangle.m_normals[1].y).toBeCloseTo(Math.SQRT1_2, 15);
    expect(triangle.m_centroid.x).toBeCloseTo(1, 15);
    expect(triangle.m_centroid.y).toBeCloseTo(1, 15);
  });

  it('Set rejects fewer than 3 or more than b2_maxPolygonVertices vertices', () => {
    const p = new b2PolygonShape();
    expect(() => p.Set([new b2Vec2(0, 0), new b2Vec2(1, 0)], 2)).toThrow();
    const many = Array.from({ length: 9 }, (_, i) => new b2Vec2(Math.cos(i), Math.sin(i)));
    expect(() => p.Set(many, 9)).toThrow();
  });

  it('ComputeMass of a box gives density * area and the rectangle inertia about the origin', () => {
    const hx = 2.0;
    const hy = 0.5;
    const box = new b2PolygonShape().SetAsBox(hx, hy);
    const massData = new b2MassData();
    box.ComputeMass(massData, 3.0);
    const mass = 3.0 * 4.0 * hx * hy;
    expect(massData.mass).toBe(mass);
    expect(massData.center).toEqual(new b2Vec2(0, 0));
    expect(massData.I).toBeCloseTo((mass * (4 * hx * hx + 4 * hy * hy)) / 12, 12);
  });

  it('ComputeMass of an offset box adds the parallel-axis term', () => {
    const box = new b2PolygonShape().SetAsBox(1.0, 1.0, new b2Vec2(3.0, 0.0), 0.0);
    const massData = new b2MassData();
    box.ComputeMass(massData, 1.0);
    expect(massData.mass).toBeCloseTo(4.0, 14);
    expect(massData.center.x).toBeCloseTo(3.0, 14);
    expect(massData.center.y).toBeCloseTo(0.0, 14);
    expect(massData.I).toBeCloseTo((4.0 * (4 + 4)) / 12 + 4.0 * 9.0, 12);
  });

  it('ComputeAABB bounds the rotated vertices and adds the skin radius', () => {
    const box = new b2PolygonShape().SetAsBox(1.0, 1.0);
    const aabb = new b2AABB();
    const xf = new b2Transform(new b2Vec2(10.0, 0.0), new b2Rot(0.25 * b2_pi));
    box.ComputeAABB(aabb, xf, 0);
    const r = Math.SQRT2 + b2_polygonRadius;
    expect(aabb.lowerBound.x).toBeCloseTo(10.0 - r, 12);
    expect(aabb.upperBound.x).toBeCloseTo(10.0 + r, 12);
    expect(aabb.lowerBound.y).toBeCloseTo(-r, 12);
    expect(aabb.upperBound.y).toBeCloseTo(r, 12);
  });

  it('TestPoint is inclusive inside the transformed polygon and false outside', () => {
    const box = new b2PolygonShape().SetAsBox(1.0, 0.5);
    const xf = new b2Transform(new b2Vec2(2.0, 0.0));
    expect(box.TestPoint(xf, new b2Vec2(2.5, 0.25))).toBe(true);
    expect(box.TestPoint(xf, new b2Vec2(3.0, 0.5))).toBe(true);
    expect(box.TestPoint(xf, new b2Vec2(3.01, 0.0))).toBe(false);
    expect(box.TestPoint(xf, new b2Vec2(0.0, 0.0))).toBe(false);
  });

  it('RayCast reports the entry fraction and face normal, and misses rays starting inside', () => {
    const box = new b2PolygonShape().SetAsBox(1.0, 1.0);
    const xf = new b2Transform();
    const input = new b2RayCastInput();
    input.p1.Set(-3.0, 0.0);
    input.p2.Set(1.0, 0.0);
    input.maxFraction = 1.0;
    const output = new b2RayCastOutput();
    expect(box.RayCast(output, input, xf, 0)).toBe(true);
    expect(output.fraction).toBe(0.5);
    expect(output.normal).toEqual(new b2Vec2(-1.0, 0.0));

    input.maxFraction = 0.4;
    expect(box.RayCast(output, input, xf, 0)).toBe(false);

    input.p1.Set(0.0, 0.0);
    input.p2.Set(3.0, 0.0);
    input.maxFraction = 1.0;
    expect(box.RayCast(output, input, xf, 0)).toBe(false);
  });

  it('holds as many vertex and normal vectors as the largest count set, and keeps them across a smaller one', () => {
    const p = new b2PolygonShape();
    expect(p.m_vertices.length).toBe(0);
    p.SetAsBox(1, 1);
    const first = p.m_vertices[0];
    const firstNormal = p.m_normals[0];
    const hexagon = Array.from({ length: 6 }, (_, i) => new b2Vec2(Math.cos(i), Math.sin(i)));
    p.Set(hexagon, 6);
    expect(p.m_vertices[0]).toBe(first);
    expect(p.m_normals[0]).toBe(firstNormal);
    const sixth = p.m_vertices[5];
    expect([p.m_vertices.length, p.m_normals.length]).toEqual([6, 6]);
    p.SetAsBox(1, 1);
    expect([p.m_vertexCount, p.m_vertices.length, p.m_normals.length]).toEqual([4, 6, 6]);
    expect(p.m_vertices[5]).toBe(sixth);
    expect(new Set([...p.m_vertices, ...p.m_normals]).size).toBe(12);
    p.Reserve(3);
    expect(p.m_vertices.length).toBe(6);
    expect(() => p.Reserve(9)).toThrow('b2PolygonShape.Reserve: count must be an integer in [0, 8], got 9');
    expect(p.m_vertices.length).toBe(6);
  });

  it('Clone copies vertices, normals, centroid and radius into independent storage', () => {
    const box = new b2PolygonShape().SetAsBox(1.0, 2.0, new b2Vec2(0.5, 0.5), 0.1);
    const clone = box.Clone();
    expect(clone).not.toBe(box);
    expect(clone.m_vertexCount).toBe(4);
    expect(clone.m_vertices).toEqual(box.m_vertices);
    expect(clone.m_normals).toEqual(box.m_normals);
    expect(clone.m_centroid).toEqual(box.m_centroid);
    clone.m_vertices[0].x = 99;
    expect(box.m_vertices[0].x).not.toBe(99);
  });
});
