/*
 * GpuPointQuery: which dynamic body holds a world point, answered on the GPU from the stepped
 * world's buffers with one small read-back (12 bytes), so that a page drawing 10^6 bodies with
 * GpuRenderer can pick one under the pointer without reading the world back (Synchronize) or
 * bringing the JavaScript broad phase up to date (QueryAABB).
 *
 * In:  the attached world's mirror: proxyRef, fixtureShape, shapePool, bodyXf, bodyCell,
 *      bodyFlags, after the steps called so far.
 * Out: bodyAt(): the b2Body (the lowest body slot when shapes of several bodies hold the point)
 *      and the point in that body's frame, or null.
 * Invariants: reads the world and never writes it; one query at a time (a second waits).
 */

import type { b2Body } from '../../src/dynamics/b2Body';
import type { WebGPUBackend } from '../backend/backend';
import { Kernel, Recorder, Uniform } from '../device/kernel';
import { MAP_READ, USAGE, WORKGROUP_SIZE } from '../device/layout';

const NO_HIT = 0xffffffff;
const HIT_BYTES = 16;

export interface GpuPointHit {
  body: b2Body;
  /** The point in the body's frame (b2Body::GetLocalPoint of it, from the GPU's transform). */
  localPoint: { x: number; y: number };
}

export class GpuPointQuery {
  readonly backend: WebGPUBackend;
  private readonly main: Kernel;
  private readonly resolve: Kernel;
  private readonly params: Uniform;
  private readonly hit: GPUBuffer;
  private readonly staging: GPUBuffer;
  private readonly clear = new Uint32Array([NO_HIT, 0, 0, 0]);
  private busy: Promise<unknown> = Promise.resolve();

  constructor(backend: WebGPUBackend) {
    this.backend = backend;
    const ctx = backend.ctx;
    this.main = new Kernel(ctx, 'pointQuery', 'main');
    this.resolve = new Kernel(ctx, 'pointQuery', 'resolve');
    this.params = new Uniform(ctx, 'pointQuery params', 8);
    this.hit = ctx.createBuffer('pointQuery hit', HIT_BYTES, USAGE.STORAGE | USAGE.COPY_SRC | USAGE.COPY_DST);
    this.staging = ctx.createBuffer('pointQuery staging', HIT_BYTES, USAGE.MAP_READ | USAGE.COPY_DST);
  }

  /** The dynamic body whose circle or polygon holds (x, y) after the steps called so far, or null. */
  bodyAt(x: number, y: number): Promise<GpuPointHit | null> {
    if (!Number.isFinite(x) || !Number.isFinite(y)) return Promise.reject(new RangeError(`GpuPointQuery.bodyAt: x and y must be finite, got (${x}, ${y})`));
    const next = this.busy.then(
      () => this.run(x, y),
      () => this.run(x, y),
    );
    this.busy = next;
    return next;
  }

  destroy(): void {
    this.params.destroy();
    this.hit.destroy();
    this.staging.destroy();
  }

  private async run(x: number, y: number): Promise<GpuPointHit | null> {
    await this.backend.submitted();
    const stepper = this.backend.stepper;
    if (stepper === null) throw new Error('GpuPointQuery.bodyAt: the backend is not attached to a world (world.SetBackend(backend) attaches it)');
    const mirror = stepper.mirror;
    const ctx = this.backend.ctx;
    const cellSize = mirror.cellSize;
    const cx = Math.round(x / cellSize);
    const cy = Math.round(y / cellSize);
    const p = this.params;
    p.i32[0] = cx;
    p.i32[1] = cy;
    p.f32[2] = x - cx * cellSize;
    p.f32[3] = y - cy * cellSize;
    p.f32[4] = cellSize;
    p.u32[5] = mirror.proxySlotCount;
    p.upload();
    ctx.device.queue.writeBuffer(this.hit, 0, this.clear);
    const search = this.main.bind({
      0: p.buffer,
      1: mirror.proxyRef.buffer,
      2: mirror.fixtureShape.buffer,
      3: mirror.shapePool.buffer,
      4: mirror.bodyXf.buffer,
      5: mirror.bodyCell.buffer,
      6: mirror.bodyFlags.buffer,
      7: this.hit,
    });
    // `resolve` reads only these (its pipeline's layout has only the bindings it uses).
    const resolve = this.resolve.bind({ 0: p.buffer, 4: mirror.bodyXf.buffer, 5: mirror.bodyCell.buffer, 7: this.hit });
    const encoder = ctx.device.createCommandEncoder({ label: 'pointQuery' });
    const pass = encoder.beginComputePass({ label: 'pointQuery' });
    const rec = new Recorder(pass, ctx.maxWorkgroupsPerDimension);
    rec.dispatch(this.main, search, Math.ceil(mirror.proxySlotCount / WORKGROUP_SIZE));
    rec.dispatch(this.resolve, resolve, 1);
    pass.end();
    encoder.copyBufferToBuffer(this.hit, 0, this.staging, 0, HIT_BYTES);
    ctx.device.queue.submit([encoder.finish()]);
    await this.staging.mapAsync(MAP_READ);
    const words = new Uint32Array(this.staging.getMappedRange().slice(0));
    this.staging.unmap();
    if (words[0] === NO_HIT) return null;
    const body = mirror.bodyAt(words[0]);
    if (body === null) return null;
    const f32 = new Float32Array(words.buffer);
    return { body, localPoint: { x: f32[1], y: f32[2] } };
  }
}
