// Types for bench/processes.mjs (plain JavaScript so `node bench/processes.mjs` needs no build).

export interface ProcessesOptions {
  scene?: string;
  /** Engine ids, as an array or a comma list (default webphysics and box2d-wasm). */
  engines?: string[] | string;
  runs?: number | string;
  steps?: number | string;
  /** Step windows [from, to), as "64-192,192-600". */
  windows?: string;
  quick?: boolean;
  /** A prebuilt webphysics.mjs to run instead of building the working tree. */
  ours?: string | null;
  /** The bundle webphysics-baseline runs. */
  baseline?: string | null;
  /** A Box2D 2.2.1 checkout, for the native engines (bench/native.mjs). */
  box2d?: string | null;
  /** Progress lines (default stderr); null for silence. */
  log?: ((line: string) => void) | null;
}

export interface ProcessesEngineResult {
  id: string;
  name: string;
  /** Per window, the median over the runs of each run's median ms per step. */
  windowMs: number[];
  /** Per run, its median ms per step in each window. */
  runsMs: number[][];
}

export interface ProcessesResult {
  scene: string;
  steps: number;
  windows: [number, number][];
  runs: number;
  engines: ProcessesEngineResult[];
}

export const PROCESSES_USAGE: string;
export function parseWindows(text: string, steps: number): [number, number][];
export function resolveProcessesOptions(options?: ProcessesOptions): {
  scene: string;
  engines: string[];
  runs: number;
  steps: number;
  windows: [number, number][];
  quick: boolean;
  ours: string | null;
  baseline: string | null;
  box2d: string | null;
  log: (line: string) => void;
};
export function runProcesses(options?: ProcessesOptions): Promise<ProcessesResult>;
export function formatProcesses(result: ProcessesResult): string;
export function main(argv?: string[]): Promise<number>;
