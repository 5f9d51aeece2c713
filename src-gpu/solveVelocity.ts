/*
 * Solver stage 6, velocity iterations (shaders/solveVelocity.wgsl): b2ContactSolver::
 * SolveVelocityConstraints, per iteration one pass per colour (the overflow set last, in one
 * invocation): friction, then the normal impulses (the two-point block solver included).
 *
 * In:  the colour lists (colour.ts), contactBodies, constraints, bodyVel.
 * Out: bodyVel of the dynamic bodies; the accumulated impulses in constraints.
 */

import type { GpuContext } from './device';
import { Kernel } from './kernel';
import type { Recorder } from './kernel';
import { COLOUR_CAP, SV_ARGS } from './layout';
import type { ColourPassInputs } from './warmStart';

export class SolveVelocityStage {
  private readonly kernel: Kernel;

  constructor(ctx: GpuContext) {
    this.kernel = new Kernel(ctx, 'solveVelocity', 'main');
  }

  /** `joints` records the joints' iteration, which runs before the contacts' (b2Island::Solve). */
  encode(rec: Recorder, io: ColourPassInputs, bodyVel: GPUBuffer, iterations: number, joints: (rec: Recorder) => void): void {
    for (let it = 0; it < iterations; ++it) {
      joints(rec);
      for (let c = 0; c <= COLOUR_CAP; ++c) {
        const group = this.kernel.bind({ 0: io.colours[c].buffer, 1: io.solverState, 2: io.colourKeys, 3: io.contactBodies, 4: io.constraints, 5: bodyVel });
        rec.dispatchIndirect(this.kernel, group, io.solverIndirect, (SV_ARGS.COLOURS + 3 * c) * 4);
      }
    }
  }
}
