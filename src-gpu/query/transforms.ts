/*
 * GpuTransformRead: the bulk read of every body's transform into a Float32Array
 * (WebGPUBackend.readTransforms), packed on the GPU in the application's layout so that the host's
 * share is one copy of 16 bytes a body (and one of a byte a body for the awake flags) whatever the
 * world's size. Converting cells and offsets on the host instead, a body at a time from the
 * mapped state, cost several times the step itself at 10^6 bodies.
 *
 * In:  the world's mirror: bodyXf, bodyCell, bodyFlags, bodyAwake, after the steps submitted.
 * Out: read(): every body slot's (x, y, cos, sin) in world coordinates at 4 * slot of `out`, NaN
 *      for a slot without a body, and its awake flag (1 or 0) at `awake[slot]`.
 * Invariants: reads the world and never writes it; one read at a time (the caller serialises).
 */

import type { GpuContext } from '../device/device';
import { Kernel, Recorder, Uniform } from '../device/kernel';
import { USAGE, WORKGROUP_SIZE } from '../device/layout';
import { StagingBuffer } from '../device/readback';
import type { GpuWorld } from '../world/world';

/** Bytes per body slot of the packed transforms (four float32). */
const TRANSFORM_BYTES = 16;
/** Body slots per awake word (a byte each). */
const SLOTS_PER_AWAKE_WORD = 4;

export class GpuTransformRead {
  private readonly ctx: GpuContext;
  private readonly kernel: Kernel;
  private readonly params: Uniform;
  private transforms: GPUBuffer | null = null;
  private awakeBytes: GPUBuffer | null = null;
  private capacity = 0;
  private readonly staging: StagingBuffer;
  /** Milliseconds the last read() took from the map resolving to the data copied out. */
  copyMs = 0;

  constructor(ctx: GpuContext) {
    this.ctx = ctx;
    this.kernel = new Kernel(ctx, 'transforms', 'main');
    this.params = new Uniform(ctx, 'transforms params', 4);
    this.staging = new StagingBuffer(ctx, 'transforms read-back', 64 * TRANSFORM_BYTES);
  }

  /**
   * Packs, maps and copies the transforms of `mirror`'s body slots into `out` (and the awake flags
   * into `awake` when given) after every submission so far. Returns the bytes mapped.
   */
  async read(mirror: GpuWorld, out: Float32Array, awake: Uint8Array | undefined): Promise<number> {
    const n = mirror.bodySlotCount;
    const words = Math.ceil(n / SLOTS_PER_AWAKE_WORD);
    const transformBytes = TRANSFORM_BYTES * n;
    this.reserve(n);
    const p = this.params;
    p.u32[0] = n;
    p.f32[1] = mirror.cellSize;
    p.upload();
    const group = this.kernel.bind({
      0: p.buffer,
      1: mirror.bodyXf.buffer,
      2: mirror.bodyCell.buffer,
      3: mirror.bodyFlags.buffer,
      4: mirror.bodyAwake.buffer,
      5: this.transforms!,
      6: this.awakeBytes!,
    });
    const bytes = transformBytes + (awake !== undefined ? 4 * words : 0);
    const staging = this.staging.get(bytes);
    const encoder = this.ctx.device.createCommandEncoder({ label: 'transforms' });
    const pass = encoder.beginComputePass({ label: 'transforms' });
    new Recorder(pass, this.ctx.maxWorkgroupsPerDimension).dispatch(this.kernel, group, Math.ceil(words / WORKGROUP_SIZE));
    pass.end();
    encoder.copyBufferToBuffer(this.transforms!, 0, staging, 0, transformBytes);
    if (awake !== undefined) encoder.copyBufferToBuffer(this.awakeBytes!, 0, staging, transformBytes, 4 * words);
    this.ctx.device.queue.submit([encoder.finish()]);
    const mapped = await this.staging.map(bytes, 'reading the transforms back from the GPU failed');
    const started = performance.now();
    out.set(new Float32Array(mapped, 0, 4 * n));
    if (awake !== undefined) awake.set(new Uint8Array(mapped, transformBytes, n));
    this.staging.unmap();
    this.copyMs = performance.now() - started;
    return bytes;
  }

  destroy(): void {
    this.params.destroy();
    this.transforms?.destroy();
    this.awakeBytes?.destroy();
    this.staging.destroy();
  }

  /** Packed buffers for at least `slots` body slots (doubling, so that a growing world rarely reallocates). */
  private reserve(slots: number): void {
    if (slots <= this.capacity && this.transforms !== null) return;
    this.transforms?.destroy();
    this.awakeBytes?.destroy();
    this.capacity = Math.max(slots, 2 * this.capacity, 64);
    const usage = USAGE.STORAGE | USAGE.COPY_SRC;
    this.transforms = this.ctx.createBuffer('transforms packed', TRANSFORM_BYTES * this.capacity, usage);
    this.awakeBytes = this.ctx.createBuffer('transforms awake bytes', 4 * Math.ceil(this.capacity / SLOTS_PER_AWAKE_WORD), usage);
  }
}
