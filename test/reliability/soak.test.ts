import { describe, expect, it } from 'vitest';
import { runSoak } from '../../scripts/reliability/soak';

/*
 * The short soak: the same run as `npm run soak` (scripts/reliability/soak.ts, which states the
 * bounds it checks), for 2,000 steps: 1,000 in the rain box and 1,000 over four golden scenes.
 * The heap is not measured here (that needs node --expose-gc: see leak.test.ts and npm run soak).
 */
describe('soak (short)', () => {
  it('2,000 steps of spawning and destroying keep every invariant, the energy bounds and the growth bounds', () => {
    const report = runSoak({ steps: 2000, seed: 7, scenes: ['mixed-rain', 'bridge', 'tumbler', 'bullet-test'] });
    expect(report.failures).toEqual([]);
    expect(report.steps).toBe(2000);
    const rain = report.segments.find((s) => s.name === 'rain-box')!;
    expect(rain.spawned).toBeGreaterThan(200);
    expect(rain.destroyed).toBeGreaterThan(100);
    expect(rain.peakEnergyRatio).toBeLessThanOrEqual(1);
    expect(report.segments.map((s) => s.name)).toEqual(['rain-box', 'mixed-rain', 'bridge', 'tumbler', 'bullet-test']);
  });
});
