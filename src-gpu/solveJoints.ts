/*
 * The solver's joints (shaders/solveJoints.wgsl): b2RevoluteJoint and b2DistanceJoint as 2.2.1
 * solves them. Other joint types are refused by GpuStepper.
 *
 * In:  the solver's parameters (h, dtRatio, warmStarting, cellSize, joint slot count), the
 *      mirror's joints, jointParams, jointState (impulses carried over), bodyFlags, bodyMass,
 *      bodySweep, bodyCell, bodyVel; solverState (SV.SKIP, SV.POSITION_DONE).
 * Out: `encodePrepare`: jointConstraints per joint slot (InitVelocityConstraints without the
 *      velocity update); `encodeWarmStart`, `encodeVelocity`, `encodePosition`: the warm start,
 *      one velocity iteration, one position iteration (SV.JOINT_ERROR for the early exit), each
 *      one invocation over the joints in slot order (joints are not coloured yet);
 *      `encodeStore`: the impulses and limit states back into jointState.
 */

import type { GpuContext } from './device';
import { GpuArray } from './buffers';
import { Kernel } from './kernel';
import type { Recorder } from './kernel';
import { WORKGROUP_SIZE } from './layout';
import type { GpuWorld } from './world';

/** vec4s per joint slot in jointConstraints (shaders/solveJoints.wgsl JOINT_VEC4). */
export const JOINT_VEC4 = 7;

export class SolveJointsStage {
  private readonly prepare: Kernel;
  private readonly warmStart: Kernel;
  private readonly velocity: Kernel;
  private readonly position: Kernel;
  private readonly store: Kernel;
  private readonly constraints: GpuArray;

  constructor(ctx: GpuContext) {
    this.prepare = new Kernel(ctx, 'solveJoints', 'prepare');
    this.warmStart = new Kernel(ctx, 'solveJoints', 'warm_start');
    this.velocity = new Kernel(ctx, 'solveJoints', 'velocity');
    this.position = new Kernel(ctx, 'solveJoints', 'position');
    this.store = new Kernel(ctx, 'solveJoints', 'store');
    this.constraints = new GpuArray(ctx, 'joint constraints', 16 * JOINT_VEC4, 16);
  }

  encodePrepare(rec: Recorder, params: GPUBuffer, mirror: GpuWorld): void {
    const n = mirror.jointSlotCount;
    if (n === 0) return;
    this.constraints.ensure(n);
    const group = this.prepare.bind({
      0: params,
      2: mirror.joints.buffer,
      3: mirror.jointParams.buffer,
      4: mirror.jointState.buffer,
      5: this.constraints.buffer,
      6: mirror.bodyFlags.buffer,
      7: mirror.bodyMass.buffer,
      8: mirror.bodySweep.buffer,
      9: mirror.bodyCell.buffer,
    });
    rec.dispatch(this.prepare, group, Math.ceil(n / WORKGROUP_SIZE));
  }

  encodeWarmStart(rec: Recorder, params: GPUBuffer, solverState: GPUBuffer, mirror: GpuWorld): void {
    if (mirror.jointSlotCount === 0) return;
    const group = this.warmStart.bind({ 0: params, 1: solverState, 2: mirror.joints.buffer, 5: this.constraints.buffer, 10: mirror.bodyVel.buffer });
    rec.dispatch(this.warmStart, group, 1);
  }

  encodeVelocity(rec: Recorder, params: GPUBuffer, solverState: GPUBuffer, mirror: GpuWorld): void {
    if (mirror.jointSlotCount === 0) return;
    const group = this.velocity.bind({
      0: params,
      1: solverState,
      2: mirror.joints.buffer,
      3: mirror.jointParams.buffer,
      5: this.constraints.buffer,
      10: mirror.bodyVel.buffer,
    });
    rec.dispatch(this.velocity, group, 1);
  }

  encodePosition(rec: Recorder, params: GPUBuffer, solverState: GPUBuffer, mirror: GpuWorld): void {
    if (mirror.jointSlotCount === 0) return;
    const group = this.position.bind({
      0: params,
      1: solverState,
      2: mirror.joints.buffer,
      3: mirror.jointParams.buffer,
      5: this.constraints.buffer,
      8: mirror.bodySweep.buffer,
    });
    rec.dispatch(this.position, group, 1);
  }

  encodeStore(rec: Recorder, params: GPUBuffer, solverState: GPUBuffer, mirror: GpuWorld): void {
    const n = mirror.jointSlotCount;
    if (n === 0) return;
    const group = this.store.bind({ 0: params, 1: solverState, 4: mirror.jointState.buffer, 5: this.constraints.buffer });
    rec.dispatch(this.store, group, Math.ceil(n / WORKGROUP_SIZE));
  }

  destroy(): void {
    this.constraints.destroy();
  }
}
