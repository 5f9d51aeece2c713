/*
 * Box2DWeb 2.1a compatibility for Box2D.Common and Box2D.Common.Math: the b2Vec2/b2Vec3 helpers,
 * b2Mat22/b2Mat33 columns named col1/col2/col3, b2Transform's position and R, b2Sweep.t0, the
 * b2Color.color packing and the b2Math static helpers. Each maps onto the 2.2.1 object or
 * function with the same arithmetic; where 2.1a allocated a result, so do these.
 */

import { b2Color } from '../common/b2Draw';
import {
  b2AbsM,
  b2AbsV,
  b2AddMM,
  b2AddVV,
  b2Clamp,
  b2ClampV,
  b2Cos,
  b2Cross,
  b2CrossSV,
  b2CrossVS,
  b2DistanceSquared,
  b2Dot,
  b2IsPowerOfTwo,
  b2IsValid,
  b2Mat22,
  b2Mat33,
  b2Max,
  b2MaxV,
  b2Min,
  b2MinV,
  b2MulMM,
  b2MulMV,
  b2MulSV,
  b2MulTMM,
  b2MulTMV,
  b2MulTXV,
  b2MulXV,
  b2NextPowerOfTwo,
  b2Rot,
  b2Sin,
  b2SubVV,
  b2Sweep,
  b2Transform,
  b2Vec2,
  b2Vec2Distance,
  b2Vec3,
} from '../common/b2Math';
import { b2Atan2 } from '../common/b2Trig';
import { acceptingArguments, defineAccessor, defineMethods, defineStatics, wrapMethod } from './patch';

declare module '../common/b2Math' {
  interface b2Vec2 {
    /** 2.1a: this = v. */
    SetV(v: Readonly<b2Vec2>): void;
    /** 2.1a: a new vector -this. */
    GetNegative(): b2Vec2;
    /** 2.1a: this = -this. */
    NegativeSelf(): void;
    /** 2.1a: a new vector equal to this (2.2.1's Clone). */
    Copy(): b2Vec2;
    /** 2.1a: this = A * this. */
    MulM(A: Readonly<b2Mat22>): void;
    /** 2.1a: this = transpose(A) * this. */
    MulTM(A: Readonly<b2Mat22>): void;
    /** 2.1a: this = cross(this, s). */
    CrossVF(s: number): void;
    /** 2.1a: this = cross(s, this). */
    CrossFV(s: number): void;
    /** 2.1a: componentwise this = min(this, b). */
    MinV(b: Readonly<b2Vec2>): void;
    /** 2.1a: componentwise this = max(this, b). */
    MaxV(b: Readonly<b2Vec2>): void;
    /** 2.1a: componentwise this = |this| (negative components are negated). */
    Abs(): void;
  }
  namespace b2Vec2 {
    /** 2.1a: new b2Vec2(x, y). */
    function Make(x?: number, y?: number): b2Vec2;
  }

  interface b2Vec3 {
    /** 2.1a: this = v. */
    SetV(v: Readonly<b2Vec3>): void;
    /** 2.1a: a new vector -this. */
    GetNegative(): b2Vec3;
    /** 2.1a: this = -this. */
    NegativeSelf(): void;
    /** 2.1a: a new vector equal to this. */
    Copy(): b2Vec3;
  }

  interface b2Mat22 {
    /** 2.1a's name for the first column (ex). */
    col1: b2Vec2;
    /** 2.1a's name for the second column (ey). */
    col2: b2Vec2;
    /** 2.1a: set the columns (2.2.1's Set). */
    SetVV(c1: Readonly<b2Vec2>, c2: Readonly<b2Vec2>): void;
    /** 2.1a: a new matrix equal to this. */
    Copy(): b2Mat22;
    /** 2.1a: this = m. */
    SetM(m: Readonly<b2Mat22>): void;
    /** 2.1a: this += m. */
    AddM(m: Readonly<b2Mat22>): void;
    /** 2.1a: the angle of a rotation matrix, atan2(col1.y, col1.x). */
    GetAngle(): number;
    /** 2.1a: componentwise this = |this|. */
    Abs(): void;
  }
  namespace b2Mat22 {
    /** 2.1a: a new rotation matrix. */
    function FromAngle(angle?: number): b2Mat22;
    /** 2.1a: a new matrix from columns. */
    function FromVV(c1: Readonly<b2Vec2>, c2: Readonly<b2Vec2>): b2Mat22;
  }

  interface b2Mat33 {
    /** 2.1a's name for the first column (ex). */
    col1: b2Vec3;
    /** 2.1a's name for the second column (ey). */
    col2: b2Vec3;
    /** 2.1a's name for the third column (ez). */
    col3: b2Vec3;
    /** 2.1a: set the columns. */
    SetVVV(c1: Readonly<b2Vec3>, c2: Readonly<b2Vec3>, c3: Readonly<b2Vec3>): void;
    /** 2.1a: a new matrix equal to this. */
    Copy(): b2Mat33;
    /** 2.1a: this = m. */
    SetM(m: Readonly<b2Mat33>): void;
    /** 2.1a: this += m. */
    AddM(m: Readonly<b2Mat33>): void;
    /** 2.1a: the identity. */
    SetIdentity(): void;
  }

  interface b2Transform {
    /** 2.1a's name for the translation (p). */
    position: b2Vec2;
    /**
     * 2.1a's rotation matrix. Reading gives a new b2Mat22 built from q (changing it does not
     * change the transform); assigning a rotation matrix sets q from its first column.
     */
    R: b2Mat22;
    /** 2.1a: set from a position and a rotation matrix. */
    Initialize(position: Readonly<b2Vec2>, R: Readonly<b2Mat22>): void;
    /** 2.1a: the rotation angle in radians. */
    GetAngle(): number;
  }

  interface b2Sweep {
    /** 2.1a's name for alpha0, the time in [0,1] of c0 and a0. */
    t0: number;
    /** 2.1a: this = other. */
    Set(other: Readonly<b2Sweep>): void;
    /** 2.1a: a new sweep equal to this. */
    Copy(): b2Sweep;
  }
}

declare module '../common/b2Draw' {
  interface b2Color {
    /** 2.1a: the color packed as 0xRRGGBB, each channel round(255 * clamp(c, 0, 1)). */
    readonly color: number;
  }
}

defineMethods(b2Vec2.prototype, {
  SetV(v) {
    this.x = v.x;
    this.y = v.y;
  },
  GetNegative() {
    return new b2Vec2(-this.x, -this.y);
  },
  NegativeSelf() {
    this.x = -this.x;
    this.y = -this.y;
  },
  Copy() {
    return new b2Vec2(this.x, this.y);
  },
  MulM(A) {
    b2MulMV(A, this, this);
  },
  MulTM(A) {
    b2MulTMV(A, this, this);
  },
  CrossVF(s) {
    b2CrossVS(this, s, this);
  },
  CrossFV(s) {
    b2CrossSV(s, this, this);
  },
  MinV(b) {
    b2MinV(this, b, this);
  },
  MaxV(b) {
    b2MaxV(this, b, this);
  },
  Abs() {
    if (this.x < 0) this.x = -this.x;
    if (this.y < 0) this.y = -this.y;
  },
});
defineStatics(b2Vec2, {
  Make: (x = 0, y = 0) => new b2Vec2(x, y),
});

defineMethods(b2Vec3.prototype, {
  SetV(v) {
    this.x = v.x;
    this.y = v.y;
    this.z = v.z;
  },
  GetNegative() {
    return new b2Vec3(-this.x, -this.y, -this.z);
  },
  NegativeSelf() {
    this.x = -this.x;
    this.y = -this.y;
    this.z = -this.z;
  },
  Copy() {
    return new b2Vec3(this.x, this.y, this.z);
  },
});

/** The rotation matrix of an angle, with the engine's own sin and cos. */
function setRotationMatrix(m: b2Mat22, angle: number): void {
  const c = b2Cos(angle);
  const s = b2Sin(angle);
  m.ex.x = c;
  m.ey.x = -s;
  m.ex.y = s;
  m.ey.y = c;
}

defineAccessor(
  b2Mat22.prototype,
  'col1',
  function () {
    return this.ex;
  },
  function (v: b2Vec2) {
    this.ex.Assign(v);
  },
);
defineAccessor(
  b2Mat22.prototype,
  'col2',
  function () {
    return this.ey;
  },
  function (v: b2Vec2) {
    this.ey.Assign(v);
  },
);
// 2.1a's Set(angle) sets the rotation matrix of an angle. It is accepted at run time only: a
// TypeScript overload cannot merge into Set(c1, c2); typed code calls b2Mat22.FromAngle or SetVV.
wrapMethod(
  b2Mat22.prototype,
  'Set',
  (set) =>
    function (this: b2Mat22, a: Readonly<b2Vec2> | number, b?: Readonly<b2Vec2>) {
      if (typeof a === 'number') {
        setRotationMatrix(this, a);
        return this;
      }
      return set.call(this, a, b as Readonly<b2Vec2>);
    } as b2Mat22['Set'],
);
defineMethods(b2Mat22.prototype, {
  SetVV(c1, c2) {
    this.ex.Assign(c1);
    this.ey.Assign(c2);
  },
  Copy() {
    return this.Clone();
  },
  SetM(m) {
    this.Assign(m);
  },
  AddM(m) {
    this.ex.x += m.ex.x;
    this.ex.y += m.ex.y;
    this.ey.x += m.ey.x;
    this.ey.y += m.ey.y;
  },
  GetAngle() {
    return b2Atan2(this.ex.y, this.ex.x);
  },
  Abs() {
    this.ex.Abs();
    this.ey.Abs();
  },
});
defineStatics(b2Mat22, {
  FromAngle: (angle = 0) => {
    const m = new b2Mat22();
    setRotationMatrix(m, angle);
    return m;
  },
  FromVV: (c1: Readonly<b2Vec2>, c2: Readonly<b2Vec2>) => new b2Mat22(c1, c2),
});

for (const [name, column] of [
  ['col1', 'ex'],
  ['col2', 'ey'],
  ['col3', 'ez'],
] as const) {
  defineAccessor(
    b2Mat33.prototype,
    name,
    function () {
      return this[column];
    },
    function (v: b2Vec3) {
      this[column].Assign(v);
    },
  );
}
defineMethods(b2Mat33.prototype, {
  SetVVV(c1, c2, c3) {
    this.Set(c1, c2, c3);
  },
  Copy() {
    return this.Clone();
  },
  SetM(m) {
    this.Assign(m);
  },
  AddM(m) {
    this.ex.Add(m.ex);
    this.ey.Add(m.ey);
    this.ez.Add(m.ez);
  },
  SetIdentity() {
    this.ex.Set(1.0, 0.0, 0.0);
    this.ey.Set(0.0, 1.0, 0.0);
    this.ez.Set(0.0, 0.0, 1.0);
  },
});

/** q = the rotation of a 2.1a rotation matrix (its first column is (cos, sin)). */
function setRotFromMatrix(q: b2Rot, R: Readonly<b2Mat22>): void {
  q.c = R.ex.x;
  q.s = R.ex.y;
}

defineAccessor(
  b2Transform.prototype,
  'position',
  function () {
    return this.p;
  },
  function (v: b2Vec2) {
    this.p.Assign(v);
  },
);
defineAccessor(
  b2Transform.prototype,
  'R',
  function () {
    const q = this.q;
    return b2Mat22.FromScalars(q.c, -q.s, q.s, q.c);
  },
  function (R: b2Mat22) {
    setRotFromMatrix(this.q, R);
  },
);
// 2.1a's Set(xf) copies a transform. Accepted at run time only (typed code calls Assign).
wrapMethod(
  b2Transform.prototype,
  'Set',
  (set) =>
    function (this: b2Transform, a: Readonly<b2Vec2> | Readonly<b2Transform>, angle?: number) {
      if (angle === undefined && a instanceof b2Transform) {
        return this.Assign(a);
      }
      return set.call(this, a as Readonly<b2Vec2>, angle as number);
    } as b2Transform['Set'],
);
defineMethods(b2Transform.prototype, {
  Initialize(position, R) {
    this.p.Assign(position);
    setRotFromMatrix(this.q, R);
  },
  GetAngle() {
    return this.q.GetAngle();
  },
});

/** b2Transform also takes 2.1a's (position, R: b2Mat22); 2.2.1's (position, q: b2Rot) as before. */
export const b2TransformCompat = acceptingArguments(b2Transform, (args, make) => {
  const [position, rotation] = args as [Readonly<b2Vec2> | undefined, Readonly<b2Rot> | Readonly<b2Mat22> | undefined];
  if (rotation instanceof b2Mat22) {
    const xf = make(position);
    setRotFromMatrix(xf.q, rotation);
    return xf;
  }
  return make(position, rotation);
}) as typeof b2Transform & (new (position?: Readonly<b2Vec2>, R?: Readonly<b2Mat22>) => b2Transform);

defineAccessor(
  b2Sweep.prototype,
  't0',
  function () {
    return this.alpha0;
  },
  function (t: number) {
    this.alpha0 = t;
  },
);
defineMethods(b2Sweep.prototype, {
  Set(other) {
    this.Assign(other);
  },
  Copy() {
    return this.Clone();
  },
});

function channel(c: number): number {
  return Math.round(255 * b2Clamp(c, 0.0, 1.0));
}

defineAccessor(b2Color.prototype, 'color', function () {
  return (channel(this.r) << 16) | (channel(this.g) << 8) | channel(this.b);
});

/**
 * 2.1a's b2Math: static helpers returning new objects, computed by the 2.2.1 functions
 * (b2Clamp is max(low, min(a, high)) as in 2.2.1).
 */
export const b2Math = {
  b2Vec2_zero: new b2Vec2(0.0, 0.0) as Readonly<b2Vec2>,
  b2Mat22_identity: new b2Mat22() as Readonly<b2Mat22>,
  b2Transform_identity: new b2Transform() as Readonly<b2Transform>,
  IsValid: (x: number): boolean => b2IsValid(x),
  Dot: (a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): number => b2Dot(a, b),
  CrossVV: (a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): number => b2Cross(a, b),
  CrossVF: (a: Readonly<b2Vec2>, s: number): b2Vec2 => b2CrossVS(a, s, new b2Vec2()),
  CrossFV: (s: number, a: Readonly<b2Vec2>): b2Vec2 => b2CrossSV(s, a, new b2Vec2()),
  MulMV: (A: Readonly<b2Mat22>, v: Readonly<b2Vec2>): b2Vec2 => b2MulMV(A, v, new b2Vec2()),
  MulTMV: (A: Readonly<b2Mat22>, v: Readonly<b2Vec2>): b2Vec2 => b2MulTMV(A, v, new b2Vec2()),
  MulX: (T: Readonly<b2Transform>, v: Readonly<b2Vec2>): b2Vec2 => b2MulXV(T, v, new b2Vec2()),
  MulXT: (T: Readonly<b2Transform>, v: Readonly<b2Vec2>): b2Vec2 => b2MulTXV(T, v, new b2Vec2()),
  AddVV: (a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): b2Vec2 => b2AddVV(a, b, new b2Vec2()),
  SubtractVV: (a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): b2Vec2 => b2SubVV(a, b, new b2Vec2()),
  Distance: (a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): number => b2Vec2Distance(a, b),
  DistanceSquared: (a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): number => b2DistanceSquared(a, b),
  MulFV: (s: number, a: Readonly<b2Vec2>): b2Vec2 => b2MulSV(s, a, new b2Vec2()),
  AddMM: (A: Readonly<b2Mat22>, B: Readonly<b2Mat22>): b2Mat22 => b2AddMM(A, B, new b2Mat22()),
  MulMM: (A: Readonly<b2Mat22>, B: Readonly<b2Mat22>): b2Mat22 => b2MulMM(A, B, new b2Mat22()),
  MulTMM: (A: Readonly<b2Mat22>, B: Readonly<b2Mat22>): b2Mat22 => b2MulTMM(A, B, new b2Mat22()),
  Abs: (a: number): number => (a > 0.0 ? a : -a),
  AbsV: (a: Readonly<b2Vec2>): b2Vec2 => b2AbsV(a, new b2Vec2()),
  AbsM: (A: Readonly<b2Mat22>): b2Mat22 => b2AbsM(A, new b2Mat22()),
  Min: (a: number, b: number): number => b2Min(a, b),
  MinV: (a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): b2Vec2 => b2MinV(a, b, new b2Vec2()),
  Max: (a: number, b: number): number => b2Max(a, b),
  MaxV: (a: Readonly<b2Vec2>, b: Readonly<b2Vec2>): b2Vec2 => b2MaxV(a, b, new b2Vec2()),
  Clamp: (a: number, low: number, high: number): number => b2Clamp(a, low, high),
  ClampV: (a: Readonly<b2Vec2>, low: Readonly<b2Vec2>, high: Readonly<b2Vec2>): b2Vec2 => b2ClampV(a, low, high, new b2Vec2()),
  /** 2.1a: exchange a[0] and b[0] (its stand-in for swapping two numbers by reference). */
  Swap: (a: unknown[], b: unknown[]): void => {
    const t = a[0];
    a[0] = b[0];
    b[0] = t;
  },
  /** A random number in [-1, 1). */
  Random: (): number => Math.random() * 2 - 1,
  /** A random number in [lo, hi). */
  RandomRange: (lo: number, hi: number): number => (hi - lo) * Math.random() + lo,
  NextPowerOfTwo: (x: number): number => b2NextPowerOfTwo(x),
  IsPowerOfTwo: (x: number): boolean => b2IsPowerOfTwo(x),
};
