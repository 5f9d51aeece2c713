import { afterEach, describe, expect, it } from 'vitest';
import { b2Log, b2SetLogSink, b2_angularSlop, b2_epsilon, b2_maxFloat, b2_pi } from '../../src/common/b2Settings';

describe('b2Settings', () => {
  it('keeps the literals of b2Settings.h as doubles, not Math.PI or float-rounded values', () => {
    expect(b2_pi).toBe(3.14159265359);
    expect(b2_pi).not.toBe(Math.PI);
    expect(b2_epsilon).toBe(1.1920928955078125e-7);
    expect(b2_maxFloat).toBe(3.4028234663852886e38);
    expect(b2_angularSlop).toBe((2.0 / 180.0) * 3.14159265359);
  });
});

describe('b2Log', () => {
  let logged = '';
  b2SetLogSink((text) => {
    logged += text;
  });
  afterEach(() => {
    logged = '';
  });

  it('formats %.15lef as C printf does: e-notation, two-digit exponent, then a literal f', () => {
    b2Log('b2Vec2(%.15lef, %.15lef);\n', 1.5, -3.25e-300);
    expect(logged).toBe('b2Vec2(1.500000000000000e+00f, -3.250000000000000e-300f);\n');
  });

  it('rounds exact decimal ties to even and keeps the sign of -0, like glibc printf', () => {
    // 2^-24 = 5.9604644775390625e-08 exactly: the 17th digit is a tie after an even digit.
    b2Log('%.15lef %.15lef %.15lef', 2 ** -24, -0, 123456789.125);
    expect(logged).toBe('5.960464477539062e-08f -0.000000000000000e+00f 1.234567891250000e+08f');
  });

  it('prints %d as an integer and %% as a percent sign', () => {
    b2Log('bodies[%d] 100%%', 7);
    expect(logged).toBe('bodies[7] 100%');
  });
});
