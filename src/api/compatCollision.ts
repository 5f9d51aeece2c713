/*
 * Box2DWeb 2.1a compatibility for Box2D.Collision and Box2D.Collision.Shapes: the b2AABB helpers,
 * `new b2RayCastInput(p1, p2)`, the manifolds' m_-prefixed fields, the shape type names of 2.1a,
 * `new b2CircleShape(radius)`, b2PolygonShape's SetAs.../As... builders and b2Collision's
 * static collide functions.
 */

import { b2CollideCircles, b2CollidePolygonAndCircle } from '../collision/b2CollideCircle';
import { b2CollidePolygons } from '../collision/b2CollidePolygon';
import {
  b2AABB,
  b2ContactID,
  b2Manifold,
  b2ManifoldPoint,
  b2RayCastInput,
  b2TestOverlap,
  b2TestOverlapShapes,
  b2WorldManifold,
} from '../collision/b2Collision';
import { b2CircleShape } from '../collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../collision/shapes/b2PolygonShape';
import { b2Shape } from '../collision/shapes/b2Shape';
import { b2ArgumentError, b2CheckObject, b2CheckVec2, b2DescribeNumber } from '../common/b2ArgumentError';
import type { b2Transform } from '../common/b2Math';
import { b2_maxPolygonVertices } from '../common/b2Settings';
import type { b2Contact } from '../dynamics/contacts/b2Contact';
import { b2EdgeAndCircleContact } from '../dynamics/contacts/b2EdgeAndCircleContact';
import { b2Vec2 } from '../common/b2Math';
import { acceptingArguments, defineAccessor, defineMethods, defineStatics, removedClass, removedMethod, wrapMethod } from './patch';

declare module '../collision/b2Collision' {
  interface b2AABB {
    /** The center (written to `out`, or to a new vector as 2.1a returns). */
    GetCenter(out?: b2Vec2): b2Vec2;
    /** The half-widths (written to `out`, or to a new vector as 2.1a returns). */
    GetExtents(out?: b2Vec2): b2Vec2;
    /** 2.2.1's Combine(aabb) grows this box; 2.1a's Combine(aabb1, aabb2) sets it to their union. */
    Combine(aabb1: Readonly<b2AABB>, aabb2?: Readonly<b2AABB>): void;
    /** 2.1a: do this box and another overlap (touching counts)? */
    TestOverlap(other: Readonly<b2AABB>): boolean;
  }
  namespace b2AABB {
    /** 2.1a: a new box, the union of two. */
    function Combine(aabb1: Readonly<b2AABB>, aabb2: Readonly<b2AABB>): b2AABB;
  }

  interface b2ContactID {
    /** 2.1a: this = id. */
    Set(id: Readonly<b2ContactID>): void;
    /** 2.1a: a new id equal to this. */
    Copy(): b2ContactID;
  }

  interface b2ManifoldPoint {
    /** 2.1a's name for localPoint. */
    m_localPoint: b2Vec2;
    /** 2.1a's name for normalImpulse. */
    m_normalImpulse: number;
    /** 2.1a's name for tangentImpulse. */
    m_tangentImpulse: number;
    /** 2.1a's name for id. */
    readonly m_id: b2ContactID;
    /** 2.1a: zero the point. */
    Reset(): void;
    /** 2.1a: this = m. */
    Set(m: Readonly<b2ManifoldPoint>): void;
  }

  interface b2Manifold {
    /** 2.1a's name for points. */
    readonly m_points: readonly b2ManifoldPoint[];
    /** 2.1a's name for localNormal. */
    m_localPlaneNormal: b2Vec2;
    /** 2.1a's name for localPoint. */
    m_localPoint: b2Vec2;
    /** 2.1a's name for type (b2Manifold.e_circles, e_faceA, e_faceB). */
    m_type: number;
    /** 2.1a's name for pointCount. */
    m_pointCount: number;
    /** 2.1a: an empty manifold. */
    Reset(): void;
    /** 2.1a: this = m. */
    Set(m: Readonly<b2Manifold>): void;
    /** 2.1a: a new manifold equal to this. */
    Copy(): b2Manifold;
  }

  interface b2WorldManifold {
    /** 2.1a's name for normal. */
    readonly m_normal: b2Vec2;
    /** 2.1a's name for points. */
    readonly m_points: readonly b2Vec2[];
  }
}

declare module '../collision/shapes/b2Shape' {
  interface b2Shape {
    /** 2.1a: a copy of this shape (2.2.1's Clone). */
    Copy(): b2Shape;
  }
  namespace b2Shape {
    /** 2.1a's shape type names. */
    const e_unknownShape: number;
    const e_circleShape: number;
    const e_polygonShape: number;
    const e_edgeShape: number;
    /** 2.1a: do two single-child shapes overlap? */
    function TestOverlap(shape1: b2Shape, transform1: Readonly<b2Transform>, shape2: b2Shape, transform2: Readonly<b2Transform>): boolean;
  }
}

declare module '../collision/shapes/b2CircleShape' {
  interface b2CircleShape {
    /** 2.1a: the center in body coordinates (the shape's own vector). */
    GetLocalPosition(): b2Vec2;
    /** 2.1a: set the center in body coordinates. */
    SetLocalPosition(position: Readonly<b2Vec2>): void;
    /** 2.1a: the radius. */
    GetRadius(): number;
    /** 2.1a: set the radius. */
    SetRadius(radius: number): void;
  }
}

declare module '../collision/shapes/b2PolygonShape' {
  interface b2PolygonShape {
    /** 2.1a: Set(vertices, count); a count of 0 or none uses every vertex. */
    SetAsArray(vertices: readonly Readonly<b2Vec2>[], vertexCount?: number): void;
    /** 2.1a: the same as SetAsArray. */
    SetAsVector(vertices: readonly Readonly<b2Vec2>[], vertexCount?: number): void;
    /** 2.1a: SetAsBox(hx, hy, center, angle). */
    SetAsOrientedBox(hx: number, hy: number, center?: Readonly<b2Vec2> | null, angle?: number): void;
    /**
     * 2.1a: a two-sided segment from v1 to v2, as a two-vertex polygon. Box2D 2.2 polygons need
     * three vertices, so b2Body.CreateFixture makes the fixture's shape a b2EdgeShape, 2.2's
     * segment shape (fixture.GetShape() is then a b2EdgeShape).
     */
    SetAsEdge(v1: Readonly<b2Vec2>, v2: Readonly<b2Vec2>): void;
    /** 2.1a: the vertices in use (the shape's own vectors, in a new array). */
    GetVertices(): b2Vec2[];
    /** 2.1a: the edge normals in use (the shape's own vectors, in a new array). */
    GetNormals(): b2Vec2[];
  }
  namespace b2PolygonShape {
    /** 2.1a: a new polygon from vertices. */
    function AsArray(vertices: readonly Readonly<b2Vec2>[], vertexCount?: number): b2PolygonShape;
    /** 2.1a: the same as AsArray. */
    function AsVector(vertices: readonly Readonly<b2Vec2>[], vertexCount?: number): b2PolygonShape;
    /** 2.1a: a new box with half-widths hx, hy about the origin. */
    function AsBox(hx: number, hy: number): b2PolygonShape;
    /** 2.1a: a new box with half-widths hx, hy, centered and rotated. */
    function AsOrientedBox(hx: number, hy: number, center?: Readonly<b2Vec2> | null, angle?: number): b2PolygonShape;
    /** 2.1a: a new two-vertex polygon (see SetAsEdge). */
    function AsEdge(v1: Readonly<b2Vec2>, v2: Readonly<b2Vec2>): b2PolygonShape;
    /** 2.1a: the centroid of a convex polygon's vertices (3 to b2_maxPolygonVertices). */
    function ComputeCentroid(vertices: readonly Readonly<b2Vec2>[], count: number): b2Vec2;
  }
}

declare module '../collision/shapes/b2EdgeShape' {
  interface b2EdgeShape {
    /** 2.1a: the first vertex (the shape's own vector). */
    GetVertex1(): b2Vec2;
    /** 2.1a: the second vertex (the shape's own vector). */
    GetVertex2(): b2Vec2;
    /** 2.1a: the distance between the vertices. */
    GetLength(): number;
  }
}

// b2AABB

wrapMethod(
  b2AABB.prototype,
  'GetCenter',
  (getCenter) =>
    function (this: b2AABB, out?: b2Vec2) {
      return getCenter.call(this, out ?? new b2Vec2());
    },
);
wrapMethod(
  b2AABB.prototype,
  'GetExtents',
  (getExtents) =>
    function (this: b2AABB, out?: b2Vec2) {
      return getExtents.call(this, out ?? new b2Vec2());
    },
);
wrapMethod(
  b2AABB.prototype,
  'Combine',
  (combine) =>
    function (this: b2AABB, aabb1: Readonly<b2AABB>, aabb2?: Readonly<b2AABB>) {
      if (aabb2 !== undefined) {
        this.Combine2(aabb1, aabb2);
      } else {
        combine.call(this, aabb1);
      }
    },
);
defineMethods(b2AABB.prototype, {
  TestOverlap(other) {
    return b2TestOverlap(this, other);
  },
});
defineStatics(b2AABB, {
  Combine: (aabb1: Readonly<b2AABB>, aabb2: Readonly<b2AABB>) => {
    const aabb = new b2AABB();
    aabb.Combine2(aabb1, aabb2);
    return aabb;
  },
});

/** b2RayCastInput also takes 2.1a's (p1, p2, maxFraction = 1). */
export const b2RayCastInputCompat = acceptingArguments(b2RayCastInput, (args, make) => {
  const input = make();
  const [p1, p2, maxFraction] = args as [Readonly<b2Vec2> | undefined, Readonly<b2Vec2> | undefined, number | undefined];
  if (p1 !== undefined) input.p1.Assign(p1);
  if (p2 !== undefined) input.p2.Assign(p2);
  if (maxFraction !== undefined) input.maxFraction = maxFraction;
  return input;
}) as typeof b2RayCastInput & (new (p1?: Readonly<b2Vec2>, p2?: Readonly<b2Vec2>, maxFraction?: number) => b2RayCastInput);

// Contact ids and manifolds

defineMethods(b2ContactID.prototype, {
  Set(id) {
    this.Assign(id);
  },
  Copy() {
    return this.Clone();
  },
});

/** 2.1a field names read and written through the 2.2.1 fields. */
function aliasFields<T extends object>(proto: T, aliases: Record<string, keyof T & string>, vectors: readonly string[]): void {
  for (const name of Object.keys(aliases)) {
    const field = aliases[name];
    if (vectors.includes(name)) {
      defineAccessor(
        proto,
        name,
        function () {
          return this[field];
        },
        function (value: b2Vec2) {
          (this[field] as b2Vec2).Assign(value);
        },
      );
    } else {
      defineAccessor(
        proto,
        name,
        function () {
          return this[field];
        },
        function (value: T[keyof T & string]) {
          this[field] = value;
        },
      );
    }
  }
}

aliasFields(b2ManifoldPoint.prototype, { m_localPoint: 'localPoint', m_normalImpulse: 'normalImpulse', m_tangentImpulse: 'tangentImpulse' }, ['m_localPoint']);
defineAccessor(b2ManifoldPoint.prototype, 'm_id', function () {
  return this.id;
});
defineMethods(b2ManifoldPoint.prototype, {
  Reset() {
    // Coordinates written one by one: the vector is a view onto the manifold's record, which
    // engine code keeps away from b2Vec2's methods (docs/PORTING.md, records).
    this.localPoint.x = 0.0;
    this.localPoint.y = 0.0;
    this.normalImpulse = 0.0;
    this.tangentImpulse = 0.0;
    this.id.key = 0;
  },
  Set(m) {
    this.Assign(m);
  },
});

aliasFields(b2Manifold.prototype, { m_localPlaneNormal: 'localNormal', m_localPoint: 'localPoint', m_type: 'type', m_pointCount: 'pointCount' }, [
  'm_localPlaneNormal',
  'm_localPoint',
]);
defineAccessor(b2Manifold.prototype, 'm_points', function () {
  return this.points;
});
defineMethods(b2Manifold.prototype, {
  Reset() {
    for (const point of this.points) point.Reset();
    this.localNormal.x = 0.0;
    this.localNormal.y = 0.0;
    this.localPoint.x = 0.0;
    this.localPoint.y = 0.0;
    this.type = b2Manifold.e_circles;
    this.pointCount = 0;
  },
  Set(m) {
    this.Assign(m);
  },
  Copy() {
    return this.Clone();
  },
});

defineAccessor(b2WorldManifold.prototype, 'm_normal', function () {
  return this.normal;
});
defineAccessor(b2WorldManifold.prototype, 'm_points', function () {
  return this.points;
});

// Shapes

defineStatics(b2Shape, {
  e_unknownShape: -1,
  e_circleShape: b2Shape.e_circle,
  e_polygonShape: b2Shape.e_polygon,
  e_edgeShape: b2Shape.e_edge,
  TestOverlap: (shape1: b2Shape, transform1: Readonly<b2Transform>, shape2: b2Shape, transform2: Readonly<b2Transform>) =>
    b2TestOverlapShapes(shape1, 0, shape2, 0, transform1, transform2),
});
defineMethods(b2Shape.prototype, {
  Copy() {
    return this.Clone();
  },
});
Object.defineProperty(b2Shape.prototype, 'ComputeSubmergedArea', {
  value: removedMethod(
    'b2Shape.ComputeSubmergedArea',
    'It served the buoyancy controller, which is gone too; compute the submerged area of your shapes yourself.',
  ),
  writable: true,
  configurable: true,
  enumerable: false,
});

defineMethods(b2CircleShape.prototype, {
  GetLocalPosition() {
    return this.m_p;
  },
  SetLocalPosition(position) {
    this.m_p.Assign(position);
  },
  GetRadius() {
    return this.m_radius;
  },
  SetRadius(radius) {
    this.m_radius = radius;
  },
});

/** b2CircleShape also takes 2.1a's radius argument. */
export const b2CircleShapeCompat = acceptingArguments(b2CircleShape, (args, make) => {
  const circle = make();
  if (args[0] !== undefined) circle.m_radius = args[0] as number;
  return circle;
}) as typeof b2CircleShape & (new (radius?: number) => b2CircleShape);

/** b2EdgeShape also takes 2.1a's (v1, v2). */
export const b2EdgeShapeCompat = acceptingArguments(b2EdgeShape, (args, make) => {
  const edge = make();
  const [v1, v2] = args as [Readonly<b2Vec2> | undefined, Readonly<b2Vec2> | undefined];
  if (v1 !== undefined && v2 !== undefined) edge.Set(v1, v2);
  return edge;
}) as typeof b2EdgeShape & (new (v1?: Readonly<b2Vec2>, v2?: Readonly<b2Vec2>) => b2EdgeShape);

defineMethods(b2EdgeShape.prototype, {
  GetVertex1() {
    return this.m_vertex1;
  },
  GetVertex2() {
    return this.m_vertex2;
  },
  GetLength() {
    const dx = this.m_vertex2.x - this.m_vertex1.x;
    const dy = this.m_vertex2.y - this.m_vertex1.y;
    return Math.sqrt(dx * dx + dy * dy);
  },
});

const b2Vec2_origin: Readonly<b2Vec2> = new b2Vec2(0.0, 0.0);

/**
 * 2.1a's SetAsArray: Set with vertexCount, where 0 (its default) means every vertex. 2.1a took any
 * number of vertices; 2.2.1's polygons hold b2_maxPolygonVertices, and splitting the outline here
 * would give the app several fixtures where it made one, so a longer outline is refused, saying how
 * to split it.
 */
function setAsArray(polygon: b2PolygonShape, method: string, vertices: readonly Readonly<b2Vec2>[], count: number | undefined): void {
  if (!Array.isArray(vertices)) {
    throw new b2ArgumentError(method, 'vertices', `must be an array of vectors, got ${b2DescribeNumber(vertices)}`);
  }
  const n = count === undefined || count === 0 ? vertices.length : count;
  if (n > b2_maxPolygonVertices) {
    throw new b2ArgumentError(
      method,
      'vertices',
      `has ${n} vertices, and Box2D 2.2 polygons have at most b2_maxPolygonVertices = ${b2_maxPolygonVertices} ` +
        `(Box2DWeb 2.1a took any number): split the outline into convex pieces of at most ${b2_maxPolygonVertices} ` +
        'vertices and create a fixture for each',
    );
  }
  polygon.Set(vertices, n);
}

defineMethods(b2PolygonShape.prototype, {
  SetAsArray(vertices, count) {
    setAsArray(this, 'b2PolygonShape.SetAsArray', vertices, count);
  },
  SetAsVector(vertices, count) {
    setAsArray(this, 'b2PolygonShape.SetAsVector', vertices, count);
  },
  SetAsOrientedBox(hx, hy, center, angle) {
    this.SetAsBox(hx, hy, center ?? b2Vec2_origin, angle ?? 0.0);
  },
  SetAsEdge(v1, v2) {
    this.Reserve(2);
    this.m_vertexCount = 2;
    this.m_vertices[0].Assign(v1);
    this.m_vertices[1].Assign(v2);
    this.m_centroid.Set(0.5 * (v1.x + v2.x), 0.5 * (v1.y + v2.y));
    const n = this.m_normals[0].Set(v2.y - v1.y, -(v2.x - v1.x));
    n.Normalize();
    this.m_normals[1].Set(-n.x, -n.y);
  },
  GetVertices() {
    return this.m_vertices.slice(0, this.m_vertexCount);
  },
  GetNormals() {
    return this.m_normals.slice(0, this.m_vertexCount);
  },
});

defineStatics(b2PolygonShape, {
  AsArray: (vertices: readonly Readonly<b2Vec2>[], count?: number) => {
    const polygon = new b2PolygonShape();
    setAsArray(polygon, 'b2PolygonShape.AsArray', vertices, count);
    return polygon;
  },
  AsVector: (vertices: readonly Readonly<b2Vec2>[], count?: number) => {
    const polygon = new b2PolygonShape();
    setAsArray(polygon, 'b2PolygonShape.AsVector', vertices, count);
    return polygon;
  },
  AsBox: (hx: number, hy: number) => new b2PolygonShape().SetAsBox(hx, hy),
  AsOrientedBox: (hx: number, hy: number, center?: Readonly<b2Vec2> | null, angle?: number) => {
    const polygon = new b2PolygonShape();
    polygon.SetAsOrientedBox(hx, hy, center, angle);
    return polygon;
  },
  AsEdge: (v1: Readonly<b2Vec2>, v2: Readonly<b2Vec2>) => {
    const polygon = new b2PolygonShape();
    polygon.SetAsEdge(v1, v2);
    return polygon;
  },
  ComputeCentroid: (vertices: readonly Readonly<b2Vec2>[], count: number) => new b2PolygonShape().Set(vertices, count).m_centroid.Clone(),
});

/**
 * The b2EdgeShape a 2.1a two-vertex polygon (SetAsEdge) becomes in a fixture. It collides as an
 * edge except with circles, which 2.1a collided with the two-vertex polygon itself: see the
 * b2EdgeAndCircleContact.Evaluate wrapper below.
 */
class b2PolygonEdgeShape extends b2EdgeShape {
  override Clone(): b2EdgeShape {
    // The class adds no fields: the edge's clone with this class's prototype is a full copy.
    return Object.setPrototypeOf(super.Clone(), b2PolygonEdgeShape.prototype) as b2PolygonEdgeShape;
  }
}

/**
 * The shape a fixture gets for a 2.1a shape: a two-vertex polygon (SetAsEdge) becomes the
 * b2EdgeShape between its vertices; every other shape is itself.
 */
export function fixtureShapeFor2_1a(shape: b2Shape): b2Shape {
  if (shape instanceof b2PolygonShape && shape.m_vertexCount === 2) {
    const edge = new b2PolygonEdgeShape().Set(shape.m_vertices[0], shape.m_vertices[1]);
    edge.m_radius = shape.m_radius;
    return edge;
  }
  return shape;
}

const s_edgePolygon = new b2PolygonShape();

// A circle against a SetAsEdge fixture collides with the two-vertex polygon, as in 2.1a. The two
// agree but for one case that apps hit: a circle centred exactly on the segment's line. 2.1a's
// polygon test then takes the first normal, cross(v2 - v1, 1), and the edge the other side, so a
// player spawned on a floor line fell through it. Other edges keep 2.2.1's edge collision.
wrapMethod(
  b2EdgeAndCircleContact,
  'Evaluate',
  (evaluate) =>
    function (contact: b2Contact, manifold: b2Manifold, xfA: b2Transform, xfB: b2Transform) {
      const edge = contact.m_fixtureA.m_shape;
      if (!(edge instanceof b2PolygonEdgeShape)) {
        evaluate(contact, manifold, xfA, xfB);
        return;
      }
      s_edgePolygon.SetAsEdge(edge.m_vertex1, edge.m_vertex2);
      s_edgePolygon.m_radius = edge.m_radius;
      b2CollidePolygonAndCircle(manifold, s_edgePolygon, xfA, contact.m_fixtureB.m_shape as b2CircleShape, xfB);
    },
);

/**
 * 2.1a's line segment (Box2D.Collision.b2Segment), which Box2D 2.2 dropped with the shapes'
 * TestSegment: a segment p1-p2 that apps intersect with others and clip to boxes. The arithmetic
 * is 2.1a's, so the results are its own to the bit.
 */
export class b2Segment {
  /** The start point. */
  readonly p1 = new b2Vec2();
  /** The end point. */
  readonly p2 = new b2Vec2();

  /**
   * Does `segment` cross this one, at no more than maxLambda of its length from its p1? If so,
   * lambda[0] is that fraction and `normal` this segment's unit normal (on the side `segment`
   * comes from).
   */
  TestSegment(lambda: number[], normal: b2Vec2, segment: Readonly<b2Segment>, maxLambda = 0.0): boolean {
    const method = 'b2Segment.TestSegment';
    if (!Array.isArray(lambda)) {
      const got = b2DescribeNumber(lambda);
      throw new b2ArgumentError(method, 'lambda', `must be an array (the fraction goes to lambda[0]), got ${got}`);
    }
    b2CheckObject(method, 'normal', normal);
    b2CheckObject(method, 'segment', segment);
    b2CheckVec2(method, 'segment.p1', segment.p1);
    b2CheckVec2(method, 'segment.p2', segment.p2);
    const s = segment.p1;
    const rX = segment.p2.x - s.x;
    const rY = segment.p2.y - s.y;
    const dX = this.p2.x - this.p1.x;
    const dY = this.p2.y - this.p1.y;
    let nX = dY;
    let nY = -dX;
    const k_slop = 100.0 * Number.MIN_VALUE;
    const denom = -(rX * nX + rY * nY);
    if (denom > k_slop) {
      const bX = s.x - this.p1.x;
      const bY = s.y - this.p1.y;
      let a = bX * nX + bY * nY;
      if (0.0 <= a && a <= maxLambda * denom) {
        const mu2 = -rX * bY + rY * bX;
        if (-k_slop * denom <= mu2 && mu2 <= denom * (1.0 + k_slop)) {
          a /= denom;
          const nLen = Math.sqrt(nX * nX + nY * nY);
          nX /= nLen;
          nY /= nLen;
          lambda[0] = a;
          normal.Set(nX, nY);
          return true;
        }
      }
    }
    return false;
  }

  /** Extend the segment both ways to the boundary of the box. */
  Extend(aabb: Readonly<b2AABB>): void {
    this.ExtendForward(aabb);
    this.ExtendBackward(aabb);
  }

  /** Move p2 along the segment's direction to the boundary of the box. */
  ExtendForward(aabb: Readonly<b2AABB>): void {
    b2CheckObject('b2Segment.ExtendForward', 'aabb', aabb);
    const dX = this.p2.x - this.p1.x;
    const dY = this.p2.y - this.p1.y;
    const lambda = Math.min(
      dX > 0 ? (aabb.upperBound.x - this.p1.x) / dX : dX < 0 ? (aabb.lowerBound.x - this.p1.x) / dX : Number.POSITIVE_INFINITY,
      dY > 0 ? (aabb.upperBound.y - this.p1.y) / dY : dY < 0 ? (aabb.lowerBound.y - this.p1.y) / dY : Number.POSITIVE_INFINITY,
    );
    this.p2.x = this.p1.x + dX * lambda;
    this.p2.y = this.p1.y + dY * lambda;
  }

  /** Move p1 against the segment's direction to the boundary of the box. */
  ExtendBackward(aabb: Readonly<b2AABB>): void {
    b2CheckObject('b2Segment.ExtendBackward', 'aabb', aabb);
    const dX = -this.p2.x + this.p1.x;
    const dY = -this.p2.y + this.p1.y;
    const lambda = Math.min(
      dX > 0 ? (aabb.upperBound.x - this.p2.x) / dX : dX < 0 ? (aabb.lowerBound.x - this.p2.x) / dX : Number.POSITIVE_INFINITY,
      dY > 0 ? (aabb.upperBound.y - this.p2.y) / dY : dY < 0 ? (aabb.lowerBound.y - this.p2.y) / dY : Number.POSITIVE_INFINITY,
    );
    this.p1.x = this.p2.x + dX * lambda;
    this.p1.y = this.p2.y + dY * lambda;
  }
}

/** 2.1a's b2Collision statics, over the 2.2.1 functions (same arguments). */
export const b2Collision = {
  CollideCircles: b2CollideCircles,
  CollidePolygonAndCircle: b2CollidePolygonAndCircle,
  CollidePolygons: b2CollidePolygons,
  /** Do two AABBs overlap (touching counts)? */
  TestOverlap: b2TestOverlap,
};

/** 2.1a's edge chains were replaced by b2ChainShape. */
export const b2EdgeChainDef = removedClass(
  'b2EdgeChainDef',
  'Use b2ChainShape: shape.CreateChain(vertices) or shape.CreateLoop(vertices), then body.CreateFixture(shape, density).',
);
