/*
 * The testbed's backend: the JavaScript engine or the WebGPU backend (webphysics/gpu) steps the
 * running test's world, switched with the world's state carried over (b2World.SetBackend).
 *
 * On WebGPU a frame is: the test's Step (world.Step records and submits the GPU step; the test
 * draws the world as the last synchronisation left it), then world.Synchronize(), which reads the
 * step back once (positions, velocities, contact events) and delivers the events. The frame timer
 * skips frames until that read is done, so the drawing is one step behind the GPU and the GPU is
 * never more than one step ahead. The step time shown is from the test's world.Step to the end of
 * that synchronisation.
 *
 * A test whose listener has its own PreSolve stays on JavaScript (Test.GpuRefusal says why); the
 * others get a listener with only the callbacks they use (Test.GpuContactListener), since the
 * backend logs and reads back only what a listener asks for.
 *
 * A large world on WebGPU (GPU_DRAW_BODIES bodies or more) is drawn by GpuRenderer from the GPU's
 * own buffers into a WebGPU canvas under the 2D one, which then holds only the text and the other
 * debug layers: drawing every body through DrawDebugData would fetch every body's state each frame
 * (b2World.PullState), which costs more than the step at that size.
 */

import { WebGPUBackend } from '../src-gpu/backend/backend';
import { GpuRenderer } from '../src-gpu/render/render';
import { requestGpu } from '../src-gpu/device/device';
import type { GpuContext } from '../src-gpu/device/device';
import type { GpuReadStats } from '../src-gpu/stepper';
import { adapterName, StepTimes } from './framework/demo';
import type { TestbedDraw } from './framework/render';
import type { Settings } from './framework/settings';
import type { Test } from './framework/test';

export type BackendName = 'js' | 'webgpu';

export const BACKEND_NAMES: readonly BackendName[] = ['js', 'webgpu'];

/** Bodies from which a world stepped on WebGPU is drawn by GpuRenderer. */
export const GPU_DRAW_BODIES = 1000;

export class TestbedBackend {
  /** What the page asks for; a test the GPU refuses still runs on JavaScript (`refusal` says why). */
  chosen: BackendName = 'js';
  /** Why the current test runs on JavaScript although WebGPU is chosen; null otherwise. */
  refusal: string | null = null;
  /** The adapter that steps the world on WebGPU, in words. */
  adapter: string | null = null;
  /** Step times of the current test on its backend. */
  readonly times = new StepTimes();
  /** Frames skipped because a switch or a synchronisation was still running. */
  skippedFrames = 0;
  private context: Promise<GpuContext> | null = null;
  private test: Test | null = null;
  private backend: WebGPUBackend | null = null;
  private pending: Promise<void> | null = null;
  /** Draws the world of `backend` on WebGPU when it is large; made for each backend. */
  private renderer: GpuRenderer | null = null;
  private gpuCanvasContext: GPUCanvasContext | null = null;

  /**
   * `report` is called with what failed (a lost device, a synchronisation that threw); the test
   * goes on on JavaScript. `gpuCanvas` (under the 2D canvas, the same size) is where GpuRenderer
   * draws large worlds, with `view`'s camera.
   */
  constructor(
    private readonly report: (error: unknown, what: string) => void,
    private readonly gpuCanvas: HTMLCanvasElement | null = null,
    private readonly view: TestbedDraw | null = null,
  ) {}

  /** Whether GpuRenderer draws `test`'s world this frame (WebGPU steps it and it is large). */
  drawsOnGpu(test: Test): boolean {
    return this.backend !== null && this.gpuCanvas !== null && test.m_world.GetBodyCount() >= GPU_DRAW_BODIES;
  }

  /** What steps the current test. */
  get active(): BackendName {
    return this.backend !== null ? 'webgpu' : 'js';
  }

  /** A switch or a synchronisation is running: the frame must wait. */
  get busy(): boolean {
    return this.pending !== null;
  }

  /** Resolves once no switch or synchronisation is running. */
  async idle(): Promise<void> {
    while (this.pending !== null) await this.pending.catch(() => undefined);
  }

  /** Makes `run` the pending work until it settles. */
  private track(run: Promise<void>): Promise<void> {
    const tracked: Promise<void> = run.finally(() => {
      if (this.pending === tracked) this.pending = null;
    });
    this.pending = tracked;
    return tracked;
  }

  /** The last read-back's bytes and host time, on WebGPU. */
  get readStats(): GpuReadStats | null {
    return this.backend?.readStats ?? null;
  }

  /**
   * Puts `test` (the current one, or a new or restarted one) on the chosen backend, after any
   * switch or synchronisation already running. A test that replaces another gives the other's GPU
   * resources back. Where no GPU work is involved (JavaScript chosen and running, or a test the GPU
   * refuses) it is done at once, so the frame timer never waits for it.
   */
  apply(test: Test): Promise<void> {
    if (this.pending === null && this.backend === null) {
      const refusal = this.chosen === 'js' ? null : test.GpuRefusal();
      if (this.chosen === 'js' || refusal !== null) {
        this.adopt(test);
        this.refusal = refusal;
        return Promise.resolve();
      }
    }
    const previous = this.pending ?? Promise.resolve();
    return this.track(previous.catch(() => undefined).then(() => this.applyNow(test)));
  }

  /** Makes `test` the current one, its times started afresh. */
  private adopt(test: Test): void {
    this.test = test;
    this.times.clear();
  }

  private async applyNow(test: Test): Promise<void> {
    if (this.test !== test) {
      const oldBackend = this.backend;
      this.adopt(test);
      this.backend = null;
      this.dropRenderer();
      // The old world is thrown away: its GPU buffers go, without a read-back.
      if (oldBackend !== null) await oldBackend.destroy().catch(() => undefined);
    }
    this.refusal = null;
    const world = test.m_world;
    if (this.chosen === 'js') {
      if (this.backend === null) return;
      this.backend = null;
      this.dropRenderer();
      this.adopt(test);
      try {
        await world.SetBackend(null);
      } finally {
        world.SetContactListener(test);
      }
      return;
    }
    if (this.backend !== null) return;
    const refusal = test.GpuRefusal();
    if (refusal !== null) {
      this.refusal = refusal;
      return;
    }
    let backend: WebGPUBackend;
    try {
      backend = await WebGPUBackend.create({ context: await this.gpu() });
      world.SetContactListener(test.GpuContactListener(test.UsesContactPoints()));
      await world.SetBackend(backend);
    } catch (error) {
      world.SetContactListener(test);
      this.refusal = error instanceof Error ? error.message : String(error);
      throw error;
    }
    this.backend = backend;
    this.adopt(test);
  }

  /** The device, requested once for the page (every test's backend shares it). */
  private gpu(): Promise<GpuContext> {
    if (this.context === null) {
      this.context = requestGpu({
        onLost: (info) => this.report(new Error(`the WebGPU device was lost (${info.reason}): ${info.message}`), 'WebGPU'),
      });
      this.context.then(
        (ctx) => (this.adapter = adapterName(ctx.adapterInfo)),
        () => (this.context = null),
      );
    }
    return this.context;
  }

  /**
   * Before the test's Step: on WebGPU, the listener that records contact points when they are drawn
   * or used, and whether the test leaves its shapes and joints to GpuRenderer.
   */
  beforeStep(test: Test, settings: Settings): void {
    test.m_gpuDrawsWorld = this.drawsOnGpu(test);
    if (this.backend === null) return;
    test.m_world.SetContactListener(test.GpuContactListener(settings.drawContactPoints !== 0 || test.UsesContactPoints()));
  }

  /**
   * After the test's Step: on JavaScript, records the step's time (the world's profile); on WebGPU,
   * starts the synchronisation, and the frames wait for it.
   */
  afterStep(test: Test): void {
    if (this.backend === null) {
      this.times.add(performance.now(), test.m_world.GetProfile().step);
      return;
    }
    if (test.m_gpuDrawsWorld) this.drawOnGpu(this.backend);
    // The synchronisation's PostSolve calls record the points the next frame draws.
    test.m_pointCount = 0;
    const started = test.m_stepStart;
    void this.track(
      test.m_world.Synchronize().then(
        () => {
          const now = performance.now();
          this.times.add(now, now - started);
        },
        (error) => this.fall(test, error),
      ),
    );
  }

  /** Records a frame of the world after the step just called, with the 2D canvas's camera. */
  private drawOnGpu(backend: WebGPUBackend): void {
    const canvas = this.gpuCanvas!;
    const view = this.view!;
    if (this.renderer === null || this.renderer.backend !== backend) {
      this.dropRenderer();
      this.gpuCanvasContext ??= canvas.getContext('webgpu');
      if (this.gpuCanvasContext === null) throw new Error('the testbed could not get a WebGPU context for its GPU canvas');
      this.renderer = new GpuRenderer(backend, this.gpuCanvasContext, { background: [0, 0, 0, 1] });
    }
    const width = Math.round(view.width * view.dpr);
    const height = Math.round(view.height * view.dpr);
    if (canvas.width !== width || canvas.height !== height) {
      canvas.width = width;
      canvas.height = height;
    }
    Object.assign(this.renderer.camera, { x: view.viewCenter.x, y: view.viewCenter.y, scale: view.PixelsPerMetre() * view.dpr });
    this.renderer.draw().catch((error) => this.report(error, 'GpuRenderer failed to draw the world'));
  }

  private dropRenderer(): void {
    this.renderer?.destroy();
    this.renderer = null;
  }

  /** The GPU failed: say so and carry on with the JavaScript engine from the last synchronised state. */
  private async fall(test: Test, error: unknown): Promise<void> {
    this.report(error, 'The WebGPU backend failed; the test goes on with the JavaScript engine');
    this.backend = null;
    this.dropRenderer();
    this.refusal = `the GPU failed: ${error instanceof Error ? error.message : String(error)}`;
    this.adopt(test);
    await test.m_world.SetBackend(null).catch(() => undefined);
    test.m_world.SetContactListener(test);
  }

  /** The overlay's lines on the backend: which, its step time and, on WebGPU, the adapter and the read-back. */
  describe(now: number): string[] {
    const ms = this.times.median(now);
    const step = Number.isFinite(ms) ? `${ms.toFixed(2)} ms` : '–';
    if (this.backend === null) {
      const why = this.refusal === null ? '' : ' (WebGPU refused this test)';
      return [`backend: JavaScript engine${why}, step ${step} (median, last second)`];
    }
    const read = this.backend.readStats;
    const lines = [
      `backend: WebGPU, step + read-back ${step} (median, last second)`,
      `adapter: ${this.adapter}`,
      `read-back per frame: ${read === null ? '–' : `${(read.bytes / 1024).toFixed(1)} KB, ${read.unpackMs.toFixed(2)} ms to unpack, ${read.pullMs.toFixed(2)} ms to update the bodies`}`,
    ];
    if (this.renderer !== null && this.test !== null && this.drawsOnGpu(this.test)) {
      lines.push(`drawn by GpuRenderer from the GPU's buffers (${GPU_DRAW_BODIES} bodies or more): no body read back to draw`);
    }
    return lines;
  }
}
