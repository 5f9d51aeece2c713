/*
 * What the pages that step and draw on the GPU share: a world attached to a WebGPUBackend and drawn
 * by GpuRenderer into a canvas, with GpuPointQuery to find the body under the pointer; and the
 * frame loop that steps and draws once per display frame while the previous frame's work is done
 * (a display frame that finds it unfinished waits, and is counted); and the device they choose,
 * with the page's note saying what steps the world.
 */

import type { b2World } from '../../src/dynamics/b2World';
import { WebGPUBackend } from '../../src-gpu/backend/backend';
import type { GpuContext } from '../../src-gpu/device/device';
import { GpuPointQuery } from '../../src-gpu/query/pointQuery';
import type { GpuPointHit } from '../../src-gpu/query/pointQuery';
import { GpuRenderer } from '../../src-gpu/render/render';
import { requestGpu } from '../../src-gpu/device/device';
import type { GpuFrameStats } from '../../src-gpu/render/render';
import { fitCanvas } from '../canvas';
import { CanvasWorldView } from './canvasView';
import { detectWebGpu, StepTimes } from './demo';

/** A view's centre in metres and its scale in CSS pixels per metre. */
export interface ViewCamera {
  x: number;
  y: number;
  scale: number;
}

/**
 * A WebGPU device when the browser has an adapter, else null; `note` says which, ending with `gpu`
 * (what the page does on WebGPU) or `js` (what it does on the JavaScript engine).
 */
export async function openGpu(note: HTMLElement, gpu: string, js: string): Promise<GpuContext | null> {
  const status = await detectWebGpu();
  let text = `${status.reason}: ${js}`;
  if (status.adapter) {
    try {
      const context = await requestGpu();
      note.textContent = `WebGPU adapter: ${status.name}. ${gpu}`;
      note.dataset.adapter = status.name ?? '';
      note.className = 'note ok';
      return context;
    } catch (error) {
      text = `The WebGPU device could not be created (${error instanceof Error ? error.message : String(error)}): ${js}`;
    }
  }
  note.textContent = text;
  note.className = 'note warn';
  return null;
}

export class GpuWorldView {
  private constructor(
    readonly world: b2World,
    readonly backend: WebGPUBackend,
    private readonly canvas: HTMLCanvasElement,
    private readonly renderer: GpuRenderer,
    private readonly query: GpuPointQuery,
  ) {}

  /** Attaches `world` to a WebGPU backend on `context` and draws it into `canvas`. */
  static async create(world: b2World, context: GpuContext, canvas: HTMLCanvasElement): Promise<GpuWorldView> {
    const backend = await WebGPUBackend.create({ context });
    await world.SetBackend(backend);
    const target = canvas.getContext('webgpu');
    if (target === null) throw new Error('this canvas gives no WebGPU context');
    return new GpuWorldView(world, backend, canvas, new GpuRenderer(backend, target), new GpuPointQuery(backend));
  }

  get lastFrame(): GpuFrameStats | null {
    return this.renderer.lastFrame;
  }

  /** Runs `step` (the page's world.Step calls), draws at `camera`, and resolves when the GPU is done with both. */
  async frame(step: () => void, camera: ViewCamera): Promise<void> {
    const { dpr } = fitCanvas(this.canvas);
    step();
    Object.assign(this.renderer.camera, { x: camera.x, y: camera.y, scale: camera.scale * dpr });
    await this.renderer.draw();
    await this.backend.ctx.device.queue.onSubmittedWorkDone();
  }

  bodyAt(x: number, y: number): Promise<GpuPointHit | null> {
    return this.query.bodyAt(x, y);
  }

  /** Frees the world's GPU buffers; the world is not handed back. */
  async close(): Promise<void> {
    this.query.destroy();
    this.renderer.destroy();
    await this.backend.destroy();
  }
}

/** A page's view of its world: drawn from the GPU's buffers, or by the engine on a 2D canvas. */
export type WorldView = GpuWorldView | CanvasWorldView;

/**
 * `world` shown in `canvas`: attached to a WebGPU backend on `context` and drawn by GpuRenderer,
 * or, without a context, stepped by the engine and drawn on a 2D canvas.
 */
export async function openWorldView(world: b2World, context: GpuContext | null, canvas: HTMLCanvasElement): Promise<WorldView> {
  return context !== null ? GpuWorldView.create(world, context, canvas) : new CanvasWorldView(world, canvas);
}

/**
 * requestAnimationFrame driving `frame` (one step and draw), at most one frame's work at a time:
 * the time between frames and from a frame's start to its work done, as medians over the last
 * second, and the display frames that waited.
 */
export class FrameLoop {
  frames = 0;
  waited = 0;
  readonly frameTimes = new StepTimes();
  readonly workTimes = new StepTimes();
  private inFlight: Promise<void> | null = null;
  private last = NaN;
  private running = false;

  /** `failed` gets the message of a frame that threw; the loop then stops. */
  constructor(
    private readonly frame: () => Promise<void> | null,
    private readonly done: (now: number) => void,
    private readonly failed: (message: string) => void,
  ) {}

  start(): void {
    if (this.running) return;
    this.running = true;
    requestAnimationFrame(this.tick);
  }

  /** Resolves when the frame in flight, if any, is done (or failed). */
  async idle(): Promise<void> {
    await this.inFlight?.catch(() => undefined);
  }

  /** Forgets the counts and times (a new scene). */
  reset(): void {
    this.frames = 0;
    this.waited = 0;
    this.frameTimes.clear();
    this.workTimes.clear();
  }

  private readonly tick = (now: number): void => {
    requestAnimationFrame(this.tick);
    if (this.inFlight !== null) {
      this.waited++;
      return;
    }
    const started = performance.now();
    const work = this.frame();
    if (work === null) return;
    if (Number.isFinite(this.last)) this.frameTimes.add(now, now - this.last);
    this.last = now;
    this.inFlight = work.then(
      () => {
        this.inFlight = null;
        this.workTimes.add(now, performance.now() - started);
        this.frames++;
        this.done(performance.now());
      },
      (error) => {
        console.error(error);
        this.failed(`The frame failed: ${error instanceof Error ? error.message : String(error)}`);
      },
    );
  };
}
