// Step times in separate processes (bench/processes.mjs): the option checks and a quick run. No
// timing assertions: speed is what the benchmark measures.
import path from 'node:path';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { buildBundles } from '../support/bundles';
import { formatProcesses, main, parseWindows, resolveProcessesOptions, runProcesses } from '../../bench/processes.mjs';

let bundles: { dir: string; remove(): void };
let oursBundle = '';

beforeAll(() => {
  bundles = buildBundles();
  oursBundle = path.join(bundles.dir, 'webphysics.mjs');
});

afterAll(() => {
  bundles.remove();
});

describe('bench/processes.mjs options', () => {
  it('reads step windows as [from, to) pairs within the steps, and rejects others by name', () => {
    expect(parseWindows('64-192,192-600', 600)).toEqual([
      [64, 192],
      [192, 600],
    ]);
    expect(() => parseWindows('64:192', 600)).toThrow('window "64:192" is not FROM-TO');
    expect(() => parseWindows('100-50', 600)).toThrow('window 100-50 must satisfy FROM < TO <= steps (600)');
    expect(() => parseWindows('0-601', 600)).toThrow('window 0-601 must satisfy FROM < TO <= steps (600)');
  });

  it('defaults to bench2d, WebPhysics against box2d-wasm, ten runs of 600 steps', () => {
    const o = resolveProcessesOptions({ log: null });
    expect([o.scene, o.engines, o.runs, o.steps, o.windows]).toEqual([
      'bench2d',
      ['webphysics', 'box2d-wasm'],
      10,
      600,
      [
        [64, 192],
        [192, 600],
      ],
    ]);
  });

  it('rejects an unknown scene or engine, a baseline without its bundle, and counts below one', () => {
    expect(() => resolveProcessesOptions({ scene: 'nope' })).toThrow('unknown scene "nope"');
    expect(() => resolveProcessesOptions({ engines: 'webphysics,nope' })).toThrow('unknown engine "nope"');
    expect(() => resolveProcessesOptions({ engines: 'webphysics-baseline' })).toThrow('webphysics-baseline needs --baseline FILE');
    expect(() => resolveProcessesOptions({ runs: 0 })).toThrow('runs must be a positive integer, not "0"');
  });
});

describe('bench/processes.mjs command line', () => {
  it('exits 0 for --help and 2, before running anything, for an unknown option or a bad value', async () => {
    const out = vi.spyOn(process.stdout, 'write').mockImplementation(() => true);
    const err = vi.spyOn(process.stderr, 'write').mockImplementation(() => true);
    try {
      expect(await main(['--help'])).toBe(0);
      expect(await main(['--bogus'])).toBe(2);
      expect(await main(['--runs', '0'])).toBe(2);
      expect(await main(['--engines', 'webphysics-baseline'])).toBe(2);
      expect(String(err.mock.calls.at(-1)?.[0])).toContain('webphysics-baseline needs --baseline FILE');
    } finally {
      out.mockRestore();
      err.mockRestore();
    }
  });
});

describe('bench/processes.mjs quick run', () => {
  it('gives every engine one median per window over its runs, each run from a process of its own', async () => {
    const result = await runProcesses({ quick: true, engines: 'webphysics,planck', ours: oursBundle, log: null });
    expect(result.engines.map((e) => e.id)).toEqual(['webphysics', 'planck']);
    for (const e of result.engines) {
      expect(e.runsMs).toHaveLength(2);
      for (const run of e.runsMs) expect(run).toHaveLength(2);
      expect(e.windowMs).toHaveLength(2);
      for (const ms of e.windowMs) expect(ms).toBeGreaterThan(0);
    }
    const table = formatProcesses(result);
    expect(table).toContain('steps 4-20');
    expect(table).toContain('1.00x');
  }, 120_000);
});
