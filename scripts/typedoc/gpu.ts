/**
 * The WebGPU backend behind b2World's API (`import { WebGPUBackend } from 'webphysics/gpu'`):
 * `await world.SetBackend(await WebGPUBackend.create())` steps the world on the GPU.
 *
 * @module webphysics/gpu
 */

// The reference of the package entry `webphysics/gpu` (src-gpu/index.ts), read by TypeDoc (npm run docs).
export * from '../../src-gpu/index';
