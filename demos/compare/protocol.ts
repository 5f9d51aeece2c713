/*
 * Messages between the comparison page and a pane's worker. The page starts one worker per pane
 * and build (a rebuild terminates the old worker, which also stops a step still running there),
 * sends 'build', then one 'step' at a time, handing the transform buffers back with each request
 * so that they travel between the threads without copies.
 */

import type { GpuAdapterSummary } from '../../src-gpu/device/device';
import type { PaneStats, SceneConfig, SceneGeometry } from './config';

export type PaneBackend = 'js' | 'webgpu';

export type ToWorker = { type: 'build'; backend: PaneBackend; config: SceneConfig } | { type: 'step'; transforms: Float32Array; awake: Uint8Array };

export type FromWorker =
  | { type: 'built'; geometry: SceneGeometry; stats: PaneStats; adapter: GpuAdapterSummary | null; buildMs: number }
  | { type: 'stepped'; stats: PaneStats; transforms: Float32Array; awake: Uint8Array }
  | { type: 'error'; message: string };
