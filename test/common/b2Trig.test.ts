import { describe, expect, it } from 'vitest';
import { b2Cos as cos, b2Sin as sin } from '../../src/common/b2Math';
import { b2Atan2 } from '../../src/common/b2Trig';

// A seeded generator so a failure names an input that can be replayed.
function mulberry32(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function firstMismatch(fn: (x: number) => number, ref: (x: number) => number, inputs: Iterable<number>): string | null {
  for (const x of inputs) {
    const a = fn(x);
    const b = ref(x);
    if (!Object.is(a, b)) return `x=${x}: got ${a}, expected ${b}`;
  }
  return null;
}

function* randomInputs(seed: number, count: number, scale: number): Generator<number> {
  const rand = mulberry32(seed);
  for (let i = 0; i < count; i++) yield (rand() * 2 - 1) * scale;
}

// Special values: signed zeros, the pi/4 reduction boundaries and their neighbours, the
// medium/large reduction thresholds, non-finite values and huge arguments.
function* specialInputs(): Generator<number> {
  const f = new Float64Array(1);
  const u = new BigUint64Array(f.buffer);
  const neighbours = (x: number): number[] => {
    f[0] = x;
    const bits = u[0];
    const out: number[] = [];
    for (let d = -3n; d <= 3n; d++) {
      u[0] = bits + d;
      out.push(f[0]);
    }
    return out;
  };
  const anchors = [
    0,
    Math.PI / 4,
    (3 * Math.PI) / 4,
    Math.PI / 2,
    Math.PI,
    (3 * Math.PI) / 2,
    2 * Math.PI,
    0.3,
    0.78125,
    2 ** -27,
    2 ** 19 * (Math.PI / 2),
    2 ** 20,
    1e6,
    1e9,
    1e15,
    1e22,
    1e100,
    1e300,
    Number.MAX_VALUE,
    Number.MIN_VALUE,
    2 ** -1022,
    3.14159265359,
    1.570796326795,
    // b2SinCos's range tests: the doubles whose high words are fdlibm's bounds.
    0.7853984832763672,
    0.2999999523162842,
    0.7812504768371582,
  ];
  for (const a of anchors) {
    for (const x of neighbours(a)) {
      yield x;
      yield -x;
    }
  }
  yield -0;
  yield Infinity;
  yield -Infinity;
  yield NaN;
  for (let k = 1; k < 2000; k++) {
    yield (k * Math.PI) / 4;
    yield (-k * Math.PI) / 2;
  }
}

describe('b2SinCos (b2Rot.Set, b2Sin, b2Cos) reproduces fdlibm (Math.sin/Math.cos in Node 20)', () => {
  it('agrees on a million random angles within +-8 pi, the range a world uses', () => {
    expect(firstMismatch(sin, Math.sin, randomInputs(1, 1_000_000, 8 * Math.PI))).toBeNull();
    expect(firstMismatch(cos, Math.cos, randomInputs(2, 1_000_000, 8 * Math.PI))).toBeNull();
  });

  it('agrees on large angles that need the medium and Payne-Hanek reductions', () => {
    expect(firstMismatch(sin, Math.sin, randomInputs(3, 100_000, 1e6))).toBeNull();
    expect(firstMismatch(cos, Math.cos, randomInputs(4, 100_000, 1e6))).toBeNull();
    expect(firstMismatch(sin, Math.sin, randomInputs(5, 100_000, 1e300))).toBeNull();
    expect(firstMismatch(cos, Math.cos, randomInputs(6, 100_000, 1e18))).toBeNull();
  });

  it("agrees on special values: signed zeros, the range tests' bounds, NaN, infinities, huge arguments", () => {
    expect(firstMismatch(sin, Math.sin, specialInputs())).toBeNull();
    expect(firstMismatch(cos, Math.cos, specialInputs())).toBeNull();
    expect(Object.is(sin(-0), -0)).toBe(true);
    expect(Number.isNaN(cos(Infinity))).toBe(true);
  });
});

describe('b2Atan2 reproduces fdlibm (Math.atan2 in Node 20)', () => {
  it('agrees on a million random points', () => {
    const rand = mulberry32(7);
    let mismatch: string | null = null;
    for (let i = 0; i < 1_000_000 && mismatch === null; i++) {
      const scale = i % 3 === 0 ? 1 : i % 3 === 1 ? 1e-3 : 1e4;
      const y = (rand() * 2 - 1) * scale;
      const x = (rand() * 2 - 1) * (i % 5 === 0 ? 1e-6 : scale);
      if (!Object.is(b2Atan2(y, x), Math.atan2(y, x))) mismatch = `atan2(${y}, ${x})`;
    }
    expect(mismatch).toBeNull();
  });

  it('agrees on signed zeros, infinities, NaN and extreme ratios', () => {
    const values = [0, -0, 1, -1, 0.5, 2 ** -1074, 1e-300, 1e300, Infinity, -Infinity, NaN, 2.4375, 1.1875];
    for (const y of values) {
      for (const x of values) {
        expect(Object.is(b2Atan2(y, x), Math.atan2(y, x)), `atan2(${y}, ${x})`).toBe(true);
      }
    }
  });
});
