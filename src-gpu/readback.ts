/*
 * Reading small results back from the GPU: one MAP_READ buffer per read in flight.
 *
 * An update copies what the host needs (state words, timestamps) into one Readback buffer in its
 * own command buffer and maps it once: one GPU round trip per update. In Node, Dawn (the `webgpu`
 * package) resolves mapAsync from wgpuInstanceProcessEvents, which its AsyncRunner calls from a
 * setImmediate callback re-armed while any promise is pending, so a map resolves within one event
 * loop turn of the GPU finishing: the cost of a read is the wait for the GPU, not the polling.
 * Awaiting it each step serialises the host and the GPU (docs/GPU.md, "Host overhead");
 * ReadbackRing lets several steps be in flight, each with its own buffer.
 */

import type { GpuContext } from './device';
import { MAP_READ, USAGE } from './layout';

/** Maps `size` bytes of a MAP_READ buffer, failing with the device's loss or with `message`. */
export async function mapRead(ctx: GpuContext, buffer: GPUBuffer, size: number, message: string): Promise<ArrayBuffer> {
  try {
    await Promise.race([buffer.mapAsync(MAP_READ, 0, size), ctx.lostRejection]);
  } catch {
    ctx.assertAlive();
    throw new Error(message);
  }
  return buffer.getMappedRange(0, size);
}

export class Readback {
  readonly buffer: GPUBuffer;
  readonly size: number;
  /** The map in progress, if any. */
  pending: Promise<ArrayBuffer> | null = null;

  constructor(ctx: GpuContext, label: string, size: number) {
    this.size = Math.max(16, Math.ceil(size / 16) * 16);
    this.buffer = ctx.createBuffer(label, this.size, USAGE.MAP_READ | USAGE.COPY_DST);
  }

  /**
   * Maps the first `bytes` bytes (after the submission that filled them) and returns a copy.
   * Rejects when the device is lost.
   */
  read(ctx: GpuContext, bytes: number): Promise<ArrayBuffer> {
    const size = Math.min(this.size, Math.ceil(bytes / 8) * 8);
    const done = (async () => {
      const data = (await mapRead(ctx, this.buffer, size, 'reading GPU results back failed')).slice(0);
      this.buffer.unmap();
      return data;
    })();
    this.pending = done;
    done.then(
      () => {
        if (this.pending === done) this.pending = null;
      },
      () => {
        if (this.pending === done) this.pending = null;
      },
    );
    return done;
  }

  destroy(): void {
    this.buffer.destroy();
  }
}

/**
 * A MAP_READ buffer for reads that grow with the world (bodies, joints, logs): it doubles when a
 * read needs more, and is mapped in place (the caller reads the mapped range, then unmaps).
 */
export class StagingBuffer {
  private buffer: GPUBuffer | null = null;
  private capacity = 0;

  constructor(
    private readonly ctx: GpuContext,
    private readonly label: string,
    private readonly minBytes: number,
  ) {}

  /** A buffer of at least `bytes` bytes to copy into before map(). */
  get(bytes: number): GPUBuffer {
    if (this.buffer === null || this.capacity < bytes) {
      this.buffer?.destroy();
      this.capacity = Math.max(bytes, 2 * this.capacity, this.minBytes);
      this.buffer = this.ctx.createBuffer(this.label, this.capacity, USAGE.MAP_READ | USAGE.COPY_DST);
    }
    return this.buffer;
  }

  /** Maps the first `bytes` bytes of the buffer get() gave, after the submissions before. */
  map(bytes: number, message: string): Promise<ArrayBuffer> {
    return mapRead(this.ctx, this.buffer!, bytes, message);
  }

  unmap(): void {
    this.buffer!.unmap();
  }

  destroy(): void {
    this.buffer?.destroy();
  }
}

/** Read-back buffers for steps in flight: next() hands out one that is not being mapped. */
export class ReadbackRing {
  private readonly buffers: Readback[] = [];
  private cursor = 0;

  constructor(ctx: GpuContext, label: string, size: number, count = 4) {
    for (let i = 0; i < count; ++i) this.buffers.push(new Readback(ctx, `${label} ${i}`, size));
  }

  /** A buffer free for the next step, waiting for the oldest read when all are in flight. */
  async next(): Promise<Readback> {
    const rb = this.buffers[this.cursor];
    this.cursor = (this.cursor + 1) % this.buffers.length;
    if (rb.pending) await rb.pending.catch(() => undefined);
    return rb;
  }

  /** Waits for every read in flight. */
  async settle(): Promise<void> {
    await Promise.all(this.buffers.map((b) => b.pending?.catch(() => undefined)));
  }

  destroy(): void {
    for (const b of this.buffers) b.destroy();
  }
}
