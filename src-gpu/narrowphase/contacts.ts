/*
 * GpuStage.Contacts (shaders/narrowphase/contacts.wgsl + one radix-sort pass): from the broad
 * phase's sorted pairs to oriented contacts, binned by pair type and matched with the previous
 * step's.
 *
 * In:  the broad phase's sorted pairs and state (STATE.PAIR_SORT_COUNT); the world mirror's
 *      proxyRef, proxyKey, bodyFlags and bodyAwake; the previous contact set's keys and count
 *      (npState).
 * Out: npState[NP.CONTACTS], NP.PREV, NP.EVENT_SLOTS and the indirect sizes of the passes over
 *      contacts (`begin`); per contact its key, its oriented fixtures (contactRef) and the previous
 *      step's index (`classify`); CONTACT_KEPT on the contacts of the previous step whose bodies are
 *      both asleep or static (`keep`: b2ContactManager::Collide skips them); the contacts sorted by
 *      bin, stably (one 4-bit radix pass, so each bin keeps key order), the kept ones after every
 *      bin (BIN.KEPT), and the bins' offsets and indirect sizes and the kept count (`bin_args`,
 *      NP.KEPT).
 * Binning costs no read-back: count (the radix pass's per-tile histograms), scan (its digit
 * totals), scatter (its downsweep); an empty bin gets an indirect size of zero workgroups, and no
 * collide kernel runs over the kept contacts: a sleeping pile costs the copy persist.ts makes.
 * Invariants: `keep` is a pass of its own since classify binds the 8 storage buffers a stage may
 * (the device keeps the default limits); the rule and its differences from 2.2.1 are in
 * contacts.wgsl's header.
 */

import type { GpuContext } from '../device/device';
import { Kernel, Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { NP, NP_ARGS } from '../device/layout';
import { RadixSort } from '../primitives/radixSort';

export interface ContactsInputs {
  broadState: GPUBuffer;
  pairs: GPUBuffer;
  proxyRef: GPUBuffer;
  proxyKey: GPUBuffer;
  npState: GPUBuffer;
  npIndirect: GPUBuffer;
  curKey: GPUBuffer;
  prevKey: GPUBuffer;
  contactRef: GPUBuffer;
  items: GPUBuffer;
  itemsTmp: GPUBuffer;
  bodyFlags: GPUBuffer;
  bodyAwake: GPUBuffer;
}

export class ContactsStage {
  private readonly begin: Kernel;
  private readonly classify: Kernel;
  private readonly keep: Kernel;
  private readonly binArgs: Kernel;
  private readonly params: Uniform;
  readonly sort: RadixSort;

  constructor(ctx: GpuContext) {
    this.begin = new Kernel(ctx, 'contacts', 'begin');
    this.classify = new Kernel(ctx, 'contacts', 'classify');
    this.keep = new Kernel(ctx, 'contacts', 'keep');
    this.binArgs = new Kernel(ctx, 'contacts', 'bin_args');
    this.params = new Uniform(ctx, 'contacts params', 4);
    this.sort = new RadixSort(ctx);
  }

  /** Makes room for `capacity` contacts. */
  reserve(capacity: number): void {
    this.sort.reserve(capacity);
  }

  /** begin, classify, keep, the bin sort, bin_args; returns the buffer holding the binned (bin, contact) list. */
  encode(rec: Recorder, io: ContactsInputs, curSet: number): GPUBuffer {
    this.params.u32[0] = curSet;
    this.params.upload();
    const u = this.params.buffer;
    rec.dispatch(this.begin, this.begin.bind({ 0: u, 1: io.broadState, 2: io.npState, 3: io.npIndirect }), 1);
    rec.dispatchIndirect(
      this.classify,
      this.classify.bind({
        2: io.npState,
        4: io.pairs,
        5: io.proxyRef,
        6: io.proxyKey,
        7: io.curKey,
        8: io.prevKey,
        9: io.contactRef,
        10: io.items,
      }),
      io.npIndirect,
      NP_ARGS.CONTACTS * 4,
    );
    rec.dispatchIndirect(
      this.keep,
      this.keep.bind({ 2: io.npState, 9: io.contactRef, 10: io.items, 12: io.bodyFlags, 13: io.bodyAwake }),
      io.npIndirect,
      NP_ARGS.CONTACTS * 4,
    );
    const binned = this.sort.encode(rec, io.items, io.itemsTmp, [{ shift: 0, component: 0 }], io.npState, NP.CONTACTS, {
      indirect: io.npIndirect,
      offset: NP_ARGS.TILES * 4,
    });
    rec.dispatch(this.binArgs, this.binArgs.bind({ 2: io.npState, 3: io.npIndirect, 11: this.sort.digitTotalsBuffer }), 1);
    return binned;
  }
}
