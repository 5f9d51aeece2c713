/*
 * Edge versus circle and edge versus polygon contact manifolds, with edge adjacency
 * (b2CollideEdge.cpp).
 */

import { b2MakeArray } from '../common/b2MakeArray';
import { b2Min, b2MulRV, b2MulTXV, b2MulTXX, b2MulXV, b2Normalize, b2Transform, b2Vec2, b2Vec2_zero } from '../common/b2Math';
import { b2_angularSlop, b2_maxFloat, b2_maxManifoldPoints, b2_maxPolygonVertices, b2_polygonRadius, b2Assert } from '../common/b2Settings';
import { b2ClipSegment, b2ClipSegmentOffset, b2ClipVertex, b2ContactFeature, b2ContactKey, b2Manifold } from './b2Collision';
import { b2SetManifoldFace, b2SetManifoldPoint } from './b2ManifoldRecord';
import type { b2CircleShape } from './shapes/b2CircleShape';
import type { b2EdgeShape } from './shapes/b2EdgeShape';
import type { b2PolygonShape } from './shapes/b2PolygonShape';

const s_pB = new b2Vec2();
const s_Q = new b2Vec2();
const s_normal = new b2Vec2();
const s_localPoint = new b2Vec2();

/**
 * Compute contact points for edge versus circle.
 * This accounts for edge connectivity.
 */
export function b2CollideEdgeAndCircle(
  manifold: b2Manifold,
  edgeA: b2EdgeShape,
  xfA: Readonly<b2Transform>,
  circleB: b2CircleShape,
  xfB: Readonly<b2Transform>,
): void {
  manifold.pointCount = 0;

  // Compute circle in frame of edge
  const Q = b2MulTXV(xfA, b2MulXV(xfB, circleB.m_p, s_pB), s_Q);

  const A = edgeA.m_vertex1;
  const B = edgeA.m_vertex2;
  const ex = B.x - A.x;
  const ey = B.y - A.y;

  // Barycentric coordinates
  const u = ex * (B.x - Q.x) + ey * (B.y - Q.y);
  const v = ex * (Q.x - A.x) + ey * (Q.y - A.y);

  const radius = edgeA.m_radius + circleB.m_radius;

  // The C++ builds the feature in a local b2ContactFeature cf and copies it into the point's id;
  // here its key goes to the manifold's record. indexB and typeB are always 0 and e_vertex.

  // Region A
  if (v <= 0.0) {
    const P = A;
    const dx = Q.x - P.x;
    const dy = Q.y - P.y;
    const dd = dx * dx + dy * dy;
    if (dd > radius * radius) {
      return;
    }

    // Is there an edge connected to A?
    if (edgeA.m_hasVertex0) {
      const A1 = edgeA.m_vertex0;
      const B1 = A;
      const e1x = B1.x - A1.x;
      const e1y = B1.y - A1.y;
      const u1 = e1x * (B1.x - Q.x) + e1y * (B1.y - Q.y);

      // Is the circle in Region AB of the previous edge?
      if (u1 > 0.0) {
        return;
      }
    }

    manifold.pointCount = 1;
    manifold.type = b2Manifold.e_circles;
    b2SetManifoldFace(manifold, b2Vec2_zero, P);
    b2SetManifoldPoint(manifold, 0, circleB.m_p, b2ContactKey(0, 0, b2ContactFeature.e_vertex, b2ContactFeature.e_vertex));
    return;
  }

  // Region B
  if (u <= 0.0) {
    const P = B;
    const dx = Q.x - P.x;
    const dy = Q.y - P.y;
    const dd = dx * dx + dy * dy;
    if (dd > radius * radius) {
      return;
    }

    // Is there an edge connected to B?
    if (edgeA.m_hasVertex3) {
      const B2 = edgeA.m_vertex3;
      const A2 = B;
      const e2x = B2.x - A2.x;
      const e2y = B2.y - A2.y;
      const v2 = e2x * (Q.x - A2.x) + e2y * (Q.y - A2.y);

      // Is the circle in Region AB of the next edge?
      if (v2 > 0.0) {
        return;
      }
    }

    manifold.pointCount = 1;
    manifold.type = b2Manifold.e_circles;
    b2SetManifoldFace(manifold, b2Vec2_zero, P);
    b2SetManifoldPoint(manifold, 0, circleB.m_p, b2ContactKey(1, 0, b2ContactFeature.e_vertex, b2ContactFeature.e_vertex));
    return;
  }

  // Region AB
  const den = ex * ex + ey * ey;
  b2Assert(den > 0.0);
  const Px = (1.0 / den) * (u * A.x + v * B.x);
  const Py = (1.0 / den) * (u * A.y + v * B.y);
  const dx = Q.x - Px;
  const dy = Q.y - Py;
  const dd = dx * dx + dy * dy;
  if (dd > radius * radius) {
    return;
  }

  // Field by field and b2Normalize: past V8's inlining budget, calls box the doubles they take
  // or return.
  const n = s_normal;
  n.x = -ey;
  n.y = ex;
  if (n.x * (Q.x - A.x) + n.y * (Q.y - A.y) < 0.0) {
    n.x = -n.x;
    n.y = -n.y;
  }
  b2Normalize(n);

  manifold.pointCount = 1;
  manifold.type = b2Manifold.e_faceA;
  b2SetManifoldFace(manifold, n, A);
  b2SetManifoldPoint(manifold, 0, circleB.m_p, b2ContactKey(0, 0, b2ContactFeature.e_face, b2ContactFeature.e_vertex));
}

/** cf = {indexA, indexB, typeA, typeB} */
function setFeature(cf: b2ContactFeature, indexA: number, indexB: number, typeA: number, typeB: number): void {
  cf.indexA = indexA;
  cf.indexB = indexB;
  cf.typeA = typeA;
  cf.typeB = typeB;
}

/** This structure is used to keep track of the best separating axis. */
class b2EPAxis {
  static readonly e_unknown = 0;
  static readonly e_edgeA = 1;
  static readonly e_edgeB = 2;

  type = b2EPAxis.e_unknown;
  index = 0;
  separation = 0.0;

  Assign(other: Readonly<b2EPAxis>): this {
    this.type = other.type;
    this.index = other.index;
    this.separation = other.separation;
    return this;
  }
}

/** This holds polygon B expressed in frame A. */
class b2TempPolygon {
  readonly vertices: b2Vec2[] = b2MakeArray(b2_maxPolygonVertices, () => new b2Vec2());
  readonly normals: b2Vec2[] = b2MakeArray(b2_maxPolygonVertices, () => new b2Vec2());
  count = 0;
}

/** Reference face used for clipping */
class b2ReferenceFace {
  i1 = 0;
  i2 = 0;

  readonly v1 = new b2Vec2();
  readonly v2 = new b2Vec2();

  readonly normal = new b2Vec2();

  readonly sideNormal1 = new b2Vec2();
  sideOffset1 = 0.0;

  readonly sideNormal2 = new b2Vec2();
  sideOffset2 = 0.0;
}

// Scratch for b2EPCollider.Collide: the C++ locals ie, clipPoints1, clipPoints2, rf and the axes.
const s_ie: readonly b2ClipVertex[] = [new b2ClipVertex(), new b2ClipVertex()];
const s_clipPoints1: readonly b2ClipVertex[] = [new b2ClipVertex(), new b2ClipVertex()];
const s_clipPoints2: readonly b2ClipVertex[] = [new b2ClipVertex(), new b2ClipVertex()];
const s_rf = new b2ReferenceFace();
const s_edgeAxis = new b2EPAxis();
const s_polygonAxis = new b2EPAxis();
const s_primaryAxis = new b2EPAxis();
const s_edge0 = new b2Vec2();
const s_edge1 = new b2Vec2();
const s_edge2 = new b2Vec2();

/** This class collides and edge and a polygon, taking into account edge adjacency. */
class b2EPCollider {
  readonly m_polygonB = new b2TempPolygon();

  readonly m_xf = new b2Transform();
  readonly m_centroidB = new b2Vec2();
  readonly m_v0 = new b2Vec2();
  readonly m_v1 = new b2Vec2();
  readonly m_v2 = new b2Vec2();
  readonly m_v3 = new b2Vec2();
  readonly m_normal0 = new b2Vec2();
  readonly m_normal1 = new b2Vec2();
  readonly m_normal2 = new b2Vec2();
  readonly m_normal = new b2Vec2();
  readonly m_lowerLimit = new b2Vec2();
  readonly m_upperLimit = new b2Vec2();
  m_radius = 0.0;
  m_front = false;

  // Algorithm:
  // 1. Classify v1 and v2
  // 2. Classify polygon centroid as front or back
  // 3. Flip normal if necessary
  // 4. Initialize normal range to [-pi, pi] about face normal
  // 5. Adjust normal range according to adjacent edges
  // 6. Visit each separating axes, only accept axes within the range
  // 7. Return if _any_ axis indicates separation
  // 8. Clip
  Collide(manifold: b2Manifold, edgeA: b2EdgeShape, xfA: Readonly<b2Transform>, polygonB: b2PolygonShape, xfB: Readonly<b2Transform>): void {
    const xf = b2MulTXX(xfA, xfB, this.m_xf);

    const centroidB = b2MulXV(xf, polygonB.m_centroid, this.m_centroidB);

    const v0 = this.m_v0.Assign(edgeA.m_vertex0);
    const v1 = this.m_v1.Assign(edgeA.m_vertex1);
    const v2 = this.m_v2.Assign(edgeA.m_vertex2);
    const v3 = this.m_v3.Assign(edgeA.m_vertex3);

    const hasVertex0 = edgeA.m_hasVertex0;
    const hasVertex3 = edgeA.m_hasVertex3;

    const normal0 = this.m_normal0;
    const normal1 = this.m_normal1;
    const normal2 = this.m_normal2;

    // b2Normalize, not b2Vec2.Normalize: this function is past V8's inlining budget, and the
    // length the method returns would be boxed.
    const edge1 = s_edge1.Set(v2.x - v1.x, v2.y - v1.y);
    b2Normalize(edge1);
    normal1.Set(edge1.y, -edge1.x);
    const offset1 = normal1.x * (centroidB.x - v1.x) + normal1.y * (centroidB.y - v1.y);
    let offset0 = 0.0;
    let offset2 = 0.0;
    let convex1 = false;
    let convex2 = false;

    // Is there a preceding edge?
    if (hasVertex0) {
      const edge0 = s_edge0.Set(v1.x - v0.x, v1.y - v0.y);
      b2Normalize(edge0);
      normal0.Set(edge0.y, -edge0.x);
      convex1 = edge0.x * edge1.y - edge0.y * edge1.x >= 0.0;
      offset0 = normal0.x * (centroidB.x - v0.x) + normal0.y * (centroidB.y - v0.y);
    }

    // Is there a following edge?
    if (hasVertex3) {
      const edge2 = s_edge2.Set(v3.x - v2.x, v3.y - v2.y);
      b2Normalize(edge2);
      normal2.Set(edge2.y, -edge2.x);
      convex2 = edge1.x * edge2.y - edge1.y * edge2.x > 0.0;
      offset2 = normal2.x * (centroidB.x - v2.x) + normal2.y * (centroidB.y - v2.y);
    }

    // Determine front or back collision. Determine collision normal limits.
    const normal = this.m_normal;
    const lowerLimit = this.m_lowerLimit;
    const upperLimit = this.m_upperLimit;
    if (hasVertex0 && hasVertex3) {
      if (convex1 && convex2) {
        this.m_front = offset0 >= 0.0 || offset1 >= 0.0 || offset2 >= 0.0;
        if (this.m_front) {
          normal.Assign(normal1);
          lowerLimit.Assign(normal0);
          upperLimit.Assign(normal2);
        } else {
          neg(normal, normal1);
          neg(lowerLimit, normal1);
          neg(upperLimit, normal1);
        }
      } else if (convex1) {
        this.m_front = offset0 >= 0.0 || (offset1 >= 0.0 && offset2 >= 0.0);
        if (this.m_front) {
          normal.Assign(normal1);
          lowerLimit.Assign(normal0);
          upperLimit.Assign(normal1);
        } else {
          neg(normal, normal1);
          neg(lowerLimit, normal2);
          neg(upperLimit, normal1);
        }
      } else if (convex2) {
        this.m_front = offset2 >= 0.0 || (offset0 >= 0.0 && offset1 >= 0.0);
        if (this.m_front) {
          normal.Assign(normal1);
          lowerLimit.Assign(normal1);
          upperLimit.Assign(normal2);
        } else {
          neg(normal, normal1);
          neg(lowerLimit, normal1);
          neg(upperLimit, normal0);
        }
      } else {
        this.m_front = offset0 >= 0.0 && offset1 >= 0.0 && offset2 >= 0.0;
        if (this.m_front) {
          normal.Assign(normal1);
          lowerLimit.Assign(normal1);
          upperLimit.Assign(normal1);
        } else {
          neg(normal, normal1);
          neg(lowerLimit, normal2);
          neg(upperLimit, normal0);
        }
      }
    } else if (hasVertex0) {
      if (convex1) {
        this.m_front = offset0 >= 0.0 || offset1 >= 0.0;
        if (this.m_front) {
          normal.Assign(normal1);
          lowerLimit.Assign(normal0);
          neg(upperLimit, normal1);
        } else {
          neg(normal, normal1);
          lowerLimit.Assign(normal1);
          neg(upperLimit, normal1);
        }
      } else {
        this.m_front = offset0 >= 0.0 && offset1 >= 0.0;
        if (this.m_front) {
          normal.Assign(normal1);
          lowerLimit.Assign(normal1);
          neg(upperLimit, normal1);
        } else {
          neg(normal, normal1);
          lowerLimit.Assign(normal1);
          neg(upperLimit, normal0);
        }
      }
    } else if (hasVertex3) {
      if (convex2) {
        this.m_front = offset1 >= 0.0 || offset2 >= 0.0;
        if (this.m_front) {
          normal.Assign(normal1);
          neg(lowerLimit, normal1);
          upperLimit.Assign(normal2);
        } else {
          neg(normal, normal1);
          neg(lowerLimit, normal1);
          upperLimit.Assign(normal1);
        }
      } else {
        this.m_front = offset1 >= 0.0 && offset2 >= 0.0;
        if (this.m_front) {
          normal.Assign(normal1);
          neg(lowerLimit, normal1);
          upperLimit.Assign(normal1);
        } else {
          neg(normal, normal1);
          neg(lowerLimit, normal2);
          upperLimit.Assign(normal1);
        }
      }
    } else {
      this.m_front = offset1 >= 0.0;
      if (this.m_front) {
        normal.Assign(normal1);
        neg(lowerLimit, normal1);
        neg(upperLimit, normal1);
      } else {
        neg(normal, normal1);
        lowerLimit.Assign(normal1);
        upperLimit.Assign(normal1);
      }
    }

    // Get polygonB in frameA
    const polygon = this.m_polygonB;
    polygon.count = polygonB.m_vertexCount;
    for (let i = 0; i < polygonB.m_vertexCount; ++i) {
      b2MulXV(xf, polygonB.m_vertices[i], polygon.vertices[i]);
      b2MulRV(xf.q, polygonB.m_normals[i], polygon.normals[i]);
    }

    this.m_radius = 2.0 * b2_polygonRadius;

    manifold.pointCount = 0;

    const edgeAxis = this.ComputeEdgeSeparation(s_edgeAxis);

    // If no valid normal can be found than this edge should not collide.
    if (edgeAxis.type === b2EPAxis.e_unknown) {
      return;
    }

    if (edgeAxis.separation > this.m_radius) {
      return;
    }

    const polygonAxis = this.ComputePolygonSeparation(s_polygonAxis);
    if (polygonAxis.type !== b2EPAxis.e_unknown && polygonAxis.separation > this.m_radius) {
      return;
    }

    // Use hysteresis for jitter reduction.
    const k_relativeTol = 0.98;
    const k_absoluteTol = 0.001;

    const primaryAxis = s_primaryAxis;
    if (polygonAxis.type === b2EPAxis.e_unknown) {
      primaryAxis.Assign(edgeAxis);
    } else if (polygonAxis.separation > k_relativeTol * edgeAxis.separation + k_absoluteTol) {
      primaryAxis.Assign(polygonAxis);
    } else {
      primaryAxis.Assign(edgeAxis);
    }

    const ie = s_ie;
    const rf = s_rf;
    if (primaryAxis.type === b2EPAxis.e_edgeA) {
      manifold.type = b2Manifold.e_faceA;

      // Search for the polygon normal that is most anti-parallel to the edge normal. The dot
      // products here and for the side offsets below are written out: this function is past
      // V8's inlining budget, and a b2Dot left a call returns its double boxed (an allocation).
      let bestIndex = 0;
      let bestValue = normal.x * polygon.normals[0].x + normal.y * polygon.normals[0].y;
      for (let i = 1; i < polygon.count; ++i) {
        const n = polygon.normals[i];
        const value = normal.x * n.x + normal.y * n.y;
        if (value < bestValue) {
          bestValue = value;
          bestIndex = i;
        }
      }

      const i1 = bestIndex;
      const i2 = i1 + 1 < polygon.count ? i1 + 1 : 0;

      ie[0].v.Assign(polygon.vertices[i1]);
      setFeature(ie[0].id, 0, i1, b2ContactFeature.e_face, b2ContactFeature.e_vertex);

      ie[1].v.Assign(polygon.vertices[i2]);
      setFeature(ie[1].id, 0, i2, b2ContactFeature.e_face, b2ContactFeature.e_vertex);

      if (this.m_front) {
        rf.i1 = 0;
        rf.i2 = 1;
        rf.v1.Assign(v1);
        rf.v2.Assign(v2);
        rf.normal.Assign(normal1);
      } else {
        rf.i1 = 1;
        rf.i2 = 0;
        rf.v1.Assign(v2);
        rf.v2.Assign(v1);
        neg(rf.normal, normal1);
      }
    } else {
      manifold.type = b2Manifold.e_faceB;

      ie[0].v.Assign(v1);
      setFeature(ie[0].id, 0, primaryAxis.index, b2ContactFeature.e_vertex, b2ContactFeature.e_face);

      ie[1].v.Assign(v2);
      setFeature(ie[1].id, 0, primaryAxis.index, b2ContactFeature.e_vertex, b2ContactFeature.e_face);

      rf.i1 = primaryAxis.index;
      rf.i2 = rf.i1 + 1 < polygon.count ? rf.i1 + 1 : 0;
      rf.v1.Assign(polygon.vertices[rf.i1]);
      rf.v2.Assign(polygon.vertices[rf.i2]);
      rf.normal.Assign(polygon.normals[rf.i1]);
    }

    rf.sideNormal1.Set(rf.normal.y, -rf.normal.x);
    neg(rf.sideNormal2, rf.sideNormal1);
    rf.sideOffset1 = rf.sideNormal1.x * rf.v1.x + rf.sideNormal1.y * rf.v1.y;
    rf.sideOffset2 = rf.sideNormal2.x * rf.v2.x + rf.sideNormal2.y * rf.v2.y;

    // Clip incident edge against extruded edge1 side edges.
    const clipPoints1 = s_clipPoints1;
    const clipPoints2 = s_clipPoints2;
    let np: number;

    // Clip to box side 1
    b2ClipSegmentOffset[0] = rf.sideOffset1;
    np = b2ClipSegment(clipPoints1, ie, rf.sideNormal1, rf.i1);

    if (np < b2_maxManifoldPoints) {
      return;
    }

    // Clip to negative box side 1
    b2ClipSegmentOffset[0] = rf.sideOffset2;
    np = b2ClipSegment(clipPoints2, clipPoints1, rf.sideNormal2, rf.i2);

    if (np < b2_maxManifoldPoints) {
      return;
    }

    // Now clipPoints2 contains the clipped points.
    if (primaryAxis.type === b2EPAxis.e_edgeA) {
      b2SetManifoldFace(manifold, rf.normal, rf.v1);
    } else {
      b2SetManifoldFace(manifold, polygonB.m_normals[rf.i1], polygonB.m_vertices[rf.i1]);
    }

    let pointCount = 0;
    for (let i = 0; i < b2_maxManifoldPoints; ++i) {
      const clipPoint = clipPoints2[i];
      const separation = rf.normal.x * (clipPoint.v.x - rf.v1.x) + rf.normal.y * (clipPoint.v.y - rf.v1.y);

      if (separation <= this.m_radius) {
        if (primaryAxis.type === b2EPAxis.e_edgeA) {
          b2SetManifoldPoint(manifold, pointCount, b2MulTXV(xf, clipPoint.v, s_localPoint), clipPoint.id.key);
        } else {
          const cf = clipPoint.id;
          b2SetManifoldPoint(manifold, pointCount, clipPoint.v, b2ContactKey(cf.indexB, cf.indexA, cf.typeB, cf.typeA));
        }

        ++pointCount;
      }
    }

    manifold.pointCount = pointCount;
  }

  ComputeEdgeSeparation(axis: b2EPAxis): b2EPAxis {
    axis.type = b2EPAxis.e_edgeA;
    axis.index = this.m_front ? 0 : 1;
    axis.separation = b2_maxFloat;

    const polygon = this.m_polygonB;
    const normal = this.m_normal;
    const v1 = this.m_v1;
    for (let i = 0; i < polygon.count; ++i) {
      const vertex = polygon.vertices[i];
      const s = normal.x * (vertex.x - v1.x) + normal.y * (vertex.y - v1.y);
      if (s < axis.separation) {
        axis.separation = s;
      }
    }

    return axis;
  }

  ComputePolygonSeparation(axis: b2EPAxis): b2EPAxis {
    axis.type = b2EPAxis.e_unknown;
    axis.index = -1;
    axis.separation = -b2_maxFloat;

    const normal = this.m_normal;
    const perpX = -normal.y;
    const perpY = normal.x;

    const polygon = this.m_polygonB;
    const v1 = this.m_v1;
    const v2 = this.m_v2;
    const lowerLimit = this.m_lowerLimit;
    const upperLimit = this.m_upperLimit;
    for (let i = 0; i < polygon.count; ++i) {
      const nx = -polygon.normals[i].x;
      const ny = -polygon.normals[i].y;
      const vertex = polygon.vertices[i];

      const s1 = nx * (vertex.x - v1.x) + ny * (vertex.y - v1.y);
      const s2 = nx * (vertex.x - v2.x) + ny * (vertex.y - v2.y);
      const s = b2Min(s1, s2);

      if (s > this.m_radius) {
        // No collision
        axis.type = b2EPAxis.e_edgeB;
        axis.index = i;
        axis.separation = s;
        return axis;
      }

      // Adjacency
      if (nx * perpX + ny * perpY >= 0.0) {
        if ((nx - upperLimit.x) * normal.x + (ny - upperLimit.y) * normal.y < -b2_angularSlop) {
          continue;
        }
      } else {
        if ((nx - lowerLimit.x) * normal.x + (ny - lowerLimit.y) * normal.y < -b2_angularSlop) {
          continue;
        }
      }

      if (s > axis.separation) {
        axis.type = b2EPAxis.e_edgeB;
        axis.index = i;
        axis.separation = s;
      }
    }

    return axis;
  }
}

/** out = -n */
function neg(out: b2Vec2, n: Readonly<b2Vec2>): void {
  out.x = -n.x;
  out.y = -n.y;
}

// The C++ makes a fresh collider per call; every field it reads is written first in Collide,
// so one instance serves all calls (the function never calls out to user code).
const s_collider = new b2EPCollider();

export function b2CollideEdgeAndPolygon(
  manifold: b2Manifold,
  edgeA: b2EdgeShape,
  xfA: Readonly<b2Transform>,
  polygonB: b2PolygonShape,
  xfB: Readonly<b2Transform>,
): void {
  s_collider.Collide(manifold, edgeA, xfA, polygonB, xfB);
}
