/*
 * What the four collide stages share on the host (collideCircle.ts, collidePolygon.ts,
 * collideEdge.ts, overlap.ts): their bindings (shaders/shared/manifold.wgsl) and one indirect dispatch
 * per bin, sized by contacts.wgsl's bin_args (zero workgroups for an empty bin, so a scene
 * without a pair type runs nothing for it).
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import type { ShaderName } from '../device/shaders';
import { NP_ARGS } from '../device/layout';

export interface CollideInputs {
  /** CollideParams (cellSize). */
  params: GPUBuffer;
  npState: GPUBuffer;
  npIndirect: GPUBuffer;
  /** (bin, contact) sorted by bin. */
  binned: GPUBuffer;
  contactRef: GPUBuffer;
  fixtureShape: GPUBuffer;
  shapePool: GPUBuffer;
  bodyXf: GPUBuffer;
  bodyCell: GPUBuffer;
  manifolds: GPUBuffer;
}

export class CollideStage {
  /** The bins this stage's kernels handle, with their kernels. */
  readonly kernels: ReadonlyMap<number, Kernel>;

  constructor(ctx: GpuContext, shader: ShaderName, entries: readonly (readonly [bin: number, entryPoint: string])[]) {
    const kernels = new Map<number, Kernel>();
    for (const [bin, entry] of entries) kernels.set(bin, new Kernel(ctx, shader, entry));
    this.kernels = kernels;
  }

  /** Dispatches the kernel of `bin` over the bin's contacts. */
  encodeBin(rec: Recorder, bin: number, io: CollideInputs): void {
    const kernel = this.kernels.get(bin);
    if (!kernel) throw new Error(`no kernel for bin ${bin}`);
    const group = kernel.bind({
      0: io.params,
      1: io.npState,
      2: io.binned,
      3: io.contactRef,
      4: io.fixtureShape,
      5: io.shapePool,
      6: io.bodyXf,
      7: io.bodyCell,
      8: io.manifolds,
    });
    rec.dispatchIndirect(kernel, group, io.npIndirect, (NP_ARGS.BINS + 3 * bin) * 4);
  }
}
