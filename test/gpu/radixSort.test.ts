import { expect, it } from 'vitest';
import { GpuArray } from '../../src-gpu/buffers';
import { Recorder } from '../../src-gpu/kernel';
import { digitPasses, RadixSort } from '../../src-gpu/radixSort';
import { PrefixScan } from '../../src-gpu/scan';
import { MAP_READ, STATE_WORDS, USAGE } from '../../src-gpu/layout';
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
