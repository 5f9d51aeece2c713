/*
 * Narrow phase, sensor contacts (shaders/narrowphase/overlap.wgsl): b2TestOverlap (GJK distance with radii
 * < 10 * b2_epsilon) in float32.
 *
 * In:  the contacts of BIN.SENSOR (either fixture a sensor; any shape pair with a contact type).
 * Out: their manifold records: no points, MF_TOUCHING when the shapes overlap.
 * One indirect dispatch, zero workgroups when there is no sensor contact.
 */

import type { GpuContext } from '../device/device';
import { CollideStage } from './collide';
import { BIN } from '../device/layout';

export class OverlapStage extends CollideStage {
  constructor(ctx: GpuContext) {
    super(ctx, 'overlap', [[BIN.SENSOR, 'sensors']]);
  }
}
