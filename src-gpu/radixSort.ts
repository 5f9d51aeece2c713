/*
 * Radix sort (shaders/radixSort.wgsl): a stable LSD sort of vec2<u32> elements, 4 bits per pass,
 * three dispatches per pass (upsweep, scan, downsweep; reduce-then-scan, no decoupled look-back).
 *
 * Used twice per broad-phase step: the proxies by the key of their lower bound (8 passes over
 * the 32-bit key), and the pairs by (proxy a, proxy b) (the passes over b's bits, then a's: as
 * many 4-bit digits as the proxy slot count needs).
 *
 * In:  elements [0, n) of `a`, n = state[countWord] (so a count computed on the GPU can drive it).
 * Out: the sorted elements, in `a` after an even number of passes, in `b` after an odd one
 *      (encode() returns which).
 * Dispatch: direct (`groups`: the host knows n) or indirect (the size written by a kernel at
 *      `indirect` byte offset, as for the pairs, whose count only the GPU knows).
 */

import type { GpuContext } from './device';
import { GpuArray } from './buffers';
import { Kernel, Uniform } from './kernel';
import type { Recorder } from './kernel';
import { SORT_TILE } from './layout';

export interface SortPass {
  /** Bit offset of the 4-bit digit. */
  shift: number;
  /** 0: sort by element.x, 1: by element.y. */
  component: 0 | 1;
}

export type SortDispatch = { groups: number } | { indirect: GPUBuffer; offset: number };

/** Passes sorting by the low `bits` bits of component `component`. */
export function digitPasses(bits: number, component: 0 | 1): SortPass[] {
  const passes: SortPass[] = [];
  for (let shift = 0; shift < Math.max(1, bits); shift += 4) passes.push({ shift, component });
  return passes;
}

export class RadixSort {
  private readonly ctx: GpuContext;
  private readonly upsweep: Kernel;
  private readonly scan: Kernel;
  private readonly downsweep: Kernel;
  private readonly tileHist: GpuArray;
  private readonly digitTotals: GpuArray;
  private readonly params = new Map<string, Uniform>();

  constructor(ctx: GpuContext) {
    this.ctx = ctx;
    this.upsweep = new Kernel(ctx, 'radixSort', 'upsweep');
    this.scan = new Kernel(ctx, 'radixSort', 'scan');
    this.downsweep = new Kernel(ctx, 'radixSort', 'downsweep');
    this.tileHist = new GpuArray(ctx, 'radix tileHist', 4, 16 * 64);
    this.digitTotals = new GpuArray(ctx, 'radix digitTotals', 4, 16);
  }

  /** The last pass's count of each digit (16 u32; the narrow phase's bin sizes). */
  get digitTotalsBuffer(): GPUBuffer {
    return this.digitTotals.buffer;
  }

  /** Makes room for sorting up to `n` elements. */
  reserve(n: number): void {
    this.tileHist.ensure(16 * Math.max(1, Math.ceil(n / SORT_TILE)));
  }

  private uniform(pass: SortPass, countWord: number): Uniform {
    const key = `${pass.shift}:${pass.component}:${countWord}`;
    let u = this.params.get(key);
    if (!u) {
      u = new Uniform(this.ctx, `radix params ${key}`, 4);
      u.u32[0] = pass.shift;
      u.u32[1] = pass.component;
      u.u32[2] = countWord;
      u.upload();
      this.params.set(key, u);
    }
    return u;
  }

  /**
   * Records the passes. `a` and `b` are vec2<u32> buffers of the same capacity; returns the one
   * that holds the result.
   */
  encode(rec: Recorder, a: GPUBuffer, b: GPUBuffer, passes: SortPass[], state: GPUBuffer, countWord: number, dispatch: SortDispatch): GPUBuffer {
    let src = a;
    let dst = b;
    for (const pass of passes) {
      const u = this.uniform(pass, countWord).buffer;
      const up = this.upsweep.bind({ 0: u, 1: src, 2: state, 3: this.tileHist.buffer });
      const sc = this.scan.bind({ 0: u, 2: state, 3: this.tileHist.buffer, 4: this.digitTotals.buffer });
      const down = this.downsweep.bind({ 0: u, 1: src, 2: state, 3: this.tileHist.buffer, 4: this.digitTotals.buffer, 5: dst });
      if ('groups' in dispatch) {
        rec.dispatch(this.upsweep, up, dispatch.groups);
        rec.dispatch(this.scan, sc, 16);
        rec.dispatch(this.downsweep, down, dispatch.groups);
      } else {
        rec.dispatchIndirect(this.upsweep, up, dispatch.indirect, dispatch.offset);
        rec.dispatch(this.scan, sc, 16);
        rec.dispatchIndirect(this.downsweep, down, dispatch.indirect, dispatch.offset);
      }
      const t = src;
      src = dst;
      dst = t;
    }
    return src;
  }
}
