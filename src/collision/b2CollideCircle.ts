/*
 * Circle-circle and polygon-circle manifolds (b2CollideCircle.cpp).
 */

import { b2MulTXV, b2MulXV, b2Normalize, b2Vec2, b2Vec2_zero } from '../common/b2Math';
import type { b2Transform } from '../common/b2Math';
import { b2_epsilon, b2_maxFloat } from '../common/b2Settings';
import { b2Manifold } from './b2Collision';
import { b2SetManifoldFace, b2SetManifoldPoint } from './b2ManifoldRecord';
import type { b2CircleShape } from './shapes/b2CircleShape';
import type { b2PolygonShape } from './shapes/b2PolygonShape';

const s_pA = new b2Vec2();
const s_pB = new b2Vec2();
const s_cLocal = new b2Vec2();
const s_normal = new b2Vec2();
const s_faceCenter = new b2Vec2();

/** Compute the collision manifold between two circles. */
export function b2CollideCircles(
  manifold: b2Manifold,
  circleA: Readonly<b2CircleShape>,
  xfA: Readonly<b2Transform>,
  circleB: Readonly<b2CircleShape>,
  xfB: Readonly<b2Transform>,
): void {
  manifold.pointCount = 0;

  const pA = b2MulXV(xfA, circleA.m_p, s_pA);
  const pB = b2MulXV(xfB, circleB.m_p, s_pB);

  const dx = pB.x - pA.x;
  const dy = pB.y - pA.y;
  const distSqr = dx * dx + dy * dy;
  const rA = circleA.m_radius;
  const rB = circleB.m_radius;
  const radius = rA + rB;
  if (distSqr > radius * radius) {
    return;
  }

  manifold.type = b2Manifold.e_circles;
  b2SetManifoldFace(manifold, b2Vec2_zero, circleA.m_p);
  manifold.pointCount = 1;

  b2SetManifoldPoint(manifold, 0, circleB.m_p, 0);
}

/** Compute the collision manifold between a polygon and a circle. */
export function b2CollidePolygonAndCircle(
  manifold: b2Manifold,
  polygonA: Readonly<b2PolygonShape>,
  xfA: Readonly<b2Transform>,
  circleB: Readonly<b2CircleShape>,
  xfB: Readonly<b2Transform>,
): void {
  manifold.pointCount = 0;

  // Compute circle position in the frame of the polygon.
  const c = b2MulXV(xfB, circleB.m_p, s_cLocal);
  const cLocal = b2MulTXV(xfA, c, s_cLocal);
  const cx = cLocal.x;
  const cy = cLocal.y;

  // Find the min separating edge.
  let normalIndex = 0;
  let separation = -b2_maxFloat;
  const radius = polygonA.m_radius + circleB.m_radius;
  const vertexCount = polygonA.m_vertexCount;
  const vertices = polygonA.m_vertices;
  const normals = polygonA.m_normals;

  for (let i = 0; i < vertexCount; ++i) {
    const n = normals[i];
    const v = vertices[i];
    const s = n.x * (cx - v.x) + n.y * (cy - v.y);

    if (s > radius) {
      // Early out.
      return;
    }

    if (s > separation) {
      separation = s;
      normalIndex = i;
    }
  }

  // Vertices that subtend the incident face.
  const vertIndex1 = normalIndex;
  const vertIndex2 = vertIndex1 + 1 < vertexCount ? vertIndex1 + 1 : 0;
  const v1 = vertices[vertIndex1];
  const v2 = vertices[vertIndex2];

  // The branches below set the scratch vectors field by field and normalize with b2Normalize:
  // each runs for few contacts, and V8 leaves calls there out of line, boxing their doubles.

  // If the center is inside the polygon ...
  if (separation < b2_epsilon) {
    manifold.pointCount = 1;
    manifold.type = b2Manifold.e_faceA;
    s_faceCenter.x = 0.5 * (v1.x + v2.x);
    s_faceCenter.y = 0.5 * (v1.y + v2.y);
    b2SetManifoldFace(manifold, normals[normalIndex], s_faceCenter);
    b2SetManifoldPoint(manifold, 0, circleB.m_p, 0);
    return;
  }

  // Compute barycentric coordinates
  const u1 = (cx - v1.x) * (v2.x - v1.x) + (cy - v1.y) * (v2.y - v1.y);
  const u2 = (cx - v2.x) * (v1.x - v2.x) + (cy - v2.y) * (v1.y - v2.y);
  if (u1 <= 0.0) {
    const dx = cx - v1.x;
    const dy = cy - v1.y;
    if (dx * dx + dy * dy > radius * radius) {
      return;
    }

    manifold.pointCount = 1;
    manifold.type = b2Manifold.e_faceA;
    const n = s_normal;
    n.x = cx - v1.x;
    n.y = cy - v1.y;
    b2Normalize(n);
    b2SetManifoldFace(manifold, n, v1);
    b2SetManifoldPoint(manifold, 0, circleB.m_p, 0);
  } else if (u2 <= 0.0) {
    const dx = cx - v2.x;
    const dy = cy - v2.y;
    if (dx * dx + dy * dy > radius * radius) {
      return;
    }

    manifold.pointCount = 1;
    manifold.type = b2Manifold.e_faceA;
    const n = s_normal;
    n.x = cx - v2.x;
    n.y = cy - v2.y;
    b2Normalize(n);
    b2SetManifoldFace(manifold, n, v2);
    b2SetManifoldPoint(manifold, 0, circleB.m_p, 0);
  } else {
    const faceCenterX = 0.5 * (v1.x + v2.x);
    const faceCenterY = 0.5 * (v1.y + v2.y);
    const n1 = normals[vertIndex1];
    const faceSeparation = (cx - faceCenterX) * n1.x + (cy - faceCenterY) * n1.y;
    if (faceSeparation > radius) {
      return;
    }

    manifold.pointCount = 1;
    manifold.type = b2Manifold.e_faceA;
    s_faceCenter.x = faceCenterX;
    s_faceCenter.y = faceCenterY;
    b2SetManifoldFace(manifold, n1, s_faceCenter);
    b2SetManifoldPoint(manifold, 0, circleB.m_p, 0);
  }
}
