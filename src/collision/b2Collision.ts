/*
 * Structures and functions used for computing contact points, distance queries, and TOI queries
 * (b2Collision.h, b2Collision.cpp).
 */

import { b2ContactFeatureType, b2ManifoldType } from '../common/b2Constants';
import { b2MakeArray } from '../common/b2MakeArray';
import { b2Abs, b2Max, b2Min, b2MulRV, b2MulXV, b2Vec2 } from '../common/b2Math';
import type { b2Transform } from '../common/b2Math';
import { b2_epsilon, b2_maxFloat, b2_maxManifoldPoints } from '../common/b2Settings';
import { b2Distance, b2DistanceInput, b2DistanceOutput, b2SimplexCache } from './b2Distance';
import { b2InspectAsJSON, b2RecordVec2 } from '../common/b2Record';
import { b2ManifoldField, b2ManifoldPointField, b2ManifoldRecords } from './b2ManifoldRecord';
import type { b2Shape } from './shapes/b2Shape';

/** Unused by the library; kept from the header. */
export const b2_nullFeature = 0xff;

/** The features that intersect to form the contact point. This must be 4 bytes or less. */
export class b2ContactFeature {
  static readonly e_vertex = b2ContactFeatureType.e_vertex;
  static readonly e_face = b2ContactFeatureType.e_face;

  /** Feature index on shapeA (uint8) */
  indexA = 0;
  /** Feature index on shapeB (uint8) */
  indexB = 0;
  /** The feature type on shapeA (uint8) */
  typeA = 0;
  /** The feature type on shapeB (uint8) */
  typeB = 0;

  Clone(): b2ContactFeature {
    return new b2ContactFeature().Assign(this);
  }

  Assign(cf: Readonly<b2ContactFeature>): this {
    this.indexA = cf.indexA;
    this.indexB = cf.indexB;
    this.typeA = cf.typeA;
    this.typeB = cf.typeB;
    return this;
  }
}

/**
 * The uint32 key of these feature bytes (x86 byte order of the C++ union): b2ContactID.key, and
 * what the collision functions write to a manifold's record.
 */
export function b2ContactKey(indexA: number, indexB: number, typeA: number, typeB: number): number {
  return (indexA | (indexB << 8) | (typeA << 16) | (typeB << 24)) >>> 0;
}

/**
 * Contact ids to facilitate warm starting. The C++ union of the feature bytes (`cf`) and their
 * uint32 view (`key`, x86 byte order): here the id is its own feature record, so `cf` returns the
 * id itself, one object for both views; `key` is computed from the bytes, and writing it writes
 * them. The engine reads and writes the bytes on the id itself (`id.indexA` is `id.cf.indexA`),
 * which saves the getter. A manifold point's id is a b2RecordContactID, which keeps the key.
 */
export class b2ContactID extends b2ContactFeature {
  /** The feature bytes: the id itself, as in the C++ union. */
  get cf(): b2ContactFeature {
    return this;
  }

  /** Used to quickly compare contact ids. */
  get key(): number {
    return b2ContactKey(this.indexA, this.indexB, this.typeA, this.typeB);
  }

  set key(value: number) {
    this.indexA = value & 0xff;
    this.indexB = (value >>> 8) & 0xff;
    this.typeA = (value >>> 16) & 0xff;
    this.typeB = (value >>> 24) & 0xff;
  }

  override Clone(): b2ContactID {
    return new b2ContactID().Assign(this);
  }
}

/**
 * A manifold point's id: a b2ContactID whose bytes are the key held in the point's record
 * (b2ManifoldPointField.key). It has b2ContactID's prototype and methods, but not its
 * constructor, whose field writes would run these setters before the record is known.
 */
class b2RecordContactID {
  constructor(
    readonly m_record: Float64Array,
    readonly m_offset: number,
  ) {}

  get key(): number {
    return this.m_record[this.m_offset];
  }

  set key(value: number) {
    this.m_record[this.m_offset] = value >>> 0;
  }

  get indexA(): number {
    return this.m_record[this.m_offset] & 0xff;
  }

  set indexA(value: number) {
    this.SetByte(0, value);
  }

  get indexB(): number {
    return (this.m_record[this.m_offset] >>> 8) & 0xff;
  }

  set indexB(value: number) {
    this.SetByte(8, value);
  }

  get typeA(): number {
    return (this.m_record[this.m_offset] >>> 16) & 0xff;
  }

  set typeA(value: number) {
    this.SetByte(16, value);
  }

  get typeB(): number {
    return this.m_record[this.m_offset] >>> 24;
  }

  set typeB(value: number) {
    this.SetByte(24, value);
  }

  toJSON(): { indexA: number; indexB: number; typeA: number; typeB: number } {
    return { indexA: this.indexA, indexB: this.indexB, typeA: this.typeA, typeB: this.typeB };
  }

  /** Replace the key's byte at this bit shift (the C++ writes a uint8 of the union). */
  private SetByte(shift: number, value: number): void {
    const key = this.m_record[this.m_offset];
    this.m_record[this.m_offset] = ((key & ~(0xff << shift)) | ((value & 0xff) << shift)) >>> 0;
  }
}

interface b2RecordContactID extends b2ContactID {}
Object.setPrototypeOf(b2RecordContactID.prototype, b2ContactID.prototype);
b2InspectAsJSON(b2RecordContactID);

/**
 * A manifold point is a contact point belonging to a contact manifold. It holds details related
 * to the geometry and dynamics of the contact points.
 * The local point usage depends on the manifold type:
 * -e_circles: the local center of circleB
 * -e_faceA: the local center of cirlceB or the clip point of polygonB
 * -e_faceB: the clip point of polygonA
 * This structure is stored across time steps, so we keep it small.
 * Note: the impulses are used for internal caching and may not provide reliable contact forces,
 * especially for high speed collisions.
 */
export class b2ManifoldPoint {
  /** The record holding this point's doubles, at m_offset (b2ManifoldPointField). */
  readonly m_record: Float64Array;
  readonly m_offset: number;
  /** usage depends on manifold type */
  readonly localPoint: b2Vec2;
  /** uniquely identifies a contact point between two shapes */
  readonly id: b2ContactID;

  /** A point of its own, or (record, offset) a point of a manifold's record. */
  constructor(record: Float64Array = new Float64Array(b2ManifoldPointField.stride), offset = 0) {
    this.m_record = record;
    this.m_offset = offset;
    this.localPoint = new b2RecordVec2(record, offset + b2ManifoldPointField.localPointX);
    this.id = new b2RecordContactID(record, offset + b2ManifoldPointField.key);
  }

  /** the non-penetration impulse */
  get normalImpulse(): number {
    return this.m_record[this.m_offset + b2ManifoldPointField.normalImpulse];
  }

  set normalImpulse(value: number) {
    this.m_record[this.m_offset + b2ManifoldPointField.normalImpulse] = value;
  }

  /** the friction impulse */
  get tangentImpulse(): number {
    return this.m_record[this.m_offset + b2ManifoldPointField.tangentImpulse];
  }

  set tangentImpulse(value: number) {
    this.m_record[this.m_offset + b2ManifoldPointField.tangentImpulse] = value;
  }

  Clone(): b2ManifoldPoint {
    return new b2ManifoldPoint().Assign(this);
  }

  Assign(mp: Readonly<b2ManifoldPoint>): this {
    for (let i = 0; i < b2ManifoldPointField.stride; ++i) {
      this.m_record[this.m_offset + i] = mp.m_record[mp.m_offset + i];
    }
    return this;
  }

  toJSON(): object {
    const { localPoint, normalImpulse, tangentImpulse, id } = this;
    return { localPoint, normalImpulse, tangentImpulse, id };
  }
}
b2InspectAsJSON(b2ManifoldPoint);

/**
 * A manifold for two touching convex shapes.
 * Box2D supports multiple types of contact:
 * - clip point versus plane with radius
 * - point versus point with radius (circles)
 * The local point usage depends on the manifold type:
 * -e_circles: the local center of circleA
 * -e_faceA: the center of faceA
 * -e_faceB: the center of faceB
 * Similarly the local normal usage:
 * -e_circles: not used
 * -e_faceA: the normal on polygonA
 * -e_faceB: the normal on polygonB
 * We store contacts in this way so that position correction can account for movement, which is
 * critical for continuous physics. All contact scenarios must be expressed in one of these types.
 * This structure is stored across time steps, so we keep it small.
 */
export class b2Manifold {
  static readonly e_circles = b2ManifoldType.e_circles;
  static readonly e_faceA = b2ManifoldType.e_faceA;
  static readonly e_faceB = b2ManifoldType.e_faceB;

  /** The record holding this manifold's doubles, at m_offset (b2ManifoldField). */
  readonly m_record: Float64Array;
  readonly m_offset: number;
  type: number = b2Manifold.e_circles;
  /** the number of manifold points */
  pointCount = 0;
  /**
   * The views below, made on first use. The engine reads only the record; made with the
   * manifold, a contact's eight view objects were a third of the heap its contacts hold (bench2d:
   * 0.9 of 2.5 MiB) and spread the objects a step does read over more cache lines and pages.
   */
  private m_pointViews: readonly b2ManifoldPoint[] | null = null;
  private m_localNormalView: b2Vec2 | null = null;
  private m_localPointView: b2Vec2 | null = null;

  constructor() {
    this.m_offset = b2ManifoldRecords.Allocate();
    this.m_record = b2ManifoldRecords.chunk;
  }

  /** the points of contact */
  get points(): readonly b2ManifoldPoint[] {
    if (this.m_pointViews === null) {
      const record = this.m_record;
      const offset = this.m_offset;
      this.m_pointViews = b2MakeArray(
        b2_maxManifoldPoints,
        (i) => new b2ManifoldPoint(record, offset + b2ManifoldField.points + i * b2ManifoldPointField.stride),
      );
    }
    return this.m_pointViews;
  }

  /** not use for Type::e_points */
  get localNormal(): b2Vec2 {
    return (this.m_localNormalView ??= new b2RecordVec2(this.m_record, this.m_offset + b2ManifoldField.localNormalX));
  }

  /** usage depends on manifold type */
  get localPoint(): b2Vec2 {
    return (this.m_localPointView ??= new b2RecordVec2(this.m_record, this.m_offset + b2ManifoldField.localPointX));
  }

  Clone(): b2Manifold {
    return new b2Manifold().Assign(this);
  }

  /** Deep copy, as the C++ struct assignment. */
  Assign(m: Readonly<b2Manifold>): this {
    for (let i = 0; i < b2ManifoldField.points + b2_maxManifoldPoints * b2ManifoldPointField.stride; ++i) {
      this.m_record[this.m_offset + i] = m.m_record[m.m_offset + i];
    }
    this.type = m.type;
    this.pointCount = m.pointCount;
    return this;
  }

  toJSON(): object {
    const { points, localNormal, localPoint, type, pointCount } = this;
    return { points, localNormal, localPoint, type, pointCount };
  }
}
b2InspectAsJSON(b2Manifold);

const s_pointA = new b2Vec2();
const s_pointB = new b2Vec2();
const s_planePoint = new b2Vec2();
const s_clipPoint = new b2Vec2();
const s_localNormal = new b2Vec2();
const s_localPoint = new b2Vec2();
const s_pointLocalPoint = new b2Vec2();

/** Manifold point i's local point, read from the manifold's record into a plain vector. */
function PointLocalPoint(manifold: Readonly<b2Manifold>, i: number): b2Vec2 {
  const p = manifold.m_offset + b2ManifoldField.points + i * b2ManifoldPointField.stride;
  const r = manifold.m_record;
  return s_pointLocalPoint.Set(r[p + b2ManifoldPointField.localPointX], r[p + b2ManifoldPointField.localPointY]);
}

/** This is used to compute the current state of a contact manifold. */
export class b2WorldManifold {
  /** world vector pointing from A to B */
  readonly normal = new b2Vec2();
  /** world contact point (point of intersection) */
  readonly points: readonly b2Vec2[] = b2MakeArray(b2_maxManifoldPoints, () => new b2Vec2());

  /**
   * Evaluate the manifold with supplied transforms. This assumes modest motion from the original
   * state. This does not change the point count, impulses, etc. The radii must come from the
   * shapes that generated the manifold.
   */
  Initialize(manifold: Readonly<b2Manifold>, xfA: Readonly<b2Transform>, radiusA: number, xfB: Readonly<b2Transform>, radiusB: number): void {
    if (manifold.pointCount === 0) {
      return;
    }

    // The manifold's vectors, read from its record into plain vectors (see b2SetManifoldFace).
    const r = manifold.m_record;
    const o = manifold.m_offset;
    const localNormal = s_localNormal.Set(r[o + b2ManifoldField.localNormalX], r[o + b2ManifoldField.localNormalY]);
    const localPoint = s_localPoint.Set(r[o + b2ManifoldField.localPointX], r[o + b2ManifoldField.localPointY]);

    const normal = this.normal;
    switch (manifold.type) {
      case b2Manifold.e_circles: {
        normal.Set(1.0, 0.0);
        const pointA = b2MulXV(xfA, localPoint, s_pointA);
        const pointB = b2MulXV(xfB, PointLocalPoint(manifold, 0), s_pointB);
        const dx = pointA.x - pointB.x;
        const dy = pointA.y - pointB.y;
        if (dx * dx + dy * dy > b2_epsilon * b2_epsilon) {
          normal.x = pointB.x - pointA.x;
          normal.y = pointB.y - pointA.y;
          normal.Normalize();
        }

        const cAx = pointA.x + radiusA * normal.x;
        const cAy = pointA.y + radiusA * normal.y;
        const cBx = pointB.x - radiusB * normal.x;
        const cBy = pointB.y - radiusB * normal.y;
        this.points[0].x = 0.5 * (cAx + cBx);
        this.points[0].y = 0.5 * (cAy + cBy);
        break;
      }

      case b2Manifold.e_faceA: {
        b2MulRV(xfA.q, localNormal, normal);
        const planePoint = b2MulXV(xfA, localPoint, s_planePoint);

        for (let i = 0; i < manifold.pointCount; ++i) {
          const clipPoint = b2MulXV(xfB, PointLocalPoint(manifold, i), s_clipPoint);
          const k = radiusA - ((clipPoint.x - planePoint.x) * normal.x + (clipPoint.y - planePoint.y) * normal.y);
          const cAx = clipPoint.x + k * normal.x;
          const cAy = clipPoint.y + k * normal.y;
          const cBx = clipPoint.x - radiusB * normal.x;
          const cBy = clipPoint.y - radiusB * normal.y;
          this.points[i].x = 0.5 * (cAx + cBx);
          this.points[i].y = 0.5 * (cAy + cBy);
        }
        break;
      }

      case b2Manifold.e_faceB: {
        b2MulRV(xfB.q, localNormal, normal);
        const planePoint = b2MulXV(xfB, localPoint, s_planePoint);

        for (let i = 0; i < manifold.pointCount; ++i) {
          const clipPoint = b2MulXV(xfA, PointLocalPoint(manifold, i), s_clipPoint);
          const k = radiusB - ((clipPoint.x - planePoint.x) * normal.x + (clipPoint.y - planePoint.y) * normal.y);
          const cBx = clipPoint.x + k * normal.x;
          const cBy = clipPoint.y + k * normal.y;
          const cAx = clipPoint.x - radiusA * normal.x;
          const cAy = clipPoint.y - radiusA * normal.y;
          this.points[i].x = 0.5 * (cAx + cBx);
          this.points[i].y = 0.5 * (cAy + cBy);
        }

        // Ensure normal points from A to B.
        normal.x = -normal.x;
        normal.y = -normal.y;
        break;
      }
    }
  }
}

/** This is used for determining the state of contact points. */
export enum b2PointState {
  /** point does not exist */
  b2_nullState,
  /** point was added in the update */
  b2_addState,
  /** point persisted across the update */
  b2_persistState,
  /** point was removed in the update */
  b2_removeState,
}

export const b2_nullState = b2PointState.b2_nullState;
export const b2_addState = b2PointState.b2_addState;
export const b2_persistState = b2PointState.b2_persistState;
export const b2_removeState = b2PointState.b2_removeState;

/**
 * Compute the point states given two manifolds. The states pertain to the transition from
 * manifold1 to manifold2. So state1 is either persist or remove while state2 is either add or
 * persist.
 */
export function b2GetPointStates(state1: b2PointState[], state2: b2PointState[], manifold1: Readonly<b2Manifold>, manifold2: Readonly<b2Manifold>): void {
  for (let i = 0; i < b2_maxManifoldPoints; ++i) {
    state1[i] = b2_nullState;
    state2[i] = b2_nullState;
  }

  // Detect persists and removes.
  for (let i = 0; i < manifold1.pointCount; ++i) {
    const key = manifold1.points[i].id.key;

    state1[i] = b2_removeState;

    for (let j = 0; j < manifold2.pointCount; ++j) {
      if (manifold2.points[j].id.key === key) {
        state1[i] = b2_persistState;
        break;
      }
    }
  }

  // Detect persists and adds.
  for (let i = 0; i < manifold2.pointCount; ++i) {
    const key = manifold2.points[i].id.key;

    state2[i] = b2_addState;

    for (let j = 0; j < manifold1.pointCount; ++j) {
      if (manifold1.points[j].id.key === key) {
        state2[i] = b2_persistState;
        break;
      }
    }
  }
}

/** Used for computing contact manifolds. */
export class b2ClipVertex {
  readonly v = new b2Vec2();
  readonly id = new b2ContactID();

  Clone(): b2ClipVertex {
    return new b2ClipVertex().Assign(this);
  }

  Assign(cv: Readonly<b2ClipVertex>): this {
    this.v.Assign(cv.v);
    this.id.Assign(cv.id);
    return this;
  }
}

/** Ray-cast input data. The ray extends from p1 to p1 + maxFraction * (p2 - p1). */
export class b2RayCastInput {
  readonly p1 = new b2Vec2();
  readonly p2 = new b2Vec2();
  maxFraction = 1.0;

  Clone(): b2RayCastInput {
    return new b2RayCastInput().Assign(this);
  }

  Assign(input: Readonly<b2RayCastInput>): this {
    this.p1.Assign(input.p1);
    this.p2.Assign(input.p2);
    this.maxFraction = input.maxFraction;
    return this;
  }
}

/**
 * Ray-cast output data. The ray hits at p1 + fraction * (p2 - p1), where p1 and p2 come from
 * b2RayCastInput.
 */
export class b2RayCastOutput {
  readonly normal = new b2Vec2();
  fraction = 0.0;

  Clone(): b2RayCastOutput {
    return new b2RayCastOutput().Assign(this);
  }

  Assign(output: Readonly<b2RayCastOutput>): this {
    this.normal.Assign(output.normal);
    this.fraction = output.fraction;
    return this;
  }
}

/** An axis aligned bounding box. */
export class b2AABB {
  /** the lower vertex */
  readonly lowerBound = new b2Vec2();
  /** the upper vertex */
  readonly upperBound = new b2Vec2();

  Clone(): b2AABB {
    return new b2AABB().Assign(this);
  }

  Assign(aabb: Readonly<b2AABB>): this {
    this.lowerBound.Assign(aabb.lowerBound);
    this.upperBound.Assign(aabb.upperBound);
    return this;
  }

  /** Verify that the bounds are sorted. */
  IsValid(): boolean {
    const dx = this.upperBound.x - this.lowerBound.x;
    const dy = this.upperBound.y - this.lowerBound.y;
    let valid = dx >= 0.0 && dy >= 0.0;
    valid = valid && this.lowerBound.IsValid() && this.upperBound.IsValid();
    return valid;
  }

  /** Get the center of the AABB. */
  GetCenter(out: b2Vec2): b2Vec2 {
    const x = 0.5 * (this.lowerBound.x + this.upperBound.x);
    const y = 0.5 * (this.lowerBound.y + this.upperBound.y);
    return out.Set(x, y);
  }

  /** Get the extents of the AABB (half-widths). */
  GetExtents(out: b2Vec2): b2Vec2 {
    const x = 0.5 * (this.upperBound.x - this.lowerBound.x);
    const y = 0.5 * (this.upperBound.y - this.lowerBound.y);
    return out.Set(x, y);
  }

  /** Get the perimeter length */
  GetPerimeter(): number {
    const wx = this.upperBound.x - this.lowerBound.x;
    const wy = this.upperBound.y - this.lowerBound.y;
    return 2.0 * (wx + wy);
  }

  /** Combine an AABB into this one. */
  Combine(aabb: Readonly<b2AABB>): void {
    this.lowerBound.x = b2Min(this.lowerBound.x, aabb.lowerBound.x);
    this.lowerBound.y = b2Min(this.lowerBound.y, aabb.lowerBound.y);
    this.upperBound.x = b2Max(this.upperBound.x, aabb.upperBound.x);
    this.upperBound.y = b2Max(this.upperBound.y, aabb.upperBound.y);
  }

  /** Combine two AABBs into this one (the C++ two-argument Combine). */
  Combine2(aabb1: Readonly<b2AABB>, aabb2: Readonly<b2AABB>): void {
    this.lowerBound.x = b2Min(aabb1.lowerBound.x, aabb2.lowerBound.x);
    this.lowerBound.y = b2Min(aabb1.lowerBound.y, aabb2.lowerBound.y);
    this.upperBound.x = b2Max(aabb1.upperBound.x, aabb2.upperBound.x);
    this.upperBound.y = b2Max(aabb1.upperBound.y, aabb2.upperBound.y);
  }

  /** Does this aabb contain the provided AABB. */
  Contains(aabb: Readonly<b2AABB>): boolean {
    let result = true;
    result = result && this.lowerBound.x <= aabb.lowerBound.x;
    result = result && this.lowerBound.y <= aabb.lowerBound.y;
    result = result && aabb.upperBound.x <= this.upperBound.x;
    result = result && aabb.upperBound.y <= this.upperBound.y;
    return result;
  }

  /** From Real-time Collision Detection, p179. */
  RayCast(output: b2RayCastOutput, input: Readonly<b2RayCastInput>): boolean {
    let tmin = -b2_maxFloat;
    let tmax = +b2_maxFloat; // unary plus: docs/PORTING.md

    const px = input.p1.x;
    const py = input.p1.y;
    const dx = input.p2.x - input.p1.x;
    const dy = input.p2.y - input.p1.y;

    let normalX = 0.0;
    let normalY = 0.0;

    // The two slabs, x then y, as the C++ loop over i.
    for (let i = 0; i < 2; ++i) {
      const p_i = i === 0 ? px : py;
      const d_i = i === 0 ? dx : dy;
      const lower_i = i === 0 ? this.lowerBound.x : this.lowerBound.y;
      const upper_i = i === 0 ? this.upperBound.x : this.upperBound.y;

      if (b2Abs(d_i) < b2_epsilon) {
        // Parallel.
        if (p_i < lower_i || upper_i < p_i) {
          return false;
        }
      } else {
        const inv_d = 1.0 / d_i;
        let t1 = (lower_i - p_i) * inv_d;
        let t2 = (upper_i - p_i) * inv_d;

        // Sign of the normal vector.
        let s = -1.0;

        if (t1 > t2) {
          const t = t1;
          t1 = t2;
          t2 = t;
          s = 1.0;
        }

        // Push the min up
        if (t1 > tmin) {
          normalX = i === 0 ? s : 0.0;
          normalY = i === 0 ? 0.0 : s;
          tmin = t1;
        }

        // Pull the max down
        tmax = b2Min(tmax, t2);

        if (tmin > tmax) {
          return false;
        }
      }
    }

    // Does the ray start inside the box?
    // Does the ray intersect beyond the max fraction?
    if (tmin < 0.0 || input.maxFraction < tmin) {
      return false;
    }

    // Intersection.
    output.fraction = tmin;
    output.normal.Set(normalX, normalY);
    return true;
  }
}

/**
 * Clipping for contact manifolds (Sutherland-Hodgman). vOut and vIn are arrays of two clip
 * vertices each and must not be the same array. Returns the number of output points.
 */
export function b2ClipSegmentToLine(
  vOut: readonly b2ClipVertex[],
  vIn: readonly b2ClipVertex[],
  normal: Readonly<b2Vec2>,
  offset: number,
  vertexIndexA: number,
): number {
  b2ClipSegmentOffset[0] = offset;
  return b2ClipSegment(vOut, vIn, normal, vertexIndexA);
}

/** The offset argument of b2ClipSegment. */
export const b2ClipSegmentOffset = new Float64Array(1);

/**
 * b2ClipSegmentToLine with its offset in b2ClipSegmentOffset[0], for the collide functions: V8
 * boxes a double passed to a call it does not inline, which made this argument a heap allocation
 * for every polygon contact of every step (most of the bytes a step allocated).
 */
export function b2ClipSegment(vOut: readonly b2ClipVertex[], vIn: readonly b2ClipVertex[], normal: Readonly<b2Vec2>, vertexIndexA: number): number {
  const offset = b2ClipSegmentOffset[0];
  const vIn0 = vIn[0];
  const vIn1 = vIn[1];

  // Start with no output points
  let numOut = 0;

  // Calculate the distance of end points to the line (b2Dot written out: a double returned from a
  // call V8 leaves out of line is boxed, and this runs for every polygon contact of every step)
  const distance0 = normal.x * vIn0.v.x + normal.y * vIn0.v.y - offset;
  const distance1 = normal.x * vIn1.v.x + normal.y * vIn1.v.y - offset;

  // If the points are behind the plane
  if (distance0 <= 0.0) vOut[numOut++].Assign(vIn0);
  if (distance1 <= 0.0) vOut[numOut++].Assign(vIn1);

  // If the points are on different sides of the plane
  if (distance0 * distance1 < 0.0) {
    // Find intersection point of edge and plane
    const interp = distance0 / (distance0 - distance1);
    const out = vOut[numOut];
    out.v.x = vIn0.v.x + interp * (vIn1.v.x - vIn0.v.x);
    out.v.y = vIn0.v.y + interp * (vIn1.v.y - vIn0.v.y);

    // VertexA is hitting edgeB.
    const cf = out.id;
    cf.indexA = vertexIndexA & 0xff;
    cf.indexB = vIn0.id.indexB;
    cf.typeA = b2ContactFeature.e_vertex;
    cf.typeB = b2ContactFeature.e_face;
    ++numOut;
  }

  return numOut;
}

const s_overlapInput = new b2DistanceInput();
const s_overlapCache = new b2SimplexCache();
const s_overlapOutput = new b2DistanceOutput();

/** Determine if two generic shapes overlap (the C++ b2TestOverlap shape overload). */
export function b2TestOverlapShapes(
  shapeA: b2Shape,
  indexA: number,
  shapeB: b2Shape,
  indexB: number,
  xfA: Readonly<b2Transform>,
  xfB: Readonly<b2Transform>,
): boolean {
  const input = s_overlapInput;
  input.proxyA.Set(shapeA, indexA);
  input.proxyB.Set(shapeB, indexB);
  input.transformA.Assign(xfA);
  input.transformB.Assign(xfB);
  input.useRadii = true;

  const cache = s_overlapCache;
  cache.count = 0;

  const output = s_overlapOutput;

  b2Distance(output, cache, input);

  return output.distance < 10.0 * b2_epsilon;
}

/** Test two AABBs for overlap (touching counts). */
export function b2TestOverlap(a: Readonly<b2AABB>, b: Readonly<b2AABB>): boolean {
  const d1x = b.lowerBound.x - a.upperBound.x;
  const d1y = b.lowerBound.y - a.upperBound.y;
  const d2x = a.lowerBound.x - b.upperBound.x;
  const d2y = a.lowerBound.y - b.upperBound.y;

  if (d1x > 0.0 || d1y > 0.0) return false;

  if (d2x > 0.0 || d2y > 0.0) return false;

  return true;
}
