// Types for bench/split.mjs (plain JavaScript so `node bench/split.mjs` needs no build).
import type { Scene } from './scenes.mjs';

/** A world built by an engine adapter, with the iteration counts settable between steps. */
export interface SplitWorld {
  step(): void;
  setIterations(velocityIterations: number, positionIterations: number): void;
  position(index: number): [number, number] | null;
  destroy(): void;
}

export interface SplitEngine {
  id: string;
  name: string;
  family: string;
  load(options: { oursBundle?: string | null }): Promise<unknown>;
  create(api: unknown, scene: Scene, options: { sleep: boolean }): SplitWorld;
}

export interface SplitOptions {
  scene?: string;
  /** Engine ids, as an array or a comma list (default webphysics and box2d-wasm). */
  engines?: string[] | string;
  /** The iterations whose count varies (default velocity). */
  vary?: 'velocity' | 'position';
  /** Iteration counts, as an array or a comma list: two or more different positive integers. */
  iterations?: number[] | string;
  rounds?: number | string;
  preroll?: number | string;
  steps?: number | string;
  quick?: boolean;
  /** A prebuilt webphysics.mjs to run instead of building the working tree. */
  ours?: string | null;
  /** Progress lines (default stderr); null for silence. */
  log?: ((line: string) => void) | null;
}

export interface SplitEngineResult {
  id: string;
  name: string;
  /** [iteration count, best-round median ms per step] */
  points: [number, number][];
  /** The fitted line's intercept: the step without the varied iterations. */
  fixedMs: number;
  /** The fitted line's slope: one more iteration. */
  perIterationMs: number;
  /** The largest distance of a point from the line. */
  maxResidualMs: number;
}

export interface SplitResult {
  scene: string;
  vary: 'velocity' | 'position';
  velocityIterations: number;
  positionIterations: number;
  machine: { cpuModel: string; caches: { level: number; kib: number; sharedBy: number }[]; node: string };
  protocol: { rounds: number; preroll: number; steps: number; iterations: number[] };
  engines: SplitEngineResult[];
}

export const SPLIT_ENGINES: SplitEngine[];
export const SPLIT_ENGINE_IDS: string[];
export const SPLIT_USAGE: string;
export function fitLine(points: [number, number][]): { intercept: number; slope: number; maxResidual: number };
export function resolveSplitOptions(options?: SplitOptions): Required<Omit<SplitOptions, 'log' | 'iterations' | 'engines'>> & {
  engines: string[];
  iterations: number[];
};
export function runSplit(options?: SplitOptions): Promise<SplitResult>;
export function formatSplit(result: SplitResult): string;
export function main(argv?: string[]): Promise<number>;
