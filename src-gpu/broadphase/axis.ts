/*
 * Broad phase, axis (shaders/broadphase/axis.wgsl): the layout of the sweep, chosen on the GPU by a two-level
 * reduction (nothing is read back): the sweep axis, the one along which the live AABB centres vary
 * most, and the strips across the other axis that keep each proxy's candidates local.
 *
 * In:  proxyAABB[0, slotCount).
 * Out: state[STATE.AXIS], STRIPS, OTHER_LO, OTHER_INV_H, AXIS_LO, AXIS_SCALE.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Kernel, Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { AXIS_ITEMS_PER_GROUP } from '../device/layout';

export class AxisStage {
  private readonly partial: Kernel;
  private readonly finish: Kernel;
  private readonly params: Uniform;
  private readonly partials: GpuArray;

  constructor(ctx: GpuContext) {
    this.partial = new Kernel(ctx, 'axis', 'partial');
    this.finish = new Kernel(ctx, 'axis', 'finish');
    this.params = new Uniform(ctx, 'axis params', 4);
    this.partials = new GpuArray(ctx, 'axis partials', 48, 64);
  }

  encode(rec: Recorder, proxyAABB: GPUBuffer, slotCount: number, state: GPUBuffer): void {
    const groups = Math.max(1, Math.ceil(slotCount / AXIS_ITEMS_PER_GROUP));
    this.partials.ensure(groups);
    this.params.u32[0] = slotCount;
    this.params.u32[1] = groups;
    this.params.upload();
    rec.dispatch(this.partial, this.partial.bind({ 0: this.params.buffer, 1: proxyAABB, 2: this.partials.buffer }), groups);
    rec.dispatch(this.finish, this.finish.bind({ 0: this.params.buffer, 2: this.partials.buffer, 3: state }), 1);
  }
}
