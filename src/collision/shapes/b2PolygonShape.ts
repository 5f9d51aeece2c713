/*
 * A convex polygon (b2PolygonShape.h, b2PolygonShape.cpp).
 */

import { b2MakeArray } from '../../common/b2MakeArray';
import { b2Max, b2Min, b2MulRV, b2Rot, b2Vec2 } from '../../common/b2Math';
import type { b2Transform } from '../../common/b2Math';
import { b2_epsilon, b2_maxPolygonVertices, b2_polygonRadius, b2Assert } from '../../common/b2Settings';
import type { b2AABB, b2RayCastInput, b2RayCastOutput } from '../b2Collision';
import { b2Shape } from './b2Shape';
import type { b2MassData } from './b2Shape';
import { b2CheckPolygonVertices } from './b2ShapeValidation';
import { b2CheckFinite, b2CheckInteger, b2CheckPositive, b2CheckVec2 } from '../../common/b2ArgumentError';

const s_boxRot = new b2Rot();

/** The area-weighted centroid of a polygon, fanned from the origin as 2.2.1 does. */
function ComputeCentroid(vs: readonly b2Vec2[], count: number, out: b2Vec2): b2Vec2 {
  b2Assert(count >= 3);

  let cx = 0.0;
  let cy = 0.0;
  let area = 0.0;

  // pRef is the reference point for forming triangles.
  // It's location doesn't change the result (except for rounding error).
  const pRefX = 0.0;
  const pRefY = 0.0;

  const inv3 = 1.0 / 3.0;

  for (let i = 0; i < count; ++i) {
    // Triangle vertices.
    const p2 = vs[i];
    const p3 = i + 1 < count ? vs[i + 1] : vs[0];

    const e1x = p2.x - pRefX;
    const e1y = p2.y - pRefY;
    const e2x = p3.x - pRefX;
    const e2y = p3.y - pRefY;

    const D = e1x * e2y - e1y * e2x;

    const triangleArea = 0.5 * D;
    area += triangleArea;

    // Area weighted centroid
    const k = triangleArea * inv3;
    cx += k * (pRefX + p2.x + p3.x);
    cy += k * (pRefY + p2.y + p3.y);
  }

  // Centroid
  b2Assert(area > b2_epsilon);
  const invArea = 1.0 / area;
  return out.Set(cx * invArea, cy * invArea);
}

/**
 * A convex polygon. It is assumed that the interior of the polygon is to the left of each edge.
 * Polygons have a maximum number of vertices equal to b2_maxPolygonVertices.
 * In most cases you should not need many vertices for a convex polygon.
 */
export class b2PolygonShape extends b2Shape {
  readonly m_centroid = new b2Vec2();
  /**
   * The first m_vertexCount are the polygon's. The C++ arrays hold b2_maxPolygonVertices; these
   * grow to the largest count set (Reserve), as Box2DWeb's do: every b2Vec2 is an object of its
   * own here, and a box's eight unused ones took nearly half its shape's memory and lay between
   * the ones each contact update reads (bench2d 4 % faster without them).
   */
  m_vertices: readonly b2Vec2[] = [];
  m_normals: readonly b2Vec2[] = [];
  m_vertexCount = 0;

  constructor() {
    super(b2Shape.e_polygon, b2_polygonRadius);
  }

  /** Implement b2Shape. */
  Clone(): b2PolygonShape {
    const clone = new b2PolygonShape();
    clone.m_type = this.m_type;
    clone.m_radius = this.m_radius;
    clone.m_centroid.Assign(this.m_centroid);
    clone.Reserve(this.m_vertexCount);
    for (let i = 0; i < this.m_vertexCount; ++i) {
      clone.m_vertices[i].Assign(this.m_vertices[i]);
      clone.m_normals[i].Assign(this.m_normals[i]);
    }
    clone.m_vertexCount = this.m_vertexCount;
    return clone;
  }

  /**
   * Not in 2.2.1 (Box2DWeb 2.1a's): make m_vertices and m_normals at least count long, with new
   * zero vectors, so that the first count entries can be written. Growing makes new arrays, sized
   * exactly (b2MakeArray), that hold the vectors the old ones held.
   */
  Reserve(count: number): void {
    b2CheckInteger('b2PolygonShape.Reserve', 'count', count, 0, b2_maxPolygonVertices);
    if (this.m_vertices.length >= count) return;
    const vertices = this.m_vertices;
    const normals = this.m_normals;
    this.m_vertices = b2MakeArray(count, (i) => (i < vertices.length ? vertices[i] : new b2Vec2()));
    this.m_normals = b2MakeArray(count, (i) => (i < normals.length ? normals[i] : new b2Vec2()));
  }

  /** @see b2Shape::GetChildCount */
  GetChildCount(): number {
    return 1;
  }

  /**
   * Copy vertices. This assumes the vertices define a convex polygon.
   * It is assumed that the exterior is the the right of each edge.
   * The count must be in the range [3, b2_maxPolygonVertices].
   * Throws b2ArgumentError, leaving the polygon unchanged, unless the vertices are finite,
   * counter-clockwise and convex, with edges longer than b2_epsilon and an area above b2_epsilon.
   */
  Set(vertices: readonly Readonly<b2Vec2>[], count: number = vertices.length): this {
    b2CheckPolygonVertices('b2PolygonShape.Set', 'vertices', 'count', vertices, count, b2_epsilon);
    b2Assert(3 <= count && count <= b2_maxPolygonVertices);
    this.Reserve(count);
    this.m_vertexCount = count;

    // Copy vertices.
    for (let i = 0; i < this.m_vertexCount; ++i) {
      this.m_vertices[i].Assign(vertices[i]);
    }

    // Compute normals. Ensure the edges have non-zero length.
    for (let i = 0; i < this.m_vertexCount; ++i) {
      const i1 = i;
      const i2 = i + 1 < this.m_vertexCount ? i + 1 : 0;
      const edgeX = this.m_vertices[i2].x - this.m_vertices[i1].x;
      const edgeY = this.m_vertices[i2].y - this.m_vertices[i1].y;
      b2Assert(edgeX * edgeX + edgeY * edgeY > b2_epsilon * b2_epsilon);
      // b2Cross(edge, 1.0)
      const normal = this.m_normals[i].Set(1.0 * edgeY, -1.0 * edgeX);
      normal.Normalize();
    }

    // Compute the polygon centroid.
    ComputeCentroid(this.m_vertices, this.m_vertexCount, this.m_centroid);
    return this;
  }

  /**
   * Build vertices to represent a box: axis-aligned about the origin when only the half-widths
   * are given, otherwise oriented (the two C++ overloads).
   * @param hx the half-width.
   * @param hy the half-height.
   * @param center the center of the box in local coordinates.
   * @param angle the rotation of the box in local coordinates.
   */
  SetAsBox(hx: number, hy: number, center?: Readonly<b2Vec2>, angle: number = 0.0): this {
    b2CheckPositive('b2PolygonShape.SetAsBox', 'hx', hx);
    b2CheckPositive('b2PolygonShape.SetAsBox', 'hy', hy);
    if (center !== undefined) {
      b2CheckVec2('b2PolygonShape.SetAsBox', 'center', center);
      b2CheckFinite('b2PolygonShape.SetAsBox', 'angle', angle);
    }
    this.Reserve(4);
    this.m_vertexCount = 4;
    this.m_vertices[0].Set(-hx, -hy);
    this.m_vertices[1].Set(hx, -hy);
    this.m_vertices[2].Set(hx, hy);
    this.m_vertices[3].Set(-hx, hy);
    this.m_normals[0].Set(0.0, -1.0);
    this.m_normals[1].Set(1.0, 0.0);
    this.m_normals[2].Set(0.0, 1.0);
    this.m_normals[3].Set(-1.0, 0.0);

    if (center === undefined) {
      this.m_centroid.SetZero();
      return this;
    }

    const cx = center.x;
    const cy = center.y;
    this.m_centroid.Set(cx, cy);

    const q = s_boxRot.Set(angle);

    // Transform vertices and normals.
    for (let i = 0; i < this.m_vertexCount; ++i) {
      const v = this.m_vertices[i];
      const vx = v.x;
      const vy = v.y;
      v.x = q.c * vx - q.s * vy + cx;
      v.y = q.s * vx + q.c * vy + cy;
      b2MulRV(q, this.m_normals[i], this.m_normals[i]);
    }
    return this;
  }

  /** @see b2Shape::TestPoint */
  TestPoint(xf: Readonly<b2Transform>, p: Readonly<b2Vec2>): boolean {
    const qc = xf.q.c;
    const qs = xf.q.s;
    const dx = p.x - xf.p.x;
    const dy = p.y - xf.p.y;
    const pLocalX = qc * dx + qs * dy;
    const pLocalY = -qs * dx + qc * dy;

    for (let i = 0; i < this.m_vertexCount; ++i) {
      const n = this.m_normals[i];
      const v = this.m_vertices[i];
      const dot = n.x * (pLocalX - v.x) + n.y * (pLocalY - v.y);
      if (dot > 0.0) {
        return false;
      }
    }

    return true;
  }

  /** Implement b2Shape. */
  RayCast(output: b2RayCastOutput, input: Readonly<b2RayCastInput>, xf: Readonly<b2Transform>, childIndex: number): boolean {
    // Put the ray into the polygon's frame of reference.
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

    let lower = 0.0;
    let upper = input.maxFraction;

    let index = -1;

    for (let i = 0; i < this.m_vertexCount; ++i) {
      // p = p1 + a * d
      // dot(normal, p - v) = 0
      // dot(normal, p1 - v) + a * dot(normal, d) = 0
      const n = this.m_normals[i];
      const v = this.m_vertices[i];
      const numerator = n.x * (v.x - p1x) + n.y * (v.y - p1y);
      const denominator = n.x * dx + n.y * dy;

      if (denominator === 0.0) {
        if (numerator < 0.0) {
          return false;
        }
      } else {
        // Note: we want this predicate without division:
        // lower < numerator / denominator, where denominator < 0
        // Since denominator < 0, we have to flip the inequality:
        // lower < numerator / denominator <==> denominator * lower > numerator.
        if (denominator < 0.0 && numerator < lower * denominator) {
          // Increase lower.
          // The segment enters this half-space.
          lower = numerator / denominator;
          index = i;
        } else if (denominator > 0.0 && numerator < upper * denominator) {
          // Decrease upper.
          // The segment exits this half-space.
          upper = numerator / denominator;
        }
      }

      if (upper < lower) {
        return false;
      }
    }

    b2Assert(0.0 <= lower && lower <= input.maxFraction);

    if (index >= 0) {
      output.fraction = lower;
      b2MulRV(xf.q, this.m_normals[index], output.normal);
      return true;
    }

    return false;
  }

  /** @see b2Shape::ComputeAABB */
  ComputeAABB(aabb: b2AABB, xf: Readonly<b2Transform>, childIndex: number): void {
    const qc = xf.q.c;
    const qs = xf.q.s;
    const px = xf.p.x;
    const py = xf.p.y;
    const v0 = this.m_vertices[0];
    let lowerX = qc * v0.x - qs * v0.y + px;
    let lowerY = qs * v0.x + qc * v0.y + py;
    let upperX = lowerX;
    let upperY = lowerY;

    for (let i = 1; i < this.m_vertexCount; ++i) {
      const vi = this.m_vertices[i];
      const vx = qc * vi.x - qs * vi.y + px;
      const vy = qs * vi.x + qc * vi.y + py;
      lowerX = b2Min(lowerX, vx);
      lowerY = b2Min(lowerY, vy);
      upperX = b2Max(upperX, vx);
      upperY = b2Max(upperY, vy);
    }

    const r = this.m_radius;
    aabb.lowerBound.Set(lowerX - r, lowerY - r);
    aabb.upperBound.Set(upperX + r, upperY + r);
  }

  /**
   * @see b2Shape::ComputeMass
   *
   * Polygon mass, centroid, and inertia.
   * Let rho be the polygon density in mass per unit area.
   * Then:
   * mass = rho * int(dA)
   * centroid.x = (1/mass) * rho * int(x * dA)
   * centroid.y = (1/mass) * rho * int(y * dA)
   * I = rho * int((x*x + y*y) * dA)
   *
   * We can compute these integrals by summing all the integrals for each triangle of the
   * polygon. To evaluate the integral for a single triangle, we make a change of variables to
   * the (u,v) coordinates of the triangle:
   * x = x0 + e1x * u + e2x * v
   * y = y0 + e1y * u + e2y * v
   * where 0 <= u && 0 <= v && u + v <= 1.
   *
   * We integrate u from [0,1-v] and then v from [0,1].
   * We also need to use the Jacobian of the transformation:
   * D = cross(e1, e2)
   *
   * Simplification: triangle centroid = (1/3) * (p1 + p2 + p3)
   *
   * The rest of the derivation is handled by computer algebra.
   */
  ComputeMass(massData: b2MassData, density: number): void {
    b2Assert(this.m_vertexCount >= 3);

    const count = this.m_vertexCount;
    const vertices = this.m_vertices;

    let centerX = 0.0;
    let centerY = 0.0;
    let area = 0.0;
    let I = 0.0;

    // s is the reference point for forming triangles.
    // It's location doesn't change the result (except for rounding error).
    let sx = 0.0;
    let sy = 0.0;

    // This code would put the reference point inside the polygon.
    for (let i = 0; i < count; ++i) {
      sx += vertices[i].x;
      sy += vertices[i].y;
    }
    const invCount = 1.0 / count;
    sx *= invCount;
    sy *= invCount;

    const k_inv3 = 1.0 / 3.0;

    for (let i = 0; i < count; ++i) {
      // Triangle vertices.
      const ex1 = vertices[i].x - sx;
      const ey1 = vertices[i].y - sy;
      const next = i + 1 < count ? vertices[i + 1] : vertices[0];
      const ex2 = next.x - sx;
      const ey2 = next.y - sy;

      const D = ex1 * ey2 - ey1 * ex2;

      const triangleArea = 0.5 * D;
      area += triangleArea;

      // Area weighted centroid
      const k = triangleArea * k_inv3;
      centerX += k * (ex1 + ex2);
      centerY += k * (ey1 + ey2);

      const intx2 = ex1 * ex1 + ex2 * ex1 + ex2 * ex2;
      const inty2 = ey1 * ey1 + ey2 * ey1 + ey2 * ey2;

      I += 0.25 * k_inv3 * D * (intx2 + inty2);
    }

    // Total mass
    massData.mass = density * area;

    // Center of mass
    b2Assert(area > b2_epsilon);
    const invArea = 1.0 / area;
    centerX *= invArea;
    centerY *= invArea;
    const mcx = centerX + sx;
    const mcy = centerY + sy;
    massData.center.Set(mcx, mcy);

    // Inertia tensor relative to the local origin (point s).
    massData.I = density * I;

    // Shift to center of mass then to original body origin.
    massData.I += massData.mass * (mcx * mcx + mcy * mcy - (centerX * centerX + centerY * centerY));
  }

  /** Get the vertex count. */
  GetVertexCount(): number {
    return this.m_vertexCount;
  }

  /** Get a vertex by index. */
  GetVertex(index: number): Readonly<b2Vec2> {
    b2Assert(0 <= index && index < this.m_vertexCount);
    return this.m_vertices[index];
  }
}
