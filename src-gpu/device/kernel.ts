/*
 * Compute pipelines and their dispatch: one Kernel per (stage, entry point), bind groups cached by
 * the identity of the buffers they hold, and a Recorder that dispatches in 2D when a grid passes
 * maxComputeWorkgroupsPerDimension and counts dispatches (the benchmark's overhead baseline).
 */

import type { GpuContext } from './device';
import { bufferId } from './device';
import { SHADERS } from './shaders';
import type { ShaderName } from './shaders';
import { split2D, USAGE } from './layout';

export type BindingEntry = GPUBuffer | { buffer: GPUBuffer; offset?: number; size?: number };

function isBufferBinding(e: BindingEntry): e is { buffer: GPUBuffer; offset?: number; size?: number } {
  return (e as { buffer?: unknown }).buffer !== undefined;
}

/** Pipelines per device and (shader, entry point): stages built again (a new stepper) reuse them. */
const pipelines = new WeakMap<GPUDevice, Map<string, GPUComputePipeline>>();

export class Kernel {
  readonly ctx: GpuContext;
  readonly label: string;
  readonly pipeline: GPUComputePipeline;
  private readonly cache = new Map<number, CachedGroup[]>();

  constructor(ctx: GpuContext, shader: ShaderName, entryPoint: string) {
    this.ctx = ctx;
    this.label = `${shader}.${entryPoint}`;
    let cache = pipelines.get(ctx.device);
    if (!cache) pipelines.set(ctx.device, (cache = new Map()));
    const key = `${this.label}:${ctx.maxWorkgroupsPerDimension}`;
    let pipeline = cache.get(key);
    if (!pipeline) {
      const module = ctx.shaderModule(shader, SHADERS[shader]);
      pipeline = ctx.device.createComputePipeline({
        label: this.label,
        layout: 'auto',
        compute: { module, entryPoint, constants: { MAX_GROUPS_PER_DIMENSION: ctx.maxWorkgroupsPerDimension } },
      });
      cache.set(key, pipeline);
    }
    this.pipeline = pipeline;
  }

  /**
   * The bind group (group 0) with these buffers at these bindings; cached by a hash of the
   * bindings and buffer ids, the entries compared on a hit, so a step that binds what it bound
   * before allocates nothing here.
   */
  bind(entries: Record<number, BindingEntry>): GPUBindGroup {
    let hash = 0;
    for (const k in entries) {
      const e = entries[k];
      const buffer = isBufferBinding(e) ? e.buffer : e;
      const offset = isBufferBinding(e) ? (e.offset ?? 0) : 0;
      hash = (Math.imul(hash ^ (+k << 24) ^ bufferId(buffer), 0x9e3779b1) + offset) | 0;
    }
    let bucket = this.cache.get(hash);
    if (bucket !== undefined) {
      for (const cached of bucket) if (sameEntries(cached, entries)) return cached.group;
    } else {
      if (this.cache.size > 256) this.cache.clear();
      bucket = [];
      this.cache.set(hash, bucket);
    }
    const list: GPUBindGroupEntry[] = [];
    const kept: Record<number, BindingEntry> = {};
    let size = 0;
    for (const k in entries) {
      const e = entries[k];
      kept[k] = isBufferBinding(e) ? { ...e } : e;
      size++;
      list.push({ binding: +k, resource: isBufferBinding(e) ? e : { buffer: e } });
    }
    const group = this.ctx.device.createBindGroup({ label: this.label, layout: this.pipeline.getBindGroupLayout(0), entries: list });
    bucket.push({ entries: kept, size, group });
    return group;
  }
}

interface CachedGroup {
  entries: Record<number, BindingEntry>;
  /** Bindings in `entries`. */
  size: number;
  group: GPUBindGroup;
}

/** Whether `b` names the cached group's buffers, offsets and sizes at the same bindings. */
function sameEntries(cached: CachedGroup, b: Record<number, BindingEntry>): boolean {
  const a = cached.entries;
  let count = 0;
  for (const k in b) {
    const x = a[k as unknown as number];
    const y = b[k];
    if (x === undefined) return false;
    if (isBufferBinding(x) || isBufferBinding(y)) {
      if (!isBufferBinding(x) || !isBufferBinding(y)) return false;
      if (x.buffer !== y.buffer || (x.offset ?? 0) !== (y.offset ?? 0) || (x.size ?? -1) !== (y.size ?? -1)) return false;
    } else if (x !== y) {
      return false;
    }
    count++;
  }
  return count === cached.size;
}

/** A compute pass being recorded. */
export class Recorder {
  readonly pass: GPUComputePassEncoder;
  readonly maxPerDimension: number;
  dispatches = 0;

  constructor(pass: GPUComputePassEncoder, maxPerDimension: number) {
    this.pass = pass;
    this.maxPerDimension = maxPerDimension;
  }

  /** Dispatches `groups` workgroups (linearised by the shader's group_index). */
  dispatch(kernel: Kernel, group: GPUBindGroup, groups: number): void {
    if (groups <= 0) return;
    const [x, y] = split2D(groups, this.maxPerDimension);
    this.pass.setPipeline(kernel.pipeline);
    this.pass.setBindGroup(0, group);
    this.pass.dispatchWorkgroups(x, y);
    this.dispatches++;
  }

  /** Dispatches with the size in `indirect` at byte `offset` (written by an earlier kernel). */
  dispatchIndirect(kernel: Kernel, group: GPUBindGroup, indirect: GPUBuffer, offset: number): void {
    this.pass.setPipeline(kernel.pipeline);
    this.pass.setBindGroup(0, group);
    this.pass.dispatchWorkgroupsIndirect(indirect, offset);
    this.dispatches++;
  }
}

/** Opens a compute pass named `name`, lets `body` record into it, and closes it. */
export type PassRecorder = (name: string, body: (rec: Recorder) => void) => void;

/** What opens a timed pass (PassTimer). */
interface PassOpener {
  beginPass(encoder: GPUCommandEncoder, name: string): GPUComputePassEncoder;
}

/**
 * The PassRecorder of one command encoder: each pass opened by `timer` (timed, when the device
 * has timestamps) or, without one, labelled with `suffix` after its name; dispatches() counts the
 * dispatches recorded so far.
 */
export function passRecorder(
  encoder: GPUCommandEncoder,
  maxPerDimension: number,
  timer: PassOpener | null,
  suffix = '',
): { pass: PassRecorder; dispatches: () => number } {
  let dispatches = 0;
  const pass: PassRecorder = (name, body) => {
    const p = timer !== null ? timer.beginPass(encoder, name) : encoder.beginComputePass({ label: `${name}${suffix}` });
    const rec = new Recorder(p, maxPerDimension);
    body(rec);
    p.end();
    dispatches += rec.dispatches;
  };
  return { pass, dispatches: () => dispatches };
}

/** A small uniform buffer holding u32/f32/i32 words, written through writeBuffer. */
export class Uniform {
  readonly buffer: GPUBuffer;
  readonly u32: Uint32Array<ArrayBuffer>;
  readonly f32: Float32Array<ArrayBuffer>;
  readonly i32: Int32Array<ArrayBuffer>;
  private readonly ctx: GpuContext;
  private readonly uploaded: Uint32Array;
  private written = false;

  constructor(ctx: GpuContext, label: string, words = 8) {
    this.ctx = ctx;
    this.buffer = ctx.createBuffer(label, Math.max(16, words * 4), USAGE.UNIFORM | USAGE.COPY_DST);
    this.u32 = new Uint32Array(Math.max(4, words));
    this.f32 = new Float32Array(this.u32.buffer);
    this.i32 = new Int32Array(this.u32.buffer);
    this.uploaded = new Uint32Array(this.u32.length);
  }

  /** Uploads the words when they differ from the last upload. */
  upload(): void {
    if (this.written && this.u32.every((w, i) => w === this.uploaded[i])) return;
    this.ctx.device.queue.writeBuffer(this.buffer, 0, this.u32);
    this.uploaded.set(this.u32);
    this.written = true;
  }

  destroy(): void {
    this.buffer.destroy();
  }
}
