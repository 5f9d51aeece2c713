// Types for bench/run.mjs (the harness is plain JavaScript so `node bench/run.mjs` needs no build).

export interface BenchOptions {
  /** Scene ids, as an array or a comma list (default all). */
  scenes?: string[] | string;
  /** Engine ids, as an array or a comma list (default all). */
  engines?: string[] | string;
  sleep?: 'on' | 'off' | 'both';
  /** Small scenes and a tiny protocol, for tests and CI smoke runs. */
  quick?: boolean;
  steps?: number;
  rounds?: number;
  preroll?: number;
  allocSteps?: number;
  /** Untimed steps run after the timed rounds, before the allocation window (default 0). */
  allocPreroll?: number;
  /** A prebuilt webphysics.mjs to run instead of building the working tree. */
  ours?: string;
  write?: boolean;
  outDir?: string;
  charts?: boolean;
  /** Progress lines (default stderr); null for silence. */
  log?: ((line: string) => void) | null;
  /** The result tables (default stdout); null for silence. */
  print?: ((text: string) => void) | null;
}

export interface Timing {
  medianMs: number;
  p95Ms: number;
  meanMs: number;
  minMs: number;
  maxMs: number;
  stepsPerSecond: number;
  samples: number;
  roundMedians: number[];
  bestRoundMedianMs: number;
}

export interface EngineResult {
  engine: string;
  sleep: boolean;
  status: 'ok' | 'skipped' | 'error';
  reason: string | null;
  timing: Timing | null;
  ratioToOurs: number | null;
  memory: {
    /** null where the built world's heap was not above an empty world's, or not measured (heap.mjs). */
    worldBytes: number | null;
    /** null where the measurement's process failed (heap.mjs). */
    heapGrowthBytes: number | null;
    allocBytesPerStep: number;
    allocSteps: number;
    gcPer1000Steps: number;
    gcMsPerStep: number;
    wasmBytes: number | null;
  } | null;
  counts: { bodies: number; contacts: number | null; steps: number } | null;
  check: { ok: boolean; detail: string } | null;
}

export interface SceneResult {
  id: string;
  title: string;
  description: string;
  bodies: number;
  joints: number;
  settings: { dt: number; velocityIterations: number; positionIterations: number };
  protocol: { preroll: number; steps: number; rounds: number; allocSteps: number; allocPreroll: number };
  results: EngineResult[];
  skipped?: string;
}

export interface BenchResults {
  schema: 'webphysics-bench/1';
  date: string;
  machine: { cpus: number; cpuModel: string; memoryGiB: number; caches: CpuCache[]; node: string; v8: string; platform: string };
  options: Record<string, unknown>;
  engines: { id: string; name: string; package: string; version: string | null; family: string; notes: string[]; loadError: string | null }[];
  scenes: SceneResult[];
  durationSeconds: number;
  files?: string[];
}

/** A data cache of the first CPU: its level, size and how many CPUs share it. */
export interface CpuCache {
  level: number;
  kib: number;
  sharedBy: number;
}

/** The first CPU's data caches from Linux's sysfs (`dir`, default /sys/devices/system/cpu/cpu0/cache); [] where there is none. */
export function cpuCaches(dir?: string): CpuCache[];
/** The caches in words, e.g. "L1 48 KiB, L2 2 MiB, L3 480 MiB shared by 2 CPUs"; "" for none. */
export function describeCaches(caches?: CpuCache[]): string;
/** builtHeap - baseHeap, or null when that is not above zero (an earlier world still reachable, or noise). */
export function worldHeapBytes(builtHeap: number, baseHeap: number): number | null;

export const SCENE_IDS: string[];
export const ENGINE_IDS: string[];
export const USAGE: string;
export function runBench(options?: BenchOptions): Promise<BenchResults>;
export function main(argv?: string[]): Promise<number>;
