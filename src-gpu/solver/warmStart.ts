/*
 * Warm start (in GpuStage.Velocity) (shaders/solver/warmStart.wgsl): b2ContactSolver::WarmStart and the joints'
 * warm start (b2*Joint::InitVelocityConstraints), one pass per colour over its joints and
 * contacts for the host's first `passColours` colours (GpuSolver.passColours: the leading colours
 * of at least TAIL_COLOUR_ITEMS items), then one tail pass of one workgroup that walks the colours
 * left, with barriers, and the overflow set (in one invocation); for a small world every colour in
 * one dispatch of one workgroup (encodeFused).
 *
 * In:  the colour lists (colour.ts: colourKeys, SV.COLOUR_START, SV_ARGS.COLOURS), contactBodies,
 *      constraints (impulses already scaled by dtRatio), jointBodies, jointConstraints
 *      (solveJoints.ts), bodyVel.
 * Out: bodyVel of the dynamic bodies.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { BindingEntry, Recorder, Uniform } from '../device/kernel';
import { COLOUR_CAP, SV_ARGS } from '../device/layout';

export interface ColourPassInputs {
  solverState: GPUBuffer;
  solverIndirect: GPUBuffer;
  colourKeys: GPUBuffer;
  contactBodies: GPUBuffer;
  constraints: GPUBuffer;
  /** The solver's parameters (SolverParams). */
  params: GPUBuffer;
  /** solveJoints.ts: per joint slot, bodies and flags, and the solver records. */
  jointBodies: GPUBuffer;
  jointConstraints: GPUBuffer;
  /** The mirror's jointParams (motor speeds, limits, forces as set this step). */
  jointParams: GPUBuffer;
  /** One uniform per colour (ColourParams), COLOUR_CAP + 1 of them (the last: a tail from the overflow set). */
  colours: Uniform[];
}

export class WarmStartStage {
  private readonly kernel: Kernel;
  private readonly tail: Kernel;
  private readonly fused: Kernel;

  constructor(ctx: GpuContext) {
    this.kernel = new Kernel(ctx, 'warmStart', 'main');
    this.tail = new Kernel(ctx, 'warmStart', 'tail');
    this.fused = new Kernel(ctx, 'warmStart', 'fused');
  }

  /** The buffers every entry point binds (`main` adds its colour's uniform at 0, `tail` its first colour's). */
  private entries(io: ColourPassInputs, bodyVel: GPUBuffer): Record<number, BindingEntry> {
    return { 1: io.solverState, 2: io.colourKeys, 3: io.contactBodies, 4: io.constraints, 5: bodyVel, 10: io.jointBodies, 12: io.jointConstraints };
  }

  /** Every colour in one dispatch of one workgroup (a small world). */
  encodeFused(rec: Recorder, io: ColourPassInputs, bodyVel: GPUBuffer): void {
    rec.dispatch(this.fused, this.fused.bind(this.entries(io, bodyVel)), 1);
  }

  /** A pass per colour below `passColours`, then the tail pass: passColours + 1 dispatches. */
  encode(rec: Recorder, io: ColourPassInputs, bodyVel: GPUBuffer, passColours: number): void {
    const shared = this.entries(io, bodyVel);
    for (let c = 0; c < passColours; ++c) {
      const group = this.kernel.bind({ 0: io.colours[c].buffer, ...shared });
      rec.dispatchIndirect(this.kernel, group, io.solverIndirect, (SV_ARGS.COLOURS + 3 * c) * 4);
    }
    const tail = this.tail.bind({ 0: io.colours[passColours].buffer, ...shared });
    rec.dispatchIndirect(this.tail, tail, io.solverIndirect, (SV_ARGS.COLOURS + 3 * COLOUR_CAP) * 4);
  }
}
