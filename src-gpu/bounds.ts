/*
 * Stage 1, bounds (shaders/bounds.wgsl): the fattened AABB of every proxy slot of a GpuWorld.
 *
 * In:  the world's proxyRef, fixtureShape, shapePool, bodyXf and bodyCell tables.
 * Out: proxyAABB[slot] (vec4<f32>, relative to the world origin cell): b2Shape::ComputeAABB of the
 *      proxy's child at the body's current transform, extended by `extension` (b2_aabbExtension,
 *      0.1 m, by default) on each side; dead slots get an AABB that overlaps nothing.
 * Unlike b2DynamicTree's fat AABBs, these are recomputed from scratch each step: no history, no
 * displacement prediction, so the pair set is a function of the current positions alone.
 */

import type { GpuContext } from './device';
import { Kernel, Uniform } from './kernel';
import type { Recorder } from './kernel';
import { WORKGROUP_SIZE } from './layout';
import type { GpuWorld } from './world';

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
    });
    rec.dispatch(this.kernel, group, Math.ceil(count / WORKGROUP_SIZE));
  }
}
