import { describe, expect, it } from 'vitest';
import * as webphysics from '../../src/index';

/*
 * Every value class of the package (a class with Clone and Assign and a constructor without
 * arguments: b2Vec2, b2Mat33, b2Sweep, b2Manifold, b2Profile, b2MassData, b2ContactImpulse...)
 * copies all of its state: Clone() and Assign() of an instance whose every number has been set to
 * a distinct value reproduce it exactly, and the copy shares no object with the original (except
 * the fields that are pointers in the C++).
 */

type Snapshot = (number | boolean)[];

/**
 * The names of an object's state: its own enumerable properties, or for an object with toJSON
 * (the classes whose doubles live in a record, common/b2Record.ts) the names toJSON gives, read
 * and written through the object's accessors.
 */
function stateKeys(value: object): string[] {
  const toJSON = (value as { toJSON?: () => object }).toJSON;
  return Object.keys(typeof toJSON === 'function' ? toJSON.call(value) : value);
}

/** Set every number (distinct small integers, so masked fields keep them) and flip every boolean. */
function fill(value: unknown, next: { n: number }, depth = 0): void {
  if (depth > 6 || typeof value !== 'object' || value === null) return;
  const record = value as Record<string, unknown>;
  for (const key of stateKeys(record)) {
    const field = record[key];
    if (typeof field === 'number') {
      try {
        record[key] = ++next.n;
      } catch {
        // A read-only field.
      }
    } else if (typeof field === 'boolean') record[key] = !field;
    else if (Array.isArray(field)) {
      for (let i = 0; i < field.length; ++i) {
        if (typeof field[i] === 'number') field[i] = ++next.n;
        else fill(field[i], next, depth + 1);
      }
    } else fill(field, next, depth + 1);
  }
}

function snapshot(value: unknown, out: Snapshot = [], depth = 0): Snapshot {
  if (depth > 6 || typeof value !== 'object' || value === null) return out;
  for (const key of stateKeys(value)) {
    const field = (value as Record<string, unknown>)[key];
    if (typeof field === 'number' || typeof field === 'boolean') out.push(field);
    else if (Array.isArray(field)) {
      for (const item of field) {
        if (typeof item === 'number') out.push(item);
        else snapshot(item, out, depth + 1);
      }
    } else snapshot(field, out, depth + 1);
  }
  return out;
}

function objects(value: unknown, out = new Set<object>(), depth = 0): Set<object> {
  if (depth > 6 || typeof value !== 'object' || value === null) return out;
  out.add(value);
  for (const key of stateKeys(value)) objects((value as Record<string, unknown>)[key], out, depth + 1);
  return out;
}

/** Structs whose C++ fields are pointers (to a shape's vertices, the island's arrays): copies share them. */
const kHoldsPointers = new Set(['b2DistanceProxy', 'b2DistanceInput', 'b2TOIInput', 'b2SolverData']);

interface ValueClass {
  new (): { Clone(): unknown; Assign(other: unknown): unknown };
}

function valueClasses(): [string, ValueClass][] {
  const found: [string, ValueClass][] = [];
  for (const [name, exported] of Object.entries(webphysics)) {
    if (typeof exported !== 'function') continue;
    const proto = (exported as { prototype?: Record<string, unknown> }).prototype;
    if (!proto || typeof proto.Clone !== 'function' || typeof proto.Assign !== 'function') continue;
    found.push([name, exported as unknown as ValueClass]);
  }
  return found;
}

describe('value classes copy all their state with Clone and Assign', () => {
  const classes = valueClasses();

  it('finds the value classes of every module', () => {
    const names = classes.map(([name]) => name);
    for (const expected of [
      'b2Vec2',
      'b2Vec3',
      'b2Mat22',
      'b2Mat33',
      'b2Rot',
      'b2Transform',
      'b2Sweep',
      'b2Manifold',
      'b2ManifoldPoint',
      'b2ContactID',
      'b2AABB',
      'b2MassData',
      'b2Profile',
      'b2TimeStep',
      'b2Position',
      'b2Velocity',
      'b2ContactImpulse',
      'b2Filter',
      'b2Jacobian',
    ]) {
      expect(names).toContain(expected);
    }
  });

  for (const [name, Class] of classes) {
    it(name, () => {
      let original: InstanceType<ValueClass>;
      try {
        original = new Class();
      } catch {
        return; // Needs constructor arguments: not a plain value class.
      }
      fill(original, { n: 0 });
      const expected = snapshot(original);
      const clone = original.Clone();
      expect(snapshot(clone)).toEqual(expected);
      const target = new Class();
      expect(target.Assign(original)).toBe(target);
      expect(snapshot(target)).toEqual(expected);
      // A deep copy: no nested object is shared, except where the C++ struct holds pointers.
      if (kHoldsPointers.has(name)) return;
      const shared = [...objects(clone)].filter((o) => objects(original).has(o));
      expect(shared).toEqual([]);
    });
  }
});
