import { describe, expect, it } from 'vitest';
import { b2ResetToiCounters, b2TimeOfImpact, b2TOIInput, b2TOIOutput, b2_toiCalls, b2_toiIters, b2_toiMaxIters } from '../../src/collision/b2TimeOfImpact';
import { b2Distance, b2DistanceInput, b2DistanceOutput, b2SimplexCache } from '../../src/collision/b2Distance';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Sweep } from '../../src/common/b2Math';
import { b2_linearSlop } from '../../src/common/b2Settings';
import { collisionVectors, compareDouble, makeShape, makeSweep, type TimeOfImpactCase } from '../support/collisionVectors';

function box(hx: number, hy: number): b2PolygonShape {
  const shape = new b2PolygonShape();
  shape.SetAsBox(hx, hy);
  return shape;
}

function sweep(c0x: number, c0y: number, a0: number, cx: number, cy: number, a: number): b2Sweep {
  const s = new b2Sweep();
  s.c0.Set(c0x, c0y);
  s.a0 = a0;
  s.c.Set(cx, cy);
  s.a = a;
  return s;
}

function timeOfImpact(shapeA: b2PolygonShape, sweepA: b2Sweep, shapeB: b2PolygonShape, sweepB: b2Sweep): b2TOIOutput {
  const input = new b2TOIInput();
  input.proxyA.Set(shapeA, 0);
  input.proxyB.Set(shapeB, 0);
  input.sweepA.Assign(sweepA);
  input.sweepB.Assign(sweepB);
  input.tMax = 1.0;
  const output = new b2TOIOutput();
  b2TimeOfImpact(output, input);
  return output;
}

function compareCase(testCase: TimeOfImpactCase): string | null {
  const input = new b2TOIInput();
  input.proxyA.Set(makeShape(testCase.shapeA), 0);
  input.proxyB.Set(makeShape(testCase.shapeB), 0);
  input.sweepA.Assign(makeSweep(testCase.sweepA));
  input.sweepB.Assign(makeSweep(testCase.sweepB));
  input.tMax = testCase.tMax;
  const output = new b2TOIOutput();
  b2TimeOfImpact(output, input);
  if (output.state !== testCase.output.state) {
    return `state: expected ${testCase.output.state}, got ${output.state}`;
  }
  return compareDouble('t', output.t, testCase.output.t);
}

describe('b2TimeOfImpact', () => {
  it('reproduces all 300 reference time-of-impact cases bit for bit (state and t)', () => {
    const cases = collisionVectors.timeOfImpact;
    expect(cases.length).toBe(300);
    let failure: string | null = null;
    for (let i = 0; i < cases.length && failure === null; ++i) {
      const difference = compareCase(cases[i]);
      if (difference !== null) failure = `case ${i}: ${difference}`;
    }
    expect(failure).toBeNull();
  });

  it('stops a fast box at a thin wall: e_touching at the time the gap closes to the target', () => {
    const wall = box(0.1, 5.0);
    const bullet = box(0.25, 0.25);
    // The bullet's right face starts at x = -4.75 and moves 10 m; the wall's left face is at -0.1.
    const output = timeOfImpact(wall, sweep(0, 0, 0, 0, 0, 0), bullet, sweep(-5.0, 0.0, 0.0, 5.0, 0.0, 0.0));
    expect(output.state).toBe(b2TOIOutput.e_touching);
    expect(output.t).toBeGreaterThan(0.0);
    expect(output.t).toBeLessThan(1.0);

    // Both proxies have the polygon radius, so the target separation is max(slop, 2 r - 3 slop).
    const target = Math.max(b2_linearSlop, 2.0 * 0.01 - 3.0 * b2_linearSlop);
    const gap = 4.65 - 10.0 * output.t;
    expect(Math.abs(gap - target)).toBeLessThan(0.25 * b2_linearSlop);
  });

  it('reports e_separated with t = tMax when the shapes never come close', () => {
    const output = timeOfImpact(box(1, 1), sweep(0, 0, 0, 0, 0, 0), box(1, 1), sweep(-5.0, 3.0, 0.0, 5.0, 3.0, 0.0));
    expect(output.state).toBe(b2TOIOutput.e_separated);
    expect(output.t).toBe(1.0);
  });

  it('reports e_overlapped with t = 0 when the shapes start overlapped', () => {
    const output = timeOfImpact(box(1, 1), sweep(0, 0, 0, 0, 0, 0), box(1, 1), sweep(0.5, 0.5, 0.0, 5.0, 0.5, 0.0));
    expect(output.state).toBe(b2TOIOutput.e_overlapped);
    expect(output.t).toBe(0.0);
  });

  it('leaves the input sweeps as given (it normalises copies)', () => {
    const input = new b2TOIInput();
    input.proxyA.Set(box(0.5, 0.5), 0);
    input.proxyB.Set(box(0.5, 0.5), 0);
    input.sweepA.Assign(sweep(0, 0, 20.0, 0, 0, 21.0));
    input.sweepB.Assign(sweep(-4, 0, -13.0, 4, 0, -12.5));
    input.tMax = 1.0;
    const output = new b2TOIOutput();
    b2TimeOfImpact(output, input);
    expect(output.state).toBe(b2TOIOutput.e_touching);
    expect([input.sweepA.a0, input.sweepA.a, input.sweepB.a0, input.sweepB.a]).toEqual([20.0, 21.0, -13.0, -12.5]);
  });

  it('returns a time at which b2Distance finds the shapes within tolerance of the target', () => {
    const shapeA = box(0.5, 2.0);
    const shapeB = box(0.3, 0.3);
    const sweepA = sweep(0, 0, 0.1, 0.2, 0, 0.3);
    const sweepB = sweep(-6, 1, 0.0, 6, -1, 2.5);
    const output = timeOfImpact(shapeA, sweepA, shapeB, sweepB);
    expect(output.state).toBe(b2TOIOutput.e_touching);

    const input = new b2DistanceInput();
    input.proxyA.Set(shapeA, 0);
    input.proxyB.Set(shapeB, 0);
    sweepA.GetTransform(input.transformA, output.t);
    sweepB.GetTransform(input.transformB, output.t);
    const distance = new b2DistanceOutput();
    b2Distance(distance, new b2SimplexCache(), input);
    expect(Math.abs(distance.distance - b2_linearSlop)).toBeLessThan(0.25 * b2_linearSlop);
  });

  it('counts calls and outer iterations', () => {
    b2ResetToiCounters();
    expect([b2_toiCalls, b2_toiIters, b2_toiMaxIters]).toEqual([0, 0, 0]);
    timeOfImpact(box(0.1, 5.0), sweep(0, 0, 0, 0, 0, 0), box(0.25, 0.25), sweep(-5.0, 0.0, 0.0, 5.0, 0.0, 0.0));
    timeOfImpact(box(1, 1), sweep(0, 0, 0, 0, 0, 0), box(1, 1), sweep(0.5, 0.5, 0.0, 5.0, 0.5, 0.0));
    expect(b2_toiCalls).toBe(2);
    // The overlapped call ends in its first iteration before counting it.
    expect(b2_toiIters).toBeGreaterThan(0);
    expect(b2_toiMaxIters).toBe(b2_toiIters);
  });
});
