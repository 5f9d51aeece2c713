/*
 * Narrow phase, circle-circle and polygon-circle (shaders/narrowphase/collideCircle.wgsl): b2CollideCircles
 * and b2CollidePolygonAndCircle in float32.
 *
 * In:  the contacts of BIN.CIRCLES and BIN.POLYGON_CIRCLE (binned list, contactRef, the world
 *      mirror's shapes and bodies; see collide.ts).
 * Out: their manifold records (layout.ts), header, ids, normal and points; the impulses and the
 *      other flags are persist.ts's.
 * One indirect dispatch per bin, zero workgroups when the bin is empty.
 */

import type { GpuContext } from '../device/device';
import { CollideStage } from './collide';
import { BIN } from '../device/layout';

export class CollideCircleStage extends CollideStage {
  constructor(ctx: GpuContext) {
    super(ctx, 'collideCircle', [
      [BIN.CIRCLES, 'circles'],
      [BIN.POLYGON_CIRCLE, 'polygon_circle'],
    ]);
  }
}
