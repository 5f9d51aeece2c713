/*
 * GpuStage.Prepare, the contacts (shaders/solver/prepareContacts.wgsl): the solver contacts of the step,
 * as b2ContactSolver's constructor and InitializeVelocityConstraints build them.
 *
 * In:  solverState[SV.COUNT] (the solver list's length), the narrow phase's solverList,
 *      contactRefs and manifolds (warm-start impulses in word 3), the mirror's fixtureShape,
 *      fixtureMaterial, bodyMass, and after GpuStage.IntegrateVelocities bodySweep, bodyVel, bodyCell; the solver's
 *      parameters (dtRatio, warmStarting, cellSize); the mirror's bodyAwake (after the island
 *      search: the contacts of sleeping islands are given no points to solve).
 * Out: contactBodies and constraints per solver contact (shaders/shared/solverCommon.wgsl): three
 *      passes, split so that no kernel binds more than 8 storage buffers.
 */

import type { GpuContext } from '../device/device';
import { Kernel } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { SV_ARGS } from '../device/layout';
import type { GpuWorld } from '../world/world';

export interface PrepareInputs {
  params: GPUBuffer;
  solverState: GPUBuffer;
  solverIndirect: GPUBuffer;
  solverList: GPUBuffer;
  contactRefs: GPUBuffer;
  manifolds: GPUBuffer;
  contactBodies: GPUBuffer;
  constraints: GPUBuffer;
}

export class PrepareContactsStage {
  private readonly bodies: Kernel;
  private readonly manifold: Kernel;
  private readonly velocity: Kernel;

  constructor(ctx: GpuContext) {
    this.bodies = new Kernel(ctx, 'prepareContacts', 'bodies');
    this.manifold = new Kernel(ctx, 'prepareContacts', 'manifold');
    this.velocity = new Kernel(ctx, 'prepareContacts', 'velocity');
  }

  encode(rec: Recorder, io: PrepareInputs, mirror: GpuWorld): void {
    const offset = SV_ARGS.CONTACTS * 4;
    rec.dispatchIndirect(
      this.bodies,
      this.bodies.bind({
        1: io.solverState,
        2: io.solverList,
        3: io.contactRefs,
        4: mirror.fixtureShape.buffer,
        5: mirror.fixtureMaterial.buffer,
        6: mirror.bodyMass.buffer,
        7: io.contactBodies,
        8: io.constraints,
      }),
      io.solverIndirect,
      offset,
    );
    rec.dispatchIndirect(
      this.manifold,
      this.manifold.bind({ 0: io.params, 1: io.solverState, 7: io.contactBodies, 8: io.constraints, 9: io.manifolds, 13: mirror.bodyAwake.buffer }),
      io.solverIndirect,
      offset,
    );
    rec.dispatchIndirect(
      this.velocity,
      this.velocity.bind({
        0: io.params,
        1: io.solverState,
        7: io.contactBodies,
        8: io.constraints,
        10: mirror.bodySweep.buffer,
        11: mirror.bodyVel.buffer,
        12: mirror.bodyCell.buffer,
      }),
      io.solverIndirect,
      offset,
    );
  }
}
