/*
 * Radix sort (shaders/primitives/radixSort.wgsl): a stable LSD sort of vec2<u32> elements, 4 or 8 bits per
 * pass (reduce-then-scan, no decoupled look-back): an upsweep counting the first pass's digits per
 * tile, then two dispatches per pass, scan and downsweep, the downsweep also counting the next
 * pass's digits per tile of its output (2P + 1 dispatches for P passes: 7 for the entry sort, 11
 * for the pair sort of 10^6 slots; 3P before).
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

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Kernel, Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { SORT_TILE } from '../device/layout';

/** Digit values of the widest pass (shaders/primitives/radixSort.wgsl MAX_RADIX). */
const MAX_RADIX = 256;
/** Tiles up to which the scan is one workgroup (shaders/primitives/radixSort.wgsl SERIAL_TILES). */
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
 * workgroups than one per digit value (shaders/primitives/radixSort.wgsl SERIAL_TILES, rows_per_group).
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

/** Digit rows per scan workgroup for at most `tiles` tiles (shaders/primitives/radixSort.wgsl rows_per_group). */
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
  /** Tile histograms, alternating per pass: pass k's counts, then prefix sums, in hist[k % 2]. */
  private readonly hist: [GpuArray, GpuArray];
  private readonly digitTotals: GpuArray;
  private readonly params = new Map<string, Uniform>();

  constructor(ctx: GpuContext) {
    this.ctx = ctx;
    this.upsweep = new Kernel(ctx, 'radixSort', 'upsweep');
    this.scan = new Kernel(ctx, 'radixSort', 'scan');
    this.downsweep = new Kernel(ctx, 'radixSort', 'downsweep');
    this.downsweepWide = new Kernel(ctx, 'radixSort', 'downsweep_wide');
    this.hist = [new GpuArray(ctx, 'radix tileHist 0', 4, MAX_RADIX * 64), new GpuArray(ctx, 'radix tileHist 1', 4, MAX_RADIX * 64)];
    this.digitTotals = new GpuArray(ctx, 'radix digitTotals', 4, MAX_RADIX);
  }

  /** The last pass's count of each digit (16 or 256 u32; the narrow phase's bin sizes). */
  get digitTotalsBuffer(): GPUBuffer {
    return this.digitTotals.buffer;
  }

  /**
   * The tile histograms after the last encoded sort (pass k's per-tile counts, turned into
   * exclusive prefix sums over the tiles by its scan, are in histograms[k % 2], at
   * digit * tiles + tile).
   */
  get histograms(): readonly [GPUBuffer, GPUBuffer] {
    return [this.hist[0].buffer, this.hist[1].buffer];
  }

  /** Makes room for sorting up to `n` elements. */
  reserve(n: number): void {
    for (const h of this.hist) h.ensure(MAX_RADIX * Math.max(1, Math.ceil(n / SORT_TILE)));
  }

  /** The parameters of `pass`, followed by `next` (undefined: the last pass). */
  private uniform(pass: SortPass, next: SortPass | undefined, countWord: number): Uniform {
    const bits = pass.bits ?? 4;
    const lowBits = pass.lowBits ?? 0;
    const nextBits = next ? (next.bits ?? 4) : 0;
    const nextLowBits = next?.lowBits ?? 0;
    const key = `${pass.shift}:${pass.component}:${countWord}:${bits}:${lowBits}>${next ? `${next.shift}:${next.component}:${nextBits}:${nextLowBits}` : 'last'}`;
    let u = this.params.get(key);
    if (!u) {
      for (const p of next ? [pass, next] : [pass]) {
        const low = p.lowBits ?? 0;
        if (p.component === 2 && !(low >= 1 && low <= 31)) throw new Error(`RadixSort: lowBits ${low} is not in [1, 31]`);
      }
      u = new Uniform(this.ctx, `radix params ${key}`, 12);
      u.u32[0] = pass.shift;
      u.u32[1] = pass.component;
      u.u32[2] = countWord;
      u.u32[3] = bits;
      u.u32[4] = lowBits;
      u.u32[5] = next?.shift ?? 0;
      u.u32[6] = next?.component ?? 0;
      u.u32[7] = nextBits;
      u.u32[8] = nextLowBits;
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
    for (let k = 0; k < passes.length; ++k) {
      const pass = passes[k];
      const u = this.uniform(pass, passes[k + 1], countWord).buffer;
      const hist = this.hist[k % 2].buffer;
      // The last pass counts nothing, but the binding is static: it gets the idle buffer too.
      const nextHist = this.hist[(k + 1) % 2].buffer;
      const bits = pass.bits ?? 4;
      const downsweep = bits === 8 ? this.downsweepWide : this.downsweep;
      const scanGroups = maxTiles <= SERIAL_TILES ? 1 : (1 << bits) / rowsPerGroup(maxTiles, 1 << bits);
      const sc = this.scan.bind({ 0: u, 2: state, 3: hist, 4: this.digitTotals.buffer, 6: nextHist });
      const down = downsweep.bind({ 0: u, 1: src, 2: state, 3: hist, 4: this.digitTotals.buffer, 5: dst, 6: nextHist });
      if (k === 0) {
        const up = this.upsweep.bind({ 0: u, 1: src, 2: state, 3: hist });
        if ('groups' in dispatch) rec.dispatch(this.upsweep, up, dispatch.groups);
        else rec.dispatchIndirect(this.upsweep, up, dispatch.indirect, dispatch.offset);
      }
      rec.dispatch(this.scan, sc, scanGroups);
      if ('groups' in dispatch) rec.dispatch(downsweep, down, dispatch.groups);
      else rec.dispatchIndirect(downsweep, down, dispatch.indirect, dispatch.offset);
      const t = src;
      src = dst;
      dst = t;
    }
    return src;
  }
}
