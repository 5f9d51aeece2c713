import { expect, it } from 'vitest';
import { GpuArray } from '../../src-gpu/device/buffers';
import { Recorder } from '../../src-gpu/device/kernel';
import { digitPasses, RadixSort } from '../../src-gpu/primitives/radixSort';
import type { SortPass } from '../../src-gpu/primitives/radixSort';
import { pairSortPasses } from '../../src-gpu/broadphase/pairs';
import { PrefixScan } from '../../src-gpu/primitives/scan';
import { KEY_BITS, MAP_READ, SORT_TILE, STATE_WORDS, USAGE } from '../../src-gpu/device/layout';
import type { GpuContext } from '../../src-gpu/device/device';
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
 * digit totals buffer's first `digits` words (the last pass's count per digit). With `indirect`,
 * the sort is dispatched indirectly (the tile count in a buffer, as a GPU-computed count would
 * be), its scan sized for `indirect.maxCount`.
 */
async function gpuSort(
  ctx: GpuContext,
  sort: RadixSort,
  data: Uint32Array<ArrayBuffer>,
  passes: SortPass[],
  digits = 16,
  indirect?: { maxCount: number },
): Promise<{ sorted: Uint32Array; totals: Uint32Array; dispatches: number }> {
  const n = data.length / 2;
  const a = new GpuArray(ctx, 'a', 8, Math.max(1, n));
  const b = new GpuArray(ctx, 'b', 8, Math.max(1, n));
  const state = ctx.createBuffer('state', 4 * STATE_WORDS, USAGE.STORAGE | USAGE.COPY_DST);
  ctx.device.queue.writeBuffer(state, 0, new Uint32Array([n, 0, 0, 0]));
  if (n > 0) ctx.device.queue.writeBuffer(a.buffer, 0, data);
  const args = ctx.createBuffer('args', 16, USAGE.INDIRECT | USAGE.COPY_DST);
  ctx.device.queue.writeBuffer(args, 0, new Uint32Array([Math.ceil(n / SORT_TILE), 1, 1, 0]));
  sort.reserve(indirect ? indirect.maxCount : n);
  const enc = ctx.device.createCommandEncoder();
  const pass = enc.beginComputePass();
  const rec = new Recorder(pass, 65535);
  const out = sort.encode(
    rec,
    a.buffer,
    b.buffer,
    passes,
    state,
    0,
    indirect ? { indirect: args, offset: 0, maxCount: indirect.maxCount } : { groups: Math.ceil(n / SORT_TILE) },
  );
  pass.end();
  ctx.device.queue.submit([enc.finish()]);
  const sorted = await read(ctx, out, Math.max(4, 8 * n));
  const totals = await read(ctx, sort.digitTotalsBuffer, 4 * digits);
  await ctx.checkErrors();
  a.destroy();
  b.destroy();
  state.destroy();
  args.destroy();
  return { sorted: sorted.subarray(0, 2 * n), totals, dispatches: rec.dispatches };
}

/** The digit `pass` reads from (x, y). */
function passDigit(pass: SortPass, x: number, y: number): number {
  const key = pass.component === 0 ? BigInt(x) : pass.component === 1 ? BigInt(y) : (BigInt(x) << BigInt(pass.lowBits ?? 0)) | BigInt(y);
  return Number((key >> BigInt(pass.shift)) & BigInt((1 << (pass.bits ?? 4)) - 1));
}

/** `data` stably sorted by `pass`'s digit: one LSD pass in JavaScript. */
function jsPass(data: Uint32Array, pass: SortPass): Uint32Array<ArrayBuffer> {
  const n = data.length / 2;
  const digits = Array.from({ length: n }, (_, i) => passDigit(pass, data[2 * i], data[2 * i + 1]));
  const order = Array.from({ length: n }, (_, i) => i).sort((x, y) => digits[x] - digits[y] || x - y);
  const out = new Uint32Array(2 * n);
  order.forEach((e, i) => out.set(data.subarray(2 * e, 2 * e + 2), 2 * i));
  return out;
}

/**
 * What a pass's scan leaves in its tile histogram when `data` is its input: per digit d and tile
 * t, at d * tiles + t, the elements of digit d in tiles before t.
 */
function tilePrefixes(data: Uint32Array, pass: SortPass): Uint32Array {
  const n = data.length / 2;
  const tiles = Math.ceil(n / SORT_TILE);
  const radix = 1 << (pass.bits ?? 4);
  const counts = new Uint32Array(radix * tiles);
  for (let i = 0; i < n; ++i) counts[passDigit(pass, data[2 * i], data[2 * i + 1]) * tiles + Math.floor(i / SORT_TILE)]++;
  for (let d = 0; d < radix; ++d) {
    let sum = 0;
    for (let t = 0; t < tiles; ++t) {
      const c = counts[d * tiles + t];
      counts[d * tiles + t] = sum;
      sum += c;
    }
  }
  return counts;
}

/** Fails at the first word where `got` differs from `expected`. */
function expectWords(got: Uint32Array, expected: Uint32Array, what: string): void {
  for (let i = 0; i < expected.length; ++i) {
    if (got[i] !== expected[i]) throw new Error(`${what}: word ${i} is ${got[i]}, expected ${expected[i]}`);
  }
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

  it("leaves the last pass's count of each digit in digitTotalsBuffer (the narrow phase's bin sizes)", async () => {
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

  it("sorts the broad phase's keys in fewer passes and dispatches: 3 passes in 7 dispatches for the entries, 5 in 11 for the pairs of 10^6 slots", async () => {
    // Before: 4-bit digits over 32-bit entry keys (8 passes) and over a and b apart (5 + 5), then
    // 3 dispatches per pass (9 and 15); now one upsweep, then a scan and a downsweep per pass.
    const entry = digitPasses(KEY_BITS, 0, 8);
    expect(entry.map((p) => p.bits)).toEqual([8, 8, 8]);
    const pairs = pairSortPasses(1_000_000);
    expect(pairs.map((p) => p.bits)).toEqual([8, 8, 8, 8, 8]);
    expect(pairSortPasses(1000).map((p) => p.bits)).toEqual([8, 8, 4]);
    const sort = new RadixSort(ctx);
    expect(
      (
        await gpuSort(
          ctx,
          sort,
          keyed(3000, (i) => i * 7919),
          entry,
        )
      ).dispatches,
    ).toBe(7);
    const pairData = keyed(3000, (i) => (i * 7919) % 1_000_000);
    expect((await gpuSort(ctx, sort, pairData, pairs)).dispatches).toBe(11);
    expect((await gpuSort(ctx, sort, pairData, [{ shift: 0, component: 0 }])).dispatches).toBe(3);
  });

  it("counts each pass's digits per tile in the previous pass's downsweep exactly as an upsweep of that pass's input counts them", async () => {
    // After a sort of P passes, histograms[(P - 1) % 2] holds the last pass's tile prefixes and the
    // other buffer the pass before's; from the second pass on, those counts came from the
    // previous downsweep's atomics. Expected: the prefixes of a JavaScript pass-by-pass sort, and
    // (last pass) what a fresh sort's upsweep and scan give for the same input.
    const random = rng(41);
    const sort = new RadixSort(ctx);
    const fresh = new RadixSort(ctx);
    for (const [label, passes] of [
      ['entry keys, 8 + 8 + 8 bits', digitPasses(KEY_BITS, 0, 8)],
      ['20-bit keys, 8 + 8 + 4 bits', digitPasses(20, 0, 8)],
      ['two 4-bit passes (the colour sort)', digitPasses(8, 0)],
      ['pair keys of 3000 slots', pairSortPasses(3000)],
    ] as const) {
      for (const n of [1, 1023, 1024, 1025, 3 * SORT_TILE + 7, 20_000]) {
        const data = new Uint32Array(2 * n);
        for (let i = 0; i < n; ++i) {
          data[2 * i] = label.startsWith('pair') ? (random() * 3000) | 0 : random() < 0.3 ? (random() * 40) | 0 : (random() * 2 ** 24) | 0;
          data[2 * i + 1] = label.startsWith('pair') ? (random() * 3000) | 0 : i;
        }
        const inputs = [data];
        for (const pass of passes.slice(0, -1)) inputs.push(jsPass(inputs[inputs.length - 1], pass));
        await gpuSort(ctx, sort, data, [...passes]);
        const tiles = Math.ceil(n / SORT_TILE);
        const last = passes.length - 1;
        for (const k of [last - 1, last]) {
          const got = await read(ctx, sort.histograms[k % 2], 4 * 256 * tiles);
          expectWords(got, tilePrefixes(inputs[k], passes[k]), `${label}, n=${n}, pass ${k}`);
        }
        await gpuSort(ctx, fresh, inputs[last], [passes[last]]);
        const upswept = await read(ctx, fresh.histograms[0], 4 * 256 * tiles);
        const fused = await read(ctx, sort.histograms[last % 2], 4 * 256 * tiles);
        expectWords(fused, upswept.subarray(0, (1 << (passes[last].bits ?? 4)) * tiles), `${label}, n=${n}: fused vs upsweep`);
      }
    }
  });

  it('sorts 10^5+ elements with the fused counts: entry keys, pair keys, all keys equal, directly and indirectly dispatched', async () => {
    const random = rng(43);
    const sort = new RadixSort(ctx);
    const n = 100_003;
    const entryPasses = digitPasses(KEY_BITS, 0, 8);
    const entries = keyed(n, () => (random() < 0.2 ? (random() * 64) | 0 : (random() * 2 ** 24) | 0));
    expectStableSort((await gpuSort(ctx, sort, entries, entryPasses)).sorted, entries, byX, 'entries');
    // Equal keys: every element of a tile counts into one next-pass counter (the most contended
    // atomics); the order must stay the input's.
    const same = keyed(n, () => 0x5a5a5a);
    expect(Array.from((await gpuSort(ctx, sort, same, entryPasses)).sorted)).toEqual(Array.from(same));
    // Pairs of 2^17 slots (34-bit keys, 8 + 8 + 8 + 8 + 4 bits, the 4-bit last pass counted by an
    // 8-bit downsweep), indirectly dispatched with a scan sized for 4x the count.
    const slots = 1 << 17;
    const pairs = new Uint32Array(2 * n);
    for (let i = 0; i < n; ++i) {
      const a = (random() * (slots - 40)) | 0;
      pairs[2 * i] = a;
      pairs[2 * i + 1] = a + 1 + ((random() * 39) | 0);
    }
    const pairPasses = pairSortPasses(slots);
    expect(pairPasses.map((p) => p.bits)).toEqual([8, 8, 8, 8, 4]);
    const { sorted } = await gpuSort(ctx, sort, pairs, pairPasses, 16, { maxCount: 4 * n });
    expectStableSort(sorted, pairs, (x, y) => (BigInt(x) << 17n) | BigInt(y), 'pairs, indirect');
  });

  it('gives the same result whatever the histograms held before: a small sort after a large one, indirect with a larger bound', async () => {
    // Stale counts from an earlier sort (in both histogram buffers) must not leak into a later
    // one: the scan zeroes the next pass's counters before the downsweep adds to them.
    const random = rng(47);
    const sort = new RadixSort(ctx);
    const big = keyed(30_000, () => (random() * 2 ** 24) | 0);
    await gpuSort(ctx, sort, big, digitPasses(32, 0, 8));
    for (const n of [0, 1, 1025, 5000]) {
      const data = keyed(n, () => (random() * 2 ** 24) | 0);
      expectStableSort((await gpuSort(ctx, sort, data, digitPasses(KEY_BITS, 0, 8))).sorted, data, byX, `direct n=${n}`);
      expectStableSort((await gpuSort(ctx, sort, data, digitPasses(KEY_BITS, 0, 8), 256, { maxCount: 40_000 })).sorted, data, byX, `indirect n=${n}`);
      expectStableSort((await gpuSort(ctx, sort, data, digitPasses(12, 0))).sorted, data, (x) => BigInt(x & 0xfff), `4-bit n=${n}`);
    }
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
