/*
 * Broad phase, sweep (shaders/broadphase/sweep.wgsl): sweep-and-prune over the sorted entries, strip by strip.
 *
 * In:  items[0, E) = (key, proxy slot) sorted by key; the proxies' records (keys.ts), the joint
 *      tables (SweepInputs).
 * Out: pairs[0, min(found, capacity)) = (a, b), a < b, unordered; state[STATE.PAIR_COUNT] = found.
 * Steps: gather (AABB keys, filter data and strip data in sorted order, and each entry's
 * candidate range in work items of SWEEP_CHUNK candidates), scan (work-item offsets; total in
 * state[STATE.WORK_TOTAL]), emit_args (the indirect size of emit), emit (the overlap tests, the
 * strip de-duplication and Box2D's pair filters; pairs appended with one atomic per workgroup).
 * Every pass over the entries is dispatched indirectly: only the GPU knows E.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Kernel, Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { ARGS, STATE } from '../device/layout';
import { PrefixScan } from '../primitives/scan';

/** What the sweep reads: the proxies' AABBs and filter data (GpuWorld + bounds, or GpuProxySet). */
export interface SweepInputs {
  /** Proxy slots [0, slotCount); dead ones (lower.x > upper.x) are skipped. */
  slotCount: number;
  /** Live proxies. */
  liveCount: number;
  proxyAABB: GPUBuffer;
  proxyRef: GPUBuffer;
  proxyFilter: GPUBuffer;
  jointRange: GPUBuffer;
  jointList: GPUBuffer;
}

export class SweepStage {
  private readonly gather: Kernel;
  private readonly emitArgs: Kernel;
  private readonly emit: Kernel;
  private readonly scan: PrefixScan;
  private readonly params: Uniform;
  readonly sortedKeys: GpuArray;
  readonly sortedInfo: GpuArray;
  readonly workOffset: GpuArray;

  constructor(ctx: GpuContext) {
    this.gather = new Kernel(ctx, 'sweep', 'gather');
    this.emitArgs = new Kernel(ctx, 'sweep', 'emit_args');
    this.emit = new Kernel(ctx, 'sweep', 'emit');
    this.scan = new PrefixScan(ctx);
    this.params = new Uniform(ctx, 'sweep params', 4);
    this.sortedKeys = new GpuArray(ctx, 'sortedKeys', 32);
    this.sortedInfo = new GpuArray(ctx, 'sortedInfo', 16);
    this.workOffset = new GpuArray(ctx, 'workOffset', 4);
  }

  /** Makes room for `entries` sweep entries. */
  reserve(entries: number): void {
    this.sortedKeys.ensure(entries);
    this.sortedInfo.ensure(entries);
    this.workOffset.ensure(entries);
    this.scan.reserve(entries);
  }

  /** Sets the pair capacity; call before encoding, again after a regrow. */
  setPairCapacity(pairCapacity: number): void {
    this.params.u32[0] = pairCapacity;
    this.params.upload();
  }

  /** gather, scan, emit_args; `records`: the proxies' records (KeysStage.records). */
  encodePrepare(rec: Recorder, records: GPUBuffer, items: GPUBuffer, state: GPUBuffer, indirect: GPUBuffer): void {
    const entryGroups = ARGS.ENTRY_GROUPS * 4;
    rec.dispatchIndirect(
      this.gather,
      this.gather.bind({
        1: items,
        2: records,
        5: state,
        6: this.sortedKeys.buffer,
        7: this.sortedInfo.buffer,
        9: this.workOffset.buffer,
      }),
      indirect,
      entryGroups,
    );
    this.scan.encode(rec, this.workOffset.buffer, state, STATE.ENTRIES, STATE.WORK_TOTAL, {
      indirect,
      offset: ARGS.ENTRY_BLOCKS * 4,
    });
    rec.dispatch(this.emitArgs, this.emitArgs.bind({ 5: state, 14: indirect }), 1);
  }

  /** emit: the pairs, sized by the indirect arguments emit_args wrote. */
  encodeEmit(rec: Recorder, inputs: SweepInputs, pairs: GPUBuffer, state: GPUBuffer, indirect: GPUBuffer): void {
    const group = this.emit.bind({
      0: this.params.buffer,
      6: this.sortedKeys.buffer,
      7: this.sortedInfo.buffer,
      9: this.workOffset.buffer,
      10: inputs.jointRange,
      11: inputs.jointList,
      12: pairs,
      13: state,
    });
    rec.dispatchIndirect(this.emit, group, indirect, ARGS.EMIT * 4);
  }
}
