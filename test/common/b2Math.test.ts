import { describe, expect, it } from 'vitest';
import {
  b2Abs,
  b2Clamp,
  b2Cross,
  b2CrossSV,
  b2CrossVS,
  b2Mat22,
  b2Mat33,
  b2Max,
  b2Min,
  b2MulRV,
  b2MulTRV,
  b2MulTXV,
  b2MulTXX,
  b2MulXV,
  b2MulXX,
  b2NextPowerOfTwo,
  b2Normalize,
  b2NormalizeLength,
  b2IsPowerOfTwo,
  b2Rot,
  b2Swap,
  b2Sweep,
  b2SweepTime,
  b2Transform,
  b2Vec2,
  b2Vec3,
} from '../../src/common/b2Math';
import { b2_pi } from '../../src/common/b2Settings';

describe('b2Vec2', () => {
  it('Normalize returns the length and leaves vectors shorter than b2_epsilon unchanged', () => {
    const v = new b2Vec2(3, 4);
    expect(v.Normalize()).toBe(5);
    // Multiplies by the reciprocal as the C++ does, so 3/5 comes out as 3 * (1 / 5).
    expect([v.x, v.y]).toEqual([3 * (1 / 5), 4 * (1 / 5)]);
    const tiny = new b2Vec2(1e-8, 0);
    expect(tiny.Normalize()).toBe(0);
    expect(tiny.x).toBe(1e-8);
  });

  it('b2Normalize normalizes as Normalize does, the length (or 0) in b2NormalizeLength[0]', () => {
    const v = new b2Vec2(3, 4);
    b2Normalize(v);
    expect([v.x, v.y, b2NormalizeLength[0]]).toEqual([3 * (1 / 5), 4 * (1 / 5), 5]);
    const w = new b2Vec2(-0.3, 0.7);
    const u = new b2Vec2(-0.3, 0.7);
    b2Normalize(w);
    expect(b2NormalizeLength[0]).toBe(u.Normalize());
    expect([w.x, w.y]).toEqual([u.x, u.y]);
    const tiny = new b2Vec2(1e-8, 0);
    b2Normalize(tiny);
    expect([tiny.x, tiny.y, b2NormalizeLength[0]]).toEqual([1e-8, 0, 0]);
  });

  it('Skew gives the vector whose dot product equals the cross product', () => {
    const a = new b2Vec2(2, -3);
    const b = new b2Vec2(5, 7);
    const s = a.Skew(new b2Vec2());
    expect(s.x * b.x + s.y * b.y).toBe(b2Cross(a, b));
  });
});

describe('the unary minus, column constructors and b2Swap', () => {
  it('Negate writes -v to out, which may alias v, and negates +0 to -0', () => {
    const v = new b2Vec2(2, 0);
    const n = v.Negate(new b2Vec2());
    expect(n.x).toBe(-2);
    expect(Object.is(n.y, -0)).toBe(true);
    expect([v.x, v.y]).toEqual([2, 0]);
    expect(v.Negate(v)).toBe(v);
    expect(v.x).toBe(-2);
    const w = new b2Vec3(1, -2, 3).Negate(new b2Vec3());
    expect([w.x, w.y, w.z]).toEqual([-1, 2, -3]);
  });

  it('b2Mat22(c1, c2) and b2Mat33(c1, c2, c3) copy the columns; no arguments give the identity', () => {
    const c1 = new b2Vec2(1, 2);
    const c2 = new b2Vec2(3, 4);
    const m = new b2Mat22(c1, c2);
    expect([m.ex.x, m.ex.y, m.ey.x, m.ey.y]).toEqual([1, 2, 3, 4]);
    c1.x = 9;
    expect(m.ex.x).toBe(1);
    expect(m.ex).not.toBe(c1);
    expect([new b2Mat22().ex.x, new b2Mat22().ey.y]).toEqual([1, 1]);
    const m3 = new b2Mat33(new b2Vec3(1, 2, 3), new b2Vec3(4, 5, 6), new b2Vec3(7, 8, 9));
    expect([m3.ex.z, m3.ey.y, m3.ez.x]).toEqual([3, 5, 7]);
    const id = new b2Mat33();
    expect([id.ex.x, id.ey.y, id.ez.z, id.ex.y]).toEqual([1, 1, 1, 0]);
  });

  it('b2Swap exchanges the contents of two value objects, nested ones included, keeping identities', () => {
    const a = new b2Vec2(1, 2);
    const b = new b2Vec2(3, 4);
    b2Swap(a, b);
    expect([a.x, a.y, b.x, b.y]).toEqual([3, 4, 1, 2]);

    const xa = new b2Transform(new b2Vec2(1, 2), new b2Rot(0.5));
    const xb = new b2Transform(new b2Vec2(-3, 4), new b2Rot(-1));
    const pA = xa.p;
    const qA = xa.q;
    const before = [xa.Clone(), xb.Clone()];
    b2Swap(xa, xb);
    expect(xa).toEqual(before[1]);
    expect(xb).toEqual(before[0]);
    expect(xa.p).toBe(pA);
    expect(xa.q).toBe(qA);
  });
});

describe('free functions', () => {
  it('b2Abs, b2Min, b2Max keep the C++ ternaries, including b2Abs(+0) = -0', () => {
    expect(Object.is(b2Abs(0), -0)).toBe(true);
    expect(b2Abs(-2.5)).toBe(2.5);
    expect(Number.isNaN(b2Min(NaN, 1))).toBe(false);
    expect(b2Min(NaN, 1)).toBe(1);
    expect(b2Max(NaN, 1)).toBe(1);
    expect(Number.isNaN(b2Max(1, NaN))).toBe(true);
    expect(b2Clamp(5, -1, 2)).toBe(2);
  });

  it('cross products with scalars follow (s*a.y, -s*a.x) and (-s*a.y, s*a.x)', () => {
    const a = new b2Vec2(2, 3);
    expect(b2CrossVS(a, 2, new b2Vec2())).toEqual(new b2Vec2(6, -4));
    expect(b2CrossSV(2, a, new b2Vec2())).toEqual(new b2Vec2(-6, 4));
  });

  it('rotations and transforms round-trip, and out may alias the input', () => {
    const q = new b2Rot(0.7);
    const v = new b2Vec2(1.5, -2);
    const r = b2MulRV(q, v, new b2Vec2());
    const back = b2MulTRV(q, r, r);
    expect(back.x).toBeCloseTo(1.5, 14);
    expect(back.y).toBeCloseTo(-2, 14);

    const xf = new b2Transform(new b2Vec2(3, 4), new b2Rot(-1.2));
    const p = b2MulXV(xf, v, new b2Vec2());
    const local = b2MulTXV(xf, p, p);
    expect(local.x).toBeCloseTo(1.5, 14);
    expect(local.y).toBeCloseTo(-2, 14);

    const ab = b2MulXX(xf, xf, new b2Transform());
    const id = b2MulTXX(ab, ab, ab);
    expect(id.p.x).toBeCloseTo(0, 14);
    expect(id.q.c).toBeCloseTo(1, 14);
  });

  it('b2NextPowerOfTwo and b2IsPowerOfTwo work on uint32', () => {
    expect(b2NextPowerOfTwo(5)).toBe(8);
    expect(b2NextPowerOfTwo(8)).toBe(16);
    expect(b2IsPowerOfTwo(64)).toBe(true);
    expect(b2IsPowerOfTwo(0)).toBe(false);
  });
});

describe('matrices', () => {
  it('b2Mat22 inverse and solve agree, and a singular matrix gives zeros', () => {
    const m = b2Mat22.FromScalars(4, 1, 2, 3);
    const inv = m.GetInverse(new b2Mat22());
    const x = m.Solve(new b2Vec2(1, 2), new b2Vec2());
    expect(inv.ex.x * 1 + inv.ey.x * 2).toBeCloseTo(x.x, 15);
    const singular = b2Mat22.FromScalars(1, 2, 2, 4).GetInverse(new b2Mat22());
    expect([singular.ex.x, singular.ey.y]).toEqual([0, 0]);
  });

  it('b2Mat33 Solve33 solves the system and GetSymInverse33 inverts a symmetric matrix', () => {
    const m = new b2Mat33().Set(new b2Vec3(4, 1, 0.5), new b2Vec3(1, 3, 0.25), new b2Vec3(0.5, 0.25, 2));
    const b = new b2Vec3(1, 2, 3);
    const x = m.Solve33(b, new b2Vec3());
    expect(4 * x.x + 1 * x.y + 0.5 * x.z).toBeCloseTo(1, 14);
    expect(0.5 * x.x + 0.25 * x.y + 2 * x.z).toBeCloseTo(3, 14);
    const inv = new b2Mat33();
    m.GetSymInverse33(inv);
    expect(inv.ex.x * 4 + inv.ey.x * 1 + inv.ez.x * 0.5).toBeCloseTo(1, 14);
    const x22 = m.Solve22(new b2Vec2(1, 2), new b2Vec2());
    expect(4 * x22.x + 1 * x22.y).toBeCloseTo(1, 14);
  });
});

describe('b2Sweep', () => {
  it('GetTransform interpolates the center and angle and shifts by the rotated local center', () => {
    const s = new b2Sweep();
    s.localCenter.Set(1, 0);
    s.c0.Set(0, 0);
    s.c.Set(2, 0);
    s.a0 = 0;
    s.a = b2_pi;
    const xf = s.GetTransform(new b2Transform(), 0.5);
    const q = new b2Rot(0.5 * b2_pi);
    expect(xf.q.s).toBe(q.s);
    expect(xf.p.x).toBe(1 - (q.c * 1 - q.s * 0));
    expect(xf.p.y).toBe(0 - (q.s * 1 + q.c * 0));
  });

  it('Advance moves the start state to alpha and Normalize wraps a0 into [0, 2pi) keeping a - a0', () => {
    const s = new b2Sweep();
    s.c0.Set(0, 0);
    s.c.Set(4, 0);
    s.a0 = 0;
    s.a = 1;
    s.Advance(0.25);
    expect(s.c0.x).toBe(1);
    expect(s.a0).toBe(0.25);
    expect(s.alpha0).toBe(0.25);
    s.a0 = 7;
    s.a = 8;
    s.Normalize();
    expect(s.a0).toBe(7 - 2 * b2_pi);
    expect(s.a).toBe(8 - 2 * b2_pi);
  });

  it('GetTransformAt and AdvanceAt take their time from b2SweepTime and match GetTransform and Advance', () => {
    const make = () => {
      const s = new b2Sweep();
      s.localCenter.Set(0.3, -0.2);
      s.c0.Set(1, 2);
      s.c.Set(3, -1);
      s.a0 = 0.4;
      s.a = 2.9;
      s.alpha0 = 0.1;
      return s;
    };
    const byArgument = make().GetTransform(new b2Transform(), 0.37);
    b2SweepTime[0] = 0.37;
    const bySlot = make().GetTransformAt(new b2Transform());
    expect([bySlot.p.x, bySlot.p.y, bySlot.q.s, bySlot.q.c]).toEqual([byArgument.p.x, byArgument.p.y, byArgument.q.s, byArgument.q.c]);

    const advanced = make();
    advanced.Advance(0.6);
    const advancedAt = make();
    b2SweepTime[0] = 0.6;
    advancedAt.AdvanceAt();
    expect(advancedAt).toEqual(advanced);
  });
});
