/*
 * Shape argument checks (no C++ counterpart; see common/b2ArgumentError.ts).
 *
 * b2PolygonShape.Set, SetAsBox, b2ChainShape.CreateChain/CreateLoop and b2EdgeShape.Set check
 * their arguments; b2Body.CreateFixture checks the whole shape it clones, because the shape's
 * fields (m_radius, m_p, m_vertices...) are public as in Box2D and may have been set directly.
 */

import type { b2Vec2 } from '../../common/b2Math';
import { b2ArgumentError, b2CheckInteger, b2CheckNonNegative, b2CheckVec2, b2DescribeNumber } from '../../common/b2ArgumentError';
import { b2_epsilon, b2_maxPolygonVertices } from '../../common/b2Settings';
import type { b2ChainShape } from './b2ChainShape';
import type { b2CircleShape } from './b2CircleShape';
import type { b2EdgeShape } from './b2EdgeShape';
import type { b2PolygonShape } from './b2PolygonShape';
import { b2Shape } from './b2Shape';

type Vec = Readonly<b2Vec2>;

const kConvexRule = 'makes the polygon non-convex (vertices must be counter-clockwise and convex)';

/** The polygon's signed area, fanned from the origin as ComputeCentroid does. */
function signedArea(vertices: readonly Vec[], count: number): number {
  let area = 0.0;
  for (let i = 0; i < count; ++i) {
    const p2 = vertices[i];
    const p3 = i + 1 < count ? vertices[i + 1] : vertices[0];
    area += 0.5 * (p2.x * p3.y - p2.y * p3.x);
  }
  return area;
}

/** cross(b - a, c - a) is clearly negative: c lies right of the line a->b beyond rounding. */
function rightOf(a: Vec, b: Vec, c: Vec): boolean {
  const ex = b.x - a.x;
  const ey = b.y - a.y;
  const dx = c.x - a.x;
  const dy = c.y - a.y;
  const cross = ex * dy - ey * dx;
  // A relative tolerance: rounding in the cross product is a few ulps of |e||d|, far below this.
  return cross < -b2_epsilon * Math.sqrt((ex * ex + ey * ey) * (dx * dx + dy * dy));
}

/**
 * Check the vertex list of a convex polygon: count in [3, b2_maxPolygonVertices], finite vertices,
 * edges longer than b2_epsilon (2.2.1's assert in Set), counter-clockwise, area above `minArea`,
 * and convex (no vertex right of any edge).
 */
export function b2CheckPolygonVertices(
  method: string,
  argument: string,
  countArgument: string,
  vertices: readonly Vec[],
  count: number,
  minArea: number,
): void {
  if (!Array.isArray(vertices)) {
    throw new b2ArgumentError(method, argument, `must be an array of vectors, got ${b2DescribeNumber(vertices)}`);
  }
  b2CheckInteger(method, countArgument, count, 3, b2_maxPolygonVertices);
  if (count > vertices.length) {
    throw new b2ArgumentError(method, countArgument, `is ${count} but ${argument} has only ${vertices.length} entries`);
  }
  for (let i = 0; i < count; ++i) {
    b2CheckVec2(method, `${argument}[${i}]`, vertices[i]);
  }
  for (let i = 0; i < count; ++i) {
    const i2 = i + 1 < count ? i + 1 : 0;
    const ex = vertices[i2].x - vertices[i].x;
    const ey = vertices[i2].y - vertices[i].y;
    if (!(ex * ex + ey * ey > b2_epsilon * b2_epsilon)) {
      throw new b2ArgumentError(method, `${argument}[${i2}]`, `coincides with ${argument}[${i}] (polygon edges must be longer than b2_epsilon)`);
    }
  }
  const area = signedArea(vertices, count);
  if (area < 0.0) {
    throw new b2ArgumentError(method, argument, `are clockwise (signed area ${area}; vertices must be counter-clockwise and convex)`);
  }
  if (!(area > minArea)) {
    const bound = minArea === 0.0 ? '0' : 'b2_epsilon';
    throw new b2ArgumentError(method, argument, `enclose an area of ${area}, which must exceed ${bound}`);
  }
  // A reflex vertex turns right.
  for (let i = 0; i < count; ++i) {
    const prev = vertices[i > 0 ? i - 1 : count - 1];
    const next = vertices[i + 1 < count ? i + 1 : 0];
    if (rightOf(prev, vertices[i], next)) {
      throw new b2ArgumentError(method, `${argument}[${i}]`, kConvexRule);
    }
  }
  // Every left turn but still self-intersecting (the polygon winds more than once).
  for (let i = 0; i < count; ++i) {
    const i2 = i + 1 < count ? i + 1 : 0;
    for (let j = 0; j < count; ++j) {
      if (j !== i && j !== i2 && rightOf(vertices[i], vertices[i2], vertices[j])) {
        throw new b2ArgumentError(method, `${argument}[${j}]`, kConvexRule);
      }
    }
  }
}

/** Check a chain's vertex list: enough vertices, finite, no vertex repeating the one before. */
export function b2CheckChainVertices(method: string, argument: string, countArgument: string, vertices: readonly Vec[], count: number, loop: boolean): void {
  if (!Array.isArray(vertices)) {
    throw new b2ArgumentError(method, argument, `must be an array of vectors, got ${b2DescribeNumber(vertices)}`);
  }
  const min = loop ? 3 : 2;
  if (typeof count !== 'number' || !Number.isInteger(count) || count < min) {
    const what = loop ? 'a loop needs at least 3 vertices' : 'a chain needs at least 2 vertices';
    throw new b2ArgumentError(method, countArgument, `must be an integer >= ${min} (${what}), got ${b2DescribeNumber(count)}`);
  }
  if (count > vertices.length) {
    throw new b2ArgumentError(method, countArgument, `is ${count} but ${argument} has only ${vertices.length} entries`);
  }
  for (let i = 0; i < count; ++i) {
    b2CheckVec2(method, `${argument}[${i}]`, vertices[i]);
  }
  const last = loop ? count : count - 1;
  for (let i = 0; i < last; ++i) {
    const i2 = i + 1 < count ? i + 1 : 0;
    const dx = vertices[i2].x - vertices[i].x;
    const dy = vertices[i2].y - vertices[i].y;
    if (!(dx * dx + dy * dy > b2_epsilon * b2_epsilon)) {
      const kind = loop && i2 === 0 ? 'closes the loop onto' : 'repeats';
      throw new b2ArgumentError(method, `${argument}[${i2}]`, `${kind} ${argument}[${i}] (consecutive chain vertices must be more than b2_epsilon apart)`);
    }
  }
}

/** Check an edge's end points: finite and more than b2_epsilon apart. */
export function b2CheckEdgeVertices(method: string, argument1: string, argument2: string, v1: Vec, v2: Vec): void {
  b2CheckVec2(method, argument1, v1);
  b2CheckVec2(method, argument2, v2);
  const dx = v2.x - v1.x;
  const dy = v2.y - v1.y;
  if (!(dx * dx + dy * dy > b2_epsilon * b2_epsilon)) {
    throw new b2ArgumentError(method, argument2, `coincides with ${argument1} (an edge must be longer than b2_epsilon)`);
  }
}

/**
 * Check a whole shape before a fixture clones it. `density` > 0 also requires what the mass
 * computation asserts (a polygon area above b2_epsilon).
 */
export function b2CheckShape(method: string, argument: string, shape: b2Shape, density: number): void {
  if (!(shape instanceof b2Shape)) {
    throw new b2ArgumentError(method, argument, `must be a b2Shape, got ${b2DescribeNumber(shape)}`);
  }
  switch (shape.m_type) {
    case b2Shape.e_circle: {
      const circle = shape as b2CircleShape;
      b2CheckNonNegative(method, `${argument}.m_radius`, circle.m_radius);
      b2CheckVec2(method, `${argument}.m_p`, circle.m_p);
      return;
    }
    case b2Shape.e_edge: {
      const edge = shape as b2EdgeShape;
      b2CheckNonNegative(method, `${argument}.m_radius`, edge.m_radius);
      b2CheckEdgeVertices(method, `${argument}.m_vertex1`, `${argument}.m_vertex2`, edge.m_vertex1, edge.m_vertex2);
      if (edge.m_hasVertex0) b2CheckVec2(method, `${argument}.m_vertex0`, edge.m_vertex0);
      if (edge.m_hasVertex3) b2CheckVec2(method, `${argument}.m_vertex3`, edge.m_vertex3);
      return;
    }
    case b2Shape.e_polygon: {
      const polygon = shape as b2PolygonShape;
      b2CheckNonNegative(method, `${argument}.m_radius`, polygon.m_radius);
      const minArea = density > 0.0 ? b2_epsilon : 0.0;
      b2CheckPolygonVertices(method, `${argument}.m_vertices`, `${argument}.m_vertexCount`, polygon.m_vertices, polygon.m_vertexCount, minArea);
      for (let i = 0; i < polygon.m_vertexCount; ++i) {
        b2CheckVec2(method, `${argument}.m_normals[${i}]`, polygon.m_normals[i]);
      }
      b2CheckVec2(method, `${argument}.m_centroid`, polygon.m_centroid);
      return;
    }
    case b2Shape.e_chain: {
      const chain = shape as b2ChainShape;
      b2CheckNonNegative(method, `${argument}.m_radius`, chain.m_radius);
      b2CheckChainVertices(method, `${argument}.m_vertices`, `${argument}.m_count`, chain.m_vertices, chain.m_count, false);
      if (chain.m_hasPrevVertex) b2CheckVec2(method, `${argument}.m_prevVertex`, chain.m_prevVertex);
      if (chain.m_hasNextVertex) b2CheckVec2(method, `${argument}.m_nextVertex`, chain.m_nextVertex);
      return;
    }
    default:
      throw new b2ArgumentError(method, `${argument}.m_type`, `must be b2Shape.e_circle, e_edge, e_polygon or e_chain, got ${b2DescribeNumber(shape.m_type)}`);
  }
}
