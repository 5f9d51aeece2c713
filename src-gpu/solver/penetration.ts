/*
 * GpuStage.Penetration (shaders/solver/penetration.wgsl): the step's deepest penetration, for the
 * accuracy target (src/dynamics/b2AccuracyTarget.ts): over the touching non-sensor contacts'
 * manifold points, the largest -s, s the separation as b2PositionSolverManifold computes it, at
 * the transforms after the step. A dispatch of its own after the last stage that moves a body
 * (the position iterations' separations are taken before their corrections and before the
 * synchronisation and the time of impact: the WGSL header says more).
 *
 * In:  the solver's parameters (cellSize), solverState[SV.COUNT], solverIndirect (SV_ARGS.CONTACTS),
 *      contactBodies, constraints (radii), this step's manifolds, the mirror's bodyXf and bodyCell.
 * Out: solverState[SV.PENETRATION], the f32 bits of the depth (0: nothing touches), zeroed by the
 *      colouring's `begin` each step and read back with the step's counts (GpuPipeline).
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { SV_ARGS } from '../device/layout';
import type { GpuWorld } from '../world/world';
import type { PrepareInputs } from './prepareContacts';

export class PenetrationStage {
  private readonly kernel: Kernel;

  constructor(ctx: GpuContext) {
    this.kernel = new Kernel(ctx, 'penetration', 'main');
  }

  /** The solver contacts' buffers are the ones GpuStage.Prepare wrote (`io`). */
  encode(rec: Recorder, io: PrepareInputs, mirror: GpuWorld): void {
    const group = this.kernel.bind({
      0: io.params,
      1: io.solverState,
      2: io.contactBodies,
      3: io.constraints,
      4: io.manifolds,
      5: mirror.bodyXf.buffer,
      6: mirror.bodyCell.buffer,
    });
    rec.dispatchIndirect(this.kernel, group, io.solverIndirect, SV_ARGS.CONTACTS * 4);
  }
}
