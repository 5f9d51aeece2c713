// The readers behind bench/cachesim.mjs, on hand-written valgrind output (valgrind itself is an
// optional tool: the counts it produces are what the benchmark reports, never a test's subject).
import { describe, expect, it } from 'vitest';
import { costsByCodeObject, eventTotals } from '../../bench/valgrind.mjs';

const perfMap = ['1000 100 JS:*Update file:///w.mjs:1:1', '1100 80 Builtin:LoadIC', '2000 40 JS:*Solve file:///w.mjs:9:1'].join('\n');

// Callgrind with --dump-instr=yes: absolute and relative instruction addresses, a line column,
// and a call whose next line is the call's inclusive cost.
const callgrind = [
  'version: 1',
  'positions: instr line',
  'events: Ir D1mr DLmr',
  'fl=???',
  'fn=0x1000',
  '0x1010 0 10 2 1',
  '+8 * 5 1 1',
  'calls=1 0x2000',
  '+4 * 100 50 40',
  '+4 * 3 0 0',
  'fn=0x1100',
  '0x1120 0 7 1 0',
  '0x2004 0 20 4 2',
  '0x9000 0 1 1 1',
  'summary: 46 9 5',
].join('\n');

describe('valgrind output readers', () => {
  it('eventTotals reads the summary line by event name', () => {
    expect(eventTotals(callgrind)).toEqual({ Ir: 46, D1mr: 9, DLmr: 5 });
    expect(eventTotals('events: Ir Dr\nsummary: 12 3\n')).toEqual({ Ir: 12, Dr: 3 });
    expect(() => eventTotals('not valgrind')).toThrow(/no events or summary/);
  });

  it('costsByCodeObject sums instruction costs per perf-map object, skipping call costs', () => {
    const { events, costs } = costsByCodeObject(callgrind, perfMap);
    expect(events).toEqual(['Ir', 'D1mr', 'DLmr']);
    expect(Object.fromEntries(costs)).toEqual({
      'JS:*Update file:///w.mjs:1:1': [18, 3, 2],
      'Builtin:LoadIC': [7, 1, 0],
      'JS:*Solve file:///w.mjs:9:1': [20, 4, 2],
      '(native)': [1, 1, 1],
    });
  });
});
