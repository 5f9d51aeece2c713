/*
 * Radix sort (shaders/radixSort.wgsl): a stable LSD sort of vec2<u32> elements, 4 or 8 bits per
 * pass, three dispatches per pass (upsweep, scan, downsweep; reduce-then-scan, no decoupled
 * look-back).
 *
 * Used twice per broad-phase step, with 8-bit digits: the sweep entries by their 24-bit key (3
 * passes), and the pairs by (proxy a, proxy b) as one key a << slotBits | b (2 x slotBits bits:
 * 5 passes for 10^6 slots). The narrow phase's bin sort and the solver's colour sort use 4-bit
 * digits (16 digit values: a cheaper scan and one local split).
 *
 * In:  elements [0, n) of `a`, n = state[countWord] (so a count computed on the GPU can drive it).
 * Out: the sorted elements, in `a` after an even number of passes, in `b` after an odd one
 *      (encode() returns which); digitTotalsBuffer: the last pass's count of each digit.
 * Dispatch: direct (`groups`: the host knows n) or indirect (the size written by a kernel at
 *      `indirect` byte offset, as for the pairs, whose count only the GPU knows).
 */

import type { GpuContext } from './device';
import { GpuArray } from './buffers';
import { Kernel, Uniform } from './kernel';
import type { Recorder } from './kernel';
import { SORT_TILE } from './layout';

/** Digit values of the widest pass (shaders/radixSort.wgsl MAX_RADIX). */
const MAX_RADIX = 256;
/** Tiles up to which the scan is one workgroup (shaders/radixSort.wgsl SERIAL_TILES). */
const SERIAL_TILES = 16;

export interface SortPass {
  /** Bit offset of the digit in the key. */
  shift: number;
  /**
   * The key: 0 element.x, 1 element.y, 2 (x, y) as the 64-bit key x << lowBits | y (for
   * y < 2^lowBits: the order of (x, y) pairs).
   */
  component: 0 | 1 | 2;
  /** Digit width (default 4). */
  bits?: 4 | 8;
  /** For component 2: the bits of y, 1 to 31. */
  lowBits?: number;
}

/**
 * Direct (`groups` workgroups of SORT_TILE elements) or indirect; `maxCount` bounds an indirect
 * sort's count, so that the scan of a sort known to be small or mid-sized runs in fewer
 * workgroups than one per digit value (shaders/radixSort.wgsl SERIAL_TILES, rows_per_group).
 */
export type SortDispatch = { groups: number } | { indirect: GPUBuffer; offset: number; maxCount?: number };

/**
 * Passes sorting by the low `bits` bits of component `component`, in digits of `digitBits`; with
 * 8-bit digits a last digit of 4 bits or fewer gets a 4-bit pass.
 */
export function digitPasses(bits: number, component: 0 | 1 | 2, digitBits: 4 | 8 = 4, lowBits?: number): SortPass[] {
  const passes: SortPass[] = [];
  for (let shift = 0; shift < Math.max(1, bits); shift += digitBits) {
    const width = digitBits === 8 && bits - shift <= 4 ? 4 : digitBits;
    passes.push(lowBits === undefined ? { shift, component, bits: width } : { shift, component, bits: width, lowBits });
  }
  return passes;
}

/** Digit rows per scan workgroup for at most `tiles` tiles (shaders/radixSort.wgsl rows_per_group). */
function rowsPerGroup(tiles: number, digits: number): number {
  let rows = 1;
  while (rows < digits && 2 * rows * tiles <= SORT_TILE) rows *= 2;
  return rows;
}

export class RadixSort {
  private readonly ctx: GpuContext;
  private readonly upsweep: Kernel;
  private readonly scan: Kernel;
  private readonly downsweep: Kernel;
  private readonly downsweepWide: Kernel;
  private readonly tileHist: GpuArray;
  private readonly digitTotals: GpuArray;
  private readonly params = new Map<string, Uniform>();

  constructor(ctx: GpuContext) {
    this.ctx = ctx;
    this.upsweep = new Kernel(ctx, 'radixSort', 'upsweep');
    this.scan = new Kernel(ctx, 'radixSort', 'scan');
    this.downsweep = new Kernel(ctx, 'radixSort', 'downsweep');
    this.downsweepWide = new Kernel(ctx, 'radixSort', 'downsweep_wide');
    this.tileHist = new GpuArray(ctx, 'radix tileHist', 4, MAX_RADIX * 64);
    this.digitTotals = new GpuArray(ctx, 'radix digitTotals', 4, MAX_RADIX);
  }

  /** The last pass's count of each digit (16 or 256 u32; the narrow phase's bin sizes). */
  get digitTotalsBuffer(): GPUBuffer {
    return this.digitTotals.buffer;
  }

  /** Makes room for sorting up to `n` elements. */
  reserve(n: number): void {
    this.tileHist.ensure(MAX_RADIX * Math.max(1, Math.ceil(n / SORT_TILE)));
  }

  private uniform(pass: SortPass, countWord: number): Uniform {
    const bits = pass.bits ?? 4;
    const lowBits = pass.lowBits ?? 0;
    const key = `${pass.shift}:${pass.component}:${countWord}:${bits}:${lowBits}`;
    let u = this.params.get(key);
    if (!u) {
      if (pass.component === 2 && !(lowBits >= 1 && lowBits <= 31)) throw new Error(`RadixSort: lowBits ${lowBits} is not in [1, 31]`);
      u = new Uniform(this.ctx, `radix params ${key}`, 8);
      u.u32[0] = pass.shift;
      u.u32[1] = pass.component;
      u.u32[2] = countWord;
      u.u32[3] = bits;
      u.u32[4] = lowBits;
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
    const maxTiles = 'groups' in dispatch ? dispatch.groups : Math.ceil((dispatch.maxCount ?? Infinity) / SORT_TILE);
    for (const pass of passes) {
      const u = this.uniform(pass, countWord).buffer;
      const up = this.upsweep.bind({ 0: u, 1: src, 2: state, 3: this.tileHist.buffer });
      const sc = this.scan.bind({ 0: u, 2: state, 3: this.tileHist.buffer, 4: this.digitTotals.buffer });
      const bits = pass.bits ?? 4;
      const downsweep = bits === 8 ? this.downsweepWide : this.downsweep;
      const scanGroups = maxTiles <= SERIAL_TILES ? 1 : (1 << bits) / rowsPerGroup(maxTiles, 1 << bits);
      const down = downsweep.bind({ 0: u, 1: src, 2: state, 3: this.tileHist.buffer, 4: this.digitTotals.buffer, 5: dst });
      if ('groups' in dispatch) {
        rec.dispatch(this.upsweep, up, dispatch.groups);
        rec.dispatch(this.scan, sc, scanGroups);
        rec.dispatch(downsweep, down, dispatch.groups);
      } else {
        rec.dispatchIndirect(this.upsweep, up, dispatch.indirect, dispatch.offset);
        rec.dispatch(this.scan, sc, scanGroups);
        rec.dispatchIndirect(downsweep, down, dispatch.indirect, dispatch.offset);
      }
      const t = src;
      src = dst;
      dst = t;
    }
    return src;
  }
}
