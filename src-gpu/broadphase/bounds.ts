/*
 * Broad phase, bounds (shaders/broadphase/bounds.wgsl): the fattened, swept AABB of every proxy slot of a GpuWorld.
 *
 * In:  the world's proxyRef, fixtureShape, shapePool, bodyXf, bodyCell, bodySweep and bodyVel
 *      tables, and its b2World's m_inv_dt0 (the last step's 1 / dt).
 * Out: proxyAABB[slot] (vec4<f32>, relative to the world origin cell): the union of
 *      b2Shape::ComputeAABB of the proxy's child at the start of the body's sweep and at its
 *      transform (b2Fixture::Synchronize's swept AABB), extended by `extension`
 *      (b2_aabbExtension, 0.1 m, by default) on each side, then by b2_aabbMultiplier x the sweep's
 *      displacement (b2DynamicTree::MoveProxy's prediction) and b2_aabbMultiplier x dt x v (the
 *      coming step's motion, dt the last step's) in their directions; dead slots get an AABB that
 *      overlaps nothing.
 * Why the prediction: 2.2.1 finds the contacts its TOI tests after the solve, from the swept AABBs
 * of the motion itself; the GPU step runs its broad phase once, before the solve, so the pairs of
 * a fast body's path must be predicted (continuous collision, src-gpu/solver/timeOfImpact.ts). A body's
 * first step in a world never stepped (m_inv_dt0 = 0), and a body whose velocity changes by more
 * than the prediction within a step, can miss a pair there.
 * Unlike b2DynamicTree's fat AABBs, these are recomputed from scratch each step: no hysteresis, so
 * the pair set is a function of the current sweeps and velocities alone. A sleeping body's proxies
 * are recomputed too and come out the same (its sweep stays, its velocity is zero): skipping them
 * would bind the awake flags, a ninth storage buffer, in a pass that costs little next to the
 * sorts and the sweep after it (docs/GPU.md, "The step").
 */

import type { GpuContext } from '../device/device';
import { Kernel, Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { WORKGROUP_SIZE } from '../device/layout';
import type { GpuWorld } from '../world/world';

/** b2_aabbExtension (b2Settings.h). */
export const AABB_EXTENSION = 0.1;

export class BoundsStage {
  private readonly kernel: Kernel;
  private readonly params: Uniform;

  constructor(ctx: GpuContext) {
    this.kernel = new Kernel(ctx, 'bounds', 'main');
    this.params = new Uniform(ctx, 'bounds params', 8);
  }

  encode(rec: Recorder, world: GpuWorld, proxyAABB: GPUBuffer, extension = AABB_EXTENSION): void {
    const count = world.proxySlotCount;
    const p = this.params;
    p.u32[0] = count;
    p.f32[1] = extension;
    p.f32[2] = world.cellSize;
    const invDt0 = world.world.m_inv_dt0;
    p.f32[3] = invDt0 > 0 ? 1 / invDt0 : 0;
    p.i32[4] = world.originCell[0];
    p.i32[5] = world.originCell[1];
    p.upload();
    const group = this.kernel.bind({
      0: p.buffer,
      1: world.proxyRef.buffer,
      2: world.fixtureShape.buffer,
      3: world.shapePool.buffer,
      4: world.bodyXf.buffer,
      5: world.bodyCell.buffer,
      6: proxyAABB,
      7: world.bodySweep.buffer,
      8: world.bodyVel.buffer,
    });
    rec.dispatch(this.kernel, group, Math.ceil(count / WORKGROUP_SIZE));
  }
}
