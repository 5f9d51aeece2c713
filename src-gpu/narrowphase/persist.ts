/*
 * GpuStage.Persist (shaders/narrowphase/persist.wgsl): touching state, warm-start impulses and
 * begin/end flags, as b2Contact::Update and b2ContactManager::Destroy give them.
 *
 * In:  this step's manifolds (from the collide kernels), contactRef (flags, previous index), the
 *      previous step's manifolds and keys, this step's keys, npState.
 * Out: completed manifold headers (MF flags, previous index) and impulses (carried by matching
 *      b2ContactID keys); a kept contact (CONTACT_KEPT, contacts.ts: bodies asleep or static, no
 *      kernel collided it) the previous step's manifold, touching state and impulses as they were;
 *      solverFlags (touching, not a sensor) and eventFlags (began or ended, then one slot per
 *      previous contact: gone while touching) for compact.ts's scans.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { NP_ARGS } from '../device/layout';

export interface PersistInputs {
  npState: GPUBuffer;
  npIndirect: GPUBuffer;
  contactRef: GPUBuffer;
  manifolds: GPUBuffer;
  prevManifolds: GPUBuffer;
  solverFlags: GPUBuffer;
  eventFlags: GPUBuffer;
  curKey: GPUBuffer;
  prevKey: GPUBuffer;
}

export class PersistStage {
  private readonly main: Kernel;
  private readonly vanished: Kernel;

  constructor(ctx: GpuContext) {
    this.main = new Kernel(ctx, 'persist', 'main');
    this.vanished = new Kernel(ctx, 'persist', 'vanished');
  }

  encode(rec: Recorder, io: PersistInputs): void {
    rec.dispatchIndirect(
      this.main,
      this.main.bind({ 0: io.npState, 1: io.contactRef, 2: io.manifolds, 3: io.prevManifolds, 4: io.solverFlags, 5: io.eventFlags }),
      io.npIndirect,
      NP_ARGS.CONTACTS * 4,
    );
    rec.dispatchIndirect(
      this.vanished,
      this.vanished.bind({ 0: io.npState, 3: io.prevManifolds, 5: io.eventFlags, 6: io.curKey, 7: io.prevKey }),
      io.npIndirect,
      NP_ARGS.PREV * 4,
    );
  }
}
