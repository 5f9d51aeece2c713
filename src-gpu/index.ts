/*
 * webphysics/gpu: the WebGPU backend behind b2World's API. The engine never imports this module;
 * it reads the engine's world through its public fields and its b2ChangeListener.
 *
 * The documented path (docs/GPU.md, "The world API on the GPU"):
 *   const backend = await WebGPUBackend.create({ onLost: (info) => console.warn('GPU lost', info) });
 *   await world.SetBackend(backend);
 *   world.Step(1 / 60, 8, 3);           // submitted; world.StepAsync() also waits and reads back
 *   await world.Synchronize();          // positions, velocities (fetched as bodies are read), contact events
 *   await backend.readTransforms(out);  // or every body's transform in bulk, for a renderer
 *   await new GpuRenderer(backend, canvas.getContext('webgpu')).draw(); // or draw from the GPU's buffers, no read-back
 *   await world.SetBackend(null);       // back to the JavaScript engine, contacts and impulses kept
 *
 * Or let the world's size decide (JavaScript below the adapter's crossover, the GPU above it):
 *   await world.SetBackend(await AutoBackend.create());  // world.GetBackend().choice says which and why
 *
 * Advanced (marked @internal: for tools, benchmarks and tests; their API may change): the
 * pieces WebGPUBackend is built from. GpuWorld mirrors a world; GpuBroadPhase finds its pairs
 * (alone, or on a GpuProxySet); GpuPipeline records a step's stages (GpuStage) for the broad
 * phase, GpuNarrowPhase and GpuSolver into one submission; GpuStepper steps a world with them.
 */

// The documented path.
export { WebGPUBackend } from './backend/backend';
export type { WebGPUBackendOptions } from './backend/backend';
export { AutoBackend, AUTO_UP, AUTO_DOWN } from './backend/auto';
export type { AutoBackendOptions, AutoChoice } from './backend/auto';
export type { AutoCalibration } from './backend/calibration';
export { GpuRenderer } from './render/render';
export type { GpuCamera, GpuRendererOptions, GpuFrameStats } from './render/render';
export { GpuPointQuery } from './query/pointQuery';
export type { GpuPointHit } from './query/pointQuery';
export { requestGpu, GpuContext, GpuUnavailableError, GpuDeviceLostError, GpuOutOfMemoryError, GpuCapacityError, GpuError } from './device/device';
export type { GpuContextOptions, GpuAdapterSummary, GpuLossInfo } from './device/device';
export { findSwiftShaderIcd, SWIFTSHADER_ICD_PATHS } from './device/node';
export type { DawnModule, IcdSearchEnv } from './device/node';

// Advanced.
export { GpuWorld } from './world/world';
export type { GpuWorldOptions, SyncStats } from './world/world';
export { GpuBroadPhase } from './broadphase/broadPhase';
export type { GpuBroadPhaseOptions, BroadPhaseResult } from './broadphase/broadPhase';
export { GpuProxySet } from './broadphase/proxies';
export type { RawProxies } from './broadphase/proxies';
export { AABB_EXTENSION } from './broadphase/bounds';
export { GpuNarrowPhase } from './narrowphase/narrowPhase';
export type { GpuNarrowPhaseOptions, NarrowPhaseResult } from './narrowphase/narrowPhase';
export type { GpuContactRecord, GpuContactEvent } from './narrowphase/records';
export { GpuSolver } from './solver/solver';
export type { SolverStep, SolverInputs, SolverState } from './solver/solver';
export { GpuPipeline, GpuStage, STAGE_PASS } from './pipeline';
export type { GpuPipelineStepOptions } from './pipeline';
export { GpuStepper } from './stepper';
export type { GpuStepperOptions, GpuStepOptions, GpuReadRange, GpuReadStats } from './stepper';
