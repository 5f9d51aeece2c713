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
  method: string;
  msPerSecond: number;
  measures: Record<string, number>;
}

export interface AccuracyScene {
  id: string;
  title: string;
  seconds: number;
  measures: string[];
  results: AccuracyResult[];
  /** Per measure, the methods on the Pareto front, cheapest first. */
  fronts: Record<string, string[]>;
}

export interface AccuracyLimit extends LimitResult {
  id: string;
  test: string;
  unit: string;
  method: string;
  range: [number, number];
  smallest: boolean;
}

export interface AccuracyRun {
  schema: string;
  date: string;
  quick: boolean;
  machine: { cpus: number; cpuModel: string; node: string };
  methods: AccuracyMethod[];
  scenes: AccuracyScene[];
  limits: AccuracyLimit[];
}

export interface AccuracyOptions {
  quick?: boolean;
  scenes?: string[];
  methods?: string[];
  limits?: boolean;
  rounds?: number;
  log?: (line: string) => void;
}

export const ACCURACY_SCHEMA: string;
export function runAccuracy(b2: unknown, options?: AccuracyOptions): Promise<AccuracyRun>;
export function stabilityLimits(b2: unknown, method: AccuracyMethod, options?: { quick?: boolean }): Promise<AccuracyLimit[]>;
export function writeAccuracy(results: AccuracyRun, dir: string): string[];
