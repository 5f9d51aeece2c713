// Types for bench/accuracy/run.mjs.
import type { LimitResult } from './limits.mjs';

export interface AccuracyMethod {
  id: string;
  label: string;
  frameHz: number;
  substeps: number;
  velocityIterations: number;
  positionIterations: number;
  warmStarting: boolean;
}

export interface AccuracyResult {
  /** The method's id, after 'webgpu ' for the GPU's runs; a peer engine's id. */
  key: string;
  /** A method's id ('default' for a peer). */
  method: string;
  /** 'js', 'webgpu', or a peer engine's id. */
  backend: string;
  /** null: not timed (the GPU on a software adapter). */
  msPerSecond: number | null;
  measures: Record<string, number>;
}

export interface AccuracyScene {
  id: string;
  title: string;
  seconds: number;
  measures: string[];
  results: AccuracyResult[];
  /** Per measure, the keys of the results on the Pareto front, cheapest first. */
  fronts: Record<string, string[]>;
}

export interface AccuracyLimit extends LimitResult {
  id: string;
  test: string;
  unit: string;
  method: string;
  range: [number, number];
  smallest: boolean;
  /** A GPU limit merged from a run on another device (merge.mjs): that device. */
  device?: string;
}

export interface AccuracyRun {
  schema: string;
  date: string;
  quick: boolean;
  machine: { cpus: number; cpuModel: string; node: string; gpu: object | null };
  methods: AccuracyMethod[];
  peers: { id: string; name: string; version: string | null; family: string; notes: string[] }[];
  scenes: AccuracyScene[];
  limits: AccuracyLimit[];
}

export interface GpuRunner {
  adapter: { description: string; device: string; software: boolean };
  timed: boolean;
  create(): Promise<unknown>;
}

export interface AccuracyOptions {
  gpu?: GpuRunner | null;
  gpuMethods?: string[];
  /** With `gpu`: the GPU methods' stability limits too (the default method's with `quick`; default true). */
  gpuLimits?: boolean;
  peers?: { engine: unknown; api: unknown }[];
  quick?: boolean;
  scenes?: string[];
  methods?: string[];
  limits?: boolean;
  rounds?: number;
  log?: (line: string) => void;
}

export const ACCURACY_SCHEMA: string;
export function runAccuracy(b2: unknown, options?: AccuracyOptions): Promise<AccuracyRun>;
export function stabilityLimits(b2: unknown, method: AccuracyMethod, options?: { quick?: boolean; gpu?: GpuRunner | null }): Promise<AccuracyLimit[]>;
export function peerLimits(engine: unknown, api: unknown): Promise<AccuracyLimit[]>;
export function gpuBackend(gpuBundle: string): Promise<GpuRunner>;
export function loadPeers(ids: string[] | null, oursBundle: string): Promise<{ engine: unknown; api: unknown }[]>;
export function writeAccuracy(results: AccuracyRun, dir: string): string[];
