/*
 * The host and the shaders agree on the shared layout: the state words, indirect argument
 * offsets, flag bits and tile sizes of src-gpu/layout.ts are the constants the WGSL declares; and
 * every stage has its WGSL file and host module, each opening with a comment on its inputs,
 * outputs and invariants. (No GPU needed.)
 */

import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, it } from 'vitest';
import * as layout from '../../src-gpu/layout';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const wgsl = (name: string) => readFileSync(path.join(root, 'shaders', `${name}.wgsl`), 'utf8');

function constants(source: string): Map<string, number> {
  const out = new Map<string, number>();
  for (const m of source.matchAll(/^const (\w+): (?:u32|f32) = ([0-9.x]+)u?;/gm)) out.set(m[1], Number(m[2]));
  return out;
}

const STAGES = ['bounds', 'axis', 'keys', 'radixSort', 'scan', 'sweep', 'pairs'];

it('declares the state words, indirect offsets and flags the host uses', () => {
  const c = constants(wgsl('common'));
  for (const [name, value] of Object.entries(layout.STATE)) expect(c.get(`STATE_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.ARGS)) expect(c.get(`ARGS_${name}`), name).toBe(value);
  expect(c.get('PROXY_LIVE')).toBe(layout.PROXY_LIVE);
  expect(c.get('PROXY_SENSOR')).toBe(layout.PROXY_SENSOR);
  expect(c.get('PROXY_JOINTED')).toBe(layout.PROXY_JOINTED);
  expect(c.get('OVERFLOW_PAIRS')).toBe(layout.OVERFLOW_PAIRS);
  expect(c.get('OVERFLOW_ENTRIES')).toBe(layout.OVERFLOW_ENTRIES);
  expect(c.get('QUANT_BITS')).toBe(layout.QUANT_BITS);
  expect(c.get('MAX_STRIPS')).toBe(layout.MAX_STRIPS);
  expect(c.get('WORKGROUP_SIZE')).toBe(layout.WORKGROUP_SIZE);
  expect(Math.max(...Object.values(layout.STATE))).toBeLessThan(layout.STATE_WORDS);
  expect(Math.max(...Object.values(layout.ARGS)) + 3).toBeLessThanOrEqual(layout.INDIRECT_WORDS);
});

it('uses the tile sizes the host dispatches with', () => {
  expect(constants(wgsl('radixSort')).get('TILE')).toBe(layout.SORT_TILE);
  expect(constants(wgsl('scan')).get('BLOCK')).toBe(layout.SCAN_BLOCK);
  expect(constants(wgsl('axis')).get('ITEMS_PER_GROUP')).toBe(layout.AXIS_ITEMS_PER_GROUP);
  expect(constants(wgsl('sweep')).get('CHUNK')).toBe(layout.SWEEP_CHUNK);
});

it('has one WGSL file and one host module per stage, each opening with what it reads and writes', () => {
  for (const stage of STAGES) {
    const shader = wgsl(stage);
    expect(shader.startsWith(`// ${stage}.wgsl: `), stage).toBe(true);
    expect(shader).toMatch(/\/\/ (In|Out):/);
    const host = readFileSync(path.join(root, 'src-gpu', `${stage}.ts`), 'utf8');
    expect(host.startsWith('/*'), stage).toBe(true);
    expect(host.slice(0, 1500)).toMatch(/In:/);
  }
});

it('keeps the engine free of the GPU backend', () => {
  const offenders: string[] = [];
  const walk = (dir: string) => {
    for (const entry of readdirSync(dir, { withFileTypes: true })) {
      const full = path.join(dir, entry.name);
      if (entry.isDirectory()) walk(full);
      else if (/from '[^']*src-gpu/.test(readFileSync(full, 'utf8'))) offenders.push(full);
    }
  };
  walk(path.join(root, 'src'));
  expect(offenders).toEqual([]);
});
