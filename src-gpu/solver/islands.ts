/*
 * Islands and sleeping (shaders/solver/islands.wgsl): b2World::Solve's islands as connected components
 * found on the GPU (union-find, the component's smallest body slot as its label), waking as 2.2.1
 * wakes, and b2Island::Solve's sleep timers per component.
 *
 * In:  the solver's state (SV.SKIP, SV.COUNT, SV.POSITION_DONE) and indirect sizes, the narrow
 *      phase's npState, contactRefs, manifolds (MF_WARM, MF_BEGAN, MF_ENDED, MF_SENSOR) and
 *      solverList of the step being recorded; the mirror's joints, bodyFlags, bodyAwake,
 *      bodySweep (sleepTime), bodyVel; h and b2World::m_allowSleep (configure()).
 * Out: `encodeFind` (before integrate velocities): bodyAwake for this step (bodies woken by new
 *      contacts, touch changes and their islands), sleeping bodies at zero velocity and sleep
 *      time, `labels` (per body slot: the island's smallest slot, NO_ISLAND for static, inactive
 *      and dead bodies). `encodeSleep` (after synchronize): sleepTime of awake bodies, and
 *      bodyAwake 0 with zero velocities for every body of an island whose bodies have all rested
 *      b2_timeToSleep and whose positions converged (SV.POSITION_DONE).
 * The stages after encodeFind skip sleeping bodies (integrateVelocities, integratePositions) and
 * the contacts of sleeping islands (prepareContacts: no points to solve, impulses kept).
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Kernel, Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { ISLAND_WORDS, SV_ARGS, WORKGROUP_SIZE } from '../device/layout';
import type { GpuWorld } from '../world/world';

/** What the island search reads of the step being recorded. */
export interface IslandInputs {
  solverState: GPUBuffer;
  solverIndirect: GPUBuffer;
  npState: GPUBuffer;
  contactRefs: GPUBuffer;
  manifolds: GPUBuffer;
  solverList: GPUBuffer;
  /** Contacts the narrow phase's buffers hold (the wake pass's grid). */
  contactCapacity: number;
}

export class IslandsStage {
  private readonly params: Uniform;
  private readonly init: Kernel;
  private readonly wake: Kernel;
  private readonly hookContacts: Kernel;
  private readonly hookJoints: Kernel;
  private readonly label: Kernel;
  private readonly spread: Kernel;
  private readonly sleepTime: Kernel;
  private readonly sleep: Kernel;
  /** ISLAND_WORDS per body slot: the union-find parent (the label after encodeFind), per-root words. */
  readonly labels: GpuArray;

  constructor(ctx: GpuContext) {
    this.params = new Uniform(ctx, 'island params', 4);
    this.init = new Kernel(ctx, 'islands', 'init');
    this.wake = new Kernel(ctx, 'islands', 'wake');
    this.hookContacts = new Kernel(ctx, 'islands', 'hook_contacts');
    this.hookJoints = new Kernel(ctx, 'islands', 'hook_joints');
    this.label = new Kernel(ctx, 'islands', 'label');
    this.spread = new Kernel(ctx, 'islands', 'spread');
    this.sleepTime = new Kernel(ctx, 'islands', 'sleep_time');
    this.sleep = new Kernel(ctx, 'islands', 'sleep');
    this.labels = new GpuArray(ctx, 'island labels', 4 * ISLAND_WORDS, 64);
  }

  /** Sets h and the world's allowSleep for the steps recorded from now on. */
  configure(h: number, mirror: GpuWorld): void {
    const u = this.params;
    u.f32[0] = h;
    u.u32[1] = mirror.bodySlotCount;
    u.u32[2] = mirror.jointSlotCount;
    u.u32[3] = mirror.world.m_allowSleep ? 1 : 0;
    u.upload();
  }

  encodeFind(rec: Recorder, io: IslandInputs, mirror: GpuWorld): void {
    const bodyGroups = Math.ceil(mirror.bodySlotCount / WORKGROUP_SIZE);
    this.labels.ensure(Math.max(1, mirror.bodySlotCount));
    const params = this.params.buffer;
    const labels = this.labels.buffer;
    rec.dispatch(this.init, this.init.bind({ 0: params, 1: io.solverState, 7: mirror.bodyFlags.buffer, 9: labels }), bodyGroups);
    rec.dispatch(
      this.wake,
      this.wake.bind({
        1: io.solverState,
        2: io.npState,
        3: io.contactRefs,
        4: io.manifolds,
        7: mirror.bodyFlags.buffer,
        8: mirror.bodyAwake.buffer,
      }),
      Math.ceil(io.contactCapacity / WORKGROUP_SIZE),
    );
    rec.dispatchIndirect(
      this.hookContacts,
      this.hookContacts.bind({ 1: io.solverState, 3: io.contactRefs, 5: io.solverList, 7: mirror.bodyFlags.buffer, 9: labels }),
      io.solverIndirect,
      SV_ARGS.CONTACTS * 4,
    );
    if (mirror.jointSlotCount > 0) {
      const group = this.hookJoints.bind({ 0: params, 1: io.solverState, 6: mirror.joints.buffer, 7: mirror.bodyFlags.buffer, 9: labels });
      rec.dispatch(this.hookJoints, group, Math.ceil(mirror.jointSlotCount / WORKGROUP_SIZE));
    }
    rec.dispatch(this.label, this.label.bind({ 0: params, 1: io.solverState, 7: mirror.bodyFlags.buffer, 8: mirror.bodyAwake.buffer, 9: labels }), bodyGroups);
    rec.dispatch(this.spread, this.spread.bind(this.motionEntries(io.solverState, mirror)), bodyGroups);
  }

  encodeSleep(rec: Recorder, solverState: GPUBuffer, mirror: GpuWorld): void {
    const bodyGroups = Math.ceil(mirror.bodySlotCount / WORKGROUP_SIZE);
    const entries = this.motionEntries(solverState, mirror);
    rec.dispatch(this.sleepTime, this.sleepTime.bind(entries), bodyGroups);
    rec.dispatch(this.sleep, this.sleep.bind(entries), bodyGroups);
  }

  /** The bindings of the per-body kernels that write the motion (spread, sleep_time, sleep). */
  private motionEntries(solverState: GPUBuffer, mirror: GpuWorld): Record<number, GPUBuffer> {
    return {
      0: this.params.buffer,
      1: solverState,
      7: mirror.bodyFlags.buffer,
      8: mirror.bodyAwake.buffer,
      9: this.labels.buffer,
      10: mirror.bodySweep.buffer,
      11: mirror.bodyVel.buffer,
    };
  }

  destroy(): void {
    this.params.destroy();
    this.labels.destroy();
  }
}
