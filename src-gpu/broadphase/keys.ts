/*
 * Broad phase, keys (shaders/broadphase/keys.wgsl): the sweep entries, one per (proxy, strip it spans), with their
 * sort keys (strip, quantised lower bound on the sweep axis).
 *
 * In:  proxyAABB, proxyRef, proxyFilter [0, slotCount); the layout axis.wgsl wrote into the state
 *      buffer.
 * Out: items[0, E) = (key, proxy slot); state[STATE.ENTRIES] = E (0 with OVERFLOW_ENTRIES set when
 *      E passed state[STATE.ENTRY_CAPACITY]); the indirect sizes ARGS.ENTRY_* for the passes over
 *      the entries. E is at most 2.5 x the live proxies plus rounding (axis.wgsl says why), so an
 *      entry capacity of 3 x slots + 64 never overflows in practice; if it does, the host grows it
 *      and redoes the update. `records`: per live proxy slot, the 32 bytes the sweep's gather
 *      reads (keys.wgsl), written here, where the proxies are read in slot order.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Kernel, Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { SCAN_BLOCK, STATE, WORKGROUP_SIZE } from '../device/layout';
import { PrefixScan } from '../primitives/scan';
import type { SweepInputs } from './sweep';

export class KeysStage {
  private readonly replicas: Kernel;
  private readonly sizeArgs: Kernel;
  private readonly entries: Kernel;
  private readonly scan: PrefixScan;
  private readonly params: Uniform;
  private readonly replicaOffset: GpuArray;
  /** Two vec4<u32> per proxy slot (keys.wgsl `entries`). */
  readonly records: GpuArray;

  constructor(ctx: GpuContext) {
    this.replicas = new Kernel(ctx, 'keys', 'replicas');
    this.sizeArgs = new Kernel(ctx, 'keys', 'size_args');
    this.entries = new Kernel(ctx, 'keys', 'entries');
    this.scan = new PrefixScan(ctx);
    this.params = new Uniform(ctx, 'keys params', 4);
    this.replicaOffset = new GpuArray(ctx, 'replicaOffset', 4);
    this.records = new GpuArray(ctx, 'proxyRecords', 32);
  }

  encode(rec: Recorder, inputs: SweepInputs, state: GPUBuffer, items: GPUBuffer, indirect: GPUBuffer): void {
    const { proxyAABB, slotCount } = inputs;
    this.replicaOffset.ensure(Math.max(1, slotCount));
    this.records.ensure(Math.max(1, slotCount));
    this.scan.reserve(slotCount);
    this.params.u32[0] = slotCount;
    this.params.upload();
    const groups = Math.ceil(slotCount / WORKGROUP_SIZE);
    const u = this.params.buffer;
    rec.dispatch(this.replicas, this.replicas.bind({ 0: u, 1: proxyAABB, 2: state, 3: this.replicaOffset.buffer }), groups);
    this.scan.encode(rec, this.replicaOffset.buffer, state, STATE.SLOT_COUNT, STATE.ENTRY_TOTAL, {
      groups: Math.ceil(slotCount / SCAN_BLOCK),
    });
    rec.dispatch(this.sizeArgs, this.sizeArgs.bind({ 2: state, 5: indirect }), 1);
    const entries = this.entries.bind({
      0: u,
      1: proxyAABB,
      2: state,
      3: this.replicaOffset.buffer,
      4: items,
      6: inputs.proxyRef,
      7: inputs.proxyFilter,
      8: this.records.buffer,
    });
    rec.dispatch(this.entries, entries, groups);
  }
}
