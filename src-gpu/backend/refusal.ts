/*
 * What the GPU cannot step: callbacks that must run inside the step on the host. One rule for
 * WebGPUBackend (which refuses the world) and AutoBackend (which keeps it on JavaScript).
 */

import type { b2World } from '../../src/dynamics/b2World';
import type { b2WorldBackendEngine } from '../../src/dynamics/b2WorldBackend';

export interface GpuRefusal {
  /** What the world has, in a few words (AutoBackend's reason). */
  readonly summary: string;
  /** Why the GPU cannot run it and what to do instead (WebGPUBackend's error). */
  readonly message: string;
}

/** Why the GPU cannot step `world` as it is now, or null when it can. */
export function gpuRefusal(world: b2World, engine: b2WorldBackendEngine): GpuRefusal | null {
  const cm = world.m_contactManager;
  if (engine.listenerOverrides(cm.m_contactListener, 'PreSolve')) {
    return {
      summary: 'the contact listener has PreSolve, which the GPU cannot run',
      message:
        'WebGPUBackend: the contact listener has PreSolve, which must run inside the solver (between collision and the velocity ' +
        'solve, where it may disable a contact or change its manifold); the GPU solves the whole step without calling back into ' +
        'JavaScript. Remove PreSolve (BeginContact, EndContact and PostSolve are delivered after the step), or step this world ' +
        'on the JavaScript engine (world.SetBackend(null)).',
    };
  }
  if (engine.listenerOverrides(cm.m_contactFilter, 'ShouldCollide')) {
    return {
      summary: 'the world has a custom contact filter (ShouldCollide), which the GPU cannot run',
      message:
        "WebGPUBackend: the world has a custom b2ContactFilter (ShouldCollide); the GPU's broad phase applies the default rules " +
        '(category bits, mask bits, group index) and cannot call JavaScript per pair. Express the filter with b2Filter data on ' +
        'the fixtures, or step this world on the JavaScript engine (world.SetBackend(null)).',
    };
  }
  return null;
}
