/*
 * bench/features.mjs: every scene is stepped under Box2D's defaults and with continuous physics or
 * sleeping turned off, and the table says what each costs; the times themselves are the
 * benchmark's, not the test's.
 */

import { describe, expect, it } from 'vitest';
import * as b2 from '../../src/index';
import { FEATURE_CONFIGS, featuresMarkdown, measureFeatures } from '../../bench/features.mjs';

describe('the features benchmark', () => {
  it('steps each scene under every configuration, and with sleeping the bodies of a settled pile fall asleep', async () => {
    const run = await measureFeatures(b2, { scenes: ['many-pyramids'], quick: true, steps: 5, settle: 120 });
    expect(run.rows).toHaveLength(1);
    const [row] = run.rows;
    expect(row.configs.map((c) => c.id)).toEqual(FEATURE_CONFIGS.map((c) => c.id));
    for (const c of row.configs) {
      expect(c.ms).toBeGreaterThan(0);
      expect(c.bodies).toBe(row.bodies);
    }
    const byId = Object.fromEntries(row.configs.map((c) => [c.id, c]));
    // Two seconds of resting pyramids: asleep with sleeping on, every dynamic body awake without it.
    expect(byId.defaults.awake).toBeLessThan(row.bodies / 10);
    expect(byId['no-sleep'].awake).toBe(row.bodies - 1);
    expect(featuresMarkdown(run)).toMatch(/\| many pyramids \| 221 \| [0-9.]+ ms, \d+ awake \| [0-9.]+ ms \([0-9.]+x\), \d+ awake \|/);
  });
});
