/*
 * Buffers that grow, and mirrored tables that upload only what changed.
 *
 * GpuArray: a storage buffer of fixed-size elements whose capacity doubles when more is needed
 * (geometric growth: n insertions cost O(n) copying in all). Growing copies the old contents on
 * the GPU (copyBufferToBuffer), so data the GPU wrote itself survives; `version` changes so that
 * bind groups holding the old buffer are rebuilt.
 *
 * MirrorTable: a GpuArray plus a CPU shadow copy of exactly what the GPU buffer holds. A sync
 * packs each element into a scratch record and compares it word by word (as u32, so -0, NaN
 * and every bit count) with the shadow; only differing elements are copied into the shadow and
 * marked dirty, and `flush` uploads the dirty elements as few contiguous ranges (runs closer than
 * MERGE_GAP elements are merged; past half the table, one write of everything). Comparing with a
 * shadow needs no hooks in the engine (which must not know about the GPU) and catches every
 * change, whoever made it, at the cost of one pass over the packed data per sync.
 */

import type { GpuContext } from './device';
import { USAGE } from './layout';

export class GpuArray {
  readonly ctx: GpuContext;
  readonly label: string;
  readonly bytesPerElement: number;
  readonly usage: number;
  buffer: GPUBuffer;
  capacity: number;
  /** Changes whenever `buffer` is replaced. */
  version = 0;

  constructor(ctx: GpuContext, label: string, bytesPerElement: number, initialCapacity = 64, extraUsage = 0) {
    this.ctx = ctx;
    this.label = label;
    this.bytesPerElement = bytesPerElement;
    this.usage = USAGE.STORAGE | USAGE.COPY_DST | USAGE.COPY_SRC | extraUsage;
    this.capacity = Math.max(1, initialCapacity);
    this.buffer = ctx.createBuffer(label, this.capacity * bytesPerElement, this.usage);
  }

  /**
   * Makes room for `needed` elements, doubling the capacity; the first `preserve` elements are
   * copied into the new buffer. Returns true when the buffer was replaced.
   */
  ensure(needed: number, preserve = 0): boolean {
    if (needed <= this.capacity) return false;
    let capacity = this.capacity;
    while (capacity < needed) capacity *= 2;
    const maxElements = Math.floor(this.ctx.limits.maxStorageBufferBindingSize / this.bytesPerElement);
    if (capacity > maxElements && needed <= maxElements) capacity = maxElements;
    const old = this.buffer;
    this.buffer = this.ctx.createBuffer(this.label, capacity * this.bytesPerElement, this.usage);
    const copy = Math.min(preserve, this.capacity) * this.bytesPerElement;
    if (copy > 0) {
      const encoder = this.ctx.device.createCommandEncoder({ label: `${this.label} grow` });
      encoder.copyBufferToBuffer(old, 0, this.buffer, 0, Math.ceil(copy / 4) * 4);
      this.ctx.device.queue.submit([encoder.finish()]);
    }
    old.destroy();
    this.capacity = capacity;
    this.version++;
    return true;
  }

  destroy(): void {
    this.buffer.destroy();
  }
}

/**
 * Memory for the mirror's host tables (shadows, slot maps), which live as long as their world.
 * V8 counts the bytes of every ArrayBuffer as memory held outside its heap and, when those grow
 * by 64 MB, marks the whole heap to find buffers to free: attaching a world of 10^6 bodies
 * (hundreds of MB of tables) cost a mark of its millions of objects, seconds that found nothing
 * to free. A SharedArrayBuffer's bytes are not counted that way, so the tables take one where the
 * platform has it (Node; a page that is cross-origin isolated) and an ArrayBuffer elsewhere.
 */
export function hostTableStore(bytes: number): ArrayBufferLike {
  return typeof SharedArrayBuffer === 'function' ? new SharedArrayBuffer(bytes) : new ArrayBuffer(bytes);
}

/** The stage of uploads from shared memory: Dawn's writeBuffer in Node takes no view of it. */
const UPLOAD_STAGE_WORDS = 1 << 20;
let uploadStage: Uint32Array | null = null;

/**
 * Writes words [first, first + count) of `words` at byte `offset` of `buffer`. From shared memory
 * the words are copied into the stage by a loop, not through views, so that a steady-state
 * upload allocates nothing.
 */
function writeShadow(queue: GPUQueue, buffer: GPUBuffer, offset: number, words: Uint32Array, first: number, count: number): void {
  if (words.buffer instanceof ArrayBuffer) {
    queue.writeBuffer(buffer, offset, words.buffer, words.byteOffset + 4 * first, 4 * count);
    return;
  }
  uploadStage ??= new Uint32Array(UPLOAD_STAGE_WORDS);
  const stage = uploadStage;
  for (let at = 0; at < count; at += UPLOAD_STAGE_WORDS) {
    const part = Math.min(UPLOAD_STAGE_WORDS, count - at);
    const from = first + at;
    for (let i = 0; i < part; ++i) stage[i] = words[from + i];
    queue.writeBuffer(buffer, offset + 4 * at, stage.buffer, 0, 4 * part);
  }
}

/** Dirty runs closer than this many elements are uploaded as one write. */
const MERGE_GAP = 16;

export interface UploadStats {
  /** Bytes written with queue.writeBuffer. */
  bytes: number;
  /** writeBuffer calls. */
  writes: number;
  /** Elements that changed. */
  elements: number;
}

export class MirrorTable {
  readonly gpu: GpuArray;
  /** u32 words per element. */
  readonly words: number;
  u32: Uint32Array;
  f32: Float32Array;
  i32: Int32Array;
  dirty: Uint8Array;
  /** Elements [0, count) are in use (the high-water mark of the slots). */
  count = 0;
  /**
   * Upload exactly the dirty elements, never clean ones in between: set when the GPU writes this
   * table itself (the solver's body motion and joint state), so a clean element's shadow may be stale.
   */
  exactUploads = false;
  dirtyCount = 0;
  /** The record `commit` compares; fill it through these views, then commit(slot). */
  readonly scratchU32: Uint32Array;
  readonly scratchF32: Float32Array;
  readonly scratchI32: Int32Array;

  constructor(ctx: GpuContext, label: string, words: number, initialCapacity = 64) {
    this.words = words;
    this.gpu = new GpuArray(ctx, label, words * 4, initialCapacity);
    const capacity = this.gpu.capacity;
    this.u32 = new Uint32Array(capacity * words);
    this.f32 = new Float32Array(this.u32.buffer);
    this.i32 = new Int32Array(this.u32.buffer);
    this.dirty = new Uint8Array(capacity);
    this.scratchU32 = new Uint32Array(words);
    this.scratchF32 = new Float32Array(this.scratchU32.buffer);
    this.scratchI32 = new Int32Array(this.scratchU32.buffer);
  }

  get buffer(): GPUBuffer {
    return this.gpu.buffer;
  }

  get capacity(): number {
    return this.gpu.capacity;
  }

  /** Makes room for slots [0, n) (the GPU copy keeps what was uploaded). */
  reserve(n: number): void {
    MirrorTable.reserveAll([this], [n]);
  }

  /**
   * reserve(n[i]) for each of `tables`, their new shadows carved from one hostTableStore.
   */
  static reserveAll(tables: readonly MirrorTable[], n: readonly number[]): void {
    const grown: MirrorTable[] = [];
    let bytes = 0;
    tables.forEach((table, i) => {
      if (n[i] <= table.gpu.capacity) return;
      table.gpu.ensure(n[i], table.count);
      grown.push(table);
      bytes += 4 * table.gpu.capacity * table.words + Math.ceil(table.gpu.capacity / 4) * 4;
    });
    if (grown.length === 0) return;
    const arena = hostTableStore(bytes);
    let at = 0;
    for (const table of grown) {
      const capacity = table.gpu.capacity;
      const u32 = new Uint32Array(arena, at, capacity * table.words);
      u32.set(table.u32);
      table.u32 = u32;
      table.f32 = new Float32Array(arena, at, capacity * table.words);
      table.i32 = new Int32Array(arena, at, capacity * table.words);
      at += 4 * capacity * table.words;
      const dirty = new Uint8Array(arena, at, capacity);
      dirty.set(table.dirty);
      table.dirty = dirty;
      at += Math.ceil(capacity / 4) * 4;
    }
  }

  /** Compares the scratch record with element `slot`; copies and marks it dirty when it differs. */
  commit(slot: number): boolean {
    if (slot >= this.gpu.capacity) this.reserve(slot + 1);
    if (slot >= this.count) this.count = slot + 1;
    const w = this.words;
    const base = slot * w;
    const u32 = this.u32;
    const s = this.scratchU32;
    let same = true;
    for (let i = 0; i < w; ++i) {
      if (u32[base + i] !== s[i]) {
        same = false;
        break;
      }
    }
    if (same) return false;
    // A loop, not u32.set(s, base): for records of a few words the builtin's setup costs more.
    for (let i = 0; i < w; ++i) u32[base + i] = s[i];
    if (this.dirty[slot] === 0) {
      this.dirty[slot] = 1;
      this.dirtyCount++;
    }
    return true;
  }

  /**
   * commit() for a two-float element, without the scratch record: the float32 values are compared
   * with Object.is (so -0 and 0 differ, as they do bit by bit; NaN payloads are not told apart).
   */
  commitF2(slot: number, x: number, y: number): void {
    if (slot >= this.count) this.setCount(slot + 1);
    const f = this.f32;
    const base = 2 * slot;
    const fx = Math.fround(x);
    const fy = Math.fround(y);
    if (Object.is(f[base], fx) && Object.is(f[base + 1], fy)) return;
    f[base] = fx;
    f[base + 1] = fy;
    this.markDirty(slot);
  }

  /** commitF2 for a four-float element. */
  commitF4(slot: number, a: number, b: number, c: number, d: number): void {
    if (slot >= this.count) this.setCount(slot + 1);
    const f = this.f32;
    const base = 4 * slot;
    const fa = Math.fround(a);
    const fb = Math.fround(b);
    const fc = Math.fround(c);
    const fd = Math.fround(d);
    if (Object.is(f[base], fa) && Object.is(f[base + 1], fb) && Object.is(f[base + 2], fc) && Object.is(f[base + 3], fd)) return;
    f[base] = fa;
    f[base + 1] = fb;
    f[base + 2] = fc;
    f[base + 3] = fd;
    this.markDirty(slot);
  }

  /** Uploads element `slot` at the next flush even if it equals the shadow. */
  markDirty(slot: number): void {
    if (this.dirty[slot] === 0) {
      this.dirty[slot] = 1;
      this.dirtyCount++;
    }
  }

  /** Sets element `slot` to the words a, b, c, d (as many as the element has) and commits it. */
  commitWords(slot: number, a: number, b = 0, c = 0, d = 0): boolean {
    const s = this.scratchU32;
    s[0] = a;
    if (this.words > 1) s[1] = b;
    if (this.words > 2) s[2] = c;
    if (this.words > 3) s[3] = d;
    return this.commit(slot);
  }

  /** Marks every element in [0, count) dirty (after the GPU buffer lost its contents). */
  markAllDirty(): void {
    this.dirty.fill(1, 0, this.count);
    this.dirtyCount = this.count;
  }

  /** Sets the high-water mark (slots past it are not uploaded). */
  setCount(n: number): void {
    if (n > this.gpu.capacity) this.reserve(n);
    this.count = n;
  }

  /** Uploads the dirty elements; returns what it wrote. */
  flush(queue: GPUQueue, stats?: UploadStats): void {
    if (this.dirtyCount === 0) return;
    const n = this.count;
    const dirty = this.dirty;
    let elements = 0;
    const gap = this.exactUploads ? 0 : MERGE_GAP;
    if (this.dirtyCount * 2 > n && !this.exactUploads) {
      for (let i = 0; i < n; ++i) elements += dirty[i];
      this.writeRange(queue, 0, n, stats);
    } else {
      let start = -1;
      let end = -1;
      for (let i = 0; i < n; ++i) {
        if (dirty[i] === 0) continue;
        elements++;
        if (start < 0) {
          start = i;
        } else if (i - end > gap) {
          this.writeRange(queue, start, end, stats);
          start = i;
        }
        end = i + 1;
      }
      if (start >= 0) this.writeRange(queue, start, end, stats);
    }
    if (stats) stats.elements += elements;
    dirty.fill(0, 0, Math.max(n, dirty.length));
    this.dirtyCount = 0;
  }

  /** Uploads elements [from, to) from the shadow. */
  private writeRange(queue: GPUQueue, from: number, to: number, stats: UploadStats | undefined): void {
    const bytesPerElement = this.words * 4;
    writeShadow(queue, this.gpu.buffer, from * bytesPerElement, this.u32, from * this.words, (to - from) * this.words);
    if (stats) {
      stats.bytes += (to - from) * bytesPerElement;
      stats.writes++;
    }
  }

  destroy(): void {
    this.gpu.destroy();
  }
}
