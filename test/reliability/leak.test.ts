import { spawnSync } from 'node:child_process';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import type { LeakReport } from '../../scripts/reliability/leak';

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/*
 * The leak checks need a full GC between measurements, so they run in a child `node --expose-gc`
 * (scripts/reliability/run.mjs leak; scripts/reliability/leak.ts says what they check).
 */
describe('memory: 10,000 create/destroy cycles of worlds, bodies, fixtures and joints', () => {
  const child = spawnSync(process.execPath, ['--expose-gc', 'scripts/reliability/run.mjs', 'leak', '--json'], {
    cwd: repoRoot,
    encoding: 'utf8',
    timeout: 300_000,
  });
  const report = (child.status === null ? null : JSON.parse(child.stdout.trim().split('\n').pop() ?? 'null')) as LeakReport | null;

  it('runs to the end', () => {
    expect(child.error, child.stderr).toBeUndefined();
    expect(report, child.stderr).not.toBeNull();
  });

  for (const name of ['worlds', 'bodies', 'churn', 'fixtures', 'joints']) {
    it(`${name}: destroyed objects are collected, the heap returns to its level after warm-up, pools stay bounded`, () => {
      const scenario = report?.scenarios.find((s) => s.name === name);
      expect(scenario).toBeDefined();
      expect(scenario!.cycles).toBe(10_000);
      expect(scenario!.collected).toBe(scenario!.sampled);
      expect(scenario!.sampled).toBeGreaterThan(0);
      expect(scenario!.growthKB).toBeLessThan(2048);
      expect(report!.failures.filter((f) => f.startsWith(`${name}:`))).toEqual([]);
    });
  }
});
