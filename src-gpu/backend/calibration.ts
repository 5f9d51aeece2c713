/*
 * AutoBackend's calibration: at what body count this adapter's GPU steps a world faster than the
 * JavaScript engine. Measured once per adapter (cached by its vendor, architecture, device and
 * description, for the page's or process's life) on the engine's pyramid load: a few steps of two
 * sizes on each side, a fixed plus a per-body cost fitted to each, and the body count where the
 * two lines cross. GPU steps are timed as StepAsync (step, wait, read back), which is what an
 * application pays when it reads the world every frame.
 */

import type { b2World } from '../../src/dynamics/b2World';
import type { b2WorldBackendEngine } from '../../src/dynamics/b2WorldBackend';
import type { GpuAdapterSummary, GpuContext } from '../device/device';
import { WebGPUBackend } from './backend';

/** Where the GPU starts to pay off on an adapter. */
export interface AutoCalibration {
  /** Bodies (b2World.GetBodyCount) above which the GPU steps faster; Infinity: never. */
  readonly crossoverBodies: number;
  /** Where the number comes from, in words (a measurement's fitted costs, or a test's stub). */
  readonly source: string;
}

/** The measured load: pyramids of this many rows, one copy and then ten side by side. */
const ROWS = 20;
const COPIES: readonly [number, number] = [1, 10];
/**
 * Untimed steps first (JIT, pipeline creation, first buffer growth): at least WARM_UP_STEPS and
 * WARM_UP_MS, since a page calibrates at first use, with the engine's code not yet optimised: a
 * few steps of a cold engine make its fitted fixed cost look higher than the GPU's, and the GPU
 * seem faster at any size. Then timed ones; the fastest counts.
 */
const WARM_UP_STEPS = 2;
const WARM_UP_MS = 100;
const TIMED_STEPS = 4;
const DT = 1 / 60;

const cache = new Map<string, Promise<AutoCalibration>>();

function adapterKey(info: GpuAdapterSummary): string {
  return [info.vendor, info.architecture, info.device, info.description].join('|');
}

/** This adapter's calibration, measured at its first request and shared by every later one. */
export function calibrationFor(ctx: GpuContext, engine: b2WorldBackendEngine): Promise<AutoCalibration> {
  const key = adapterKey(ctx.adapterInfo);
  let calibration = cache.get(key);
  if (calibration === undefined) {
    calibration = measureCalibration(ctx, engine);
    cache.set(key, calibration);
    // A failed measurement (a lost device) is not kept: the next device measures again.
    calibration.catch(() => cache.delete(key));
  }
  return calibration;
}

/** The fastest of TIMED_STEPS steps (ms) after the warm-up. */
async function fastestStep(step: () => Promise<void> | void): Promise<number> {
  const warmUpStart = performance.now();
  for (let i = 0; i < WARM_UP_STEPS || performance.now() - warmUpStart < WARM_UP_MS; ++i) await step();
  let fastest = Infinity;
  for (let i = 0; i < TIMED_STEPS; ++i) {
    const started = performance.now();
    await step();
    fastest = Math.min(fastest, performance.now() - started);
  }
  return fastest;
}

interface Line {
  fixedMs: number;
  perBodyMs: number;
}

function fit(bodies: readonly number[], ms: readonly number[]): Line {
  const perBodyMs = (ms[1] - ms[0]) / (bodies[1] - bodies[0]);
  return { fixedMs: ms[0] - perBodyMs * bodies[0], perBodyMs };
}

function costText(name: string, line: Line): string {
  return `${name} ${line.fixedMs.toFixed(2)} ms + ${(1000 * line.perBodyMs).toFixed(2)} µs a body`;
}

/**
 * Steps the pyramid load on the JavaScript engine and on the GPU (WebGPUBackend on `ctx`) and
 * returns the body count where their fitted costs cross. Not cached (calibrationFor is).
 */
async function measureCalibration(ctx: GpuContext, engine: b2WorldBackendEngine): Promise<AutoCalibration> {
  const bodies: number[] = [];
  const jsMs: number[] = [];
  const gpuMs: number[] = [];
  for (const copies of COPIES) {
    const onEngine: b2World = engine.createPyramidWorld(ROWS, copies);
    bodies.push(onEngine.GetBodyCount());
    jsMs.push(await fastestStep(() => onEngine.Step(DT, 8, 3)));
    const onGpu = engine.createPyramidWorld(ROWS, copies);
    const backend = await WebGPUBackend.create({ context: ctx });
    await onGpu.SetBackend(backend);
    try {
      gpuMs.push(await fastestStep(() => onGpu.StepAsync(DT, 8, 3)));
    } finally {
      await backend.destroy();
    }
  }
  const js = fit(bodies, jsMs);
  const gpu = fit(bodies, gpuMs);
  // Where fixed + per-body costs are equal; a GPU no cheaper per body never catches up.
  const crossover = js.perBodyMs > gpu.perBodyMs ? Math.max(1, Math.round((gpu.fixedMs - js.fixedMs) / (js.perBodyMs - gpu.perBodyMs))) : Infinity;
  return {
    crossoverBodies: crossover,
    source: `measured: ${costText('JavaScript', js)}, ${costText('WebGPU', gpu)} (${bodies.join(' and ')} bodies)`,
  };
}
