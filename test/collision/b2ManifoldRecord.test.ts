import { inspect } from 'node:util';
import { describe, expect, it } from 'vitest';
import { b2ContactID, b2Manifold, b2ManifoldPoint, b2WorldManifold } from '../../src/collision/b2Collision';
import { b2ManifoldField, b2ManifoldPointField, b2SetManifoldFace, b2SetManifoldPoint } from '../../src/collision/b2ManifoldRecord';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2RecordVec2 } from '../../src/common/b2Record';
import { b2dJsonRead } from '../../src/io/b2dJsonRead';
import { b2dJsonWriteString } from '../../src/io/b2dJsonWrite';
import { goldenSceneNames, loadGoldenScene } from '../support/scene';

describe('manifold records', () => {
  it('keeps a manifold’s vectors, impulses and ids at the record offsets the engine reads', () => {
    const m = new b2Manifold();
    m.localNormal.Set(1, 2);
    m.localPoint.Set(3, 4);
    m.points[1].localPoint.Set(5, 6);
    m.points[1].normalImpulse = 7;
    m.points[1].tangentImpulse = 8;
    m.points[1].id.key = 0x04030201;

    const r = m.m_record;
    const o = m.m_offset;
    const p1 = o + b2ManifoldField.points + b2ManifoldPointField.stride;
    expect([r[o + b2ManifoldField.localNormalX], r[o + b2ManifoldField.localNormalY]]).toEqual([1, 2]);
    expect([r[o + b2ManifoldField.localPointX], r[o + b2ManifoldField.localPointY]]).toEqual([3, 4]);
    expect([r[p1 + b2ManifoldPointField.localPointX], r[p1 + b2ManifoldPointField.localPointY]]).toEqual([5, 6]);
    expect(r[p1 + b2ManifoldPointField.normalImpulse]).toBe(7);
    expect(r[p1 + b2ManifoldPointField.tangentImpulse]).toBe(8);
    expect(r[p1 + b2ManifoldPointField.key]).toBe(0x04030201);

    r[o + b2ManifoldField.localNormalX] = -1;
    r[p1 + b2ManifoldPointField.normalImpulse] = -7;
    expect(m.localNormal.x).toBe(-1);
    expect(m.points[1].normalImpulse).toBe(-7);
  });

  it('gives every manifold a record of its own, across chunks', () => {
    const manifolds = Array.from({ length: 200 }, () => new b2Manifold());
    manifolds.forEach((m, i) => {
      m.localNormal.Set(i, -i);
      m.points[0].tangentImpulse = 1000 + i;
      m.points[1].id.key = i;
    });
    manifolds.forEach((m, i) => {
      expect(m.localNormal.x).toBe(i);
      expect(m.localNormal.y).toBe(-i);
      expect(m.points[0].tangentImpulse).toBe(1000 + i);
      expect(m.points[1].id.key).toBe(i);
      expect(m.points[0].localPoint.x).toBe(0);
    });
    expect(new Set(manifolds.map((m) => m.m_record)).size).toBeGreaterThan(1);
  });

  it('presents an id’s feature bytes and its key as the C++ union does', () => {
    const id = new b2Manifold().points[0].id;
    id.indexA = 1;
    id.indexB = 2;
    id.typeA = 1;
    id.typeB = 0;
    expect(id.key).toBe(0x00010201);
    expect(id.cf).toBe(id);

    id.key = 0xff000003;
    expect([id.indexA, id.indexB, id.typeA, id.typeB]).toEqual([3, 0, 0, 255]);

    // A uint8 keeps the low byte, and a key is a uint32.
    id.indexB = 0x1ff;
    expect(id.indexB).toBe(0xff);
    expect([id.indexA, id.typeB]).toEqual([3, 255]);
    id.key = -1;
    expect(id.key).toBe(0xffffffff);

    expect(id).toBeInstanceOf(b2ContactID);
    const copy = id.Clone();
    expect(copy.constructor).toBe(b2ContactID);
    expect(copy.key).toBe(0xffffffff);
    new b2ContactID().Assign(copy);
    id.Assign(new b2ContactID());
    expect(id.key).toBe(0);
  });

  it('makes the vectors b2Vec2s whose methods and copies work as before', () => {
    const v = new b2Manifold().localPoint;
    expect(v).toBeInstanceOf(b2Vec2);
    v.Set(3, 4);
    expect(v.Length()).toBe(5);
    expect(v.Clone()).toEqual(new b2Vec2(3, 4));
    expect(v.Clone().constructor).toBe(b2Vec2);
    v.Multiply(2).Add(new b2Vec2(1, 1));
    v.SetIndex(1, v.GetIndex(1) + 1);
    expect([v.x, v.y]).toEqual([7, 10]);
    expect(v.Negate(new b2Vec2())).toEqual(new b2Vec2(-7, -10));
  });

  it('lets a point stand alone, and copies points and manifolds by value', () => {
    const p = new b2ManifoldPoint();
    p.localPoint.Set(1, 2);
    p.normalImpulse = 3;
    p.tangentImpulse = 4;
    p.id.key = 5;
    const q = p.Clone();
    p.localPoint.x = 0;
    p.id.key = 0;
    expect([q.localPoint.x, q.localPoint.y, q.normalImpulse, q.tangentImpulse, q.id.key]).toEqual([1, 2, 3, 4, 5]);

    const m = new b2Manifold();
    m.points[1].Assign(q);
    expect(m.points[1].normalImpulse).toBe(3);
    expect(m.points[0].normalImpulse).toBe(0);
  });

  it('shows values, not records, to JSON.stringify and console.log', () => {
    const m = new b2Manifold();
    m.type = b2Manifold.e_faceA;
    m.pointCount = 1;
    m.localNormal.Set(0, 1);
    m.points[0].normalImpulse = 2;
    m.points[0].id.indexB = 3;
    const point = { localPoint: { x: 0, y: 0 }, normalImpulse: 2, tangentImpulse: 0, id: { indexA: 0, indexB: 3, typeA: 0, typeB: 0 } };
    const plain = {
      points: [point, { ...point, normalImpulse: 0, id: { indexA: 0, indexB: 0, typeA: 0, typeB: 0 } }],
      localNormal: { x: 0, y: 1 },
      localPoint: { x: 0, y: 0 },
      type: b2Manifold.e_faceA,
      pointCount: 1,
    };
    expect(JSON.parse(JSON.stringify(m))).toEqual(plain);
    expect(inspect(m, { depth: 4 })).not.toContain('Float64Array');
    expect(inspect(m.localNormal)).toBe('{ x: 0, y: 1 }');
  });

  it('writes faces and points through b2SetManifoldFace and b2SetManifoldPoint, leaving the impulses', () => {
    const m = new b2Manifold();
    m.points[1].normalImpulse = 9;
    b2SetManifoldFace(m, new b2Vec2(0, -1), new b2Vec2(2, 3));
    b2SetManifoldPoint(m, 1, new b2Vec2(4, 5), 0x00010200);
    expect([m.localNormal.x, m.localNormal.y, m.localPoint.x, m.localPoint.y]).toEqual([0, -1, 2, 3]);
    expect([m.points[1].localPoint.x, m.points[1].localPoint.y, m.points[1].id.key]).toEqual([4, 5, 0x00010200]);
    expect([m.points[1].id.indexB, m.points[1].id.typeA]).toEqual([2, 1]);
    expect(m.points[1].normalImpulse).toBe(9);
    expect(m.points[0].localPoint.x).toBe(0);
  });

  it('is never handed to b2Vec2 methods by the engine: every golden scene, its world manifolds and a state round trip', () => {
    // A b2Vec2 method that runs on a view is compiled for two layouts wherever V8 inlines it, and
    // then boxes the doubles it stores (docs/PORTING.md): the engine reads and writes the record.
    const proto = b2Vec2.prototype as unknown as Record<string, unknown>;
    const names = Object.getOwnPropertyNames(proto).filter((n) => n !== 'constructor' && typeof proto[n] === 'function');
    const original = new Map(names.map((n) => [n, proto[n] as (...args: unknown[]) => unknown]));
    const misuses = new Set<string>();
    for (const [name, method] of original) {
      proto[name] = function (this: unknown, ...args: unknown[]) {
        if (this instanceof b2RecordVec2) misuses.add(`${name}: ${new Error().stack?.split('\n')[2]?.trim()}`);
        return method.apply(this, args);
      };
    }
    try {
      const worldManifold = new b2WorldManifold();
      for (const name of goldenSceneNames()) {
        const scene = loadGoldenScene(name);
        for (let i = 0; i < 30; ++i) {
          scene.step();
          for (let c = scene.world.GetContactList(); c; c = c.GetNext()) c.GetWorldManifold(worldManifold);
        }
        b2dJsonRead(b2dJsonWriteString(scene, '', { solverState: true })).step();
      }
    } finally {
      for (const [name, method] of original) proto[name] = method;
    }
    expect([...misuses]).toEqual([]);
  });
});
