/*
 * Exclusive prefix sum (shaders/primitives/scan.wgsl), in place, reduce-then-scan: three dispatches whatever
 * the size (one workgroup scans the block sums in rounds).
 *
 * In:  data[0, count) (u32), count = state[countWord] (written by the host or by a kernel).
 * Out: data[i] = sum of data[0, i); state[totalWord] = the total.
 * Dispatch: `groups` workgroups of SCAN_BLOCK elements, at least enough for the count (the host
 * knows a bound), or indirect (a size a kernel wrote).
 * Used for the proxies' entry offsets and the entries' work-item offsets.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Kernel, Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { SCAN_BLOCK } from '../device/layout';

export class PrefixScan {
  private readonly reduce: Kernel;
  private readonly scanBlocks: Kernel;
  private readonly downsweep: Kernel;
  private readonly params: Uniform;
  private readonly blockSums: GpuArray;

  constructor(ctx: GpuContext) {
    this.reduce = new Kernel(ctx, 'scan', 'reduce');
    this.scanBlocks = new Kernel(ctx, 'scan', 'scan_blocks');
    this.downsweep = new Kernel(ctx, 'scan', 'downsweep');
    this.params = new Uniform(ctx, 'scan params', 4);
    this.blockSums = new GpuArray(ctx, 'scan blockSums', 4, 64);
  }

  /** Makes room for scanning up to `maxCount` elements. */
  reserve(maxCount: number): void {
    this.blockSums.ensure(Math.max(1, Math.ceil(maxCount / SCAN_BLOCK)));
  }

  encode(
    rec: Recorder,
    data: GPUBuffer,
    state: GPUBuffer,
    countWord: number,
    totalWord: number,
    dispatch: { groups: number } | { indirect: GPUBuffer; offset: number },
  ): void {
    this.params.u32[0] = countWord;
    this.params.u32[1] = totalWord;
    this.params.upload();
    const group = (k: Kernel) => k.bind({ 0: this.params.buffer, 1: data, 2: this.blockSums.buffer, 3: state });
    const run = (k: Kernel) => {
      if ('groups' in dispatch) rec.dispatch(k, group(k), Math.max(1, dispatch.groups));
      else rec.dispatchIndirect(k, group(k), dispatch.indirect, dispatch.offset);
    };
    run(this.reduce);
    rec.dispatch(this.scanBlocks, this.scanBlocks.bind({ 0: this.params.buffer, 2: this.blockSums.buffer, 3: state }), 1);
    run(this.downsweep);
  }
}
