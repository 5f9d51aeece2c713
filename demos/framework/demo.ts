/*
 * What every demo page shares: `window.webphysicsDemo`, the state tests and scripts read while a
 * page runs; step times as a median over the last second; whether there is WebGPU, and the
 * adapter named for people; finding elements, showing a note, and formatting numbers.
 */

import type { GpuAdapterSummary } from '../../src-gpu/device/device';

/** The element of this id (the page's own markup: it exists). */
export const $ = <T extends HTMLElement>(id: string) => document.getElementById(id) as T;

/** Milliseconds with three significant digits or so; a dash when unknown. */
export const fmtMs = (ms: number) => (!Number.isFinite(ms) ? '–' : ms < 10 ? ms.toFixed(2) : ms < 100 ? ms.toFixed(1) : ms.toFixed(0));
export const fmtCount = (n: number) => n.toLocaleString('en-US');

/** Shows `text` in `note`, or hides the note when the text is empty. */
export function showNote(note: HTMLElement, text: string): void {
  note.textContent = text;
  note.hidden = text === '';
}

export interface DemoPane {
  backend: 'js' | 'webgpu';
  /** The WebGPU adapter that steps this pane, in words; null for the JavaScript engine. */
  adapter: string | null;
  bodies: number;
  steps: number;
  /** Median step time over the last second, in milliseconds (NaN before the first step). */
  stepMs: number;
}

export interface WebPhysicsDemo {
  /** The page has built its scene and stepped it at least once. */
  ready: boolean;
  panes: DemoPane[];
}

declare global {
  interface Window {
    webphysicsDemo: WebPhysicsDemo;
  }
}

/** The adapter's vendor, architecture and description, and whether it is a software one. */
export function adapterName(info: Pick<GpuAdapterSummary, 'vendor' | 'architecture' | 'description'> & { software?: boolean }): string {
  const parts = [info.vendor, info.architecture, info.description].filter((s) => s !== '');
  const name = parts.length > 0 ? parts.join(' / ') : 'an adapter that gives no name';
  return info.software ? `${name} (software: a CPU emulating a GPU)` : name;
}

export interface WebGpuStatus {
  /** navigator.gpu exists. */
  api: boolean;
  /** requestAdapter() gave an adapter. */
  adapter: boolean;
  /** The adapter in words (adapterName), when there is one. */
  name: string | null;
  /** Why there is no adapter, in words; null when there is one. */
  reason: string | null;
}

/** Whether this browser (or worker) has WebGPU and an adapter. */
export async function detectWebGpu(): Promise<WebGpuStatus> {
  const gpu = (navigator as Navigator & { gpu?: GPU }).gpu;
  if (gpu === undefined) return { api: false, adapter: false, name: null, reason: 'This browser lacks WebGPU (no navigator.gpu)' };
  try {
    const adapter = await gpu.requestAdapter();
    if (adapter === null) {
      return { api: true, adapter: false, name: null, reason: 'This browser has WebGPU but no adapter (GPU access disabled or blocked)' };
    }
    const info = adapter.info;
    const software =
      (info as GPUAdapterInfo & { isFallbackAdapter?: boolean }).isFallbackAdapter === true ||
      /swiftshader|llvmpipe|lavapipe|warp/i.test(`${info.vendor} ${info.architecture} ${info.description}`);
    return {
      api: true,
      adapter: true,
      name: adapterName({ vendor: info.vendor, architecture: info.architecture, description: info.description, software }),
      reason: null,
    };
  } catch (error) {
    return { api: true, adapter: false, name: null, reason: `The WebGPU adapter request failed (${error instanceof Error ? error.message : String(error)})` };
  }
}

/** Step times kept for a second: the median of those, or the last one when the last second had none. */
export class StepTimes {
  private readonly times: number[] = [];
  private readonly values: number[] = [];
  private readonly scratch: number[] = [];

  add(now: number, ms: number): void {
    this.times.push(now);
    this.values.push(ms);
  }

  clear(): void {
    this.times.length = 0;
    this.values.length = 0;
  }

  median(now: number): number {
    let drop = 0;
    while (drop < this.times.length - 1 && this.times[drop] < now - 1000) drop++;
    if (drop > 0) {
      this.times.splice(0, drop);
      this.values.splice(0, drop);
    }
    const v = this.scratch;
    v.length = 0;
    for (const x of this.values) v.push(x);
    if (v.length === 0) return NaN;
    v.sort((a, b) => a - b);
    const mid = v.length >> 1;
    return v.length % 2 === 1 ? v[mid] : 0.5 * (v[mid - 1] + v[mid]);
  }
}
