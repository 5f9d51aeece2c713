/*
 * GpuStage.Velocity, the velocity iterations (shaders/solver/solveVelocity.wgsl): per iteration one pass per
 * colour for the host's first `passColours` colours (GpuSolver.passColours: the leading colours of
 * at least TAIL_COLOUR_ITEMS items), each solving its joints (b2*Joint::SolveVelocityConstraints)
 * and its contacts (b2ContactSolver::SolveVelocityConstraints: friction, then the normal
 * impulses, the two-point block solver included) in parallel, then one tail pass of one workgroup
 * that walks the colours left, with barriers, and the overflow set (one invocation: its joints,
 * then its contacts). For a small world every iteration in one dispatch of one workgroup
 * (encodeFused), the same bits.
 *
 * In:  the colour lists (colour.ts), contactBodies, constraints, jointBodies, jointParams,
 *      jointConstraints, bodyVel.
 * Out: bodyVel of the dynamic bodies; the accumulated impulses in constraints and
 *      jointConstraints.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { BindingEntry, Recorder } from '../device/kernel';
import { COLOUR_CAP, SV_ARGS } from '../device/layout';
import type { ColourPassInputs } from './warmStart';

export class SolveVelocityStage {
  private readonly kernel: Kernel;
  /** Per colour with a pass of its own: this step's bind group. */
  private readonly groups: GPUBindGroup[] = [];
  private readonly tail: Kernel;
  private readonly fused: Kernel;

  constructor(ctx: GpuContext) {
    this.kernel = new Kernel(ctx, 'solveVelocity', 'main');
    this.tail = new Kernel(ctx, 'solveVelocity', 'tail');
    this.fused = new Kernel(ctx, 'solveVelocity', 'fused');
  }

  /** The buffers every entry point binds (`main` adds its colour's uniform at 0, `tail` its first colour's). */
  private entries(io: ColourPassInputs, bodyVel: GPUBuffer): Record<number, BindingEntry> {
    return {
      1: io.solverState,
      2: io.colourKeys,
      3: io.contactBodies,
      4: io.constraints,
      5: bodyVel,
      9: io.params,
      10: io.jointBodies,
      11: io.jointParams,
      12: io.jointConstraints,
    };
  }

  /** Every iteration (SolverParams.velocityIterations) in one dispatch of one workgroup (a small world). */
  encodeFused(rec: Recorder, io: ColourPassInputs, bodyVel: GPUBuffer): void {
    rec.dispatch(this.fused, this.fused.bind(this.entries(io, bodyVel)), 1);
  }

  /** Per iteration a pass per colour below `passColours`, then the tail pass: passColours + 1 dispatches. */
  encode(rec: Recorder, io: ColourPassInputs, bodyVel: GPUBuffer, iterations: number, passColours: number): void {
    // The bind groups once, for every iteration.
    const shared = this.entries(io, bodyVel);
    for (let c = 0; c < passColours; ++c) {
      this.groups[c] = this.kernel.bind({ 0: io.colours[c].buffer, ...shared });
    }
    const tail = this.tail.bind({ 0: io.colours[passColours].buffer, ...shared });
    for (let it = 0; it < iterations; ++it) {
      for (let c = 0; c < passColours; ++c) {
        rec.dispatchIndirect(this.kernel, this.groups[c], io.solverIndirect, (SV_ARGS.COLOURS + 3 * c) * 4);
      }
      rec.dispatchIndirect(this.tail, tail, io.solverIndirect, (SV_ARGS.COLOURS + 3 * COLOUR_CAP) * 4);
    }
  }
}
