import { describe, expect, it } from 'vitest';
import { b2AABB, b2RayCastInput, b2RayCastOutput } from '../../../src/collision/b2Collision';
import { b2ChainShape } from '../../../src/collision/shapes/b2ChainShape';
import { b2EdgeShape } from '../../../src/collision/shapes/b2EdgeShape';
import { b2MassData, b2Shape } from '../../../src/collision/shapes/b2Shape';
import { b2Transform, b2Vec2 } from '../../../src/common/b2Math';
import { b2_polygonRadius } from '../../../src/common/b2Settings';

const square = (): b2Vec2[] => [new b2Vec2(0, 0), new b2Vec2(1, 0), new b2Vec2(1, 1), new b2Vec2(0, 1)];

describe('b2ChainShape', () => {
  it('CreateLoop copies the vertices, repeats the first and links the ends as ghosts', () => {
    const input = square();
    const chain = new b2ChainShape();
    chain.CreateLoop(input, input.length);
    expect(chain.GetType()).toBe(b2Shape.e_chain);
    expect(chain.m_count).toBe(5);
    expect(chain.GetChildCount()).toBe(4);
    expect(chain.m_vertices[4]).toEqual(new b2Vec2(0, 0));
    expect(chain.m_vertices[4]).not.toBe(chain.m_vertices[0]);
    expect(chain.m_vertices[0]).not.toBe(input[0]);
    expect(chain.m_prevVertex).toEqual(new b2Vec2(0, 1));
    expect(chain.m_nextVertex).toEqual(new b2Vec2(1, 0));
    expect(chain.m_hasPrevVertex).toBe(true);
    expect(chain.m_hasNextVertex).toBe(true);
    input[1].x = 42;
    expect(chain.m_vertices[1].x).toBe(1);
  });

  it('GetChildEdge of a loop has ghost vertices on both sides of every edge', () => {
    const chain = new b2ChainShape();
    chain.CreateLoop(square(), 4);
    const edge = new b2EdgeShape();

    chain.GetChildEdge(edge, 0);
    expect(edge.GetType()).toBe(b2Shape.e_edge);
    expect(edge.m_radius).toBe(chain.m_radius);
    expect(edge.m_vertex1).toEqual(new b2Vec2(0, 0));
    expect(edge.m_vertex2).toEqual(new b2Vec2(1, 0));
    expect(edge.m_vertex0).toEqual(new b2Vec2(0, 1));
    expect(edge.m_vertex3).toEqual(new b2Vec2(1, 1));
    expect(edge.m_hasVertex0).toBe(true);
    expect(edge.m_hasVertex3).toBe(true);

    chain.GetChildEdge(edge, 3);
    expect(edge.m_vertex1).toEqual(new b2Vec2(0, 1));
    expect(edge.m_vertex2).toEqual(new b2Vec2(0, 0));
    expect(edge.m_vertex0).toEqual(new b2Vec2(1, 1));
    expect(edge.m_vertex3).toEqual(new b2Vec2(1, 0));
    expect(edge.m_hasVertex0).toBe(true);
    expect(edge.m_hasVertex3).toBe(true);
  });

  it('GetChildEdge of an open chain has no ghosts at the ends unless prev/next are set', () => {
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(0, 0), new b2Vec2(1, 0), new b2Vec2(2, 1)], 3);
    expect(chain.GetChildCount()).toBe(2);
    const edge = new b2EdgeShape();

    chain.GetChildEdge(edge, 0);
    expect(edge.m_hasVertex0).toBe(false);
    expect(edge.m_hasVertex3).toBe(true);
    expect(edge.m_vertex3).toEqual(new b2Vec2(2, 1));

    chain.GetChildEdge(edge, 1);
    expect(edge.m_hasVertex0).toBe(true);
    expect(edge.m_vertex0).toEqual(new b2Vec2(0, 0));
    expect(edge.m_hasVertex3).toBe(false);

    chain.SetPrevVertex(new b2Vec2(-1, -1));
    chain.SetNextVertex(new b2Vec2(3, 3));
    chain.GetChildEdge(edge, 0);
    expect(edge.m_hasVertex0).toBe(true);
    expect(edge.m_vertex0).toEqual(new b2Vec2(-1, -1));
    chain.GetChildEdge(edge, 1);
    expect(edge.m_hasVertex3).toBe(true);
    expect(edge.m_vertex3).toEqual(new b2Vec2(3, 3));
  });

  it('refuses to be created twice or with too few vertices', () => {
    const chain = new b2ChainShape();
    expect(() => chain.CreateChain([new b2Vec2(0, 0)], 1)).toThrow();
    expect(() => new b2ChainShape().CreateLoop([new b2Vec2(0, 0), new b2Vec2(1, 0)], 2)).toThrow();
    chain.CreateChain([new b2Vec2(0, 0), new b2Vec2(1, 0)], 2);
    expect(() => chain.CreateChain([new b2Vec2(0, 0), new b2Vec2(1, 0)], 2)).toThrow();
  });

  it('has zero mass and never contains a point', () => {
    const chain = new b2ChainShape();
    chain.CreateLoop(square(), 4);
    const massData = new b2MassData();
    massData.center.Set(5, 5);
    chain.ComputeMass(massData, 3.0);
    expect(massData.mass).toBe(0);
    expect(massData.I).toBe(0);
    expect(massData.center).toEqual(new b2Vec2(0, 0));
    expect(chain.TestPoint(new b2Transform(), new b2Vec2(0.5, 0.5))).toBe(false);
  });

  it('ComputeAABB bounds one child edge without the skin radius', () => {
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(0, 0), new b2Vec2(2, 1), new b2Vec2(3, -1)], 3);
    expect(chain.m_radius).toBe(b2_polygonRadius);
    const aabb = new b2AABB();
    chain.ComputeAABB(aabb, new b2Transform(new b2Vec2(1, 1)), 1);
    expect(aabb.lowerBound).toEqual(new b2Vec2(3, 0));
    expect(aabb.upperBound).toEqual(new b2Vec2(4, 2));
  });

  it('RayCast tests the chosen child edge only', () => {
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(0, 0), new b2Vec2(2, 0), new b2Vec2(4, 0)], 3);
    const input = new b2RayCastInput();
    input.p1.Set(1, 1);
    input.p2.Set(1, -1);
    input.maxFraction = 1.0;
    const output = new b2RayCastOutput();
    expect(chain.RayCast(output, input, new b2Transform(), 0)).toBe(true);
    expect(output.fraction).toBe(0.5);
    expect(output.normal.y).toBe(1);
    expect(chain.RayCast(output, input, new b2Transform(), 1)).toBe(false);
  });

  it('Clone deep-copies the vertices and the ghost settings', () => {
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(0, 0), new b2Vec2(1, 0)], 2);
    chain.SetNextVertex(new b2Vec2(2, 0));
    const clone = chain.Clone();
    expect(clone.m_count).toBe(2);
    expect(clone.m_vertices).toEqual(chain.m_vertices);
    expect(clone.m_vertices[0]).not.toBe(chain.m_vertices[0]);
    expect(clone.m_hasNextVertex).toBe(true);
    expect(clone.m_nextVertex).toEqual(new b2Vec2(2, 0));
    expect(clone.m_hasPrevVertex).toBe(false);
  });
});
