/*
 * A manifold's record (common/b2Record.ts). In the C++ a b2Manifold is 80-odd contiguous bytes in
 * its contact; as objects it was some twenty, and the contact update, the contact solver's set-up
 * and its impulse store each visited them all for every contact. The record holds its doubles;
 * type and pointCount stay fields of b2Manifold. b2Manifold's vectors, points and ids are views
 * onto the record (b2RecordVec2, b2ManifoldPoint, b2RecordContactID in b2Collision.ts).
 */

import { b2RecordPool } from '../common/b2Record';

/** Doubles of a manifold record, from its offset. */
export const enum b2ManifoldField {
  localNormalX = 0,
  localNormalY = 1,
  localPointX = 2,
  localPointY = 3,
  /** The first point's record (b2ManifoldPointField); the second follows it. */
  points = 4,
  /** Two points of five doubles after the four above, rounded up to two 64-byte lines. */
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
