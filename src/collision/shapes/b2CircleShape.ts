/*
 * A circle shape (b2CircleShape.h, b2CircleShape.cpp).
 */

import { b2Vec2 } from '../../common/b2Math';
import type { b2Transform } from '../../common/b2Math';
import { b2_epsilon, b2_pi, b2Assert } from '../../common/b2Settings';
import type { b2AABB, b2RayCastInput, b2RayCastOutput } from '../b2Collision';
import { b2Shape } from './b2Shape';
import type { b2MassData } from './b2Shape';

/** A circle shape. */
export class b2CircleShape extends b2Shape {
  /** Position */
  readonly m_p = new b2Vec2();

  constructor() {
    super(b2Shape.e_circle, 0.0);
  }

  /** Implement b2Shape. */
  Clone(): b2CircleShape {
    const clone = new b2CircleShape();
    clone.m_radius = this.m_radius;
    clone.m_p.Assign(this.m_p);
    return clone;
  }

  /** @see b2Shape::GetChildCount */
  GetChildCount(): number {
    return 1;
  }

  /** Implement b2Shape. */
  TestPoint(transform: Readonly<b2Transform>, p: Readonly<b2Vec2>): boolean {
    const q = transform.q;
    const centerX = transform.p.x + (q.c * this.m_p.x - q.s * this.m_p.y);
    const centerY = transform.p.y + (q.s * this.m_p.x + q.c * this.m_p.y);
    const dx = p.x - centerX;
    const dy = p.y - centerY;
    return dx * dx + dy * dy <= this.m_radius * this.m_radius;
  }

  /**
   * Collision Detection in Interactive 3D Environments by Gino van den Bergen
   * From Section 3.1.2
   * x = s + a * r
   * norm(x) = radius
   */
  RayCast(output: b2RayCastOutput, input: Readonly<b2RayCastInput>, transform: Readonly<b2Transform>, childIndex: number): boolean {
    const q = transform.q;
    const positionX = transform.p.x + (q.c * this.m_p.x - q.s * this.m_p.y);
    const positionY = transform.p.y + (q.s * this.m_p.x + q.c * this.m_p.y);
    const sx = input.p1.x - positionX;
    const sy = input.p1.y - positionY;
    const b = sx * sx + sy * sy - this.m_radius * this.m_radius;

    // Solve quadratic equation.
    const rx = input.p2.x - input.p1.x;
    const ry = input.p2.y - input.p1.y;
    const c = sx * rx + sy * ry;
    const rr = rx * rx + ry * ry;
    const sigma = c * c - rr * b;

    // Check for negative discriminant and short segment.
    if (sigma < 0.0 || rr < b2_epsilon) {
      return false;
    }

    // Find the point of intersection of the line with the circle.
    let a = -(c + Math.sqrt(sigma));

    // Is the intersection point on the segment?
    if (0.0 <= a && a <= input.maxFraction * rr) {
      a /= rr;
      output.fraction = a;
      output.normal.Set(sx + a * rx, sy + a * ry);
      output.normal.Normalize();
      return true;
    }

    return false;
  }

  /** @see b2Shape::ComputeAABB */
  ComputeAABB(aabb: b2AABB, transform: Readonly<b2Transform>, childIndex: number): void {
    const q = transform.q;
    const px = transform.p.x + (q.c * this.m_p.x - q.s * this.m_p.y);
    const py = transform.p.y + (q.s * this.m_p.x + q.c * this.m_p.y);
    aabb.lowerBound.Set(px - this.m_radius, py - this.m_radius);
    aabb.upperBound.Set(px + this.m_radius, py + this.m_radius);
  }

  /** @see b2Shape::ComputeMass */
  ComputeMass(massData: b2MassData, density: number): void {
    massData.mass = density * b2_pi * this.m_radius * this.m_radius;
    massData.center.Assign(this.m_p);

    // inertia about the local origin
    massData.I = massData.mass * (0.5 * this.m_radius * this.m_radius + (this.m_p.x * this.m_p.x + this.m_p.y * this.m_p.y));
  }

  /** Get the supporting vertex index in the given direction. */
  GetSupport(d: Readonly<b2Vec2>): number {
    return 0;
  }

  /** Get the supporting vertex in the given direction. */
  GetSupportVertex(d: Readonly<b2Vec2>): Readonly<b2Vec2> {
    return this.m_p;
  }

  /** Get the vertex count. */
  GetVertexCount(): number {
    return 1;
  }

  /** Get a vertex by index. Used by b2Distance. */
  GetVertex(index: number): Readonly<b2Vec2> {
    b2Assert(index === 0);
    return this.m_p;
  }
}
