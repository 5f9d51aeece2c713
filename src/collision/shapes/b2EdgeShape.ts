/*
 * A line segment (edge) shape (b2EdgeShape.h, b2EdgeShape.cpp).
 */

import { b2Max, b2Min, b2Vec2 } from '../../common/b2Math';
import type { b2Transform } from '../../common/b2Math';
import { b2_polygonRadius } from '../../common/b2Settings';
import type { b2AABB, b2RayCastInput, b2RayCastOutput } from '../b2Collision';
import { b2Shape } from './b2Shape';
import type { b2MassData } from './b2Shape';
import { b2CheckEdgeVertices } from './b2ShapeValidation';

const s_normal = new b2Vec2();

/**
 * A line segment (edge) shape. These can be connected in chains or loops to other edge shapes.
 * The connectivity information is used to ensure correct contact normals.
 */
export class b2EdgeShape extends b2Shape {
  /** These are the edge vertices */
  readonly m_vertex1 = new b2Vec2();
  readonly m_vertex2 = new b2Vec2();

  /** Optional adjacent vertices. These are used for smooth collision. */
  readonly m_vertex0 = new b2Vec2();
  readonly m_vertex3 = new b2Vec2();
  m_hasVertex0 = false;
  m_hasVertex3 = false;

  constructor() {
    super(b2Shape.e_edge, b2_polygonRadius);
  }

  /** Set this as an isolated edge. */
  Set(v1: Readonly<b2Vec2>, v2: Readonly<b2Vec2>): this {
    b2CheckEdgeVertices('b2EdgeShape.Set', 'v1', 'v2', v1, v2);
    this.m_vertex1.Assign(v1);
    this.m_vertex2.Assign(v2);
    this.m_hasVertex0 = false;
    this.m_hasVertex3 = false;
    return this;
  }

  /** Implement b2Shape. */
  Clone(): b2EdgeShape {
    const clone = new b2EdgeShape();
    clone.m_type = this.m_type;
    clone.m_radius = this.m_radius;
    clone.m_vertex1.Assign(this.m_vertex1);
    clone.m_vertex2.Assign(this.m_vertex2);
    clone.m_vertex0.Assign(this.m_vertex0);
    clone.m_vertex3.Assign(this.m_vertex3);
    clone.m_hasVertex0 = this.m_hasVertex0;
    clone.m_hasVertex3 = this.m_hasVertex3;
    return clone;
  }

  /** @see b2Shape::GetChildCount */
  GetChildCount(): number {
    return 1;
  }

  /** @see b2Shape::TestPoint */
  TestPoint(xf: Readonly<b2Transform>, p: Readonly<b2Vec2>): boolean {
    return false;
  }

  /**
   * Implement b2Shape.
   * p = p1 + t * d
   * v = v1 + s * e
   * p1 + t * d = v1 + s * e
   * s * e - t * d = p1 - v1
   */
  RayCast(output: b2RayCastOutput, input: Readonly<b2RayCastInput>, xf: Readonly<b2Transform>, childIndex: number): boolean {
    // Put the ray into the edge's frame of reference.
    const qc = xf.q.c;
    const qs = xf.q.s;
    const t1x = input.p1.x - xf.p.x;
    const t1y = input.p1.y - xf.p.y;
    const p1x = qc * t1x + qs * t1y;
    const p1y = -qs * t1x + qc * t1y;
    const t2x = input.p2.x - xf.p.x;
    const t2y = input.p2.y - xf.p.y;
    const p2x = qc * t2x + qs * t2y;
    const p2y = -qs * t2x + qc * t2y;
    const dx = p2x - p1x;
    const dy = p2y - p1y;

    const v1 = this.m_vertex1;
    const v2 = this.m_vertex2;
    const ex = v2.x - v1.x;
    const ey = v2.y - v1.y;
    const normal = s_normal.Set(ey, -ex);
    normal.Normalize();

    // q = p1 + t * d
    // dot(normal, q - v1) = 0
    // dot(normal, p1 - v1) + t * dot(normal, d) = 0
    const numerator = normal.x * (v1.x - p1x) + normal.y * (v1.y - p1y);
    const denominator = normal.x * dx + normal.y * dy;

    if (denominator === 0.0) {
      return false;
    }

    const t = numerator / denominator;
    if (t < 0.0 || input.maxFraction < t) {
      return false;
    }

    const qx = p1x + t * dx;
    const qy = p1y + t * dy;

    // q = v1 + s * r
    // s = dot(q - v1, r) / dot(r, r)
    const rx = v2.x - v1.x;
    const ry = v2.y - v1.y;
    const rr = rx * rx + ry * ry;
    if (rr === 0.0) {
      return false;
    }

    const s = ((qx - v1.x) * rx + (qy - v1.y) * ry) / rr;
    if (s < 0.0 || 1.0 < s) {
      return false;
    }

    output.fraction = t;
    if (numerator > 0.0) {
      output.normal.Set(-normal.x, -normal.y);
    } else {
      output.normal.Set(normal.x, normal.y);
    }
    return true;
  }

  /** @see b2Shape::ComputeAABB */
  ComputeAABB(aabb: b2AABB, xf: Readonly<b2Transform>, childIndex: number): void {
    const qc = xf.q.c;
    const qs = xf.q.s;
    const v1 = this.m_vertex1;
    const v2 = this.m_vertex2;
    const v1x = qc * v1.x - qs * v1.y + xf.p.x;
    const v1y = qs * v1.x + qc * v1.y + xf.p.y;
    const v2x = qc * v2.x - qs * v2.y + xf.p.x;
    const v2y = qs * v2.x + qc * v2.y + xf.p.y;

    const r = this.m_radius;
    aabb.lowerBound.Set(b2Min(v1x, v2x) - r, b2Min(v1y, v2y) - r);
    aabb.upperBound.Set(b2Max(v1x, v2x) + r, b2Max(v1y, v2y) + r);
  }

  /** @see b2Shape::ComputeMass */
  ComputeMass(massData: b2MassData, density: number): void {
    massData.mass = 0.0;
    massData.center.Set(0.5 * (this.m_vertex1.x + this.m_vertex2.x), 0.5 * (this.m_vertex1.y + this.m_vertex2.y));
    massData.I = 0.0;
  }
}
