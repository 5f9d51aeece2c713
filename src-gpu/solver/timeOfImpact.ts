/*
 * Continuous collision (shaders/solver/timeOfImpact.wgsl): 2.2.1's b2World::SolveTOI as one parallel
 * pass at the end of the step, so that a fast body does not tunnel through a thin wall.
 *
 * In:  this step's contacts (npState, contactRefs), solverState (SV.SKIP), the mirror's fixture
 *      and body tables; bodySweep holds the step's motion (c0, a0 at its start, c, a at its end).
 *      Recorded after the solver's sleep pass, as 2.2.1 runs SolveTOI after Solve.
 * Out: every awake dynamic body with a time of impact 0 < alpha <= 1 - 10 b2_epsilon among its
 *      contacts is moved back to its pose at the earliest one (b2Body::Advance: bodySweep c0 = c,
 *      a0 = a, alpha0, bodyXf); velocities are kept, so the next step's regular solver takes the
 *      contact.
 * Which contacts, which bodies (2.2.1): only when the world's continuous physics is on (the stage
 * records nothing otherwise: no dispatch); no sensors; one side a bullet or not dynamic (static,
 * kinematic), i.e. bullets against everything, every dynamic body against static and kinematic
 * ones; and only where the two shapes can approach by `minMotion` (b2_linearSlop) over the step:
 * resting and slow bodies are not tested, which changes no result but for pairs that already
 * overlap by more than 1.75 b2_linearSlop (timeOfImpact.wgsl says why). The contacts come from
 * this step's broad phase, whose AABBs include the motion predicted for the step
 * (src-gpu/broadphase/bounds.ts): 2.2.1 finds them after the solve from the swept AABBs of the
 * motion itself.
 * How it differs from 2.2.1 (which, in a loop, takes the earliest TOI of the world, advances its
 * two bodies, solves a mini island of them with b2_toiVelocityIterations / b2_toiPositionIterations
 * and continues the rest of the step in sub-steps):
 *   - one TOI per contact over the whole step, computed in parallel; each dynamic body stops at
 *     the minimum over its contacts (an integer atomicMax: the same bits every run);
 *   - no TOI island solve and no sub-stepping: the rest of the step (1 - alpha) is dropped, the
 *     contact is solved by the next step (so a bullet stops at the wall and bounces one step
 *     later instead of within the step); kinematic bodies are not moved back;
 *   - a contact touching at alpha = 0 is left to the regular solver (2.2.1 solves it as a TOI
 *     island): stopping there would undo the step's position correction every step;
 *   - bodies touching the TOI bodies are not advanced with them;
 *   - slow pairs are not tested (above);
 *   - a pair can be missed where the prediction falls short (a world's first step, whose dt is
 *     not known yet; a velocity changed within the step by more than the prediction).
 * Costs: three dispatches (one invocation, one per contact, one per body slot); the distance
 * computations only for the fast pairs.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Kernel, Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { MAP_READ, USAGE, WORKGROUP_SIZE } from '../device/layout';
import { readBuffer } from '../device/readback';
import { b2_linearSlop } from '../../src/common/b2Settings';
import type { GpuWorld } from '../world/world';

export interface TimeOfImpactInputs {
  solverState: GPUBuffer;
  npState: GPUBuffer;
  contactRefs: GPUBuffer;
}

/** b2TOIOutput's state and time, as evaluate() returns them. */
export interface ToiResult {
  state: number;
  t: number;
}

export class TimeOfImpactStage {
  private readonly ctx: GpuContext;
  private readonly begin: Kernel;
  private readonly candidates: Kernel;
  private readonly advance: Kernel;
  private readonly params: Uniform;
  private readonly indirect: GPUBuffer;
  /**
   * Word 0: contacts to test; word 1: contacts tested; word 2 + body slot: that body's TOI key (0:
   * none, the state between steps).
   */
  private readonly bodies: GpuArray;
  /**
   * The least approach of two shapes over a step (metres) for which their contact is tested. A
   * seam for tests: 0 tests every contact 2.2.1 would; Infinity none.
   */
  minMotion = b2_linearSlop;

  constructor(ctx: GpuContext) {
    this.ctx = ctx;
    this.begin = new Kernel(ctx, 'timeOfImpact', 'begin');
    this.candidates = new Kernel(ctx, 'timeOfImpact', 'candidates');
    this.advance = new Kernel(ctx, 'timeOfImpact', 'advance');
    this.params = new Uniform(ctx, 'toi params', 4);
    this.indirect = ctx.createBuffer('toi indirect', 16, USAGE.STORAGE | USAGE.INDIRECT);
    this.bodies = new GpuArray(ctx, 'toi bodies', 4, 64);
  }

  /** Records begin, candidates and advance for the step whose contacts are `io`. */
  encode(rec: Recorder, io: TimeOfImpactInputs, mirror: GpuWorld): void {
    const slots = mirror.bodySlotCount;
    // A new buffer is zeros, which is the state between steps: nothing to carry over.
    this.bodies.ensure(slots + 2);
    const p = this.params;
    p.f32[0] = mirror.cellSize;
    p.u32[1] = slots;
    p.f32[3] = this.minMotion;
    p.upload();
    const bodies = this.bodies.buffer;
    rec.dispatch(this.begin, this.begin.bind({ 1: io.npState, 10: io.solverState, 11: this.indirect, 12: bodies }), 1);
    const candidates = this.candidates.bind({
      3: io.contactRefs,
      4: mirror.fixtureShape.buffer,
      5: mirror.shapePool.buffer,
      7: mirror.bodyCell.buffer,
      9: p.buffer,
      12: bodies,
      13: mirror.bodyFlags.buffer,
      14: mirror.bodyMass.buffer,
      15: mirror.bodySweep.buffer,
    });
    rec.dispatchIndirect(this.candidates, candidates, this.indirect, 0);
    const advance = this.advance.bind({
      9: p.buffer,
      10: io.solverState,
      12: bodies,
      14: mirror.bodyMass.buffer,
      16: mirror.bodySweep.buffer,
      17: mirror.bodyXf.buffer,
      19: mirror.bodyAwake.buffer,
    });
    rec.dispatch(this.advance, advance, Math.ceil(slots / WORKGROUP_SIZE));
  }

  /**
   * For tests and tools (not part of a step): b2TimeOfImpact over [0, 1] on the GPU for records
   * in contactRef's layout (8 words each: fixture A, child A, body A, 0, fixture B, child B,
   * body B, 0), with the mirror's sweeps and shapes as uploaded, without the stage's filters.
   */
  async evaluate(mirror: GpuWorld, refs: Uint32Array<ArrayBuffer>): Promise<ToiResult[]> {
    const ctx = this.ctx;
    ctx.assertAlive();
    const n = refs.length / 8;
    if (n === 0) return [];
    const kernel = new Kernel(ctx, 'timeOfImpact', 'evaluate');
    const params = new Uniform(ctx, 'toi evaluate params', 4);
    params.f32[0] = mirror.cellSize;
    params.u32[1] = mirror.bodySlotCount;
    params.u32[2] = n;
    params.upload();
    const input = ctx.createBuffer('toi evaluate refs', refs.byteLength, USAGE.STORAGE | USAGE.COPY_DST);
    ctx.device.queue.writeBuffer(input, 0, refs);
    const output = ctx.createBuffer('toi evaluate output', 8 * n, USAGE.STORAGE | USAGE.COPY_SRC);
    const staging = ctx.createBuffer('toi evaluate read', 8 * n, USAGE.MAP_READ | USAGE.COPY_DST);
    const group = kernel.bind({
      3: input,
      4: mirror.fixtureShape.buffer,
      5: mirror.shapePool.buffer,
      7: mirror.bodyCell.buffer,
      9: params.buffer,
      14: mirror.bodyMass.buffer,
      15: mirror.bodySweep.buffer,
      18: output,
    });
    const encoder = ctx.device.createCommandEncoder({ label: 'toi evaluate' });
    const pass = encoder.beginComputePass({ label: 'toi evaluate' });
    pass.setPipeline(kernel.pipeline);
    pass.setBindGroup(0, group);
    pass.dispatchWorkgroups(Math.ceil(n / WORKGROUP_SIZE));
    pass.end();
    encoder.copyBufferToBuffer(output, 0, staging, 0, 8 * n);
    ctx.device.queue.submit([encoder.finish()]);
    await staging.mapAsync(MAP_READ);
    const words = new Uint32Array(staging.getMappedRange().slice(0));
    staging.unmap();
    for (const b of [input, output, staging]) b.destroy();
    params.destroy();
    const f32 = new Float32Array(words.buffer);
    const out: ToiResult[] = [];
    for (let k = 0; k < n; ++k) out.push({ state: words[2 * k], t: f32[2 * k + 1] });
    return out;
  }

  /** For tests and tools: the contacts the last recorded step ran b2TimeOfImpact for. */
  async testedContacts(): Promise<number> {
    return new Uint32Array(await readBuffer(this.ctx, this.bodies.buffer, 8, 'toi debug read'))[1];
  }

  destroy(): void {
    this.params.destroy();
    this.indirect.destroy();
    this.bodies.destroy();
  }
}
