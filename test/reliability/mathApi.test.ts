import { describe, expect, it } from 'vitest';
import {
  b2AbsM,
  b2AddVV3,
  b2Cross3,
  b2DistanceSquared,
  b2Dot3,
  b2InvSqrt,
  b2Mat22,
  b2Mat33,
  b2MaxV,
  b2MinV,
  b2MulSV,
  b2MulSV3,
  b2Rot,
  b2SubVV3,
  b2Transform,
  b2Vec2,
  b2Vec3,
} from '../../src/common/b2Math';
import { b2Color } from '../../src/common/b2Draw';

/*
 * The b2Math.h API that the engine itself never calls but applications do: each computes what the
 * C++ inline does, operation for operation (results compared with Object.is).
 */
describe('b2Math API outside the engine', () => {
  it('vector members: Subtract, Multiply, GetIndex, SetIndex', () => {
    const v = new b2Vec2(3, -2);
    expect(v.Subtract(new b2Vec2(1, 1))).toBe(v);
    expect([v.x, v.y]).toEqual([2, -3]);
    v.Multiply(-0.5);
    expect([v.x, v.y]).toEqual([-1, 1.5]);
    expect([v.GetIndex(0), v.GetIndex(1)]).toEqual([-1, 1.5]);
    v.SetIndex(0, 7);
    v.SetIndex(1, -0);
    expect(Object.is(v.y, -0)).toBe(true);
    expect(v.x).toBe(7);
    const w = new b2Vec3(1, 2, 3).Subtract(new b2Vec3(0.5, 0.5, 0.5));
    expect([w.x, w.y, w.z]).toEqual([0.5, 1.5, 2.5]);
  });

  it('3-vector free functions', () => {
    const a = new b2Vec3(1, 2, 3);
    const b = new b2Vec3(-4, 0.5, 2);
    const out = new b2Vec3();
    expect(b2MulSV3(2, a, out)).toBe(out);
    expect([out.x, out.y, out.z]).toEqual([2, 4, 6]);
    b2AddVV3(a, b, out);
    expect([out.x, out.y, out.z]).toEqual([-3, 2.5, 5]);
    b2SubVV3(a, b, out);
    expect([out.x, out.y, out.z]).toEqual([5, 1.5, 1]);
    expect(b2Dot3(a, b)).toBe(1 * -4 + 2 * 0.5 + 3 * 2);
    b2Cross3(a, b, out);
    expect([out.x, out.y, out.z]).toEqual([2 * 2 - 3 * 0.5, 3 * -4 - 1 * 2, 1 * 0.5 - 2 * -4]);
    // out may alias an input.
    b2Cross3(a, b, a);
    expect([a.x, a.y, a.z]).toEqual([2.5, -14, 8.5]);
  });

  it('2-vector free functions: b2MulSV, b2DistanceSquared, b2MinV, b2MaxV (C++ ternaries on -0)', () => {
    const out = new b2Vec2();
    expect(b2MulSV(3, new b2Vec2(1, -2), out)).toBe(out);
    expect([out.x, out.y]).toEqual([3, -6]);
    expect(b2DistanceSquared(new b2Vec2(1, 1), new b2Vec2(4, 5))).toBe(25);
    b2MinV(new b2Vec2(0, 5), new b2Vec2(-0, 2), out);
    // b2Min(0, -0) is the second argument (0 < -0 is false), unlike Math.min.
    expect(Object.is(out.x, -0)).toBe(true);
    expect(out.y).toBe(2);
    b2MaxV(new b2Vec2(-0, 5), new b2Vec2(0, 2), out);
    expect(Object.is(out.x, 0)).toBe(true);
    expect(out.y).toBe(5);
  });

  it('matrix and rotation helpers: SetIdentity, SetZero, b2AbsM, GetXAxis, GetYAxis', () => {
    const m = new b2Mat22();
    m.ex.Set(-1, 2);
    m.ey.Set(3, -4);
    const abs = b2AbsM(m, new b2Mat22());
    expect([abs.ex.x, abs.ex.y, abs.ey.x, abs.ey.y]).toEqual([1, 2, 3, 4]);
    m.SetIdentity();
    expect([m.ex.x, m.ex.y, m.ey.x, m.ey.y]).toEqual([1, 0, 0, 1]);
    const m3 = new b2Mat33(new b2Vec3(1, 2, 3), new b2Vec3(4, 5, 6), new b2Vec3(7, 8, 9)).SetZero();
    expect([m3.ex.x, m3.ey.y, m3.ez.z]).toEqual([0, 0, 0]);
    const q = new b2Rot().Set(0.5);
    const x = q.GetXAxis(new b2Vec2());
    const y = q.GetYAxis(new b2Vec2());
    expect([x.x, x.y, y.x, y.y]).toEqual([q.c, q.s, -q.s, q.c]);
    q.SetIdentity();
    expect([q.s, q.c]).toEqual([0, 1]);
    const xf = new b2Transform();
    xf.p.Set(1, 2);
    xf.q.Set(1);
    xf.SetIdentity();
    expect([xf.p.x, xf.p.y, xf.q.s, xf.q.c]).toEqual([0, 0, 0, 1]);
  });

  it('b2InvSqrt is the float32 approximation of b2Math.h', () => {
    expect(b2InvSqrt(4)).toBeCloseTo(0.5, 2);
    expect(Math.abs(b2InvSqrt(2) - 1 / Math.SQRT2)).toBeLessThan(2e-3);
    expect(b2InvSqrt(100)).toBe(Math.fround(b2InvSqrt(100)));
  });

  it('b2Color.Set', () => {
    const c = new b2Color();
    expect(c.Set(0.1, 0.2, 0.3)).toBe(c);
    expect([c.r, c.g, c.b]).toEqual([0.1, 0.2, 0.3]);
  });
});
