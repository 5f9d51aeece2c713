/*
 * GpuStage.Compact (shaders/narrowphase/compact.wgsl + two scans, shaders/primitives/scan.wgsl): the
 * solver's list of touching non-sensor contacts and the list of begin/end events.
 *
 * In:  solverFlags[0, NP.CONTACTS) and eventFlags[0, NP.EVENT_SLOTS) (persist.ts), the manifold
 *      headers and keys of this step and the previous one.
 * Out: solverList[0, NP.SOLVER) (contact indices, ascending), events[0, NP.EVENTS) (layout.ts),
 *      the counts in npState and the indirect size of a pass over the solver list (NP_ARGS.SOLVER).
 * Prefix scans (reduce-then-scan) give each kept element its place: the lists are in contact
 * order on every run. The flags are scanned in place.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { NP, NP_ARGS } from '../device/layout';
import { PrefixScan } from '../primitives/scan';

export interface CompactInputs {
  npState: GPUBuffer;
  npIndirect: GPUBuffer;
  manifolds: GPUBuffer;
  prevManifolds: GPUBuffer;
  solverFlags: GPUBuffer;
  eventFlags: GPUBuffer;
  curKey: GPUBuffer;
  prevKey: GPUBuffer;
  solverList: GPUBuffer;
  events: GPUBuffer;
}

export class CompactStage {
  private readonly main: Kernel;
  private readonly vanished: Kernel;
  private readonly args: Kernel;
  private readonly solverScan: PrefixScan;
  private readonly eventScan: PrefixScan;

  constructor(ctx: GpuContext) {
    this.main = new Kernel(ctx, 'compact', 'main');
    this.vanished = new Kernel(ctx, 'compact', 'vanished');
    this.args = new Kernel(ctx, 'compact', 'args');
    this.solverScan = new PrefixScan(ctx);
    this.eventScan = new PrefixScan(ctx);
  }

  /** Makes room for `capacity` contacts (and as many previous ones). */
  reserve(capacity: number): void {
    this.solverScan.reserve(capacity);
    this.eventScan.reserve(2 * capacity);
  }

  encode(rec: Recorder, io: CompactInputs): void {
    this.solverScan.encode(rec, io.solverFlags, io.npState, NP.CONTACTS, NP.SOLVER, { indirect: io.npIndirect, offset: NP_ARGS.BLOCKS * 4 });
    this.eventScan.encode(rec, io.eventFlags, io.npState, NP.EVENT_SLOTS, NP.EVENTS, {
      indirect: io.npIndirect,
      offset: NP_ARGS.EVENT_BLOCKS * 4,
    });
    rec.dispatchIndirect(
      this.main,
      this.main.bind({ 0: io.npState, 2: io.manifolds, 4: io.solverFlags, 5: io.eventFlags, 6: io.curKey, 8: io.solverList, 9: io.events }),
      io.npIndirect,
      NP_ARGS.CONTACTS * 4,
    );
    rec.dispatchIndirect(
      this.vanished,
      this.vanished.bind({ 0: io.npState, 3: io.prevManifolds, 5: io.eventFlags, 7: io.prevKey, 9: io.events }),
      io.npIndirect,
      NP_ARGS.PREV * 4,
    );
    rec.dispatch(this.args, this.args.bind({ 0: io.npState, 1: io.npIndirect }), 1);
  }
}
