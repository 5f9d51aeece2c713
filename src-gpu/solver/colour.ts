/*
 * GpuStage.Colour, graph colouring (shaders/solver/colour.wgsl + a two-pass radix sort): hashed-priority
 * Jones-Plassmann over the solver's items, joints and contacts together (items 0 .. joints - 1
 * are joint slots, then solver contact k is item joints + k), then the items of each colour as
 * one list: joints, then contacts.
 *
 * In:  the solver's parameters (joint slots), the broad phase's and narrow phase's state
 *      (overflow flags, NP_SOLVER), contactBodies (prepareContacts.ts) and jointBodies
 *      (solveJoints.ts): bodies, which are dynamic (a gear joint has four).
 * Out: colours[item] in [0, COLOUR_CAP), COLOUR_CAP (the overflow set) or COLOUR_IDLE (no dynamic
 *      body: nothing to solve); colourKeys: (colour, item) sorted by colour, items ascending
 *      within one; solverState[SV.COLOUR_START + c] (COLOUR_CAP + 2 words: the last is the
 *      overflow set's end, so no pass reaches the idle items after it); the indirect sizes of
 *      each colour's passes (SV_ARGS.COLOURS, SV_ARGS.POSITION: a 1-invocation pass for the
 *      overflow set, which is solved in order).
 *      `encodeBegin` also sets SV.SKIP / SV.COUNT / SV.JOINTS / SV.ITEMS (nothing is solved when
 *      collision overflowed: the host reruns it, and the solver with it), zeroes SV.PENETRATION
 *      (penetration.ts) and SV.AWAKE (islands.ts counts into it) and sets the per-contact and per-item indirect sizes.
 * Rounds: COLOUR_CAP rounds of two dispatches (post priorities with atomicMax, then pick the
 *      local maxima), whatever the contact count: no read-back decides when to stop. A round
 *      with nothing left to colour costs two empty-ish dispatches. A small world runs every
 *      round in one dispatch of one workgroup (`rounds`, with barriers): the same colours.
 * Reuse: a colouring depends only on each item's dynamic bodies, so while the items and their
 *      dynamic bodies are those of the last colouring (a resting pile: same contacts in the same
 *      order), `compare` finds no change and the rounds and the sort are dispatched with zero
 *      workgroups; the last colours and sorted keys stand, bit for bit what colouring again would
 *      give. Decided on the GPU (no read-back); the host only forces a colouring when it replaced
 *      a buffer that holds the last one.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Kernel } from '../device/kernel';
import type { Recorder, Uniform } from '../device/kernel';
import { COLOUR_CAP, COLOUR_IDLE, SV, SV_ARGS } from '../device/layout';
import { RadixSort, digitPasses } from '../primitives/radixSort';
import type { SortPass } from '../primitives/radixSort';

export interface ColourInputs {
  broadState: GPUBuffer;
  npState: GPUBuffer;
  solverState: GPUBuffer;
  solverIndirect: GPUBuffer;
  contactBodies: GPUBuffer;
  /** The solver's parameters (SolverParams: the joint slot count). */
  params: GPUBuffer;
  /** Per joint slot: bodies and dynamic mask (solveJoints.ts). */
  jointBodies: GPUBuffer;
  /** One uniform per round / colour (ColourParams), COLOUR_CAP + 1 of them. */
  rounds: Uniform[];
}

export class ColourStage {
  private readonly beginKernel: Kernel;
  private readonly invalidate: Kernel;
  private readonly compare: Kernel;
  private readonly decide: Kernel;
  private readonly mark: Kernel;
  private readonly pick: Kernel;
  private readonly rounds: Kernel;
  private readonly offsets: Kernel;
  private readonly sort: RadixSort;
  private readonly sortPasses: SortPass[] = digitPasses(Math.ceil(Math.log2(COLOUR_IDLE + 1)), 0);
  /** Colour per item. */
  readonly colours: GpuArray;
  /** (colour, item) per item; sorted by colour after encode(). */
  readonly keys: GpuArray;
  private readonly keysTmp: GpuArray;
  /** Two words per body slot (round parity), zero between steps. */
  private readonly bodyMark: GpuArray;
  /** Per item, the dynamic bodies the last colouring saw. */
  private readonly signatures: GpuArray;
  /** A buffer holding the last colouring was replaced: the next step colours again. */
  private stale = true;

  constructor(ctx: GpuContext) {
    this.beginKernel = new Kernel(ctx, 'colour', 'begin');
    this.invalidate = new Kernel(ctx, 'colour', 'invalidate');
    this.compare = new Kernel(ctx, 'colour', 'compare');
    this.decide = new Kernel(ctx, 'colour', 'decide');
    this.mark = new Kernel(ctx, 'colour', 'mark');
    this.pick = new Kernel(ctx, 'colour', 'pick');
    this.rounds = new Kernel(ctx, 'colour', 'rounds');
    this.offsets = new Kernel(ctx, 'colour', 'offsets');
    this.sort = new RadixSort(ctx);
    this.colours = new GpuArray(ctx, 'colours', 4, 64);
    this.keys = new GpuArray(ctx, 'colour keys', 8, 64);
    this.keysTmp = new GpuArray(ctx, 'colour keys tmp', 8, 64);
    this.bodyMark = new GpuArray(ctx, 'colour body marks', 8, 64);
    this.signatures = new GpuArray(ctx, 'colour signatures', 16, 64);
  }

  /** Makes room for `items` items (joint slots and solver contacts) and `bodies` body slots. */
  reserve(items: number, bodies: number): void {
    let replaced = this.colours.ensure(items);
    replaced = this.keys.ensure(items) || replaced;
    replaced = this.signatures.ensure(items) || replaced;
    if (replaced) this.stale = true;
    this.keysTmp.ensure(items);
    this.sort.reserve(items);
    // A new buffer is zero: the marks' invariant holds without copying.
    this.bodyMark.ensure(bodies);
  }

  encodeBegin(rec: Recorder, io: ColourInputs): void {
    rec.dispatch(this.beginKernel, this.beginKernel.bind({ 1: io.broadState, 2: io.npState, 3: io.solverState, 4: io.solverIndirect, 9: io.params }), 1);
  }

  /** The colouring; `fused`: every round in one dispatch of one workgroup (a small world). */
  encode(rec: Recorder, io: ColourInputs, fused: boolean): void {
    if (this.stale) {
      rec.dispatch(this.invalidate, this.invalidate.bind({ 3: io.solverState }), 1);
      this.stale = false;
    }
    const compare = this.compare.bind({ 3: io.solverState, 5: io.contactBodies, 10: io.jointBodies, 11: this.signatures.buffer });
    rec.dispatchIndirect(this.compare, compare, io.solverIndirect, SV_ARGS.ITEMS * 4);
    rec.dispatch(this.decide, this.decide.bind({ 3: io.solverState, 4: io.solverIndirect }), 1);
    const args = SV_ARGS.ROUNDS * 4;
    // What `pick` and `rounds` bind (`pick` adds its round's uniform at 0).
    const picks = {
      3: io.solverState,
      5: io.contactBodies,
      6: this.colours.buffer,
      7: this.bodyMark.buffer,
      8: this.keys.buffer,
      10: io.jointBodies,
      11: this.signatures.buffer,
    };
    if (fused) rec.dispatch(this.rounds, this.rounds.bind(picks), 1);
    for (let round = 0; round <= COLOUR_CAP && !fused; ++round) {
      const u = io.rounds[round].buffer;
      if (round < COLOUR_CAP) {
        const group = this.mark.bind({ 0: u, 3: io.solverState, 5: io.contactBodies, 6: this.colours.buffer, 7: this.bodyMark.buffer, 10: io.jointBodies });
        rec.dispatchIndirect(this.mark, group, io.solverIndirect, args);
      }
      rec.dispatchIndirect(this.pick, this.pick.bind({ 0: u, ...picks }), io.solverIndirect, args);
    }
    const sorted = this.sort.encode(rec, this.keys.buffer, this.keysTmp.buffer, this.sortPasses, io.solverState, SV.COLOUR_SORT_COUNT, {
      indirect: io.solverIndirect,
      offset: SV_ARGS.TILES * 4,
    });
    if (sorted !== this.keys.buffer) throw new Error('colour sort: an even number of passes is expected');
    rec.dispatch(this.offsets, this.offsets.bind({ 3: io.solverState, 4: io.solverIndirect, 8: this.keys.buffer }), 1);
  }

  destroy(): void {
    for (const a of [this.colours, this.keys, this.keysTmp, this.bodyMark, this.signatures]) a.destroy();
  }
}
