/*
 * Broad phase, pairs (shaders/broadphase/pairs.wgsl + the radix sort): from the sweep's unordered pair list to
 * the canonical one.
 *
 * In:  pairs[0, found) from the sweep (a < b, no duplicates, order depending on atomics),
 *      state[STATE.PAIR_COUNT], state[STATE.PAIR_CAPACITY].
 * Out: state[STATE.OVERFLOW] (1: the capacity was too small; the host grows it and redoes the
 *      sweep), and, when nothing overflowed, pairs sorted by (a, b): 8-bit LSD passes over the
 *      key a << slotBits | b (2 x slotBits bits, so no pass sorts bits that are always zero: 5
 *      passes for 10^6 slots, where separate passes over a and b took 10 of 4 bits). Pairs are
 *      unique, so the sorted list is the same on every run whatever order the atomics gave.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { digitPasses } from '../primitives/radixSort';
import type { RadixSort, SortPass } from '../primitives/radixSort';
import { ARGS, STATE } from '../device/layout';

/** Bits needed for proxy slots [0, slotCount). */
export function slotBits(slotCount: number): number {
  let bits = 1;
  while (bits < 32 && 2 ** bits < slotCount) bits++;
  return bits;
}

/** The pair sort's passes: the digits of a << slotBits | b, least significant first. */
export function pairSortPasses(slotCount: number): SortPass[] {
  const bits = slotBits(slotCount);
  return digitPasses(2 * bits, 2, 8, bits);
}

export class PairsStage {
  private readonly finish: Kernel;

  constructor(ctx: GpuContext) {
    this.finish = new Kernel(ctx, 'pairs', 'finish');
  }

  /**
   * finish, then the pair sort; returns the buffer holding the sorted pairs. `pairCapacity`: the
   * pairs the pair buffer holds (a bound on the sort's count).
   */
  encode(
    rec: Recorder,
    sort: RadixSort,
    pairs: GPUBuffer,
    pairsTmp: GPUBuffer,
    pairCapacity: number,
    slotCount: number,
    state: GPUBuffer,
    indirect: GPUBuffer,
  ): GPUBuffer {
    rec.dispatch(this.finish, this.finish.bind({ 0: state, 1: indirect }), 1);
    return sort.encode(rec, pairs, pairsTmp, pairSortPasses(slotCount), state, STATE.PAIR_SORT_COUNT, {
      indirect,
      offset: ARGS.PAIR_TILES * 4,
      maxCount: pairCapacity,
    });
  }
}
