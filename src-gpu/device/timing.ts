/*
 * GPU time per compute pass with timestamp queries ('timestamp-query'), when the device has them.
 * Each pass writes a timestamp at its start and end; read() (its own map) or resolveTo() + parse()
 * (copied into a read-back buffer shared with other results) give milliseconds per pass name and
 * the span from the first start to the last end.
 */

import type { GpuContext } from './device';
import { MAP_READ, USAGE } from './layout';

export class PassTimer {
  readonly enabled: boolean;
  private readonly querySet: GPUQuerySet | null = null;
  private readonly resolveBuffer: GPUBuffer | null = null;
  private readonly readBuffer: GPUBuffer | null = null;
  private readonly capacity: number;
  private names: string[] = [];

  constructor(ctx: GpuContext, maxPasses = 16) {
    this.enabled = ctx.timestamps;
    this.capacity = maxPasses;
    if (this.enabled) {
      this.querySet = ctx.device.createQuerySet({ label: 'pass timer', type: 'timestamp', count: 2 * maxPasses });
      this.resolveBuffer = ctx.createBuffer('pass timer resolve', 16 * maxPasses, USAGE.QUERY_RESOLVE | USAGE.COPY_SRC);
      this.readBuffer = ctx.createBuffer('pass timer read', 16 * maxPasses, USAGE.MAP_READ | USAGE.COPY_DST);
    }
  }

  /** Starts a new frame of passes. */
  reset(): void {
    this.names = [];
  }

  /** A compute pass, timed when timestamps are available. */
  beginPass(encoder: GPUCommandEncoder, name: string): GPUComputePassEncoder {
    if (!this.enabled || this.names.length >= this.capacity) return encoder.beginComputePass({ label: name });
    const i = this.names.length;
    this.names.push(name);
    return encoder.beginComputePass({
      label: name,
      timestampWrites: { querySet: this.querySet!, beginningOfPassWriteIndex: 2 * i, endOfPassWriteIndex: 2 * i + 1 },
    });
  }

  /** Bytes the timestamps take in a read-back buffer (resolveTo). */
  get bytes(): number {
    return 16 * this.capacity;
  }

  /**
   * Records the resolve of this frame's timestamps and their copy to `dst` at byte `offset` (a
   * multiple of 8), so that they come back with the other results in one map; parse() reads them.
   */
  resolveTo(encoder: GPUCommandEncoder, dst: GPUBuffer, offset: number): void {
    if (!this.enabled || this.names.length === 0) return;
    const n = 2 * this.names.length;
    encoder.resolveQuerySet(this.querySet!, 0, n, this.resolveBuffer!, 0);
    encoder.copyBufferToBuffer(this.resolveBuffer!, 0, dst, offset, 8 * n);
  }

  /** Milliseconds per pass and `total` from bytes copied by resolveTo, or null without timestamps. */
  parse(bytes: ArrayBuffer, offset: number): Record<string, number> | null {
    if (!this.enabled || this.names.length === 0) return null;
    return this.times(new BigInt64Array(bytes, offset, 2 * this.names.length));
  }

  private times(t: BigInt64Array): Record<string, number> {
    const out: Record<string, number> = {};
    let first = t[0];
    let last = t[1];
    for (let i = 0; i < this.names.length; ++i) {
      const begin = t[2 * i];
      const end = t[2 * i + 1];
      if (begin < first) first = begin;
      if (end > last) last = end;
      out[this.names[i]] = (out[this.names[i]] ?? 0) + Number(end - begin) / 1e6;
    }
    out.total = Number(last - first) / 1e6;
    return out;
  }

  /** Records the resolve of this frame's timestamps (after the last pass). */
  resolve(encoder: GPUCommandEncoder): void {
    if (!this.enabled || this.names.length === 0) return;
    const n = 2 * this.names.length;
    encoder.resolveQuerySet(this.querySet!, 0, n, this.resolveBuffer!, 0);
    encoder.copyBufferToBuffer(this.resolveBuffer!, 0, this.readBuffer!, 0, 8 * n);
  }

  /** Milliseconds per pass (summed when a name repeats) and `total`, or null without timestamps. */
  async read(): Promise<Record<string, number> | null> {
    if (!this.enabled || this.names.length === 0) return null;
    const buffer = this.readBuffer!;
    await buffer.mapAsync(MAP_READ, 0, 16 * this.names.length);
    const t = new BigInt64Array(buffer.getMappedRange(0, 16 * this.names.length).slice(0));
    buffer.unmap();
    return this.times(t);
  }

  destroy(): void {
    this.querySet?.destroy();
    this.resolveBuffer?.destroy();
    this.readBuffer?.destroy();
  }
}
