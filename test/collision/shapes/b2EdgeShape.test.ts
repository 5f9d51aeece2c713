import { describe, expect, it } from 'vitest';
import { b2AABB, b2RayCastInput, b2RayCastOutput } from '../../../src/collision/b2Collision';
import { b2EdgeShape } from '../../../src/collision/shapes/b2EdgeShape';
import { b2MassData, b2Shape } from '../../../src/collision/shapes/b2Shape';
import { b2Transform, b2Vec2 } from '../../../src/common/b2Math';
import { b2_polygonRadius } from '../../../src/common/b2Settings';

describe('b2EdgeShape', () => {
  it('starts with the polygon skin radius, no ghost vertices and one child', () => {
    const edge = new b2EdgeShape();
    expect(edge.GetType()).toBe(b2Shape.e_edge);
    expect(edge.m_radius).toBe(b2_polygonRadius);
    expect(edge.m_hasVertex0).toBe(false);
    expect(edge.m_hasVertex3).toBe(false);
    expect(edge.GetChildCount()).toBe(1);
  });

  it('Set copies the vertices and clears the ghost flags', () => {
    const edge = new b2EdgeShape();
    edge.m_hasVertex0 = true;
    edge.m_hasVertex3 = true;
    const v1 = new b2Vec2(1, 2);
    edge.Set(v1, new b2Vec2(3, 4));
    expect(edge.m_vertex1).toEqual(new b2Vec2(1, 2));
    expect(edge.m_vertex2).toEqual(new b2Vec2(3, 4));
    expect(edge.m_vertex1).not.toBe(v1);
    expect(edge.m_hasVertex0).toBe(false);
    expect(edge.m_hasVertex3).toBe(false);
  });

  it('has zero mass and inertia, centered at the midpoint', () => {
    const edge = new b2EdgeShape().Set(new b2Vec2(0, 0), new b2Vec2(2, 4));
    const massData = new b2MassData();
    edge.ComputeMass(massData, 10.0);
    expect(massData.mass).toBe(0);
    expect(massData.I).toBe(0);
    expect(massData.center).toEqual(new b2Vec2(1, 2));
  });

  it('never contains a point', () => {
    const edge = new b2EdgeShape().Set(new b2Vec2(-1, 0), new b2Vec2(1, 0));
    expect(edge.TestPoint(new b2Transform(), new b2Vec2(0, 0))).toBe(false);
  });

  it('ComputeAABB bounds both transformed vertices plus the radius', () => {
    const edge = new b2EdgeShape().Set(new b2Vec2(-1, 2), new b2Vec2(3, -4));
    const aabb = new b2AABB();
    edge.ComputeAABB(aabb, new b2Transform(new b2Vec2(10, 0)), 0);
    const r = b2_polygonRadius;
    expect(aabb.lowerBound).toEqual(new b2Vec2(9 - r, -4 - r));
    expect(aabb.upperBound).toEqual(new b2Vec2(13 + r, 2 + r));
  });

  it('RayCast is two-sided: the normal faces the ray origin', () => {
    const edge = new b2EdgeShape().Set(new b2Vec2(-1, 0), new b2Vec2(1, 0));
    const xf = new b2Transform();
    const input = new b2RayCastInput();
    const output = new b2RayCastOutput();
    input.p1.Set(0.5, 2.0);
    input.p2.Set(0.5, -2.0);
    input.maxFraction = 1.0;
    expect(edge.RayCast(output, input, xf, 0)).toBe(true);
    expect(output.fraction).toBe(0.5);
    expect(output.normal.x).toBe(-0);
    expect(output.normal.y).toBe(1);

    input.p1.Set(0.5, -2.0);
    input.p2.Set(0.5, 2.0);
    expect(edge.RayCast(output, input, xf, 0)).toBe(true);
    expect(output.normal.y).toBe(-1);
  });

  it('RayCast misses parallel rays, rays past the ends and hits beyond maxFraction', () => {
    const edge = new b2EdgeShape().Set(new b2Vec2(-1, 0), new b2Vec2(1, 0));
    const xf = new b2Transform();
    const input = new b2RayCastInput();
    const output = new b2RayCastOutput();
    input.maxFraction = 1.0;
    input.p1.Set(-2, 1);
    input.p2.Set(2, 1);
    expect(edge.RayCast(output, input, xf, 0)).toBe(false);
    input.p1.Set(1.5, 1);
    input.p2.Set(1.5, -1);
    expect(edge.RayCast(output, input, xf, 0)).toBe(false);
    input.p1.Set(0, 1);
    input.p2.Set(0, -1);
    input.maxFraction = 0.4;
    expect(edge.RayCast(output, input, xf, 0)).toBe(false);
  });

  it('Clone copies vertices, ghost vertices and flags', () => {
    const edge = new b2EdgeShape().Set(new b2Vec2(0, 0), new b2Vec2(1, 0));
    edge.m_vertex0.Set(-1, 0);
    edge.m_hasVertex0 = true;
    const clone = edge.Clone();
    expect(clone.m_vertex1).toEqual(edge.m_vertex1);
    expect(clone.m_vertex2).toEqual(edge.m_vertex2);
    expect(clone.m_vertex0).toEqual(new b2Vec2(-1, 0));
    expect(clone.m_hasVertex0).toBe(true);
    expect(clone.m_hasVertex3).toBe(false);
    expect(clone.m_vertex1).not.toBe(edge.m_vertex1);
  });
});
