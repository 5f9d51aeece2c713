/*
 * What the four collide stages share on the host (collideCircle.ts, collidePolygon.ts,
 * collideEdge.ts, overlap.ts): their bindings (shaders/shared/manifold.wgsl) and one indirect dispatch
 * per bin, sized by contacts.wgsl's bin_args (zero workgroups for an empty bin), recorded only
 * for the bins the world's fixtures can fill (binInUse). The contacts of bodies asleep or static
 * are sorted after every bin (BIN.KEPT, contacts.ts) and reach no kernel: persist.ts carries their
 * manifolds over. The kernels bind 8 storage buffers, the most a stage may, so the awake flags
 * are read by contacts.wgsl's `keep` pass instead.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import type { ShaderName } from '../device/shaders';
import { b2ShapeType } from '../../src/common/b2Constants';
import { BIN, NP_ARGS } from '../device/layout';
import type { WorldCensus } from '../world/world';

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

/** Whether a world with these fixtures can have a pair in `bin` (BIN); false: its dispatch is left out. */
export function binInUse(bin: number, census: WorldCensus): boolean {
  const n = census.shapes;
  switch (bin) {
    case BIN.CIRCLES:
      return n[b2ShapeType.e_circle] > 1;
    case BIN.POLYGON_CIRCLE:
      return n[b2ShapeType.e_polygon] > 0 && n[b2ShapeType.e_circle] > 0;
    case BIN.POLYGONS:
      return n[b2ShapeType.e_polygon] > 1;
    case BIN.EDGE_CIRCLE:
      return n[b2ShapeType.e_edge] > 0 && n[b2ShapeType.e_circle] > 0;
    case BIN.EDGE_POLYGON:
      return n[b2ShapeType.e_edge] > 0 && n[b2ShapeType.e_polygon] > 0;
    case BIN.CHAIN_CIRCLE:
      return n[b2ShapeType.e_chain] > 0 && n[b2ShapeType.e_circle] > 0;
    case BIN.CHAIN_POLYGON:
      return n[b2ShapeType.e_chain] > 0 && n[b2ShapeType.e_polygon] > 0;
    case BIN.SENSOR:
      return census.sensors > 0;
    default:
      return true;
  }
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
