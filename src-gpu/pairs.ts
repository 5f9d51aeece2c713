/*
 * Stage 6, pairs (shaders/pairs.wgsl + the radix sort): from the sweep's unordered pair list to
 * the canonical one.
 *
 * In:  pairs[0, found) from the sweep (a < b, no duplicates, order depending on atomics),
 *      state[STATE.PAIR_COUNT], state[STATE.PAIR_CAPACITY].
 * Out: state[STATE.OVERFLOW] (1: the capacity was too small; the host grows it and redoes the
 *      sweep), and, when nothing overflowed, pairs sorted by (a, b): LSD passes over the digits
 *      of b, then of a. Pairs are unique, so the sorted list is the same on every run whatever
 *      order the atomics gave.
 */

import type { GpuContext } from './device';
import { Kernel } from './kernel';
import type { Recorder } from './kernel';
import { digitPasses } from './radixSort';
import type { RadixSort, SortPass } from './radixSort';
import { ARGS, STATE } from './layout';

/** Bits needed for proxy slots [0, slotCount). */
export function slotBits(slotCount: number): number {
  let bits = 1;
  while (bits < 32 && 2 ** bits < slotCount) bits++;
  return bits;
}

/** The pair sort's passes: b's digits, then a's (LSD order for the key (a, b)). */
export function pairSortPasses(slotCount: number): SortPass[] {
  const bits = slotBits(slotCount);
  return [...digitPasses(bits, 1), ...digitPasses(bits, 0)];
}

export class PairsStage {
  private readonly finish: Kernel;

  constructor(ctx: GpuContext) {
    this.finish = new Kernel(ctx, 'pairs', 'finish');
  }

  /** finish, then the pair sort; returns the buffer holding the sorted pairs. */
  encode(rec: Recorder, sort: RadixSort, pairs: GPUBuffer, pairsTmp: GPUBuffer, slotCount: number, state: GPUBuffer, indirect: GPUBuffer): GPUBuffer {
    rec.dispatch(this.finish, this.finish.bind({ 0: state, 1: indirect }), 1);
    return sort.encode(rec, pairs, pairsTmp, pairSortPasses(slotCount), state, STATE.PAIR_SORT_COUNT, { indirect, offset: ARGS.PAIR_TILES * 4 });
  }
}
