/*
 * Narrow phase, polygon-polygon (shaders/narrowphase/collidePolygon.wgsl): b2CollidePolygons in float32.
 *
 * In:  the contacts of BIN.POLYGONS (binned list, contactRef, the world mirror's shapes and
 *      bodies; see collide.ts).
 * Out: their manifold records (layout.ts): e_faceA / e_faceB, up to two clip points with their
 *      b2ContactFeature keys.
 * One indirect dispatch, zero workgroups when the bin is empty.
 */

import type { GpuContext } from '../device/device';
import { CollideStage } from './collide';
import { BIN } from '../device/layout';

export class CollidePolygonStage extends CollideStage {
  constructor(ctx: GpuContext) {
    super(ctx, 'collidePolygon', [[BIN.POLYGONS, 'polygons']]);
  }
}
