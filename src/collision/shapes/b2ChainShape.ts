/*
 * A free-form sequence of line segments (b2ChainShape.h, b2ChainShape.cpp).
 */

import { b2Max, b2Min, b2Vec2 } from '../../common/b2Math';
import type { b2Transform } from '../../common/b2Math';
import { b2_polygonRadius, b2Assert } from '../../common/b2Settings';
import type { b2AABB, b2RayCastInput, b2RayCastOutput } from '../b2Collision';
import { b2EdgeShape } from './b2EdgeShape';
import { b2Shape } from './b2Shape';
import type { b2MassData } from './b2Shape';
import { b2CheckChainVertices } from './b2ShapeValidation';
import { b2ArgumentError, b2CheckVec2 } from '../../common/b2ArgumentError';

function checkUnused(method: string, chain: b2ChainShape): void {
  if (chain.m_vertices.length !== 0 || chain.m_count !== 0) {
    throw new b2ArgumentError(method, 'this chain', 'already has vertices (create a new b2ChainShape)');
  }
}

const s_edgeShape = new b2EdgeShape();

/**
 * A chain shape is a free form sequence of line segments.
 * The chain has two-sided collision, so you can use inside and outside collision.
 * Therefore, you may use any winding order.
 * Connectivity information is used to create smooth collisions.
 * WARNING: The chain will not collide properly if there are self-intersections.
 */
export class b2ChainShape extends b2Shape {
  /** The vertices. Owned by this class (copies of the caller's); empty until created. */
  m_vertices: b2Vec2[] = [];

  /** The vertex count. */
  m_count = 0;

  readonly m_prevVertex = new b2Vec2();
  readonly m_nextVertex = new b2Vec2();
  m_hasPrevVertex = false;
  m_hasNextVertex = false;

  constructor() {
    super(b2Shape.e_chain, b2_polygonRadius);
  }

  /**
   * Create a loop. This automatically adjusts connectivity.
   * @param vertices an array of vertices, these are copied
   * @param count the vertex count
   */
  CreateLoop(vertices: readonly Readonly<b2Vec2>[], count: number = vertices.length): void {
    checkUnused('b2ChainShape.CreateLoop', this);
    b2CheckChainVertices('b2ChainShape.CreateLoop', 'vertices', 'count', vertices, count, true);
    b2Assert(this.m_vertices.length === 0 && this.m_count === 0);
    b2Assert(count >= 3);
    this.m_count = count + 1;
    const owned: b2Vec2[] = [];
    for (let i = 0; i < count; ++i) {
      owned.push(new b2Vec2(vertices[i].x, vertices[i].y));
    }
    owned.push(owned[0].Clone());
    this.m_vertices = owned;
    this.m_prevVertex.Assign(owned[this.m_count - 2]);
    this.m_nextVertex.Assign(owned[1]);
    this.m_hasPrevVertex = true;
    this.m_hasNextVertex = true;
  }

  /**
   * Create a chain with isolated end vertices.
   * @param vertices an array of vertices, these are copied
   * @param count the vertex count
   */
  CreateChain(vertices: readonly Readonly<b2Vec2>[], count: number = vertices.length): void {
    checkUnused('b2ChainShape.CreateChain', this);
    b2CheckChainVertices('b2ChainShape.CreateChain', 'vertices', 'count', vertices, count, false);
    b2Assert(this.m_vertices.length === 0 && this.m_count === 0);
    b2Assert(count >= 2);
    this.m_count = count;
    const owned: b2Vec2[] = [];
    for (let i = 0; i < count; ++i) {
      owned.push(new b2Vec2(vertices[i].x, vertices[i].y));
    }
    this.m_vertices = owned;
    this.m_hasPrevVertex = false;
    this.m_hasNextVertex = false;
  }

  /**
   * Establish connectivity to a vertex that precedes the first vertex.
   * Don't call this for loops.
   */
  SetPrevVertex(prevVertex: Readonly<b2Vec2>): void {
    b2CheckVec2('b2ChainShape.SetPrevVertex', 'prevVertex', prevVertex);
    this.m_prevVertex.Assign(prevVertex);
    this.m_hasPrevVertex = true;
  }

  /**
   * Establish connectivity to a vertex that follows the last vertex.
   * Don't call this for loops.
   */
  SetNextVertex(nextVertex: Readonly<b2Vec2>): void {
    b2CheckVec2('b2ChainShape.SetNextVertex', 'nextVertex', nextVertex);
    this.m_nextVertex.Assign(nextVertex);
    this.m_hasNextVertex = true;
  }

  /** Implement b2Shape. Vertices are copied. */
  Clone(): b2ChainShape {
    const clone = new b2ChainShape();
    clone.CreateChain(this.m_vertices, this.m_count);
    clone.m_prevVertex.Assign(this.m_prevVertex);
    clone.m_nextVertex.Assign(this.m_nextVertex);
    clone.m_hasPrevVertex = this.m_hasPrevVertex;
    clone.m_hasNextVertex = this.m_hasNextVertex;
    return clone;
  }

  /** @see b2Shape::GetChildCount */
  GetChildCount(): number {
    // edge count = vertex count - 1
    return this.m_count - 1;
  }

  /** Get a child edge. */
  GetChildEdge(edge: b2EdgeShape, index: number): void {
    b2Assert(0 <= index && index < this.m_count - 1);
    edge.m_type = b2Shape.e_edge;
    edge.m_radius = this.m_radius;

    edge.m_vertex1.Assign(this.m_vertices[index + 0]);
    edge.m_vertex2.Assign(this.m_vertices[index + 1]);

    if (index > 0) {
      edge.m_vertex0.Assign(this.m_vertices[index - 1]);
      edge.m_hasVertex0 = true;
    } else {
      edge.m_vertex0.Assign(this.m_prevVertex);
      edge.m_hasVertex0 = this.m_hasPrevVertex;
    }

    if (index < this.m_count - 2) {
      edge.m_vertex3.Assign(this.m_vertices[index + 2]);
      edge.m_hasVertex3 = true;
    } else {
      edge.m_vertex3.Assign(this.m_nextVertex);
      edge.m_hasVertex3 = this.m_hasNextVertex;
    }
  }

  /**
   * This always return false.
   * @see b2Shape::TestPoint
   */
  TestPoint(xf: Readonly<b2Transform>, p: Readonly<b2Vec2>): boolean {
    return false;
  }

  /** Implement b2Shape. */
  RayCast(output: b2RayCastOutput, input: Readonly<b2RayCastInput>, xf: Readonly<b2Transform>, childIndex: number): boolean {
    b2Assert(childIndex < this.m_count);

    const edgeShape = s_edgeShape;

    const i1 = childIndex;
    let i2 = childIndex + 1;
    if (i2 === this.m_count) {
      i2 = 0;
    }

    edgeShape.m_vertex1.Assign(this.m_vertices[i1]);
    edgeShape.m_vertex2.Assign(this.m_vertices[i2]);

    return edgeShape.RayCast(output, input, xf, 0);
  }

  /** @see b2Shape::ComputeAABB */
  ComputeAABB(aabb: b2AABB, xf: Readonly<b2Transform>, childIndex: number): void {
    b2Assert(childIndex < this.m_count);

    const i1 = childIndex;
    let i2 = childIndex + 1;
    if (i2 === this.m_count) {
      i2 = 0;
    }

    const qc = xf.q.c;
    const qs = xf.q.s;
    const a = this.m_vertices[i1];
    const b = this.m_vertices[i2];
    const v1x = qc * a.x - qs * a.y + xf.p.x;
    const v1y = qs * a.x + qc * a.y + xf.p.y;
    const v2x = qc * b.x - qs * b.y + xf.p.x;
    const v2y = qs * b.x + qc * b.y + xf.p.y;

    aabb.lowerBound.Set(b2Min(v1x, v2x), b2Min(v1y, v2y));
    aabb.upperBound.Set(b2Max(v1x, v2x), b2Max(v1y, v2y));
  }

  /**
   * Chains have zero mass.
   * @see b2Shape::ComputeMass
   */
  ComputeMass(massData: b2MassData, density: number): void {
    massData.mass = 0.0;
    massData.center.SetZero();
    massData.I = 0.0;
  }
}
