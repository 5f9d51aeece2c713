/*
 * AutoBackend: `await world.SetBackend(await AutoBackend.create())` steps the world on the
 * JavaScript engine or on the GPU (an inner WebGPUBackend), whichever is faster for its size on
 * this adapter, and decides again as the world grows or shrinks (docs/GPU.md, "Choosing the
 * backend automatically").
 *
 * The rule: JavaScript when there is no adapter, when it is a software one (unless a calibration
 * is given), when the GPU refuses the world (gpuRefusal: PreSolve, a custom contact filter) and
 * after the device is lost; otherwise the body count against the adapter's crossover
 * (calibration.ts), with hysteresis: the GPU above crossover * AUTO_UP, JavaScript again below
 * crossover * AUTO_DOWN.
 * Switches need an await (the GPU's state is read back), and Step is synchronous: Step notes that
 * a switch is due, and the next Synchronize, StepAsync or settle() makes it. Steps the GPU cannot
 * take (it failed, or the world now asks for what it refuses) are kept, at most the inner
 * backend's maxQueuedSteps, and taken by the engine once the world is back on it.
 */

import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2World } from '../../src/dynamics/b2World';
import type { b2WorldBackend, b2WorldBackendEngine } from '../../src/dynamics/b2WorldBackend';
import { GpuContext, requestGpu } from '../device/device';
import type { GpuContextOptions } from '../device/device';
import { WebGPUBackend } from './backend';
import { calibrationFor } from './calibration';
import type { AutoCalibration } from './calibration';
import { gpuRefusal } from './refusal';

/** The GPU is picked once the body count exceeds the crossover times this. */
export const AUTO_UP = 1.25;
/** The JavaScript engine is picked again once the body count falls below the crossover times this. */
export const AUTO_DOWN = 0.8;

export interface AutoBackendOptions extends GpuContextOptions {
  /** A device already requested (requestGpu); otherwise create() requests one with these options. */
  context?: GpuContext;
  /**
   * For tests and tools: the crossover to use instead of measuring it on the adapter. Taken as it
   * is, also on a software adapter (which is otherwise never picked).
   */
  calibration?: AutoCalibration;
  /** Called with the new choice after every switch, the fall-back after a GPU failure included. */
  onChange?: (choice: AutoChoice) => void;
}

/** Which backend steps the world, and why (words and numbers). */
export interface AutoChoice {
  readonly backend: 'js' | 'webgpu';
  readonly reason: string;
}

function count(n: number): string {
  return n.toLocaleString('en-US');
}

function errorText(err: unknown): string {
  return err instanceof Error ? err.message : String(err);
}

function checkOptions(options: unknown): asserts options is AutoBackendOptions {
  const fail = (rule: string): never => {
    throw new TypeError(`AutoBackend.create: ${rule}`);
  };
  if (typeof options !== 'object' || options === null) fail(`options must be an object, got ${String(options)}`);
  const o = options as Record<string, unknown>;
  if (o.context !== undefined && !(o.context instanceof GpuContext)) fail('options.context must be a GpuContext (requestGpu)');
  if (o.onChange !== undefined && typeof o.onChange !== 'function') fail('options.onChange must be a function');
  if (o.calibration !== undefined) {
    const c = o.calibration as Record<string, unknown> | null;
    if (typeof c !== 'object' || c === null) fail('options.calibration must be an object { crossoverBodies, source }');
    const crossover = c!.crossoverBodies;
    if (typeof crossover !== 'number' || !(crossover > 0)) {
      fail(`options.calibration.crossoverBodies must be a number > 0 (Infinity: never the GPU), got ${String(crossover)}`);
    }
    if (typeof c!.source !== 'string' || c!.source === '') fail('options.calibration.source must be a non-empty string saying where the crossover comes from');
  }
}

/**
 * Steps a world on the JavaScript engine or on WebGPU, whichever is faster for its body count on
 * this adapter, and moves it as it grows or shrinks:
 * `await world.SetBackend(await AutoBackend.create())`. `choice` says which and why; moves happen
 * at Synchronize, StepAsync or settle(). Never fails for lack of WebGPU: it stays on JavaScript.
 */
export class AutoBackend implements b2WorldBackend {
  /** The device, or null when there is no WebGPU adapter. */
  readonly ctx: GpuContext | null;
  private readonly inner: WebGPUBackend | null;
  private readonly onChange: ((choice: AutoChoice) => void) | null;
  private calibration: AutoCalibration | null;
  /** Why the GPU can never be picked here (no adapter, software, lost, failed); null while it can. */
  private ruledOut: string | null;
  private world: b2World | null = null;
  private engine: b2WorldBackendEngine | null = null;
  private onGpu = false;
  /** dt, velocity and position iterations of the steps kept for the engine (see the file comment). */
  private readonly kept: number[] = [];
  private settling: Promise<void> | null = null;
  private switching = false;

  private constructor(ctx: GpuContext | null, inner: WebGPUBackend | null, ruledOut: string | null, options: AutoBackendOptions) {
    this.ctx = ctx;
    this.inner = inner;
    this.ruledOut = ruledOut;
    this.calibration = options.calibration ?? null;
    this.onChange = options.onChange ?? null;
  }

  /**
   * An AutoBackend on options.context, or on the device requestGpu(options) gives; on the
   * JavaScript engine for good when there is none (its choice says so).
   */
  static async create(options: AutoBackendOptions = {}): Promise<AutoBackend> {
    checkOptions(options);
    let ctx = options.context ?? null;
    let ruledOut: string | null = null;
    if (ctx === null) {
      try {
        ctx = await requestGpu(options);
      } catch (err) {
        ruledOut = `no WebGPU adapter (${errorText(err)})`;
      }
    }
    if (ctx !== null && ctx.adapterInfo.software && options.calibration === undefined) {
      ruledOut = `the adapter is software (${ctx.adapterInfo.description || ctx.adapterInfo.vendor || ctx.adapterInfo.source}): never picked for speed`;
    }
    // Made now, so that a switch to the GPU attaches it at once (Attach is synchronous).
    const inner = ctx !== null && ruledOut === null ? await WebGPUBackend.create({ context: ctx, stepper: { keepReadBack: true } }) : null;
    return new AutoBackend(ctx, inner, ruledOut, options);
  }

  /** The inner WebGPUBackend while it steps the world; null while the JavaScript engine does. */
  get active(): WebGPUBackend | null {
    return this.onGpu ? this.inner : null;
  }

  /** The adapter's crossover, once known (given, or measured at the first settle()). */
  get crossover(): AutoCalibration | null {
    return this.calibration;
  }

  /** The backend stepping the world now and why; a switch noted by Step shows once settle() makes it. */
  get choice(): AutoChoice {
    const backend = this.onGpu ? 'webgpu' : 'js';
    return { backend, reason: `${backend}: ${this.reason()}` };
  }

  /** Makes a switch that is due (and, at the first call on a GPU, measures the crossover). */
  settle(): Promise<void> {
    this.attached('settle');
    this.settling ??= this.makeSwitch().finally(() => {
      this.settling = null;
    });
    return this.settling;
  }

  Attach(world: b2World, engine: b2WorldBackendEngine): void {
    if (this.world !== null) throw new Error('AutoBackend: already attached to a world; one backend steps one world');
    this.world = world;
    this.engine = engine;
    if (this.target() === 'webgpu') this.enterGpu();
  }

  async Detach(): Promise<void> {
    this.attached('Detach');
    await this.settling;
    if (this.onGpu) await this.leaveGpu();
    this.takeKeptSteps();
    this.world = null;
    this.engine = null;
  }

  Step(dt: number, velocityIterations: number, positionIterations: number): void {
    const { world, engine } = this.attached('Step');
    if (this.switching) throw new Error('b2World.Step: AutoBackend is moving the world between backends; await world.Synchronize() first');
    if (!this.onGpu) {
      engine.step(world, dt, velocityIterations, positionIterations);
      return;
    }
    const inner = this.inner!;
    if (this.kept.length === 0 && this.gpuFailure() === null && gpuRefusal(world, engine) === null) {
      try {
        inner.Step(dt, velocityIterations, positionIterations);
        return;
      } catch (err) {
        if (inner.failed === null) throw err;
      }
    }
    if (this.kept.length >= 3 * inner.maxQueuedSteps) {
      throw new Error(
        `b2World.Step: ${this.kept.length / 3} steps wait for the world to move to the JavaScript engine (${this.reason()}); ` +
          'await world.Synchronize() before stepping again',
      );
    }
    this.kept.push(dt, velocityIterations, positionIterations);
  }

  async StepAsync(dt: number, velocityIterations: number, positionIterations: number): Promise<void> {
    const { world } = this.attached('StepAsync');
    // Through the world, so that the arguments are checked as Step checks them.
    world.Step(dt, velocityIterations, positionIterations);
    await this.Synchronize();
  }

  async Synchronize(): Promise<void> {
    this.attached('Synchronize');
    if (this.onGpu && this.target() === 'webgpu') {
      try {
        await this.inner!.Synchronize();
      } catch (err) {
        if (this.inner!.failed === null) throw err;
      }
    }
    await this.settle();
  }

  PullBody(body: b2Body): void {
    if (this.onGpu) this.inner!.PullBody(body);
  }

  PullAll(): void {
    if (this.onGpu) this.inner!.PullAll();
  }

  /** On the GPU the inner backend keeps the contacts; on JavaScript the world's list is the engine's. */
  KeepsContacts(): boolean {
    return this.onGpu;
  }

  /** The inner backend's while the GPU steps the world; on JavaScript the world's contacts are the engine's own. */
  GetPenetration(): number | null {
    return this.onGpu ? this.inner!.GetPenetration() : null;
  }

  private attached(method: string): { world: b2World; engine: b2WorldBackendEngine } {
    if (this.world === null || this.engine === null) {
      throw new Error(`AutoBackend.${method}: not attached to a world (world.SetBackend(backend) attaches it)`);
    }
    return { world: this.world, engine: this.engine };
  }

  /** Where the world should be stepped now, hysteresis included. */
  private target(): 'js' | 'webgpu' {
    const { world, engine } = this.attached('Step');
    if (this.ruledOut !== null || this.calibration === null || this.gpuFailure() !== null) return 'js';
    if (gpuRefusal(world, engine) !== null) return 'js';
    const bodies = world.GetBodyCount();
    const crossover = this.calibration.crossoverBodies;
    return this.onGpu ? (bodies < crossover * AUTO_DOWN ? 'js' : 'webgpu') : bodies > crossover * AUTO_UP ? 'webgpu' : 'js';
  }

  /** What went wrong on the GPU while it stepped the world, in words; null while nothing did. */
  private gpuFailure(): string | null {
    const lost = this.ctx?.lossInfo ?? null;
    if (lost !== null) return `the WebGPU device was lost (${lost.reason}${lost.message ? `: ${lost.message}` : ''})`;
    const failure = this.inner?.failed ?? null;
    if (failure !== null) return `the GPU failed (${errorText(failure)})`;
    return null;
  }

  /** The reason of `choice` (and of a due switch), without the backend's name. */
  private reason(): string {
    if (this.ruledOut !== null) return this.ruledOut;
    const world = this.world;
    if (world === null || this.engine === null) return 'not attached to a world';
    const failure = this.gpuFailure();
    if (failure !== null) return this.onGpu ? `${failure}; the JavaScript engine takes over at the next Synchronize` : failure;
    const refusal = gpuRefusal(world, this.engine);
    if (refusal !== null) return refusal.summary;
    const bodies = `${count(world.GetBodyCount())} bodies`;
    if (this.calibration === null) return `${bodies}; the adapter's crossover is measured at the first Synchronize`;
    const crossover = this.calibration.crossoverBodies;
    if (crossover === Infinity) return `${bodies}; the GPU was not faster at any size on this adapter (${this.calibration.source})`;
    const on = `the crossover on this adapter (${count(crossover)} bodies; ${this.calibration.source})`;
    const due = this.target() !== (this.onGpu ? 'webgpu' : 'js') ? '; switching at the next Synchronize' : '';
    const n = world.GetBodyCount();
    if (this.onGpu) return n >= crossover ? `${bodies}, above ${on}${due}` : `${bodies}, not below ${AUTO_DOWN} x ${on}${due}`;
    return n <= crossover ? `${bodies}, below ${on}${due}` : `${bodies}, not above ${AUTO_UP} x ${on}${due}`;
  }

  private async makeSwitch(): Promise<void> {
    const { engine } = this.attached('settle');
    if (this.calibration === null && this.ruledOut === null) {
      try {
        this.calibration = await calibrationFor(this.ctx!, engine);
      } catch (err) {
        this.ruledOut = `the calibration failed on this adapter (${errorText(err)})`;
      }
    }
    const target = this.target();
    if (this.onGpu && target === 'js') {
      await this.leaveGpu();
      this.changed();
    } else if (!this.onGpu && target === 'webgpu') {
      this.enterGpu();
      this.changed();
    }
    if (!this.onGpu) this.takeKeptSteps();
  }

  private changed(): void {
    this.onChange?.(this.choice);
  }

  private enterGpu(): void {
    const { world, engine } = this.attached('settle');
    try {
      this.inner!.Attach(world, engine);
    } catch (err) {
      // The GPU cannot hold this world (a buffer over the device's limits, a lost device).
      this.ruledOut = `the GPU could not take the world (${errorText(err)})`;
      return;
    }
    this.onGpu = true;
    // The backend takes the contacts over (as b2World.SetBackend notes).
    world.m_toiCandidatesStale = true;
  }

  /**
   * Hands the world back to the engine with the GPU's state. After a failure the read-back cannot
   * come: every body takes the last synchronisation's state from the host copy the inner backend
   * keeps of each read-back (keepReadBack: a lost device takes the map with it), and the engine
   * finds the contacts afresh.
   */
  private async leaveGpu(): Promise<void> {
    const { world } = this.attached('settle');
    const inner = this.inner!;
    this.switching = true;
    let error: unknown = null;
    try {
      if (this.gpuFailure() !== null) {
        inner.PullAll();
      }
      await inner.Detach();
    } catch (err) {
      error = err;
    } finally {
      this.onGpu = false;
      this.switching = false;
      world.m_toiCandidatesStale = true;
    }
    const failure = this.gpuFailure() ?? (error === null ? null : `the GPU failed (${errorText(error)})`);
    if (failure !== null) this.ruledOut = `${failure}; carried on from the last synchronisation`;
  }

  private takeKeptSteps(): void {
    const { world, engine } = this.attached('settle');
    const kept = this.kept.splice(0);
    for (let i = 0; i < kept.length; i += 3) engine.step(world, kept[i], kept[i + 1], kept[i + 2]);
  }
}
