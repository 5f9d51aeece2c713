/*
 * GpuStage.Position, the position iterations (shaders/solver/solvePosition.wgsl): per iteration one pass per
 * colour for the host's first `passColours` colours (GpuSolver.passColours: the leading colours of
 * at least TAIL_COLOUR_ITEMS items), each solving its contacts
 * (b2ContactSolver::SolvePositionConstraints) and its joints (b2*Joint::SolvePositionConstraints)
 * in parallel, then one tail pass of one workgroup that walks the colours left, with barriers,
 * and the overflow set (one invocation: its contacts, then its joints, as 2.2.1 orders an
 * island's), then `check`: 2.2.1's early exit (minimum separation >= -3 b2_linearSlop and every
 * joint within its slop) zeroes the position passes' indirect sizes, the tail's included, so
 * later iterations dispatch no workgroups. For a small world every iteration and the exit in one
 * dispatch of one workgroup (encodeFused). No read-back.
 *
 * In:  the colour lists (colour.ts; SV_ARGS.POSITION sizes), contactBodies, constraints,
 *      jointBodies, jointParams, jointConstraints, bodySweep (after integratePositions.ts).
 * Out: bodySweep c, a of the dynamic bodies; SV.POSITION_ITERATIONS (iterations that ran),
 *      SV.POSITION_DONE.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { BindingEntry, Recorder } from '../device/kernel';
import { COLOUR_CAP, SV_ARGS } from '../device/layout';
import type { ColourPassInputs } from './warmStart';

export class SolvePositionStage {
  private readonly kernel: Kernel;
  /** Per colour with a pass of its own: this step's bind group. */
  private readonly groups: GPUBindGroup[] = [];
  private readonly tail: Kernel;
  private readonly check: Kernel;
  private readonly fused: Kernel;

  constructor(ctx: GpuContext) {
    this.kernel = new Kernel(ctx, 'solvePosition', 'main');
    this.tail = new Kernel(ctx, 'solvePosition', 'tail');
    this.check = new Kernel(ctx, 'solvePosition', 'check');
    this.fused = new Kernel(ctx, 'solvePosition', 'fused');
  }

  /** Every iteration (SolverParams.positionIterations) and its early exit in one dispatch of one workgroup (a small world). */
  encodeFused(rec: Recorder, io: ColourPassInputs, bodySweep: GPUBuffer): void {
    rec.dispatch(this.fused, this.fused.bind({ 9: io.params, ...this.entries(io, bodySweep) }), 1);
  }

  /** The buffers every entry point binds (`main` adds its colour's uniform, `tail` its first colour's, `fused` the iteration count). */
  private entries(io: ColourPassInputs, bodySweep: GPUBuffer): Record<number, BindingEntry> {
    return {
      1: io.solverState,
      2: io.colourKeys,
      3: io.contactBodies,
      4: io.constraints,
      5: bodySweep,
      10: io.jointBodies,
      11: io.jointParams,
      12: io.jointConstraints,
    };
  }

  /** Per iteration a pass per colour below `passColours`, the tail pass and `check`: passColours + 2 dispatches. */
  encode(rec: Recorder, io: ColourPassInputs, bodySweep: GPUBuffer, iterations: number, passColours: number): void {
    const check = this.check.bind({ 1: io.solverState, 6: io.solverIndirect });
    // The bind groups once, for every iteration.
    const shared = this.entries(io, bodySweep);
    for (let c = 0; c < passColours; ++c) {
      this.groups[c] = this.kernel.bind({ 0: io.colours[c].buffer, ...shared });
    }
    const tail = this.tail.bind({ 0: io.colours[passColours].buffer, ...shared });
    for (let it = 0; it < iterations; ++it) {
      for (let c = 0; c < passColours; ++c) {
        rec.dispatchIndirect(this.kernel, this.groups[c], io.solverIndirect, (SV_ARGS.POSITION + 3 * c) * 4);
      }
      rec.dispatchIndirect(this.tail, tail, io.solverIndirect, (SV_ARGS.POSITION + 3 * COLOUR_CAP) * 4);
      rec.dispatch(this.check, check, 1);
    }
  }
}
