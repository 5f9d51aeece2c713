/*
 * Vectors, matrices, rotations, transforms and sweeps (b2Math.h, b2Math.cpp).
 *
 * C++ passes these structs by value; here they are classes passed by reference. Where the C++
 * returns a new value, the port takes an `out` argument last and returns it, so hot paths do not
 * allocate. Every function reads all of its inputs before writing `out`, so `out` may alias an
 * input (b2MulRV(q, v, v) is safe, like `v = b2Mul(q, v)` in C++). Overloaded C++ functions get
 * a suffix naming their argument types: V vector, S scalar, M b2Mat22, R b2Rot, X b2Transform.
 *
 * Expression order follows the C++ operator by operator: with float64 arithmetic and no fused
 * multiply-add this reproduces the reference engine bit for bit.
 */

import { b2_epsilon, b2_pi } from './b2Settings';
import { b2Atan2, b2SinCos, b2SinCosArg } from './b2Trig';

/** False for NaN and +-Infinity. */
export function b2IsValid(x: number): boolean {
  return Number.isFinite(x);
}

const invSqrtF = new Float32Array(1);
const invSqrtI = new Int32Array(invSqrtF.buffer);

/** The approximate inverse square root of b2Math.h (float32 bit hack; unused by the engine). */
export function b2InvSqrt(x: number): number {
  invSqrtF[0] = x;
  const xhalf = Math.fround(0.5 * x);
  invSqrtI[0] = 0x5f3759df - (invSqrtI[0] >> 1);
  const y = invSqrtF[0];
  return Math.fround(y * Math.fround(1.5 - Math.fround(Math.fround(xhalf * y) * y)));
}

export const b2Sqrt = Math.sqrt;

/** A 2D column vector. */
export class b2Vec2 {
  constructor(
    public x = 0.0,
    public y = 0.0,
  ) {}

  Clone(): b2Vec2 {
    return new b2Vec2(this.x, this.y);
  }

  /** this = v */
  Assign(v: Readonly<b2Vec2>): this {
    this.x = v.x;
    this.y = v.y;
    return this;
  }

  /** Set this vector to all zeros. */
  SetZero(): this {
    this.x = 0.0;
    this.y = 0.0;
    return this;
  }

  /** Set this vector to some specified coordinates. */
  Set(x: number, y: number): this {
    this.x = x;
    this.y = y;
    return this;
  }

  /** -this (the C++ unary operator -). */
  Negate(out: b2Vec2): b2Vec2 {
    out.x = -this.x;
    out.y = -this.y;
    return out;
  }

  /** this += v */
  Add(v: Readonly<b2Vec2>): this {
    this.x += v.x;
    this.y += v.y;
    return this;
  }

  /** this -= v */
  Subtract(v: Readonly<b2Vec2>): this {
    this.x -= v.x;
    this.y -= v.y;
    return this;
  }

  /** this *= a */
  Multiply(a: number): this {
    this.x *= a;
    this.y *= a;
    return this;
  }

  /** Read an indexed element (0 = x, 1 = y). */
  GetIndex(i: number): number {
    return i === 0 ? this.x : this.y;
  }

  /** Write an indexed element (0 = x, 1 = y). */
  SetIndex(i: number, value: number): void {
    if (i === 0) this.x = value;
    else this.y = value;
  }

  /** Get the length of this vector (the norm). */
  Length(): number {
    return Math.sqrt(this.x * this.x + this.y * this.y);
  }

  /** Get the length squared. */
  LengthSquared(): number {
    return this.x * this.x + this.y * this.y;
  }

  /**
   * Convert this vector into a unit vector. Returns the length; a vector shorter than
   * b2_epsilon is left unchanged and 0 is returned.
   */
  Normalize(): number {
    b2Normalize(this);
    return b2NormalizeLength[0];
  }

  /** Does this vector contain finite coordinates? */
  IsValid(): boolean {
    return b2IsValid(this.x) && b2IsValid(this.y);
  }

  /** The skew vector such that dot(skew_vec, other) == cross(vec, other). */
  Skew(out: b2Vec2): b2Vec2 {
    const x = this.x;
    out.x = -this.y;
    out.y = x;
    return out;
  }
}

/** The length b2Normalize found: 0 for a vector shorter than b2_epsilon. */
export const b2NormalizeLength = new Float64Array(1);

/**
 * b2Vec2.Normalize with the length written to b2NormalizeLength[0] instead of returned. The
 * collide and TOI functions call it where V8 may not inline the call (a branch taken by few
 * contacts, a function past V8's inlining budget), and a double returned from a call V8 leaves
 * out of line is boxed: a heap allocation per call.
 */
export function b2Normalize(v: b2Vec2): void {
  const length = Math.sqrt(v.x * v.x + v.y * v.y);
  if (length < b2_epsilon) {
    b2NormalizeLength[0] = 0.0;
    return;
  }
  const invLength = 1.0 / length;
  v.x *= invLength;
  v.y *= invLength;
  b2NormalizeLength[0] = length;
}

/** A 2D column vector with 3 elements. */
export class b2Vec3 {
  constructor(
    public x = 0.0,
    public y = 0.0,
    public z = 0.0,
  ) {}

  Clone(): b2Vec3 {
    return new b2Vec3(this.x, this.y, this.z);
  }

  Assign(v: Readonly<b2Vec3>): this {
    this.x = v.x;
    this.y = v.y;
    this.z = v.z;
    return this;
  }

  SetZero(): this {
    this.x = 0.0;
    this.y = 0.0;
    this.z = 0.0;
    return this;
  }

  Set(x: number, y: number, z: number): this {
    this.x = x;
    this.y = y;
    this.z = z;
    return this;
  }

  /** -this (the C++ unary operator -). */
  Negate(out: b2Vec3): b2Vec3 {
    out.x = -this.x;
    out.y = -this.y;
    out.z = -this.z;
    return out;
  }

  Add(v: Readonly<b2Vec3>): this {
    this.x += v.x;
    this.y += v.y;
    this.z += v.z;
    return this;
  }

  Subtract(v: Readonly<b2Vec3>): this {
    this.x -= v.x;
    this.y -= v.y;
    this.z -= v.z;
    return this;
  }

  Multiply(s: number): this {
    this.x *= s;
    this.y *= s;
    this.z *= s;
    return this;
  }
}

/** A 2-by-2 matrix stored in column-major order. */
export class b2Mat22 {
  readonly ex = new b2Vec2(1.0, 0.0);
  readonly ey = new b2Vec2(0.0, 1.0);

  /**
   * Construct this matrix using columns (the identity when omitted; the C++ default constructor
   * leaves it uninitialised).
   */
  constructor(c1?: Readonly<b2Vec2>, c2?: Readonly<b2Vec2>) {
    if (c1 !== undefined) this.ex.Assign(c1);
    if (c2 !== undefined) this.ey.Assign(c2);
  }

  /** Construct from scalars, as the C++ b2Mat22(a11, a12, a21, a22). */
  static FromScalars(a11: number, a12: number, a21: number, a22: number): b2Mat22 {
    const m = new b2Mat22();
    m.ex.x = a11;
    m.ex.y = a21;
    m.ey.x = a12;
    m.ey.y = a22;
    return m;
  }

  Clone(): b2Mat22 {
    return new b2Mat22().Assign(this);
  }

  Assign(m: Readonly<b2Mat22>): this {
    this.ex.Assign(m.ex);
    this.ey.Assign(m.ey);
    return this;
  }

  /** Initialize this matrix using columns. */
  Set(c1: Readonly<b2Vec2>, c2: Readonly<b2Vec2>): this {
    this.ex.Assign(c1);
    this.ey.Assign(c2);
    return this;
  }

  SetIdentity(): this {
    this.ex.x = 1.0;
    this.ey.x = 0.0;
    this.ex.y = 0.0;
    this.ey.y = 1.0;
    return this;
  }

  SetZero(): this {
    this.ex.x = 0.0;
    this.ey.x = 0.0;
    this.ex.y = 0.0;
    this.ey.y = 0.0;
    return this;
  }

  /** The inverse; the zero matrix if singular. */
  GetInverse(out: b2Mat22): b2Mat22 {
    const a = this.ex.x;
    const b = this.ey.x;
    const c = this.ex.y;
    const d = this.ey.y;
    let det = a * d - b * c;
    if (det !== 0.0) {
      det = 1.0 / det;
    }
    out.ex.x = det * d;
    out.ey.x = -det * b;
    out.ex.y = -det * c;
    out.ey.y = det * a;
    return out;
  }

  /** Solve A * x = b, where b is a column vector. */
  Solve(b: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
    const a11 = this.ex.x;
    const a12 = this.ey.x;
    const a21 = this.ex.y;
    const a22 = this.ey.y;
    let det = a11 * a22 - a12 * a21;
    if (det !== 0.0) {
      det = 1.0 / det;
    }
    const bx = b.x;
    const by = b.y;
    out.x = det * (a22 * bx - a12 * by);
    out.y = det * (a11 * by - a21 * bx);
    return out;
  }
}

/** A 3-by-3 matrix stored in column-major order. */
export class b2Mat33 {
  readonly ex = new b2Vec3(1.0, 0.0, 0.0);
  readonly ey = new b2Vec3(0.0, 1.0, 0.0);
  readonly ez = new b2Vec3(0.0, 0.0, 1.0);

  /**
   * Construct this matrix using columns (the identity when omitted; the C++ default constructor
   * leaves it uninitialised).
   */
  constructor(c1?: Readonly<b2Vec3>, c2?: Readonly<b2Vec3>, c3?: Readonly<b2Vec3>) {
    if (c1 !== undefined) this.ex.Assign(c1);
    if (c2 !== undefined) this.ey.Assign(c2);
    if (c3 !== undefined) this.ez.Assign(c3);
  }

  Clone(): b2Mat33 {
    return new b2Mat33().Assign(this);
  }

  Assign(m: Readonly<b2Mat33>): this {
    this.ex.Assign(m.ex);
    this.ey.Assign(m.ey);
    this.ez.Assign(m.ez);
    return this;
  }

  /** Initialize this matrix using columns. */
  Set(c1: Readonly<b2Vec3>, c2: Readonly<b2Vec3>, c3: Readonly<b2Vec3>): this {
    this.ex.Assign(c1);
    this.ey.Assign(c2);
    this.ez.Assign(c3);
    return this;
  }

  SetZero(): this {
    this.ex.SetZero();
    this.ey.SetZero();
    this.ez.SetZero();
    return this;
  }

  /** Solve A * x = b. */
  Solve33(b: Readonly<b2Vec3>, out: b2Vec3): b2Vec3 {
    const ex = this.ex;
    const ey = this.ey;
    const ez = this.ez;
    // det = dot(ex, cross(ey, ez))
    let det = ex.x * (ey.y * ez.z - ey.z * ez.y) + ex.y * (ey.z * ez.x - ey.x * ez.z) + ex.z * (ey.x * ez.y - ey.y * ez.x);
    if (det !== 0.0) {
      det = 1.0 / det;
    }
    const bx = b.x;
    const by = b.y;
    const bz = b.z;
    // x = det * dot(b, cross(ey, ez))
    const x = det * (bx * (ey.y * ez.z - ey.z * ez.y) + by * (ey.z * ez.x - ey.x * ez.z) + bz * (ey.x * ez.y - ey.y * ez.x));
    // y = det * dot(ex, cross(b, ez))
    const y = det * (ex.x * (by * ez.z - bz * ez.y) + ex.y * (bz * ez.x - bx * ez.z) + ex.z * (bx * ez.y - by * ez.x));
    // z = det * dot(ex, cross(ey, b))
    const z = det * (ex.x * (ey.y * bz - ey.z * by) + ex.y * (ey.z * bx - ey.x * bz) + ex.z * (ey.x * by - ey.y * bx));
    out.x = x;
    out.y = y;
    out.z = z;
    return out;
  }

  /** Solve the upper 2-by-2 equation A * x = b. */
  Solve22(b: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
    const a11 = this.ex.x;
    const a12 = this.ey.x;
    const a21 = this.ex.y;
    const a22 = this.ey.y;
    let det = a11 * a22 - a12 * a21;
    if (det !== 0.0) {
      det = 1.0 / det;
    }
    const bx = b.x;
    const by = b.y;
    out.x = det * (a22 * bx - a12 * by);
    out.y = det * (a11 * by - a21 * bx);
    return out;
  }

  /** The inverse of the upper 2-by-2 as a 3-by-3; the zero matrix if singular. */
  GetInverse22(M: b2Mat33): void {
    const a = this.ex.x;
    const b = this.ey.x;
    const c = this.ex.y;
    const d = this.ey.y;
    let det = a * d - b * c;
    if (det !== 0.0) {
      det = 1.0 / det;
    }
    M.ex.x = det * d;
    M.ey.x = -det * b;
    M.ex.z = 0.0;
    M.ex.y = -det * c;
    M.ey.y = det * a;
    M.ey.z = 0.0;
    M.ez.x = 0.0;
    M.ez.y = 0.0;
    M.ez.z = 0.0;
  }

  /** The symmetric inverse as a 3-by-3; the zero matrix if singular. */
  GetSymInverse33(M: b2Mat33): void {
    const ex = this.ex;
    const ey = this.ey;
    const ez = this.ez;
    let det = ex.x * (ey.y * ez.z - ey.z * ez.y) + ex.y * (ey.z * ez.x - ey.x * ez.z) + ex.z * (ey.x * ez.y - ey.y * ez.x);
    if (det !== 0.0) {
      det = 1.0 / det;
    }
    const a11 = ex.x;
    const a12 = ey.x;
    const a13 = ez.x;
    const a22 = ey.y;
    const a23 = ez.y;
    const a33 = ez.z;

    M.ex.x = det * (a22 * a33 - a23 * a23);
    M.ex.y = det * (a13 * a23 - a12 * a33);
    M.ex.z = det * (a12 * a23 - a13 * a22);

    M.ey.x = M.ex.y;
    M.ey.y = det * (a11 * a33 - a13 * a13);
    M.ey.z = det * (a13 * a12 - a11 * a23);

    M.ez.x = M.ex.z;
    M.ez.y = M.ey.z;
    M.ez.z = det * (a11 * a22 - a12 * a12);
  }
}

/** Rotation as sine and cosine. */
export class b2Rot {
  s = 0.0;
  c = 1.0;

  /** Initialize from an angle in radians (the identity when omitted). */
  constructor(angle?: number) {
    if (angle !== undefined) {
      this.Set(angle);
    }
  }

  Clone(): b2Rot {
    const r = new b2Rot();
    r.s = this.s;
    r.c = this.c;
    return r;
  }

  Assign(q: Readonly<b2Rot>): this {
    this.s = q.s;
    this.c = q.c;
    return this;
  }

  /** Set using an angle in radians (sinf and cosf, computed together by b2SinCos). */
  Set(angle: number): this {
    // The angle travels in a typed array slot so the call does not box it (see b2SinCos).
    b2SinCosArg[0] = angle;
    b2SinCos(this);
    return this;
  }

  /** Set to the identity rotation. */
  SetIdentity(): this {
    this.s = 0.0;
    this.c = 1.0;
    return this;
  }

  /** Get the angle in radians. */
  GetAngle(): number {
    return b2Atan2(this.s, this.c);
  }

  /** Get the x-axis. */
  GetXAxis(out: b2Vec2): b2Vec2 {
    return out.Set(this.c, this.s);
  }

  /** Get the y-axis. */
  GetYAxis(out: b2Vec2): b2Vec2 {
    return out.Set(-this.s, this.c);
  }
}

/** A translation and rotation: the position and orientation of a rigid frame. */
export class b2Transform {
  readonly p = new b2Vec2();
  readonly q = new b2Rot();

  /** Initialize using a position vector and a rotation (the identity when omitted). */
  constructor(position?: Readonly<b2Vec2>, rotation?: Readonly<b2Rot>) {
    if (position) this.p.Assign(position);
    if (rotation) this.q.Assign(rotation);
  }

  Clone(): b2Transform {
    return new b2Transform(this.p, this.q);
  }

  Assign(xf: Readonly<b2Transform>): this {
    this.p.Assign(xf.p);
    this.q.Assign(xf.q);
    return this;
  }

  /** Set this to the identity transform. */
  SetIdentity(): this {
    this.p.SetZero();
    this.q.SetIdentity();
    return this;
  }

  /** Set this based on the position and angle. */
  Set(position: Readonly<b2Vec2>, angle: number): this {
    this.p.Assign(position);
    this.q.Set(angle);
    return this;
  }
}

/**
 * The time argument of b2Sweep.GetTransformAt and AdvanceAt, and of b2Body.AdvanceAt: V8 boxes a
 * double passed to a call it leaves out of line, and the time of impact code makes these calls
 * on paths too rare for V8 to inline them.
 */
export const b2SweepTime = new Float64Array(1);

/**
 * The motion of a body/shape for TOI computation. Shapes are defined with respect to the body
 * origin, which may not coincide with the center of mass, but dynamics interpolates the center
 * of mass position.
 */
export class b2Sweep {
  /** Local center of mass position. */
  readonly localCenter = new b2Vec2();
  /** Center world position at alpha0. */
  readonly c0 = new b2Vec2();
  /** Center world position. */
  readonly c = new b2Vec2();
  /** World angle at alpha0. */
  a0 = 0.0;
  /** World angle. */
  a = 0.0;
  /** Fraction of the current time step in the range [0,1]; c0 and a0 are the state at alpha0. */
  alpha0 = 0.0;

  Clone(): b2Sweep {
    return new b2Sweep().Assign(this);
  }

  Assign(s: Readonly<b2Sweep>): this {
    this.localCenter.Assign(s.localCenter);
    this.c0.Assign(s.c0);
    this.c.Assign(s.c);
    this.a0 = s.a0;
    this.a = s.a;
    this.alpha0 = s.alpha0;
    return this;
  }

  /** The interpolated transform at beta in [0,1], where 0 is alpha0. */
  GetTransform(xf: b2Transform, beta: number): b2Transform {
    b2SweepTime[0] = beta;
    return this.GetTransformAt(xf);
  }

  /** Not in the C++: GetTransform at beta = b2SweepTime[0]. */
  GetTransformAt(xf: b2Transform): b2Transform {
    const beta = b2SweepTime[0];
    xf.p.x = (1.0 - beta) * this.c0.x + beta * this.c.x;
    xf.p.y = (1.0 - beta) * this.c0.y + beta * this.c.y;
    const angle = (1.0 - beta) * this.a0 + beta * this.a;
    // xf.q.Set(angle) written out: the time of impact code inlines this method into functions
    // where V8 has no inlining budget left for Set, which would box the angle.
    b2SinCosArg[0] = angle;
    b2SinCos(xf.q);

    // Shift to origin
    const q = xf.q;
    const lc = this.localCenter;
    xf.p.x -= q.c * lc.x - q.s * lc.y;
    xf.p.y -= q.s * lc.x + q.c * lc.y;
    return xf;
  }

  /** Advance the sweep forward, yielding a new initial state at time alpha. */
  Advance(alpha: number): void {
    b2SweepTime[0] = alpha;
    this.AdvanceAt();
  }

  /** Not in the C++: Advance to alpha = b2SweepTime[0]. */
  AdvanceAt(): void {
    const alpha = b2SweepTime[0];
    const beta = (alpha - this.alpha0) / (1.0 - this.alpha0);
    this.c0.x = (1.0 - beta) * this.c0.x + beta * this.c.x;
    this.c0.y = (1.0 - beta) * this.c0.y + beta * this.c.y;
    this.a0 = (1.0 - beta) * this.a0 + beta * this.a;
    this.alpha0 = alpha;
  }

  /** Normalize the angles. */
  Normalize(): void {
    const twoPi = 2.0 * b2_pi;
    const d = twoPi * Math.floor(this.a0 / twoPi);
    this.a0 -= d;
    this.a -= d;
  }
}

/** The zero vector. Treat it as read-only. */
export const b2Vec2_zero: Readonly<b2Vec2> = new b2Vec2(0.0, 0.0);

/** Dot product of two vectors. */
export function b2Dot(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): number {
  return a.x * b.x + a.y * b.y;
}

/** Cross product of two vectors; in 2D this is a scalar. */
export function b2Cross(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): number {
  return a.x * b.y - a.y * b.x;
}

/** Cross product of a vector and a scalar: (s * a.y, -s * a.x). */
export function b2CrossVS(a: Readonly<b2Vec2>, s: number, out: b2Vec2): b2Vec2 {
  const ax = a.x;
  out.x = s * a.y;
  out.y = -s * ax;
  return out;
}

/** Cross product of a scalar and a vector: (-s * a.y, s * a.x). */
export function b2CrossSV(s: number, a: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  const ax = a.x;
  out.x = -s * a.y;
  out.y = s * ax;
  return out;
}

/** A * v */
export function b2MulMV(A: Readonly<b2Mat22>, v: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  const vx = v.x;
  const vy = v.y;
  out.x = A.ex.x * vx + A.ey.x * vy;
  out.y = A.ex.y * vx + A.ey.y * vy;
  return out;
}

/** transpose(A) * v */
export function b2MulTMV(A: Readonly<b2Mat22>, v: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  const vx = v.x;
  const vy = v.y;
  out.x = vx * A.ex.x + vy * A.ex.y;
  out.y = vx * A.ey.x + vy * A.ey.y;
  return out;
}

/** a + b */
export function b2AddVV(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  out.x = a.x + b.x;
  out.y = a.y + b.y;
  return out;
}

/** a - b */
export function b2SubVV(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  out.x = a.x - b.x;
  out.y = a.y - b.y;
  return out;
}

/** s * a */
export function b2MulSV(s: number, a: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  out.x = s * a.x;
  out.y = s * a.y;
  return out;
}

/** a == b (the C++ has no operator!=). */
export function b2Vec2Equals(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): boolean {
  return a.x === b.x && a.y === b.y;
}

/** Distance between two points (the C++ b2Distance(b2Vec2, b2Vec2)). */
export function b2Vec2Distance(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): number {
  const cx = a.x - b.x;
  const cy = a.y - b.y;
  return Math.sqrt(cx * cx + cy * cy);
}

/** Squared distance between two points. */
export function b2DistanceSquared(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): number {
  const cx = a.x - b.x;
  const cy = a.y - b.y;
  return cx * cx + cy * cy;
}

/** s * a */
export function b2MulSV3(s: number, a: Readonly<b2Vec3>, out: b2Vec3): b2Vec3 {
  out.x = s * a.x;
  out.y = s * a.y;
  out.z = s * a.z;
  return out;
}

/** a + b */
export function b2AddVV3(a: Readonly<b2Vec3>, b: Readonly<b2Vec3>, out: b2Vec3): b2Vec3 {
  out.x = a.x + b.x;
  out.y = a.y + b.y;
  out.z = a.z + b.z;
  return out;
}

/** a - b */
export function b2SubVV3(a: Readonly<b2Vec3>, b: Readonly<b2Vec3>, out: b2Vec3): b2Vec3 {
  out.x = a.x - b.x;
  out.y = a.y - b.y;
  out.z = a.z - b.z;
  return out;
}

/** Dot product of two 3-vectors. */
export function b2Dot3(a: Readonly<b2Vec3>, b: Readonly<b2Vec3>): number {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

/** Cross product of two 3-vectors. */
export function b2Cross3(a: Readonly<b2Vec3>, b: Readonly<b2Vec3>, out: b2Vec3): b2Vec3 {
  const x = a.y * b.z - a.z * b.y;
  const y = a.z * b.x - a.x * b.z;
  const z = a.x * b.y - a.y * b.x;
  out.x = x;
  out.y = y;
  out.z = z;
  return out;
}

/** A + B */
export function b2AddMM(A: Readonly<b2Mat22>, B: Readonly<b2Mat22>, out: b2Mat22): b2Mat22 {
  b2AddVV(A.ex, B.ex, out.ex);
  b2AddVV(A.ey, B.ey, out.ey);
  return out;
}

/** A * B */
export function b2MulMM(A: Readonly<b2Mat22>, B: Readonly<b2Mat22>, out: b2Mat22): b2Mat22 {
  const a11 = A.ex.x;
  const a21 = A.ex.y;
  const a12 = A.ey.x;
  const a22 = A.ey.y;
  const b11 = B.ex.x;
  const b21 = B.ex.y;
  const b12 = B.ey.x;
  const b22 = B.ey.y;
  out.ex.x = a11 * b11 + a12 * b21;
  out.ex.y = a21 * b11 + a22 * b21;
  out.ey.x = a11 * b12 + a12 * b22;
  out.ey.y = a21 * b12 + a22 * b22;
  return out;
}

/** transpose(A) * B */
export function b2MulTMM(A: Readonly<b2Mat22>, B: Readonly<b2Mat22>, out: b2Mat22): b2Mat22 {
  const a11 = A.ex.x;
  const a21 = A.ex.y;
  const a12 = A.ey.x;
  const a22 = A.ey.y;
  const b11 = B.ex.x;
  const b21 = B.ex.y;
  const b12 = B.ey.x;
  const b22 = B.ey.y;
  out.ex.x = a11 * b11 + a21 * b21;
  out.ex.y = a12 * b11 + a22 * b21;
  out.ey.x = a11 * b12 + a21 * b22;
  out.ey.y = a12 * b12 + a22 * b22;
  return out;
}

/** A * v for a 3-by-3 matrix. */
export function b2Mul33(A: Readonly<b2Mat33>, v: Readonly<b2Vec3>, out: b2Vec3): b2Vec3 {
  const vx = v.x;
  const vy = v.y;
  const vz = v.z;
  out.x = vx * A.ex.x + vy * A.ey.x + vz * A.ez.x;
  out.y = vx * A.ex.y + vy * A.ey.y + vz * A.ez.y;
  out.z = vx * A.ex.z + vy * A.ey.z + vz * A.ez.z;
  return out;
}

/** The upper 2-by-2 of A times v. */
export function b2Mul22(A: Readonly<b2Mat33>, v: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  const vx = v.x;
  const vy = v.y;
  out.x = A.ex.x * vx + A.ey.x * vy;
  out.y = A.ex.y * vx + A.ey.y * vy;
  return out;
}

/** q * r */
export function b2MulRR(q: Readonly<b2Rot>, r: Readonly<b2Rot>, out: b2Rot): b2Rot {
  const s = q.s * r.c + q.c * r.s;
  const c = q.c * r.c - q.s * r.s;
  out.s = s;
  out.c = c;
  return out;
}

/** transpose(q) * r */
export function b2MulTRR(q: Readonly<b2Rot>, r: Readonly<b2Rot>, out: b2Rot): b2Rot {
  const s = q.c * r.s - q.s * r.c;
  const c = q.c * r.c + q.s * r.s;
  out.s = s;
  out.c = c;
  return out;
}

/** Rotate a vector. */
export function b2MulRV(q: Readonly<b2Rot>, v: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  const vx = v.x;
  const vy = v.y;
  out.x = q.c * vx - q.s * vy;
  out.y = q.s * vx + q.c * vy;
  return out;
}

/** Inverse rotate a vector. */
export function b2MulTRV(q: Readonly<b2Rot>, v: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  const vx = v.x;
  const vy = v.y;
  out.x = q.c * vx + q.s * vy;
  out.y = -q.s * vx + q.c * vy;
  return out;
}

/** Transform a point. */
export function b2MulXV(T: Readonly<b2Transform>, v: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  const vx = v.x;
  const vy = v.y;
  out.x = T.q.c * vx - T.q.s * vy + T.p.x;
  out.y = T.q.s * vx + T.q.c * vy + T.p.y;
  return out;
}

/** Inverse transform a point. */
export function b2MulTXV(T: Readonly<b2Transform>, v: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  const px = v.x - T.p.x;
  const py = v.y - T.p.y;
  out.x = T.q.c * px + T.q.s * py;
  out.y = -T.q.s * px + T.q.c * py;
  return out;
}

/** A * B: v2 = A.q.Rot(B.q.Rot(v1) + B.p) + A.p = (A.q * B.q).Rot(v1) + A.q.Rot(B.p) + A.p */
export function b2MulXX(A: Readonly<b2Transform>, B: Readonly<b2Transform>, out: b2Transform): b2Transform {
  const aqs = A.q.s;
  const aqc = A.q.c;
  const apx = A.p.x;
  const apy = A.p.y;
  const bpx = B.p.x;
  const bpy = B.p.y;
  b2MulRR(A.q, B.q, out.q);
  out.p.x = aqc * bpx - aqs * bpy + apx;
  out.p.y = aqs * bpx + aqc * bpy + apy;
  return out;
}

/** transpose(A) * B: v2 = A.q' * (B.q * v1 + B.p - A.p) */
export function b2MulTXX(A: Readonly<b2Transform>, B: Readonly<b2Transform>, out: b2Transform): b2Transform {
  const aqs = A.q.s;
  const aqc = A.q.c;
  const dx = B.p.x - A.p.x;
  const dy = B.p.y - A.p.y;
  b2MulTRR(A.q, B.q, out.q);
  out.p.x = aqc * dx + aqs * dy;
  out.p.y = -aqs * dx + aqc * dy;
  return out;
}

const s_sinCos = new b2Rot();

/** sin(x), bit for bit fdlibm's (b2SinCos; b2Rot.Set computes sine and cosine together). */
export function b2Sin(x: number): number {
  return s_sinCos.Set(x).s;
}

/** cos(x), bit for bit fdlibm's (b2SinCos; b2Rot.Set computes sine and cosine together). */
export function b2Cos(x: number): number {
  return s_sinCos.Set(x).c;
}

/** |a| as the C++ template writes it: a > 0 ? a : -a (so b2Abs(+0) is -0). */
export function b2Abs(a: number): number {
  return a > 0.0 ? a : -a;
}

export function b2AbsV(a: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  out.x = b2Abs(a.x);
  out.y = b2Abs(a.y);
  return out;
}

export function b2AbsM(A: Readonly<b2Mat22>, out: b2Mat22): b2Mat22 {
  b2AbsV(A.ex, out.ex);
  b2AbsV(A.ey, out.ey);
  return out;
}

/** a < b ? a : b (differs from Math.min for NaN and signed zeros, as in C++). */
export function b2Min(a: number, b: number): number {
  return a < b ? a : b;
}

export function b2MinV(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  out.x = b2Min(a.x, b.x);
  out.y = b2Min(a.y, b.y);
  return out;
}

/** a > b ? a : b (differs from Math.max for NaN and signed zeros, as in C++). */
export function b2Max(a: number, b: number): number {
  return a > b ? a : b;
}

export function b2MaxV(a: Readonly<b2Vec2>, b: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  out.x = b2Max(a.x, b.x);
  out.y = b2Max(a.y, b.y);
  return out;
}

/** max(low, min(a, high)) */
export function b2Clamp(a: number, low: number, high: number): number {
  return b2Max(low, b2Min(a, high));
}

export function b2ClampV(a: Readonly<b2Vec2>, low: Readonly<b2Vec2>, high: Readonly<b2Vec2>, out: b2Vec2): b2Vec2 {
  out.x = b2Clamp(a.x, low.x, high.x);
  out.y = b2Clamp(a.y, low.y, high.y);
  return out;
}

/**
 * b2Swap(a, b) for value objects (b2Vec2, b2Rot, b2Transform, b2Manifold...): exchanges their
 * contents in place, field by field and recursively through nested value objects and arrays, as
 * the C++ template swaps two structs. Both must be of the same class. Numbers cannot be passed by
 * reference in JavaScript; swap those at the call site (`const t = a; a = b; b = t;`), as
 * b2AABB.RayCast does.
 */
export function b2Swap<T extends object>(a: T, b: T): void {
  const ra = a as Record<string, unknown>;
  const rb = b as Record<string, unknown>;
  for (const key of Object.keys(ra)) {
    const va = ra[key];
    const vb = rb[key];
    if (va !== null && vb !== null && typeof va === 'object' && typeof vb === 'object') {
      b2Swap(va, vb);
    } else {
      ra[key] = vb;
      rb[key] = va;
    }
  }
}

/** The next largest power of 2 of a uint32 (SWAR fold). */
export function b2NextPowerOfTwo(x: number): number {
  x >>>= 0;
  x |= x >>> 1;
  x |= x >>> 2;
  x |= x >>> 4;
  x |= x >>> 8;
  x |= x >>> 16;
  return ((x >>> 0) + 1) >>> 0;
}

export function b2IsPowerOfTwo(x: number): boolean {
  x >>>= 0;
  return x > 0 && (x & (x - 1)) === 0;
}
