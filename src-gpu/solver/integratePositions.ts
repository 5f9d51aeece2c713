/*
 * Integrate positions (in GpuStage.Velocity) and synchronize (GpuStage.Position) (shaders/solver/integratePositions.wgsl): positions from
 * the solved velocities with 2.2.1's b2_maxTranslation / b2_maxRotation clamps, and after the
 * position iterations the body transforms (b2Body::SynchronizeTransform) and cells.
 *
 * In:  the solver's parameters (h, cellSize), solverState[SV.SKIP], the mirror's bodyFlags,
 *      bodyAwake, bodyMass, bodySweep, bodyVel, bodyXf, bodyCell.
 * Out: `encodeIntegrate`: bodySweep c, a and clamped bodyVel of awake non-static bodies (sleeping
 *      bodies neither move nor synchronize).
 *      `encodeSynchronize`: bodyXf, and bodyCell (with bodySweep shifted to match) for a body whose
 *      offset left half a cell, as GpuWorld would place it.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { WORKGROUP_SIZE } from '../device/layout';
import type { GpuWorld } from '../world/world';

export class IntegratePositionsStage {
  private readonly integrate: Kernel;
  private readonly synchronize: Kernel;

  constructor(ctx: GpuContext) {
    this.integrate = new Kernel(ctx, 'integratePositions', 'main');
    this.synchronize = new Kernel(ctx, 'integratePositions', 'synchronize');
  }

  encodeIntegrate(rec: Recorder, params: GPUBuffer, solverState: GPUBuffer, mirror: GpuWorld): void {
    const group = this.integrate.bind({
      0: params,
      1: solverState,
      2: mirror.bodyFlags.buffer,
      4: mirror.bodySweep.buffer,
      5: mirror.bodyVel.buffer,
      8: mirror.bodyAwake.buffer,
    });
    rec.dispatch(this.integrate, group, Math.ceil(mirror.bodySlotCount / WORKGROUP_SIZE));
  }

  encodeSynchronize(rec: Recorder, params: GPUBuffer, solverState: GPUBuffer, mirror: GpuWorld): void {
    const group = this.synchronize.bind({
      0: params,
      1: solverState,
      2: mirror.bodyFlags.buffer,
      3: mirror.bodyMass.buffer,
      4: mirror.bodySweep.buffer,
      6: mirror.bodyXf.buffer,
      7: mirror.bodyCell.buffer,
      8: mirror.bodyAwake.buffer,
    });
    rec.dispatch(this.synchronize, group, Math.ceil(mirror.bodySlotCount / WORKGROUP_SIZE));
  }
}
