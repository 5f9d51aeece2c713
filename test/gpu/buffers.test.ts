/*
 * Mirrored tables (src-gpu/device/buffers.ts): the host shadows live in a SharedArrayBuffer where
 * Node has one, uploads from them reach the GPU exactly (through the staging ArrayBuffer, in
 * pieces for a table over its size), and only changed records are written.
 */

import { expect, it } from 'vitest';
import { hostTableStore, MirrorTable } from '../../src-gpu/device/buffers';
import { readBuffer } from '../../src-gpu/device/readback';
import { withRoom } from '../../src-gpu/world/slots';
import { describeGpu } from './support';

it('host tables take shared memory where the platform has it; withRoom grows into it and keeps the contents and the fill', () => {
  expect(hostTableStore(64)).toBeInstanceOf(SharedArrayBuffer);
  const a = new Int32Array([5, 6, 7]);
  const grown = withRoom(a, 5, -1);
  expect(grown.buffer).toBeInstanceOf(SharedArrayBuffer);
  expect(Array.from(grown)).toEqual([5, 6, 7, -1, -1, -1]);
  expect(withRoom(grown, 2)).toBe(grown);
});

describeGpu('MirrorTable uploads', (ctx) => {
  it('a table of 6 MB (more than one staging piece) reaches the GPU word for word from its shared shadow', async () => {
    const n = 400_000;
    const table = new MirrorTable(ctx, 'test table', 4);
    table.reserve(n);
    expect(table.u32.buffer).toBeInstanceOf(SharedArrayBuffer);
    for (let slot = 0; slot < n; ++slot) table.commitWords(slot, slot, slot ^ 0x5a5a5a5a, 3 * slot + 1, 0xffffffff - slot);
    const stats = { bytes: 0, writes: 0, elements: 0 };
    table.flush(ctx.device.queue, stats);
    expect(stats).toEqual({ bytes: 16 * n, writes: 1, elements: n });
    const gpu = new Uint32Array(await readBuffer(ctx, table.buffer, 16 * n, 'test table read'));
    expect(gpu).toEqual(table.u32.subarray(0, 4 * n));
    table.destroy();
  });

  it('after a flush, changing two records uploads those two and nothing else', async () => {
    const n = 1000;
    const table = new MirrorTable(ctx, 'test table', 2);
    for (let slot = 0; slot < n; ++slot) table.commitWords(slot, slot, 1);
    table.flush(ctx.device.queue);
    for (let slot = 0; slot < n; ++slot) table.commitWords(slot, slot, slot === 10 || slot === 900 ? 2 : 1);
    const stats = { bytes: 0, writes: 0, elements: 0 };
    table.flush(ctx.device.queue, stats);
    expect(stats).toEqual({ bytes: 16, writes: 2, elements: 2 });
    const gpu = new Uint32Array(await readBuffer(ctx, table.buffer, 8 * n, 'test table read'));
    expect(gpu).toEqual(table.u32.subarray(0, 2 * n));
    table.destroy();
  });
});
