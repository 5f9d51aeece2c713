/*
 * The GPU tests' device: one per test file, from requestGpu() (navigator.gpu, Dawn, or Dawn on
 * SwiftShader). When no adapter can be found the GPU tests are skipped, loudly, with the reason;
 * under CI (CI=true), where `npm run setup` installs SwiftShader, a missing adapter fails instead.
 */

import { describe } from 'vitest';
import { GpuUnavailableError, requestGpu } from '../../src-gpu/device/device';
import type { GpuContext } from '../../src-gpu/device/device';

let context: GpuContext | null = null;
let reason = '';
try {
  context = await requestGpu();
} catch (err) {
  if (!(err instanceof GpuUnavailableError)) throw err;
  reason = err.message;
}

if (context === null) {
  const banner = `\n${'!'.repeat(78)}\n!! WebGPU tests SKIPPED: no adapter. ${reason}\n${'!'.repeat(78)}\n`;
  if (process.env.CI) throw new Error(`No WebGPU adapter under CI (npm run setup should provide SwiftShader): ${reason}`);
  console.warn(banner);
}

/** The test device, or null when the GPU tests are skipped. */
export const gpu: GpuContext | null = context;

/** describe() when a device exists, else a skipped describe whose name says why. */
export function describeGpu(name: string, fn: (ctx: GpuContext) => void): void {
  if (context) {
    const ctx = context;
    describe(name, () => fn(ctx));
  } else {
    describe.skip(`${name} (SKIPPED: no WebGPU adapter: ${reason})`, () => {});
  }
}

/** A seeded generator (mulberry32) for reproducible random scenes. */
export function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
