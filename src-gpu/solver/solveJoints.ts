/*
 * The solver's joints (shaders/solver/solveJoints.wgsl, shaders/shared/solveJointsCommon.wgsl): the ten joint
 * types of 2.2.1 (revolute, prismatic, distance, pulley, mouse, gear, wheel, weld, friction,
 * rope) in float32. The per-step records are made here; the joints are solved inside the colour
 * passes (warmStart.ts, solveVelocity.ts, solvePosition.ts), coloured with the contacts
 * (colour.ts: joint slots are the first items).
 *
 * In:  the solver's parameters (h, dtRatio, warmStarting, cellSize, joint slot count), the
 *      mirror's joints, jointParams, jointState (impulses carried over), bodyFlags, bodyAwake
 *      (a joint with a dynamic body asleep is not solved: 2.2.1 solves awake islands only),
 *      bodyMass, bodySweep, bodyCell; solverState (SV.SKIP).
 * Out: `encodePrepare`: jointBodies (bodies, type, which bodies are dynamic, whether the joint is
 *      solved, limit state) and jointConstraints per joint slot (InitVelocityConstraints without
 *      the velocity update); `encodeStore`: the impulses and limit states back into jointState.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { WORKGROUP_SIZE } from '../device/layout';
import type { GpuWorld } from '../world/world';

/** vec4s per joint slot in jointConstraints (shaders/shared/solveJointsCommon.wgsl JOINT_VEC4). */
export const JOINT_VEC4 = 9;
/** vec4s per joint slot in jointParams (shaders/shared/solveJointsCommon.wgsl JOINT_PARAMS_VEC4). */
export const JOINT_PARAMS_VEC4 = 5;
/** vec4<u32>s per joint slot in jointBodies. */
export const JOINT_BODIES_VEC4 = 2;

export class SolveJointsStage {
  private readonly bodiesKernel: Kernel;
  private readonly prepare: Kernel;
  private readonly store: Kernel;
  private readonly bodyArray: GpuArray;
  private readonly constraintArray: GpuArray;

  constructor(ctx: GpuContext) {
    this.bodiesKernel = new Kernel(ctx, 'solveJoints', 'bodies');
    this.prepare = new Kernel(ctx, 'solveJoints', 'prepare');
    this.store = new Kernel(ctx, 'solveJoints', 'store');
    this.bodyArray = new GpuArray(ctx, 'joint bodies', 16 * JOINT_BODIES_VEC4, 16);
    this.constraintArray = new GpuArray(ctx, 'joint constraints', 16 * JOINT_VEC4, 16);
  }

  /** Per joint slot: bodies, type, dynamic mask, solved flag, limit state (solveJointsCommon.wgsl). */
  get bodies(): GPUBuffer {
    return this.bodyArray.buffer;
  }

  get constraints(): GPUBuffer {
    return this.constraintArray.buffer;
  }

  /** Makes room for the mirror's joint slots (call before taking `bodies` / `constraints`). */
  reserve(mirror: GpuWorld): void {
    const n = Math.max(1, mirror.jointSlotCount);
    this.bodyArray.ensure(n);
    this.constraintArray.ensure(n);
  }

  encodePrepare(rec: Recorder, params: GPUBuffer, mirror: GpuWorld): void {
    const n = mirror.jointSlotCount;
    if (n === 0) return;
    const groups = Math.ceil(n / WORKGROUP_SIZE);
    const bodies = this.bodiesKernel.bind({
      2: mirror.joints.buffer,
      5: mirror.bodyAwake.buffer,
      6: mirror.bodyFlags.buffer,
      7: mirror.bodyMass.buffer,
      9: params,
      10: this.bodyArray.buffer,
      11: mirror.jointParams.buffer,
      12: this.constraintArray.buffer,
    });
    rec.dispatch(this.bodiesKernel, bodies, groups);
    const prepare = this.prepare.bind({
      3: mirror.bodyCell.buffer,
      4: mirror.jointState.buffer,
      7: mirror.bodyMass.buffer,
      8: mirror.bodySweep.buffer,
      9: params,
      10: this.bodyArray.buffer,
      11: mirror.jointParams.buffer,
      12: this.constraintArray.buffer,
    });
    rec.dispatch(this.prepare, prepare, groups);
  }

  encodeStore(rec: Recorder, params: GPUBuffer, solverState: GPUBuffer, mirror: GpuWorld): void {
    const n = mirror.jointSlotCount;
    if (n === 0) return;
    const group = this.store.bind({ 1: solverState, 4: mirror.jointState.buffer, 9: params, 10: this.bodyArray.buffer, 12: this.constraintArray.buffer });
    rec.dispatch(this.store, group, Math.ceil(n / WORKGROUP_SIZE));
  }

  destroy(): void {
    this.bodyArray.destroy();
    this.constraintArray.destroy();
  }
}
