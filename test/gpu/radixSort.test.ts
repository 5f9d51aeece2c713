import { expect, it } from 'vitest';
import { GpuArray } from '../../src-gpu/buffers';
import { Recorder } from '../../src-gpu/kernel';
import { digitPasses, RadixSort } from '../../src-gpu/radixSort';
import type { SortPass } from '../../src-gpu/radixSort';
import { pairSortPasses } from '../../src-gpu/pairs';
import { PrefixScan } from '../../src-gpu/scan';
import { KEY_BITS, MAP_READ, SORT_TILE, STATE_WORDS, USAGE } from '../../src-gpu/layout';
import type { GpuContext } from '../../src-gpu/device';
import { describeGpu, rng } from './support';

async function read(ctx: GpuContext, buffer: GPUBuffer, bytes: number): Promise<Uint32Array> {
  const staging = ctx.createBuffer('test read', bytes, USAGE.MAP_READ | USAGE.COPY_DST);
  const enc = ctx.device.createCommandEncoder();
  enc.copyBufferToBuffer(buffer, 0, staging, 0, Math.ceil(bytes / 16) * 16);
  ctx.device.queue.submit([enc.finish()]);
  await staging.mapAsync(MAP_READ);
  const out = new Uint32Array(staging.getMappedRange().slice(0, bytes));
  staging.unmap();
  staging.destroy();
  return out;
}

/**
 * Sorts `data` (2 words per element) on the GPU with `passes` and returns the result and the
 * digit totals buffer's first `digits` words (the last pass's count per digit).
 */
async function gpuSort(ctx: GpuContext, sort: RadixSort, data: Uint32Array<ArrayBuffer>, passes: SortPass[], digits = 16): Promise<{ sorted: Uint32Array; totals: Uint32Array; dispatches: number }> {
  const n = data.length / 2;
  const a = new GpuArray(ctx, 'a', 8, Math.max(1, n));
  const b = new GpuArray(ctx, 'b', 8, Math.max(1, n));
  const state = ctx.createBuffer('state', 4 * STATE_WORDS, USAGE.STORAGE | USAGE.COPY_DST);
  ctx.device.queue.writeBuffer(state, 0, new Uint32Array([n, 0, 0, 0]));
  if (n > 0) ctx.device.queue.writeBuffer(a.buffer, 0, data);
  sort.reserve(n);
  const enc = ctx.device.createCommandEncoder();
  const pass = enc.beginComputePass();
  const rec = new Recorder(pass, 65535);
  const out = sort.encode(rec, a.buffer, b.buffer, passes, state, 0, { groups: Math.ceil(n / SORT_TILE) });
  pass.end();
  ctx.device.queue.submit([enc.finish()]);
  const sorted = await read(ctx, out, Math.max(4, 8 * n));
  const totals = await read(ctx, sort.digitTotalsBuffer, 4 * digits);
  await ctx.checkErrors();
  a.destroy();
  b.destroy();
  state.destroy();
  return { sorted: sorted.subarray(0, 2 * n), totals, dispatches: rec.dispatches };
}

/** Fails at the first element where `got` differs from a stable JS sort of `data` by `key`. */
function expectStableSort(got: Uint32Array, data: Uint32Array, key: (x: number, y: number) => bigint, what: string): void {
  const n = data.length / 2;
  const keys = Array.from({ length: n }, (_, i) => key(data[2 * i], data[2 * i + 1]));
  const expected = Array.from({ length: n }, (_, i) => i).sort((x, y) => (keys[x] < keys[y] ? -1 : keys[x] > keys[y] ? 1 : x - y));
  for (let i = 0; i < n; ++i) {
    const e = expected[i];
    if (got[2 * i] !== data[2 * e] || got[2 * i + 1] !== data[2 * e + 1]) {
      throw new Error(`${what}: position ${i} holds (${got[2 * i]}, ${got[2 * i + 1]}), expected element ${e} (${data[2 * e]}, ${data[2 * e + 1]})`);
    }
  }
}

/** n elements (key, index) with keys from `key(i)`. */
function keyed(n: number, key: (i: number) => number): Uint32Array<ArrayBuffer> {
  const data = new Uint32Array(2 * n);
  for (let i = 0; i < n; ++i) {
    data[2 * i] = key(i) >>> 0;
    data[2 * i + 1] = i;
  }
  return data;
}

const byX = (x: number) => BigInt(x);

describeGpu('radix sort and scan stages', (ctx) => {
  it('sorts (key, value) pairs stably by a 32-bit key, like a stable JS sort', async () => {
    const random = rng(7);
    const sort = new RadixSort(ctx);
    for (const n of [0, 1, 5, 1023, 1024, 1025, 70_000]) {
      const data = new Uint32Array(2 * n);
      for (let i = 0; i < n; ++i) {
        // few distinct keys in the low bits so stability is exercised
        data[2 * i] = (random() < 0.5 ? (random() * 16) | 0 : (random() * 2 ** 32) >>> 0) >>> 0;
        data[2 * i + 1] = i;
      }
      const a = new GpuArray(ctx, 'a', 8, Math.max(1, n));
      const b = new GpuArray(ctx, 'b', 8, Math.max(1, n));
      const state = ctx.createBuffer('state', 4 * STATE_WORDS, USAGE.STORAGE | USAGE.COPY_DST);
      ctx.device.queue.writeBuffer(state, 0, new Uint32Array([n, 0, 0, 0]));
      if (n > 0) ctx.device.queue.writeBuffer(a.buffer, 0, data);
      sort.reserve(n);
      const enc = ctx.device.createCommandEncoder();
      const pass = enc.beginComputePass();
      const rec = new Recorder(pass, 65535);
      const out = sort.encode(rec, a.buffer, b.buffer, digitPasses(32, 0), state, 0, { groups: Math.ceil(n / 1024) });
      pass.end();
      ctx.device.queue.submit([enc.finish()]);
      const got = await read(ctx, out, Math.max(4, 8 * n));
      const expected = Array.from({ length: n }, (_, i) => i).sort((x, y) => data[2 * x] - data[2 * y] || x - y);
      for (let i = 0; i < n; ++i) {
        if (got[2 * i + 1] !== expected[i] || got[2 * i] !== data[2 * expected[i]]) {
          throw new Error(`n=${n}: position ${i} holds (${got[2 * i]}, ${got[2 * i + 1]}), expected index ${expected[i]}`);
        }
      }
      await ctx.checkErrors();
    }
  });

  it('sorts stably with 8-bit digits: 24-bit keys (the entry sort), keys using all 32 bits, sizes around the tile', async () => {
    const random = rng(17);
    const sort = new RadixSort(ctx);
    const entryPasses = digitPasses(KEY_BITS, 0, 8);
    for (const n of [0, 1, 2, 1023, 1024, 1025, 3 * SORT_TILE + 7, 40_000]) {
      // keys with few distinct low digits (ties inside a digit) and random high ones
      const key24 = keyed(n, () => (random() < 0.5 ? (random() * 300) | 0 : (random() * 2 ** 24) | 0));
      expectStableSort((await gpuSort(ctx, sort, key24, entryPasses)).sorted, key24, byX, `24-bit n=${n}`);
      const key32 = keyed(n, (i) => (i % 3 === 0 ? 0xffffffff - ((random() * 4) | 0) : (random() * 2 ** 32) >>> 0));
      expectStableSort((await gpuSort(ctx, sort, key32, digitPasses(32, 0, 8))).sorted, key32, byX, `32-bit n=${n}`);
    }
  });

  it('keeps the input order when every digit is constant (all keys equal) and with many equal keys', async () => {
    const sort = new RadixSort(ctx);
    const random = rng(19);
    for (const n of [1, 1000, 5000]) {
      for (const passes of [digitPasses(KEY_BITS, 0, 8), digitPasses(32, 0)]) {
        const same = keyed(n, () => 0xa5c3e1);
        const { sorted } = await gpuSort(ctx, sort, same, passes);
        expect(Array.from(sorted)).toEqual(Array.from(same));
        // three key values, so every tile holds long runs of equal keys in every digit
        const few = keyed(n, () => [0x010203, 0xff00ff, 0x0203ff][(random() * 3) | 0]);
        expectStableSort((await gpuSort(ctx, sort, few, passes)).sorted, few, byX, `three keys n=${n}`);
      }
    }
  });

  it('sorts (x, y) lexicographically as the key x << lowBits | y, digits straddling the two words', async () => {
    const sort = new RadixSort(ctx);
    const random = rng(23);
    const lex = (lowBits: number) => (x: number, y: number) => (BigInt(x) << BigInt(lowBits)) | BigInt(y);
    // lowBits 31 with full 32-bit x: a 63-bit key, 8 passes, the fourth straddling bit 32
    for (const lowBits of [1, 10, 20, 31]) {
      const n = 5000;
      const data = new Uint32Array(2 * n);
      for (let i = 0; i < n; ++i) {
        data[2 * i] = lowBits === 31 ? (random() * 2 ** 32) >>> 0 : (random() * 40) | 0;
        data[2 * i + 1] = Math.floor(random() * 2 ** lowBits) >>> 0;
      }
      const passes = digitPasses(32 + lowBits, 2, 8, lowBits);
      expectStableSort((await gpuSort(ctx, sort, data, passes)).sorted, data, lex(lowBits), `lowBits ${lowBits}`);
    }
    // the pair sort's passes order unique pairs (a, b), a < b < slotCount
    const slots = 3000;
    const seen = new Set<number>();
    const pairs: number[] = [];
    while (pairs.length < 2 * 20_000) {
      const a = Math.floor(random() * slots);
      const b = Math.floor(random() * slots);
      if (a >= b || seen.has(a * slots + b)) continue;
      seen.add(a * slots + b);
      pairs.push(a, b);
    }
    const data = Uint32Array.from(pairs);
    const { sorted } = await gpuSort(ctx, sort, data, pairSortPasses(slots));
    expectStableSort(sorted, data, lex(12), 'pairs');
  });

  it('scans the tile counts in each of its shapes: one invocation per digit (<= 16 tiles), several digits per workgroup, several rounds per digit (> 1024 tiles)', async () => {
    const sort = new RadixSort(ctx);
    const random = rng(31);
    // 16 and 17 tiles: the serial scan and the first size past it (64 rows per workgroup);
    // 1025 tiles + 5: one digit per workgroup, two rounds of 1024 tile counts (a 4-bit pass
    // keeps this 1.05 M-element case cheap on a CPU device).
    for (const [n, passes] of [
      [16 * SORT_TILE, digitPasses(16, 0, 8)],
      [17 * SORT_TILE + 3, digitPasses(16, 0, 8)],
      [1025 * SORT_TILE + 5, digitPasses(4, 0)],
    ] as const) {
      const data = keyed(n, () => (random() * 2 ** 16) | 0);
      const { sorted } = await gpuSort(ctx, sort, data, [...passes]);
      const bits = 4 * passes.length * (passes[0].bits === 8 ? 2 : 1);
      expectStableSort(sorted, data, (x) => BigInt(x & (2 ** bits - 1)), `n=${n}`);
    }
  });

  it('leaves the last pass\'s count of each digit in digitTotalsBuffer (the narrow phase\'s bin sizes)', async () => {
    const sort = new RadixSort(ctx);
    const random = rng(29);
    const n = 4000;
    const data = keyed(n, () => (random() * 2 ** 24) | 0);
    for (const [passes, digits, shift] of [
      [[{ shift: 0, component: 0 as const }], 16, 0],
      [digitPasses(KEY_BITS, 0, 8), 256, 16],
    ] as const) {
      const { totals } = await gpuSort(ctx, sort, data, [...passes], digits);
      const expected = new Uint32Array(digits);
      for (let i = 0; i < n; ++i) expected[(data[2 * i] >>> shift) & (digits - 1)]++;
      expect(Array.from(totals)).toEqual(Array.from(expected));
    }
  });

  it('sorts the broad phase\'s keys in fewer passes: 3 for the entries, 5 for the pairs of 10^6 slots (3 dispatches each)', async () => {
    // Before: 4-bit digits over 32-bit entry keys (8 passes) and over a and b apart (5 + 5).
    const entry = digitPasses(KEY_BITS, 0, 8);
    expect(entry.map((p) => p.bits)).toEqual([8, 8, 8]);
    expect(pairSortPasses(1_000_000).map((p) => p.bits)).toEqual([8, 8, 8, 8, 8]);
    expect(pairSortPasses(1000).map((p) => p.bits)).toEqual([8, 8, 4]);
    const { dispatches } = await gpuSort(ctx, new RadixSort(ctx), keyed(3000, (i) => i * 7919), entry);
    expect(dispatches).toBe(3 * entry.length);
  });

  it('computes exclusive prefix sums and their total in place', async () => {
    const random = rng(3);
    for (const n of [1, 4095, 4096, 4097, 300_000]) {
      const data = new Uint32Array(n);
      for (let i = 0; i < n; ++i) data[i] = (random() * 40) | 0;
      const buf = new GpuArray(ctx, 'data', 4, n);
      ctx.device.queue.writeBuffer(buf.buffer, 0, data);
      const state = ctx.createBuffer('state', 4 * STATE_WORDS, USAGE.STORAGE | USAGE.COPY_DST | USAGE.COPY_SRC);
      ctx.device.queue.writeBuffer(state, 0, new Uint32Array([n]));
      const scan = new PrefixScan(ctx);
      scan.reserve(n);
      const enc = ctx.device.createCommandEncoder();
      const pass = enc.beginComputePass();
      scan.encode(new Recorder(pass, 65535), buf.buffer, state, 0, 2, { groups: Math.ceil(n / 4096) });
      pass.end();
      ctx.device.queue.submit([enc.finish()]);
      const got = await read(ctx, buf.buffer, 4 * n);
      const total = (await read(ctx, state, 16))[2];
      let sum = 0;
      for (let i = 0; i < n; ++i) {
        if (got[i] !== sum) throw new Error(`n=${n}: prefix ${i} is ${got[i]}, expected ${sum}`);
        sum += data[i];
      }
      expect(total).toBe(sum);
    }
  });
});
