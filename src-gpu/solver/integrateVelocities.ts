/*
 * GpuStage.IntegrateVelocities (shaders/solver/integrateVelocities.wgsl): b2Island::Solve's first
 * loop for every body slot.
 *
 * In:  the solver's parameters (h, gravity), solverState[SV.SKIP], the mirror's bodyFlags,
 *      bodyAwake (this step's, after the island search), bodyForce, bodyMass, bodyParams,
 *      bodySweep, bodyVel.
 * Out: bodySweep c0 = c, a0 = a (awake non-static bodies); bodyVel of awake dynamic bodies with
 *      gravity x gravity scale, forces and damping applied. Sleeping bodies are left alone.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { WORKGROUP_SIZE } from '../device/layout';
import type { GpuWorld } from '../world/world';

export class IntegrateVelocitiesStage {
  private readonly kernel: Kernel;

  constructor(ctx: GpuContext) {
    this.kernel = new Kernel(ctx, 'integrateVelocities', 'main');
  }

  encode(rec: Recorder, params: GPUBuffer, solverState: GPUBuffer, mirror: GpuWorld): void {
    const group = this.kernel.bind({
      0: params,
      1: solverState,
      2: mirror.bodyFlags.buffer,
      3: mirror.bodyForce.buffer,
      4: mirror.bodyMass.buffer,
      5: mirror.bodyParams.buffer,
      6: mirror.bodySweep.buffer,
      7: mirror.bodyVel.buffer,
      8: mirror.bodyAwake.buffer,
    });
    rec.dispatch(this.kernel, group, Math.ceil(mirror.bodySlotCount / WORKGROUP_SIZE));
  }
}
