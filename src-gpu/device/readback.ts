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

/** Waits for `size` bytes of a MAP_READ buffer to be mapped, failing with the device's loss or with `message`. */
async function mapReadAsync(ctx: GpuContext, buffer: GPUBuffer, size: number, message: string): Promise<void> {
  try {
    await Promise.race([buffer.mapAsync(MAP_READ, 0, size), ctx.lostRejection]);
  } catch {
    ctx.assertAlive();
    throw new Error(message);
  }
}

/** Maps `size` bytes of a MAP_READ buffer, failing with the device's loss or with `message`. */
export async function mapRead(ctx: GpuContext, buffer: GPUBuffer, size: number, message: string): Promise<ArrayBuffer> {
  await mapReadAsync(ctx, buffer, size, message);
  return buffer.getMappedRange(0, size);
}

/**
 * Copies the first `bytes` bytes of a GPU buffer to the host through a staging buffer of its own:
 * a whole GPU round trip, for tests and tools, never inside a step.
 */
export async function readBuffer(ctx: GpuContext, buffer: GPUBuffer, bytes: number, label: string): Promise<ArrayBuffer> {
  ctx.assertAlive();
  const size = Math.max(4, Math.ceil(bytes / 4) * 4);
  const staging = ctx.createBuffer(label, size, USAGE.MAP_READ | USAGE.COPY_DST);
  try {
    const encoder = ctx.device.createCommandEncoder({ label });
    encoder.copyBufferToBuffer(buffer, 0, staging, 0, size);
    ctx.device.queue.submit([encoder.finish()]);
    const data = (await mapRead(ctx, staging, size, `${label} failed`)).slice(0, bytes);
    staging.unmap();
    return data;
  } finally {
    staging.destroy();
  }
}

export class Readback {
  readonly buffer: GPUBuffer;
  readonly size: number;
  /** The map in progress, if any. */
  pending: Promise<ArrayBuffer> | null = null;
  /**
   * Where read() copies the mapped bytes: allocated once, because allocating an ArrayBuffer while
   * a large mapped range is young in V8's heap (a readState() of a million bodies) forces a
   * scavenge first.
   */
  private readonly copy: ArrayBuffer;

  constructor(ctx: GpuContext, label: string, size: number) {
    this.size = Math.max(16, Math.ceil(size / 16) * 16);
    this.buffer = ctx.createBuffer(label, this.size, USAGE.MAP_READ | USAGE.COPY_DST);
    this.copy = new ArrayBuffer(this.size);
  }

  /**
   * Maps the first `bytes` bytes (after the submission that filled them) and resolves with a copy,
   * which the next read() of this Readback overwrites. Rejects when the device is lost.
   */
  read(ctx: GpuContext, bytes: number): Promise<ArrayBuffer> {
    const size = Math.min(this.size, Math.ceil(bytes / 8) * 8);
    const done = (async () => {
      new Uint8Array(this.copy, 0, size).set(new Uint8Array(await mapRead(ctx, this.buffer, size, 'reading GPU results back failed')));
      this.buffer.unmap();
      return this.copy;
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

  /**
   * map() in two halves: the wait, then (range()) the ArrayBuffer of the mapped bytes, so that the
   * caller can release another mapped range in between (V8 counts each mapped range as memory it
   * holds, and starts marking the whole heap when that count grows past what it last saw).
   */
  mapAsync(bytes: number, message: string): Promise<void> {
    return mapReadAsync(this.ctx, this.buffer!, bytes, message);
  }

  /** `size` mapped bytes from `offset` (a multiple of 8) after mapAsync(). */
  range(offset: number, size: number): ArrayBuffer {
    return this.buffer!.getMappedRange(offset, size);
  }

  /** The buffer get() gave. */
  get current(): GPUBuffer {
    return this.buffer!;
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

type FieldArray = Float32Array | Int32Array | Uint32Array;

/** One per-body field of a mapped state: its 32-bit words per body, and the view its chunks get (`length` words from `byteOffset`). */
export interface MappedField {
  words: number;
  view: (buffer: ArrayBuffer, byteOffset: number, length: number) => FieldArray;
}

/** Bodies per chunk of a MappedState (a power of two). */
export const STATE_CHUNK = 8192;
const STATE_CHUNK_SHIFT = Math.log2(STATE_CHUNK);

/**
 * Per-body fields read back into a mapped staging buffer, one after another from its start (field
 * f at 4 * count * the words of the fields before it), taken from the map a chunk of
 * STATE_CHUNK bodies at a time when a body of the chunk is first read: a synchronisation after
 * which the application reads a few bodies maps a few chunks, not the whole state. (V8 counts every
 * mapped range it is handed as memory it holds; a million bodies' whole state, 76 MB at each
 * synchronisation, kept it marking the heap.) Field f's chunk for `slot` is chunk(f, slot); the
 * body's words start at (slot % STATE_CHUNK) * words. Opened to keep a host copy, the whole state
 * is copied out of the map at once instead, and the chunks are views of the copy: they outlive
 * the map, and a lost device, at the price of a copy of every body's state at each read.
 */
export class MappedState {
  private buffer: GPUBuffer | null = null;
  private count = 0;
  /** The host copy of the state when open() was asked to keep one; null when chunks come from the map. */
  private copy: ArrayBuffer | null = null;
  private copyStore = new ArrayBuffer(0);
  private readonly offsets: number[];
  private readonly chunks: FieldArray[][];
  /** Bytes taken from the map since open(). */
  bytes = 0;

  constructor(private readonly fields: readonly MappedField[]) {
    this.chunks = fields.map(() => []);
    this.offsets = fields.map(() => 0);
  }

  /**
   * Hands out the fields of `count` bodies mapped in `buffer`. The fields before each field take an
   * even number of words a body, so that every chunk starts at a multiple of 8 bytes, as
   * getMappedRange requires.
   */
  open(buffer: GPUBuffer, count: number, keepCopy = false): void {
    this.close();
    this.buffer = buffer;
    this.count = count;
    let at = 0;
    for (let f = 0; f < this.fields.length; ++f) {
      this.offsets[f] = at;
      at += 4 * this.fields[f].words * count;
    }
    if (keepCopy && at > 0) {
      if (this.copyStore.byteLength < at) this.copyStore = new ArrayBuffer(Math.max(at, 2 * this.copyStore.byteLength));
      new Uint8Array(this.copyStore, 0, at).set(new Uint8Array(buffer.getMappedRange(0, at)));
      this.copy = this.copyStore;
      this.bytes = at;
    }
  }

  /** Forgets the chunks (before the buffer is unmapped, which detaches them). */
  close(): void {
    this.buffer = null;
    this.copy = null;
    this.count = 0;
    this.bytes = 0;
    for (const list of this.chunks) list.length = 0;
  }

  get slots(): number {
    return this.count;
  }

  /** Field f's chunk holding body `slot` (taken from the map on first use). */
  chunk(f: number, slot: number): FieldArray {
    const c = slot >>> STATE_CHUNK_SHIFT;
    const list = this.chunks[f];
    let a = list[c];
    if (a === undefined) {
      const words = this.fields[f].words;
      const first = c * STATE_CHUNK;
      const size = 4 * words * Math.min(STATE_CHUNK, this.count - first);
      const offset = this.offsets[f] + 4 * words * first;
      if (this.copy !== null) {
        a = this.fields[f].view(this.copy, offset, size / 4);
      } else {
        a = this.fields[f].view(this.buffer!.getMappedRange(offset, size), 0, size / 4);
        this.bytes += size;
      }
      list[c] = a;
    }
    return a;
  }
}
