/*
 * webphysics/gpu: the WebGPU backend (devices, the world mirrored on the GPU, a sweep-and-prune
 * broad phase, the narrow phase, the graph-coloured solver, GpuStepper, and WebGPUBackend behind
 * b2World's API). The engine never imports this module; it reads the engine's world through its
 * public fields and its b2ChangeListener.
 *
 *   const gpu = await requestGpu({ onLost: (info) => console.warn('GPU lost', info) });
 *   const mirror = new GpuWorld(gpu, world);
 *   const broadPhase = new GpuBroadPhase(gpu);
 *   world.Step(1 / 60, 8, 3);     // the JavaScript engine steps the world
 *   mirror.sync();                // uploads what changed
 *   const { pairCount } = await broadPhase.update(mirror);
 *   const pairs = await broadPhase.readPairs();  // (proxy a, proxy b) slots; mirror.proxyAt(a)
 *
 * The world API on the GPU (docs/GPU.md, "The world API on the GPU"):
 *   await world.SetBackend(await WebGPUBackend.create());
 *   world.Step(1 / 60, 8, 3);           // submitted; world.StepAsync() also waits and reads back
 *   await world.Synchronize();          // positions, velocities (fetched as bodies are read), contact events
 *   await backend.readTransforms(out);  // or every body's transform in bulk, for a renderer
 *   await world.SetBackend(null);       // back to the JavaScript engine, contacts and impulses kept
 *
 * Stepping on the GPU (contacts, the ten joint types, sleeping, a time-of-impact pass):
 *   const stepper = new GpuStepper(gpu, world);
 *   await stepper.step(1 / 60, 8, 3);   // broad phase, narrow phase and solver, one submission
 *   await stepper.readBodies();         // motion and joint impulses back into the world's objects
 */

export {
  requestGpu,
  GpuContext,
  GpuUnavailableError,
  GpuDeviceLostError,
  GpuOutOfMemoryError,
  GpuCapacityError,
  GpuError,
} from './device/device';
export type { GpuContextOptions, GpuAdapterSummary, GpuLossInfo } from './device/device';
export { findSwiftShaderIcd, SWIFTSHADER_ICD_PATHS } from './device/node';
export type { DawnModule, IcdSearchEnv } from './device/node';
export { GpuWorld } from './world/world';
export type { GpuWorldOptions, SyncStats } from './world/world';
export { GpuBroadPhase } from './broadphase/broadPhase';
export type { GpuBroadPhaseOptions, BroadPhaseResult } from './broadphase/broadPhase';
export { GpuProxySet } from './broadphase/proxies';
export type { RawProxies } from './broadphase/proxies';
export { AABB_EXTENSION } from './broadphase/bounds';
export * as layout from './device/layout';
export { GpuNarrowPhase } from './narrowphase/narrowPhase';
export type { GpuNarrowPhaseOptions, NarrowPhaseResult, GpuContactRecord, GpuContactEvent } from './narrowphase/narrowPhase';
export { GpuSolver } from './solver/solver';
export type { SolverStep, SolverInputs, SolverState } from './solver/solver';
export { GpuPipeline, GpuStage, STAGE_PASS } from './pipeline';
export type { GpuPipelineStepOptions } from './pipeline';
export { GpuStepper } from './stepper';
export type { GpuStepperOptions, GpuStepOptions, GpuReadRange, GpuReadStats } from './stepper';
export { WebGPUBackend } from './backend/backend';
export type { WebGPUBackendOptions } from './backend/backend';
