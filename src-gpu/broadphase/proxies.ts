/*
 * A proxy set given directly as AABBs, without a b2World: for the broad phase alone (tests of
 * random AABB sets against a brute-force reference, the benchmark's raw mode). It fills the same
 * proxy buffers as GpuWorld + the bounds stage (layout.ts), so the sweep cannot tell them apart.
 */

import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { PROXY_JOINTED, PROXY_LIVE } from '../device/layout';
import type { SweepInputs } from './sweep';

export interface RawProxies {
  /** lower.x, lower.y, upper.x, upper.y per proxy; a proxy with lower.x > upper.x is dead. */
  aabbs: Float32Array;
  /** Body of each proxy (default: its own index, so every proxy is on its own body). */
  bodies?: Uint32Array;
  /** Body type per body (b2BodyType: 0 static, 1 kinematic, 2 dynamic; default 2). */
  bodyTypes?: Uint8Array;
  /** Shape type per proxy (b2Shape: 0 circle, 1 edge, 2 polygon, 3 chain; default 2). */
  shapeTypes?: Uint8Array;
  categoryBits?: Uint16Array;
  maskBits?: Uint16Array;
  groupIndex?: Int16Array;
  /** Body pairs joined by a joint with collideConnected == false. */
  noCollide?: [number, number][];
}

/**
 * Raw proxies (AABBs and filters without a b2World) for the broad phase alone.
 * @internal Advanced: exported for tools, benchmarks and tests; applications use WebGPUBackend
 * through b2World.SetBackend (docs/GPU.md, "The world API on the GPU").
 */
export class GpuProxySet implements SweepInputs {
  readonly ctx: GpuContext;
  slotCount = 0;
  liveCount = 0;
  private readonly aabb: GpuArray;
  private readonly ref: GpuArray;
  private readonly filter: GpuArray;
  private readonly range: GpuArray;
  private readonly list: GpuArray;

  constructor(ctx: GpuContext) {
    this.ctx = ctx;
    this.aabb = new GpuArray(ctx, 'raw proxyAABB', 16);
    this.ref = new GpuArray(ctx, 'raw proxyRef', 16);
    this.filter = new GpuArray(ctx, 'raw proxyFilter', 8);
    this.range = new GpuArray(ctx, 'raw jointRange', 8);
    this.list = new GpuArray(ctx, 'raw jointList', 4);
  }

  get proxyAABB(): GPUBuffer {
    return this.aabb.buffer;
  }
  get proxyRef(): GPUBuffer {
    return this.ref.buffer;
  }
  get proxyFilter(): GPUBuffer {
    return this.filter.buffer;
  }
  get jointRange(): GPUBuffer {
    return this.range.buffer;
  }
  get jointList(): GPUBuffer {
    return this.list.buffer;
  }

  /** Uploads a whole proxy set. */
  set(raw: RawProxies): void {
    const n = raw.aabbs.length / 4;
    const queue = this.ctx.device.queue;
    let bodyCount = 0;
    for (let i = 0; i < n; ++i) bodyCount = Math.max(bodyCount, (raw.bodies ? raw.bodies[i] : i) + 1);

    // Joint lists per body, ascending.
    const lists: number[][] = Array.from({ length: bodyCount }, () => []);
    for (const [a, b] of raw.noCollide ?? []) {
      lists[a].push(b);
      lists[b].push(a);
    }
    const range = new Uint32Array(2 * Math.max(1, bodyCount));
    const flat: number[] = [];
    for (let b = 0; b < bodyCount; ++b) {
      lists[b].sort((x, y) => x - y);
      range[2 * b] = flat.length;
      range[2 * b + 1] = lists[b].length;
      flat.push(...lists[b]);
    }

    const ref = new Uint32Array(4 * Math.max(1, n));
    const filter = new Uint32Array(2 * Math.max(1, n));
    let live = 0;
    for (let i = 0; i < n; ++i) {
      const body = raw.bodies ? raw.bodies[i] : i;
      const alive = raw.aabbs[4 * i] <= raw.aabbs[4 * i + 2];
      if (alive) live++;
      const bodyType = raw.bodyTypes ? raw.bodyTypes[body] : 2;
      const shapeType = raw.shapeTypes ? raw.shapeTypes[i] : 2;
      ref[4 * i] = i;
      ref[4 * i + 2] = body;
      ref[4 * i + 3] = shapeType | (bodyType << 2) | (alive ? PROXY_LIVE : 0) | (lists[body].length > 0 ? PROXY_JOINTED : 0);
      const cat = raw.categoryBits ? raw.categoryBits[i] : 1;
      const mask = raw.maskBits ? raw.maskBits[i] : 0xffff;
      filter[2 * i] = (cat | (mask << 16)) >>> 0;
      filter[2 * i + 1] = (raw.groupIndex ? raw.groupIndex[i] : 0) & 0xffff;
    }

    this.aabb.ensure(Math.max(1, n));
    this.ref.ensure(Math.max(1, n));
    this.filter.ensure(Math.max(1, n));
    this.range.ensure(Math.max(1, bodyCount));
    this.list.ensure(Math.max(1, flat.length));
    if (n > 0) queue.writeBuffer(this.aabb.buffer, 0, raw.aabbs.buffer, raw.aabbs.byteOffset, n * 16);
    queue.writeBuffer(this.ref.buffer, 0, ref);
    queue.writeBuffer(this.filter.buffer, 0, filter);
    queue.writeBuffer(this.range.buffer, 0, range);
    if (flat.length > 0) queue.writeBuffer(this.list.buffer, 0, Uint32Array.from(flat));
    this.slotCount = n;
    this.liveCount = live;
  }

  /** Replaces the AABBs only (same proxies, each as live or dead as before, new positions). */
  setAABBs(aabbs: Float32Array): void {
    if (aabbs.length / 4 !== this.slotCount) throw new RangeError('setAABBs: the proxy count changed; use set()');
    let live = 0;
    for (let i = 0; i < this.slotCount; ++i) if (aabbs[4 * i] <= aabbs[4 * i + 2]) live++;
    if (live !== this.liveCount) throw new RangeError('setAABBs: proxies became live or dead; use set()');
    this.ctx.device.queue.writeBuffer(this.aabb.buffer, 0, aabbs.buffer, aabbs.byteOffset, aabbs.length * 4);
  }

  destroy(): void {
    for (const a of [this.aabb, this.ref, this.filter, this.range, this.list]) a.destroy();
  }
}
