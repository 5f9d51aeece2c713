/*
 * Polygon-polygon manifolds: separating axis search plus clipping (b2CollidePolygon.cpp).
 */

import { b2Vec2 } from '../common/b2Math';
import type { b2Transform } from '../common/b2Math';
import { b2_maxFloat, b2_maxManifoldPoints, b2Assert } from '../common/b2Settings';
import { b2ClipSegment, b2ClipSegmentOffset, b2ClipVertex, b2ContactFeature, b2ContactKey, b2Manifold } from './b2Collision';
import { b2ManifoldField, b2ManifoldPointField } from './b2ManifoldRecord';
import type { b2PolygonShape } from './shapes/b2PolygonShape';

// The separations the two functions below compute are returned in these slots: a double returned
// from a call V8 does not inline is boxed (a heap allocation per call), a typed array slot is not.
const s_edgeSeparation = new Float64Array(1);
const s_maxSeparation = new Float64Array(1);

/**
 * Find the separation between poly1 and poly2 for a give edge normal on poly1; the separation is
 * written to s_edgeSeparation[0].
 */
function b2EdgeSeparation(
  poly1: Readonly<b2PolygonShape>,
  xf1: Readonly<b2Transform>,
  edge1: number,
  poly2: Readonly<b2PolygonShape>,
  xf2: Readonly<b2Transform>,
): void {
  const count2 = poly2.m_vertexCount;
  const vertices2 = poly2.m_vertices;

  b2Assert(0 <= edge1 && edge1 < poly1.m_vertexCount);

  // The transforms' parts in locals, poly1's arrays read where used: V8 inlines a function only up
  // to 460 bytes of bytecode, and each repeated xf.q.c is two property loads.
  const q1c = xf1.q.c;
  const q1s = xf1.q.s;
  const p1 = xf1.p;
  const q2c = xf2.q.c;
  const q2s = xf2.q.s;
  const p2 = xf2.p;

  // Convert normal from poly1's frame into poly2's frame.
  const n = poly1.m_normals[edge1];
  const normal1WorldX = q1c * n.x - q1s * n.y;
  const normal1WorldY = q1s * n.x + q1c * n.y;
  const normal1X = q2c * normal1WorldX + q2s * normal1WorldY;
  const normal1Y = -q2s * normal1WorldX + q2c * normal1WorldY;

  // Find support vertex on poly2 for -normal.
  let index = 0;
  let minDot = +b2_maxFloat; // unary plus: docs/PORTING.md

  for (let i = 0; i < count2; ++i) {
    const v = vertices2[i];
    const dot = v.x * normal1X + v.y * normal1Y;
    if (dot < minDot) {
      minDot = dot;
      index = i;
    }
  }

  const a = poly1.m_vertices[edge1];
  const v1x = q1c * a.x - q1s * a.y + p1.x;
  const v1y = q1s * a.x + q1c * a.y + p1.y;
  const b = vertices2[index];
  const v2x = q2c * b.x - q2s * b.y + p2.x;
  const v2y = q2s * b.x + q2c * b.y + p2.y;
  const separation = (v2x - v1x) * normal1WorldX + (v2y - v1y) * normal1WorldY;
  s_edgeSeparation[0] = separation;
}

/**
 * Find the max separation between poly1 and poly2 using edge normals from poly1. The edge is
 * written to edgeIndex[0], the separation to s_maxSeparation[0].
 */
function b2FindMaxSeparation(
  edgeIndex: number[],
  poly1: Readonly<b2PolygonShape>,
  xf1: Readonly<b2Transform>,
  poly2: Readonly<b2PolygonShape>,
  xf2: Readonly<b2Transform>,
): void {
  const count1 = poly1.m_vertexCount;
  const normals1 = poly1.m_normals;

  // Vector pointing from the centroid of poly1 to the centroid of poly2.
  const c2 = poly2.m_centroid;
  const c1 = poly1.m_centroid;
  const dx = xf2.q.c * c2.x - xf2.q.s * c2.y + xf2.p.x - (xf1.q.c * c1.x - xf1.q.s * c1.y + xf1.p.x);
  const dy = xf2.q.s * c2.x + xf2.q.c * c2.y + xf2.p.y - (xf1.q.s * c1.x + xf1.q.c * c1.y + xf1.p.y);
  const dLocal1X = xf1.q.c * dx + xf1.q.s * dy;
  const dLocal1Y = -xf1.q.s * dx + xf1.q.c * dy;

  // Find edge normal on poly1 that has the largest projection onto d.
  let edge = 0;
  let maxDot = -b2_maxFloat;
  for (let i = 0; i < count1; ++i) {
    const dot = normals1[i].x * dLocal1X + normals1[i].y * dLocal1Y;
    if (dot > maxDot) {
      maxDot = dot;
      edge = i;
    }
  }

  // Get the separation for the edge normal.
  b2EdgeSeparation(poly1, xf1, edge, poly2, xf2);
  let s = s_edgeSeparation[0];

  // Check the separation for the previous edge normal.
  const prevEdge = edge - 1 >= 0 ? edge - 1 : count1 - 1;
  b2EdgeSeparation(poly1, xf1, prevEdge, poly2, xf2);
  const sPrev = s_edgeSeparation[0];

  // Check the separation for the next edge normal.
  const nextEdge = edge + 1 < count1 ? edge + 1 : 0;
  b2EdgeSeparation(poly1, xf1, nextEdge, poly2, xf2);
  const sNext = s_edgeSeparation[0];

  // Find the best edge and the search direction.
  let bestEdge: number;
  let bestSeparation: number;
  let increment: number;
  if (sPrev > s && sPrev > sNext) {
    increment = -1;
    bestEdge = prevEdge;
    bestSeparation = sPrev;
  } else if (sNext > s) {
    increment = 1;
    bestEdge = nextEdge;
    bestSeparation = sNext;
  } else {
    edgeIndex[0] = edge;
    s_maxSeparation[0] = s;
    return;
  }

  // Perform a local search for the best edge normal.
  for (;;) {
    if (increment === -1) edge = bestEdge - 1 >= 0 ? bestEdge - 1 : count1 - 1;
    else edge = bestEdge + 1 < count1 ? bestEdge + 1 : 0;

    b2EdgeSeparation(poly1, xf1, edge, poly2, xf2);
    s = s_edgeSeparation[0];

    if (s > bestSeparation) {
      bestEdge = edge;
      bestSeparation = s;
    } else {
      break;
    }
  }

  edgeIndex[0] = bestEdge;
  s_maxSeparation[0] = bestSeparation;
}

function b2FindIncidentEdge(
  c: readonly b2ClipVertex[],
  poly1: Readonly<b2PolygonShape>,
  xf1: Readonly<b2Transform>,
  edge1: number,
  poly2: Readonly<b2PolygonShape>,
  xf2: Readonly<b2Transform>,
): void {
  const normals1 = poly1.m_normals;

  const count2 = poly2.m_vertexCount;
  const vertices2 = poly2.m_vertices;
  const normals2 = poly2.m_normals;

  b2Assert(0 <= edge1 && edge1 < poly1.m_vertexCount);

  // Get the normal of the reference edge in poly2's frame.
  const n = normals1[edge1];
  const wx = xf1.q.c * n.x - xf1.q.s * n.y;
  const wy = xf1.q.s * n.x + xf1.q.c * n.y;
  const normal1X = xf2.q.c * wx + xf2.q.s * wy;
  const normal1Y = -xf2.q.s * wx + xf2.q.c * wy;

  // Find the incident edge on poly2.
  let index = 0;
  let minDot = +b2_maxFloat; // unary plus: docs/PORTING.md
  for (let i = 0; i < count2; ++i) {
    const dot = normal1X * normals2[i].x + normal1Y * normals2[i].y;
    if (dot < minDot) {
      minDot = dot;
      index = i;
    }
  }

  // Build the clip vertices for the incident edge.
  const i1 = index;
  const i2 = i1 + 1 < count2 ? i1 + 1 : 0;

  const a = vertices2[i1];
  const c0 = c[0];
  c0.v.x = xf2.q.c * a.x - xf2.q.s * a.y + xf2.p.x;
  c0.v.y = xf2.q.s * a.x + xf2.q.c * a.y + xf2.p.y;
  c0.id.indexA = edge1 & 0xff;
  c0.id.indexB = i1 & 0xff;
  c0.id.typeA = b2ContactFeature.e_face;
  c0.id.typeB = b2ContactFeature.e_vertex;

  const b = vertices2[i2];
  const c1 = c[1];
  c1.v.x = xf2.q.c * b.x - xf2.q.s * b.y + xf2.p.x;
  c1.v.y = xf2.q.s * b.x + xf2.q.c * b.y + xf2.p.y;
  c1.id.indexA = edge1 & 0xff;
  c1.id.indexB = i2 & 0xff;
  c1.id.typeA = b2ContactFeature.e_face;
  c1.id.typeB = b2ContactFeature.e_vertex;
}

const s_edgeA = [0];
const s_edgeB = [0];
const s_incidentEdge = [new b2ClipVertex(), new b2ClipVertex()];
const s_clipPoints1 = [new b2ClipVertex(), new b2ClipVertex()];
const s_clipPoints2 = [new b2ClipVertex(), new b2ClipVertex()];
const s_localTangent = new b2Vec2();
const s_tangent = new b2Vec2();
const s_negTangent = new b2Vec2();

/**
 * Compute the collision manifold between two polygons.
 *
 * Find edge normal of max separation on A - return if separating axis is found
 * Find edge normal of max separation on B - return if separation axis is found
 * Choose reference edge as min(minA, minB)
 * Find incident edge
 * Clip
 *
 * The normal points from 1 to 2
 */
export function b2CollidePolygons(
  manifold: b2Manifold,
  polyA: Readonly<b2PolygonShape>,
  xfA: Readonly<b2Transform>,
  polyB: Readonly<b2PolygonShape>,
  xfB: Readonly<b2Transform>,
): void {
  manifold.pointCount = 0;
  const totalRadius = polyA.m_radius + polyB.m_radius;

  b2FindMaxSeparation(s_edgeA, polyA, xfA, polyB, xfB);
  const separationA = s_maxSeparation[0];
  const edgeA = s_edgeA[0];
  if (separationA > totalRadius) return;

  b2FindMaxSeparation(s_edgeB, polyB, xfB, polyA, xfA);
  const separationB = s_maxSeparation[0];
  const edgeB = s_edgeB[0];
  if (separationB > totalRadius) return;

  let poly1: Readonly<b2PolygonShape>; // reference polygon
  let poly2: Readonly<b2PolygonShape>; // incident polygon
  let xf1: Readonly<b2Transform>;
  let xf2: Readonly<b2Transform>;
  let edge1: number; // reference edge
  let flip: number;
  const k_relativeTol = 0.98;
  const k_absoluteTol = 0.001;

  if (separationB > k_relativeTol * separationA + k_absoluteTol) {
    poly1 = polyB;
    poly2 = polyA;
    xf1 = xfB;
    xf2 = xfA;
    edge1 = edgeB;
    manifold.type = b2Manifold.e_faceB;
    flip = 1;
  } else {
    poly1 = polyA;
    poly2 = polyB;
    xf1 = xfA;
    xf2 = xfB;
    edge1 = edgeA;
    manifold.type = b2Manifold.e_faceA;
    flip = 0;
  }

  const incidentEdge = s_incidentEdge;
  b2FindIncidentEdge(incidentEdge, poly1, xf1, edge1, poly2, xf2);

  const count1 = poly1.m_vertexCount;
  const vertices1 = poly1.m_vertices;

  const iv1 = edge1;
  const iv2 = edge1 + 1 < count1 ? edge1 + 1 : 0;

  const v11 = vertices1[iv1];
  const v12 = vertices1[iv2];

  const localTangent = s_localTangent.Set(v12.x - v11.x, v12.y - v11.y);
  localTangent.Normalize();

  // b2Cross(localTangent, 1.0)
  const localNormalX = 1.0 * localTangent.y;
  const localNormalY = -1.0 * localTangent.x;
  const planePointX = 0.5 * (v11.x + v12.x);
  const planePointY = 0.5 * (v11.y + v12.y);

  const qc = xf1.q.c;
  const qs = xf1.q.s;
  const tangentX = qc * localTangent.x - qs * localTangent.y;
  const tangentY = qs * localTangent.x + qc * localTangent.y;
  const normalX = 1.0 * tangentY;
  const normalY = -1.0 * tangentX;

  const v11x = qc * v11.x - qs * v11.y + xf1.p.x;
  const v11y = qs * v11.x + qc * v11.y + xf1.p.y;
  const v12x = qc * v12.x - qs * v12.y + xf1.p.x;
  const v12y = qs * v12.x + qc * v12.y + xf1.p.y;

  // Face offset.
  const frontOffset = normalX * v11x + normalY * v11y;

  // Side offsets, extended by polytope skin thickness.
  const sideOffset1 = -(tangentX * v11x + tangentY * v11y) + totalRadius;
  const sideOffset2 = tangentX * v12x + tangentY * v12y + totalRadius;

  // Clip incident edge against extruded edge1 side edges.
  const clipPoints1 = s_clipPoints1;
  const clipPoints2 = s_clipPoints2;

  // Clip to box side 1
  b2ClipSegmentOffset[0] = sideOffset1;
  let np = b2ClipSegment(clipPoints1, incidentEdge, s_negTangent.Set(-tangentX, -tangentY), iv1);

  if (np < 2) return;

  // Clip to negative box side 1
  b2ClipSegmentOffset[0] = sideOffset2;
  np = b2ClipSegment(clipPoints2, clipPoints1, s_tangent.Set(tangentX, tangentY), iv2);

  if (np < 2) {
    return;
  }

  // Now clipPoints2 contains the clipped points.
  const record = manifold.m_record;
  const mo = manifold.m_offset;
  record[mo + b2ManifoldField.localNormalX] = localNormalX;
  record[mo + b2ManifoldField.localNormalY] = localNormalY;
  record[mo + b2ManifoldField.localPointX] = planePointX;
  record[mo + b2ManifoldField.localPointY] = planePointY;

  let pointCount = 0;
  for (let i = 0; i < b2_maxManifoldPoints; ++i) {
    const cv = clipPoints2[i].v;
    const separation = normalX * cv.x + normalY * cv.y - frontOffset;

    if (separation <= totalRadius) {
      const mp = mo + b2ManifoldField.points + pointCount * b2ManifoldPointField.stride;
      const px = cv.x - xf2.p.x;
      const py = cv.y - xf2.p.y;
      record[mp + b2ManifoldPointField.localPointX] = xf2.q.c * px + xf2.q.s * py;
      record[mp + b2ManifoldPointField.localPointY] = -xf2.q.s * px + xf2.q.c * py;
      const cf = clipPoints2[i].id;
      // The id's key; with flip, the features swapped (indexA with indexB, typeA with typeB).
      record[mp + b2ManifoldPointField.key] = flip ? b2ContactKey(cf.indexB, cf.indexA, cf.typeB, cf.typeA) : cf.key;
      ++pointCount;
    }
  }

  manifold.pointCount = pointCount;
}
