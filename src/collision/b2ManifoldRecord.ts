/*
 * A manifold's record (common/b2Record.ts). In the C++ built with doubles a b2Manifold is 120
 * contiguous bytes in its contact; as objects it was some twenty, and the contact update, the
 * contact solver's set-up and its impulse store each visited them all for every contact. The
 * record holds its doubles; type and pointCount stay fields of b2Manifold. b2Manifold's vectors,
 * points and ids are views onto the record (b2RecordVec2, b2ManifoldPoint, b2RecordContactID in
 * b2Collision.ts).
 */

import type { b2Vec2 } from '../common/b2Math';
import { b2RecordPool } from '../common/b2Record';

/** Doubles of a manifold record, from its offset. */
export const enum b2ManifoldField {
  localNormalX = 0,
  localNormalY = 1,
  localPointX = 2,
  localPointY = 3,
  /** The first point's record (b2ManifoldPointField); the second follows it. */
  points = 4,
  /**
   * Not the manifold's: its contact's friction and restitution (b2Contact.m_friction and
   * m_restitution), which the contact solver reads with the manifold. Unused outside a contact;
   * Assign and Clone leave them.
   */
  friction = 14,
  restitution = 15,
  /** Two 64-byte lines. */
  stride = 16,
}

/** Doubles of a manifold point record. */
export const enum b2ManifoldPointField {
  localPointX = 0,
  localPointY = 1,
  normalImpulse = 2,
  tangentImpulse = 3,
  /** The contact id's key (b2ContactID.key: the feature bytes as a uint32). */
  key = 4,
  stride = 5,
}

/** Every b2Manifold's record, 64 to an 8 KiB chunk. */
export const b2ManifoldRecords = new b2RecordPool(b2ManifoldField.stride, 64);

/** What the writers below need of a b2Manifold (a type-only view: b2Collision.ts imports this module). */
interface b2ManifoldRecordOwner {
  readonly m_record: Float64Array;
  readonly m_offset: number;
}

/*
 * The collision functions write a manifold through these rather than through its views: engine
 * code never hands a view to b2Vec2's methods or b2Math's functions, which would then see two
 * layouts at every call and box the doubles they pass (docs/PORTING.md). They take vectors, not
 * doubles, for the same reason: a double passed to a call V8 does not inline is boxed.
 */

/** Set the manifold's local normal and local point. */
export function b2SetManifoldFace(manifold: b2ManifoldRecordOwner, normal: Readonly<b2Vec2>, point: Readonly<b2Vec2>): void {
  const r = manifold.m_record;
  const o = manifold.m_offset;
  r[o + b2ManifoldField.localNormalX] = normal.x;
  r[o + b2ManifoldField.localNormalY] = normal.y;
  r[o + b2ManifoldField.localPointX] = point.x;
  r[o + b2ManifoldField.localPointY] = point.y;
}

/** Set manifold point `index`'s local point and id key; its impulses are left as they are. */
export function b2SetManifoldPoint(manifold: b2ManifoldRecordOwner, index: number, localPoint: Readonly<b2Vec2>, key: number): void {
  const p = manifold.m_offset + b2ManifoldField.points + index * b2ManifoldPointField.stride;
  const r = manifold.m_record;
  r[p + b2ManifoldPointField.localPointX] = localPoint.x;
  r[p + b2ManifoldPointField.localPointY] = localPoint.y;
  r[p + b2ManifoldPointField.key] = key;
}
