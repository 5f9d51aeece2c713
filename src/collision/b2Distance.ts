/*
 * GJK distance between convex shapes (b2Distance.h, b2Distance.cpp).
 *
 * GJK using Voronoi regions (Christer Ericson) and barycentric coordinates.
 */

import { b2Cross, b2Max, b2MulTRV, b2MulXV, b2SubVV, b2Transform, b2Vec2, b2Vec2Distance } from '../common/b2Math';
import { b2Assert, b2_epsilon } from '../common/b2Settings';
import type { b2ChainShape } from './shapes/b2ChainShape';
import type { b2CircleShape } from './shapes/b2CircleShape';
import type { b2EdgeShape } from './shapes/b2EdgeShape';
import type { b2PolygonShape } from './shapes/b2PolygonShape';
import { b2Shape } from './shapes/b2Shape';

/*
 * GJK statistics (the C++ globals b2_gjkCalls, b2_gjkIters, b2_gjkMaxIters). Importers read them
 * as live bindings; ES modules do not let an importer assign them, so the Testbed's
 * `b2_gjkCalls = 0; ...` is b2ResetGjkCounters().
 */
export let b2_gjkCalls = 0;
export let b2_gjkIters = 0;
export let b2_gjkMaxIters = 0;

/** Zero the GJK statistics. */
export function b2ResetGjkCounters(): void {
  b2_gjkCalls = 0;
  b2_gjkIters = 0;
  b2_gjkMaxIters = 0;
}

/**
 * A distance proxy is used by the GJK algorithm.
 * It encapsulates any shape.
 */
export class b2DistanceProxy {
  /** A chain child's two vertices, copied (the C++ m_buffer). */
  readonly m_buffer: b2Vec2[] = [new b2Vec2(), new b2Vec2()];
  /**
   * The C++ points m_vertices at a circle's m_p or at an edge's m_vertex1 (m_vertex2 follows it
   * in memory). This array holds those same vector objects, not copies, so the proxy sees the
   * shape as the C++ pointer does.
   */
  readonly m_shapeVertices: b2Vec2[] = [new b2Vec2(), new b2Vec2()];
  /** The shape's vertices, m_shapeVertices or m_buffer; the C++ NULL is m_buffer with m_count 0. */
  m_vertices: readonly b2Vec2[] = this.m_buffer;
  m_count = 0;
  m_radius = 0.0;

  /**
   * this = other, as the C++ struct copy: m_buffer by value, m_vertices by pointer (to the same
   * shape vertices, or to other's m_buffer).
   */
  Assign(other: Readonly<b2DistanceProxy>): this {
    this.m_buffer[0].Assign(other.m_buffer[0]);
    this.m_buffer[1].Assign(other.m_buffer[1]);
    this.m_shapeVertices[0] = other.m_shapeVertices[0];
    this.m_shapeVertices[1] = other.m_shapeVertices[1];
    this.m_vertices = other.m_vertices === other.m_shapeVertices ? this.m_shapeVertices : other.m_vertices;
    this.m_count = other.m_count;
    this.m_radius = other.m_radius;
    return this;
  }

  Clone(): b2DistanceProxy {
    return new b2DistanceProxy().Assign(this);
  }

  /**
   * Initialize the proxy using the given shape. The shape
   * must remain in scope while the proxy is in use.
   */
  Set(shape: b2Shape, index: number): void {
    switch (shape.GetType()) {
      case b2Shape.e_circle: {
        const circle = shape as b2CircleShape;
        this.m_shapeVertices[0] = circle.m_p;
        this.m_vertices = this.m_shapeVertices;
        this.m_count = 1;
        this.m_radius = circle.m_radius;
        break;
      }

      case b2Shape.e_polygon: {
        const polygon = shape as b2PolygonShape;
        this.m_vertices = polygon.m_vertices;
        this.m_count = polygon.m_vertexCount;
        this.m_radius = polygon.m_radius;
        break;
      }

      case b2Shape.e_chain: {
        const chain = shape as b2ChainShape;
        b2Assert(0 <= index && index < chain.m_count);

        this.m_buffer[0].Assign(chain.m_vertices[index]);
        if (index + 1 < chain.m_count) {
          this.m_buffer[1].Assign(chain.m_vertices[index + 1]);
        } else {
          this.m_buffer[1].Assign(chain.m_vertices[0]);
        }

        this.m_vertices = this.m_buffer;
        this.m_count = 2;
        this.m_radius = chain.m_radius;
        break;
      }

      case b2Shape.e_edge: {
        const edge = shape as b2EdgeShape;
        this.m_shapeVertices[0] = edge.m_vertex1;
        this.m_shapeVertices[1] = edge.m_vertex2;
        this.m_vertices = this.m_shapeVertices;
        this.m_count = 2;
        this.m_radius = edge.m_radius;
        break;
      }

      default:
        b2Assert(false);
    }
  }

  /** Get the supporting vertex index in the given direction. */
  GetSupport(d: Readonly<b2Vec2>): number {
    const vertices = this.m_vertices;
    let bestIndex = 0;
    // b2Dot written out: GJK and the time of impact call this where V8 has no inlining budget
    // left, and a double returned from a call that is not inlined is boxed.
    let bestValue = vertices[0].x * d.x + vertices[0].y * d.y;
    for (let i = 1; i < this.m_count; ++i) {
      const value = vertices[i].x * d.x + vertices[i].y * d.y;
      if (value > bestValue) {
        bestIndex = i;
        bestValue = value;
      }
    }

    return bestIndex;
  }

  /** Get the supporting vertex in the given direction. */
  GetSupportVertex(d: Readonly<b2Vec2>): Readonly<b2Vec2> {
    return this.m_vertices[this.GetSupport(d)];
  }

  /** Get the vertex count. */
  GetVertexCount(): number {
    return this.m_count;
  }

  /** Get a vertex by index. Used by b2Distance. */
  GetVertex(index: number): Readonly<b2Vec2> {
    b2Assert(0 <= index && index < this.m_count);
    return this.m_vertices[index];
  }
}

/**
 * Used to warm start b2Distance.
 * Set count to zero on first call.
 */
export class b2SimplexCache {
  /** length or area */
  metric = 0.0;
  /** uint16 */
  count = 0;
  /** vertices on shape A (uint8) */
  readonly indexA: number[] = [0, 0, 0];
  /** vertices on shape B (uint8) */
  readonly indexB: number[] = [0, 0, 0];

  Assign(other: Readonly<b2SimplexCache>): this {
    this.metric = other.metric;
    this.count = other.count;
    for (let i = 0; i < 3; ++i) {
      this.indexA[i] = other.indexA[i];
      this.indexB[i] = other.indexB[i];
    }
    return this;
  }

  Clone(): b2SimplexCache {
    return new b2SimplexCache().Assign(this);
  }
}

/**
 * Input for b2Distance.
 * You have to option to use the shape radii
 * in the computation.
 */
export class b2DistanceInput {
  readonly proxyA = new b2DistanceProxy();
  readonly proxyB = new b2DistanceProxy();
  readonly transformA = new b2Transform();
  readonly transformB = new b2Transform();
  useRadii = false;

  Assign(other: Readonly<b2DistanceInput>): this {
    this.proxyA.Assign(other.proxyA);
    this.proxyB.Assign(other.proxyB);
    this.transformA.Assign(other.transformA);
    this.transformB.Assign(other.transformB);
    this.useRadii = other.useRadii;
    return this;
  }

  Clone(): b2DistanceInput {
    return new b2DistanceInput().Assign(this);
  }
}

/** Output for b2Distance. */
export class b2DistanceOutput {
  /** closest point on shapeA */
  readonly pointA = new b2Vec2();
  /** closest point on shapeB */
  readonly pointB = new b2Vec2();
  distance = 0.0;
  /** number of GJK iterations used */
  iterations = 0;

  Assign(other: Readonly<b2DistanceOutput>): this {
    this.pointA.Assign(other.pointA);
    this.pointB.Assign(other.pointB);
    this.distance = other.distance;
    this.iterations = other.iterations;
    return this;
  }

  Clone(): b2DistanceOutput {
    return new b2DistanceOutput().Assign(this);
  }
}

class b2SimplexVertex {
  /** support point in proxyA */
  readonly wA = new b2Vec2();
  /** support point in proxyB */
  readonly wB = new b2Vec2();
  /** wB - wA */
  readonly w = new b2Vec2();
  /** barycentric coordinate for closest point */
  a = 0.0;
  /** wA index */
  indexA = 0;
  /** wB index */
  indexB = 0;

  Assign(other: Readonly<b2SimplexVertex>): this {
    this.wA.Assign(other.wA);
    this.wB.Assign(other.wB);
    this.w.Assign(other.w);
    this.a = other.a;
    this.indexA = other.indexA;
    this.indexB = other.indexB;
    return this;
  }
}

class b2Simplex {
  readonly m_v1 = new b2SimplexVertex();
  readonly m_v2 = new b2SimplexVertex();
  readonly m_v3 = new b2SimplexVertex();
  /** The C++ walks &m_v1 as an array. */
  readonly m_vertices: b2SimplexVertex[] = [this.m_v1, this.m_v2, this.m_v3];
  m_count = 0;

  ReadCache(
    cache: Readonly<b2SimplexCache>,
    proxyA: b2DistanceProxy,
    transformA: Readonly<b2Transform>,
    proxyB: b2DistanceProxy,
    transformB: Readonly<b2Transform>,
  ): void {
    b2Assert(cache.count <= 3);

    // Copy data from cache.
    this.m_count = cache.count;
    const vertices = this.m_vertices;
    for (let i = 0; i < this.m_count; ++i) {
      const v = vertices[i];
      v.indexA = cache.indexA[i];
      v.indexB = cache.indexB[i];
      b2MulXV(transformA, proxyA.GetVertex(v.indexA), v.wA);
      b2MulXV(transformB, proxyB.GetVertex(v.indexB), v.wB);
      b2SubVV(v.wB, v.wA, v.w);
      v.a = 0.0;
    }

    // Compute the new simplex metric, if it is substantially different than
    // old metric then flush the simplex.
    if (this.m_count > 1) {
      const metric1 = cache.metric;
      const metric2 = this.GetMetric();
      if (metric2 < 0.5 * metric1 || 2.0 * metric1 < metric2 || metric2 < b2_epsilon) {
        // Reset the simplex.
        this.m_count = 0;
      }
    }

    // If the cache is empty or invalid ...
    if (this.m_count === 0) {
      const v = vertices[0];
      v.indexA = 0;
      v.indexB = 0;
      b2MulXV(transformA, proxyA.GetVertex(0), v.wA);
      b2MulXV(transformB, proxyB.GetVertex(0), v.wB);
      b2SubVV(v.wB, v.wA, v.w);
      this.m_count = 1;
    }
  }

  WriteCache(cache: b2SimplexCache): void {
    cache.metric = this.GetMetric();
    cache.count = this.m_count & 0xffff;
    const vertices = this.m_vertices;
    for (let i = 0; i < this.m_count; ++i) {
      cache.indexA[i] = vertices[i].indexA & 0xff;
      cache.indexB[i] = vertices[i].indexB & 0xff;
    }
  }

  GetSearchDirection(out: b2Vec2): b2Vec2 {
    // out is written field by field: b2Distance is past V8's inlining budget, and a Set it leaves
    // out of line boxes its arguments.
    switch (this.m_count) {
      case 1:
        out.x = -this.m_v1.w.x;
        out.y = -this.m_v1.w.y;
        return out;

      case 2: {
        const w1 = this.m_v1.w;
        const w2 = this.m_v2.w;
        const e12x = w2.x - w1.x;
        const e12y = w2.y - w1.y;
        // b2Cross(e12, -m_v1.w)
        const sgn = e12x * -w1.y - e12y * -w1.x;
        if (sgn > 0.0) {
          // Origin is left of e12: b2Cross(1.0, e12).
          out.x = -1.0 * e12y;
          out.y = 1.0 * e12x;
        } else {
          // Origin is right of e12: b2Cross(e12, 1.0).
          out.x = 1.0 * e12y;
          out.y = -1.0 * e12x;
        }
        return out;
      }

      default:
        b2Assert(false);
    }
  }

  GetWitnessPoints(pA: b2Vec2, pB: b2Vec2): void {
    const v1 = this.m_v1;
    const v2 = this.m_v2;
    switch (this.m_count) {
      case 1:
        pA.Assign(v1.wA);
        pB.Assign(v1.wB);
        break;

      case 2:
        pA.x = v1.a * v1.wA.x + v2.a * v2.wA.x;
        pA.y = v1.a * v1.wA.y + v2.a * v2.wA.y;
        pB.x = v1.a * v1.wB.x + v2.a * v2.wB.x;
        pB.y = v1.a * v1.wB.y + v2.a * v2.wB.y;
        break;

      case 3: {
        const v3 = this.m_v3;
        pA.x = v1.a * v1.wA.x + v2.a * v2.wA.x + v3.a * v3.wA.x;
        pA.y = v1.a * v1.wA.y + v2.a * v2.wA.y + v3.a * v3.wA.y;
        pB.Assign(pA);
        break;
      }

      default:
        b2Assert(false);
    }
  }

  GetMetric(): number {
    switch (this.m_count) {
      case 1:
        return 0.0;

      case 2:
        return b2Vec2Distance(this.m_v1.w, this.m_v2.w);

      case 3: {
        const w1 = this.m_v1.w;
        const w2 = this.m_v2.w;
        const w3 = this.m_v3.w;
        // b2Cross(w2 - w1, w3 - w1)
        return (w2.x - w1.x) * (w3.y - w1.y) - (w2.y - w1.y) * (w3.x - w1.x);
      }

      default:
        b2Assert(false);
    }
  }

  // Solve a line segment using barycentric coordinates.
  //
  // p = a1 * w1 + a2 * w2
  // a1 + a2 = 1
  //
  // The vector from the origin to the closest point on the line is
  // perpendicular to the line.
  // e12 = w2 - w1
  // dot(p, e) = 0
  // a1 * dot(w1, e) + a2 * dot(w2, e) = 0
  //
  // 2-by-2 linear system
  // [1      1     ][a1] = [1]
  // [w1.e12 w2.e12][a2] = [0]
  //
  // Define
  // d12_1 =  dot(w2, e12)
  // d12_2 = -dot(w1, e12)
  // d12 = d12_1 + d12_2
  //
  // Solution
  // a1 = d12_1 / d12
  // a2 = d12_2 / d12
  Solve2(): void {
    const w1 = this.m_v1.w;
    const w2 = this.m_v2.w;
    const e12x = w2.x - w1.x;
    const e12y = w2.y - w1.y;

    // w1 region
    const d12_2 = -(w1.x * e12x + w1.y * e12y);
    if (d12_2 <= 0.0) {
      // a2 <= 0, so we clamp it to 0
      this.m_v1.a = 1.0;
      this.m_count = 1;
      return;
    }

    // w2 region
    const d12_1 = w2.x * e12x + w2.y * e12y;
    if (d12_1 <= 0.0) {
      // a1 <= 0, so we clamp it to 0
      this.m_v2.a = 1.0;
      this.m_count = 1;
      this.m_v1.Assign(this.m_v2);
      return;
    }

    // Must be in e12 region.
    const inv_d12 = 1.0 / (d12_1 + d12_2);
    this.m_v1.a = d12_1 * inv_d12;
    this.m_v2.a = d12_2 * inv_d12;
    this.m_count = 2;
  }

  // Possible regions:
  // - points[2]
  // - edge points[0]-points[2]
  // - edge points[1]-points[2]
  // - inside the triangle
  Solve3(): void {
    const w1 = this.m_v1.w;
    const w2 = this.m_v2.w;
    const w3 = this.m_v3.w;

    // Edge12
    // [1      1     ][a1] = [1]
    // [w1.e12 w2.e12][a2] = [0]
    // a3 = 0
    const e12x = w2.x - w1.x;
    const e12y = w2.y - w1.y;
    const w1e12 = w1.x * e12x + w1.y * e12y;
    const w2e12 = w2.x * e12x + w2.y * e12y;
    const d12_1 = w2e12;
    const d12_2 = -w1e12;

    // Edge13
    // [1      1     ][a1] = [1]
    // [w1.e13 w3.e13][a3] = [0]
    // a2 = 0
    const e13x = w3.x - w1.x;
    const e13y = w3.y - w1.y;
    const w1e13 = w1.x * e13x + w1.y * e13y;
    const w3e13 = w3.x * e13x + w3.y * e13y;
    const d13_1 = w3e13;
    const d13_2 = -w1e13;

    // Edge23
    // [1      1     ][a2] = [1]
    // [w2.e23 w3.e23][a3] = [0]
    // a1 = 0
    const e23x = w3.x - w2.x;
    const e23y = w3.y - w2.y;
    const w2e23 = w2.x * e23x + w2.y * e23y;
    const w3e23 = w3.x * e23x + w3.y * e23y;
    const d23_1 = w3e23;
    const d23_2 = -w2e23;

    // Triangle123
    const n123 = e12x * e13y - e12y * e13x;

    const d123_1 = n123 * b2Cross(w2, w3);
    const d123_2 = n123 * b2Cross(w3, w1);
    const d123_3 = n123 * b2Cross(w1, w2);

    // w1 region
    if (d12_2 <= 0.0 && d13_2 <= 0.0) {
      this.m_v1.a = 1.0;
      this.m_count = 1;
      return;
    }

    // e12
    if (d12_1 > 0.0 && d12_2 > 0.0 && d123_3 <= 0.0) {
      const inv_d12 = 1.0 / (d12_1 + d12_2);
      this.m_v1.a = d12_1 * inv_d12;
      this.m_v2.a = d12_2 * inv_d12;
      this.m_count = 2;
      return;
    }

    // e13
    if (d13_1 > 0.0 && d13_2 > 0.0 && d123_2 <= 0.0) {
      const inv_d13 = 1.0 / (d13_1 + d13_2);
      this.m_v1.a = d13_1 * inv_d13;
      this.m_v3.a = d13_2 * inv_d13;
      this.m_count = 2;
      this.m_v2.Assign(this.m_v3);
      return;
    }

    // w2 region
    if (d12_1 <= 0.0 && d23_2 <= 0.0) {
      this.m_v2.a = 1.0;
      this.m_count = 1;
      this.m_v1.Assign(this.m_v2);
      return;
    }

    // w3 region
    if (d13_1 <= 0.0 && d23_1 <= 0.0) {
      this.m_v3.a = 1.0;
      this.m_count = 1;
      this.m_v1.Assign(this.m_v3);
      return;
    }

    // e23
    if (d23_1 > 0.0 && d23_2 > 0.0 && d123_1 <= 0.0) {
      const inv_d23 = 1.0 / (d23_1 + d23_2);
      this.m_v2.a = d23_1 * inv_d23;
      this.m_v3.a = d23_2 * inv_d23;
      this.m_count = 2;
      this.m_v1.Assign(this.m_v3);
      return;
    }

    // Must be in triangle123
    const inv_d123 = 1.0 / (d123_1 + d123_2 + d123_3);
    this.m_v1.a = d123_1 * inv_d123;
    this.m_v2.a = d123_2 * inv_d123;
    this.m_v3.a = d123_3 * inv_d123;
    this.m_count = 3;
  }
}

// b2Distance never calls out to user code and never re-enters itself, so one simplex serves all calls.
const s_simplex = new b2Simplex();
const s_saveA: number[] = [0, 0, 0];
const s_saveB: number[] = [0, 0, 0];
const s_d = new b2Vec2();
const s_negD = new b2Vec2();
const s_axis = new b2Vec2();
const s_normal = new b2Vec2();

/**
 * Compute the closest points between two shapes. Supports any combination of:
 * b2CircleShape, b2PolygonShape, b2EdgeShape. The simplex cache is input/output.
 * On the first call set b2SimplexCache.count to zero.
 */
export function b2Distance(output: b2DistanceOutput, cache: b2SimplexCache, input: Readonly<b2DistanceInput>): void {
  ++b2_gjkCalls;

  const proxyA = input.proxyA;
  const proxyB = input.proxyB;

  // The C++ copies the transforms; nothing here writes them, and output holds no transform.
  const transformA = input.transformA;
  const transformB = input.transformB;

  // Initialize the simplex.
  const simplex = s_simplex;
  simplex.ReadCache(cache, proxyA, transformA, proxyB, transformB);

  // Get simplex vertices as an array.
  const vertices = simplex.m_vertices;
  const k_maxIters = 20;

  // These store the vertices of the last simplex so that we
  // can check for duplicates and prevent cycling.
  const saveA = s_saveA;
  const saveB = s_saveB;
  let saveCount = 0;

  // The C++ also tracks the squared distance of the closest point here, for a progress check
  // that is commented out; it decides nothing, so it is not computed.

  // Main iteration loop.
  let iter = 0;
  while (iter < k_maxIters) {
    // Copy simplex so we can identify duplicates.
    saveCount = simplex.m_count;
    for (let i = 0; i < saveCount; ++i) {
      saveA[i] = vertices[i].indexA;
      saveB[i] = vertices[i].indexB;
    }

    switch (simplex.m_count) {
      case 1:
        break;

      case 2:
        simplex.Solve2();
        break;

      case 3:
        simplex.Solve3();
        break;

      default:
        b2Assert(false);
    }

    // If we have 3 points, then the origin is in the corresponding triangle.
    if (simplex.m_count === 3) {
      break;
    }

    // Get search direction.
    const d = simplex.GetSearchDirection(s_d);

    // Ensure the search direction is numerically fit.
    // d.LengthSquared() written out, and s_negD filled field by field below, for the reason
    // GetSupport gives.
    if (d.x * d.x + d.y * d.y < b2_epsilon * b2_epsilon) {
      // The origin is probably contained by a line segment
      // or triangle. Thus the shapes are overlapped.

      // We can't return zero here even though there may be overlap.
      // In case the simplex is a point, segment, or triangle it is difficult
      // to determine if the origin is contained in the CSO or very close to it.
      break;
    }

    // Compute a tentative new simplex vertex using support points.
    const vertex = vertices[simplex.m_count];
    s_negD.x = -d.x;
    s_negD.y = -d.y;
    vertex.indexA = proxyA.GetSupport(b2MulTRV(transformA.q, s_negD, s_axis));
    b2MulXV(transformA, proxyA.GetVertex(vertex.indexA), vertex.wA);
    vertex.indexB = proxyB.GetSupport(b2MulTRV(transformB.q, d, s_axis));
    b2MulXV(transformB, proxyB.GetVertex(vertex.indexB), vertex.wB);
    b2SubVV(vertex.wB, vertex.wA, vertex.w);

    // Iteration count is equated to the number of support point calls.
    ++iter;
    ++b2_gjkIters;

    // Check for duplicate support points. This is the main termination criteria.
    let duplicate = false;
    for (let i = 0; i < saveCount; ++i) {
      if (vertex.indexA === saveA[i] && vertex.indexB === saveB[i]) {
        duplicate = true;
        break;
      }
    }

    // If we found a duplicate support point we must exit to avoid cycling.
    if (duplicate) {
      break;
    }

    // New vertex is ok and needed.
    ++simplex.m_count;
  }

  b2_gjkMaxIters = b2Max(b2_gjkMaxIters, iter);

  // Prepare output.
  const pointA = output.pointA;
  const pointB = output.pointB;
  simplex.GetWitnessPoints(pointA, pointB);
  // b2Distance(pointA, pointB) written out: as a call V8 does not inline, its result was boxed.
  const dx = pointA.x - pointB.x;
  const dy = pointA.y - pointB.y;
  output.distance = Math.sqrt(dx * dx + dy * dy);
  output.iterations = iter;

  // Cache the simplex.
  simplex.WriteCache(cache);

  // Apply radii if requested.
  if (input.useRadii) {
    const rA = proxyA.m_radius;
    const rB = proxyB.m_radius;

    if (output.distance > rA + rB && output.distance > b2_epsilon) {
      // Shapes are still no overlapped.
      // Move the witness points to the outer surface.
      output.distance -= rA + rB;
      const normal = b2SubVV(pointB, pointA, s_normal);
      normal.Normalize();
      pointA.x += rA * normal.x;
      pointA.y += rA * normal.y;
      pointB.x -= rB * normal.x;
      pointB.y -= rB * normal.y;
    } else {
      // Shapes are overlapped when radii are considered.
      // Move the witness points to the middle.
      const px = 0.5 * (pointA.x + pointB.x);
      const py = 0.5 * (pointA.y + pointB.y);
      pointA.Set(px, py);
      pointB.Set(px, py);
      output.distance = 0.0;
    }
  }
}
