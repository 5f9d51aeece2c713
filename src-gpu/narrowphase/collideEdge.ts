/*
 * Narrow phase, edges and chain children against circles and polygons (shaders/narrowphase/collideEdge.wgsl):
 * b2CollideEdgeAndCircle and b2CollideEdgeAndPolygon (b2EPCollider) of 2.2.1 in float32, with
 * ghost vertices (smooth collision over chain joints, one-sided edges).
 *
 * In:  the contacts of BIN.EDGE_CIRCLE, BIN.EDGE_POLYGON, BIN.CHAIN_CIRCLE, BIN.CHAIN_POLYGON
 *      (binned list, contactRef with the chain child index, the world mirror's shapes and
 *      bodies; see collide.ts).
 * Out: their manifold records (layout.ts).
 * One indirect dispatch per bin, zero workgroups when the bin is empty.
 */

import type { GpuContext } from '../device/device';
import { CollideStage } from './collide';
import { BIN } from '../device/layout';

export class CollideEdgeStage extends CollideStage {
  constructor(ctx: GpuContext) {
    super(ctx, 'collideEdge', [
      [BIN.EDGE_CIRCLE, 'edge_circle'],
      [BIN.EDGE_POLYGON, 'edge_polygon'],
      [BIN.CHAIN_CIRCLE, 'chain_circle'],
      [BIN.CHAIN_POLYGON, 'chain_polygon'],
    ]);
  }
}
