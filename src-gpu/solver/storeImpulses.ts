/*
 * Store impulses (in GpuStage.Velocity) (shaders/solver/storeImpulses.wgsl): b2ContactSolver::StoreImpulses.
 *
 * In:  solverState[SV.COUNT], contactBodies (contact index, points used), constraints (impulses).
 * Out: word 3 of each solver contact's manifold (normal and tangent impulses of its points), which
 *      the next step's persist pass carries to the matching points.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { SV_ARGS } from '../device/layout';

export class StoreImpulsesStage {
  private readonly kernel: Kernel;

  constructor(ctx: GpuContext) {
    this.kernel = new Kernel(ctx, 'storeImpulses', 'main');
  }

  encode(rec: Recorder, solverState: GPUBuffer, solverIndirect: GPUBuffer, contactBodies: GPUBuffer, constraints: GPUBuffer, manifolds: GPUBuffer): void {
    const group = this.kernel.bind({ 0: solverState, 1: contactBodies, 2: constraints, 3: manifolds });
    rec.dispatchIndirect(this.kernel, group, solverIndirect, SV_ARGS.CONTACTS * 4);
  }
}
