/*
 * The GPU step as one pipeline: b2World::Step's Collide, Solve and SolveTOI as an ordered list of
 * stages (GpuStage), recorded by one function (record) into the passes of one command buffer.
 *
 * In:  a synced GpuWorld (the mirror); the broad phase, the narrow phase and the solver, which own
 *      their buffers and kernels and encode their stages' dispatches when record() asks.
 * Out: one step's pairs, contacts and (with the solver) motion on the GPU; the step's counts
 *      (NarrowPhaseResult) from one read-back of 324 bytes plus timestamps: the broad phase's and
 *      the narrow phase's state words and the solver's SV.COLOUR_START .. SV.AWAKE (the
 *      colours' sizes, which GpuSolver.passColours follows, the accuracy target's measure, so
 *      that it costs no read-back of its own, and the bodies left awake).
 * Invariants: the stages run in GpuStage order and read only what earlier stages of the same
 *      submission (or earlier steps) wrote; nothing is read back inside a step. Same inputs, same
 *      outputs, bit for bit, on one device; so a world at rest, whose step would give its buffers
 *      the bits they hold, records none (skipResting).
 *
 * Overflow: the host sizes the buffers, the GPU counts what it needed. When the sweep entries,
 * the pairs or the contacts did not fit, the counts read back say exactly how much room is
 * needed: the phase that owns the list grows it, and the stages from the one that overflowed on
 * run again (the solver with them: its stages do nothing while an overflow flag is set, and the
 * rerun's state has none). The previous step's contact set is untouched until a step succeeds.
 *
 * With { wait: false } a step returns once submitted: its read-back completes in the background
 * (a ring of four read-back buffers keeps up to four steps in flight) and is looked at before the
 * next step records anything. An overflow found that way grows the buffers for the following
 * steps; the step that overflowed keeps the first `capacity` contacts in key order (or none, for
 * a pair overflow) and says so in its result (`overflowed`). Headroom (capacities of at least
 * 1.5 x the last counts seen) makes that rare.
 */

import type { GpuContext } from './device/device';
import { GpuArray } from './device/buffers';
import { passRecorder } from './device/kernel';
import type { PassRecorder } from './device/kernel';
import type { BroadPhaseResult, GpuBroadPhase } from './broadphase/broadPhase';
import type { GpuNarrowPhase, NarrowPhaseResult } from './narrowphase/narrowPhase';
import type { GpuSolver } from './solver/solver';
import { PassTimer } from './device/timing';
import { Readback, ReadbackRing } from './device/readback';
import {
  BIN_COUNT,
  BIN_NAMES,
  COLOUR_CAP,
  NP,
  NP_STATE_WORDS,
  OVERFLOW_CONTACTS,
  OVERFLOW_ENTRIES,
  OVERFLOW_PAIRS,
  STATE,
  STATE_WORDS,
  SV,
  SV_READBACK_WORDS,
  USAGE,
} from './device/layout';
import type { GpuWorld } from './world/world';

/** The stages of a GPU step, in the order they are recorded. */
export enum GpuStage {
  /** Sweep-and-prune: bounds, axis, sort, sweep, pairs (broadPhase.ts; five passes). */
  BroadPhase,
  /** Contacts from the pairs: orientation, keys, match with the previous step, bins by pair type (contacts.ts). */
  Contacts,
  /** One collide kernel per pair type (collideCircle.ts, collidePolygon.ts, collideEdge.ts, overlap.ts). */
  Collide,
  /** Touching state, impulses carried by key, began / ended (persist.ts). */
  Persist,
  /** The solver's contact list and the begin / end events, by prefix scans (compact.ts). */
  Compact,
  /** Solver state; bodies woken by new contacts; islands through touching contacts and joints (islands.ts). */
  Islands,
  /** Gravity, forces and damping into the velocities (integrateVelocities.ts). */
  IntegrateVelocities,
  /** Solver contacts and joint constraints (prepareContacts.ts, solveJoints.ts). */
  Prepare,
  /** Joints and contacts coloured together, so that a colour's items share no dynamic body (colour.ts). */
  Colour,
  /** Warm start, velocity iterations per colour, impulses stored, positions integrated. */
  Velocity,
  /** Position iterations per colour, transforms from the sweeps (solvePosition.ts, integratePositions.ts). */
  Position,
  /** Sleep timers; islands at rest put to sleep (islands.ts). */
  Sleep,
  /** Continuous physics: bodies moved back to their earliest time of impact (timeOfImpact.ts). */
  TimeOfImpact,
  /** The deepest penetration of the touching contacts at the final transforms (penetration.ts). */
  Penetration,
}

/** The name of each stage's pass (the broad phase names its own five; Collide may be one pass per pair type). */
export const STAGE_PASS: Readonly<Record<GpuStage, string>> = {
  [GpuStage.BroadPhase]: 'broad phase',
  [GpuStage.Contacts]: 'contacts',
  [GpuStage.Collide]: 'collide',
  [GpuStage.Persist]: 'persist',
  [GpuStage.Compact]: 'compact',
  [GpuStage.Islands]: 'solve: islands',
  [GpuStage.IntegrateVelocities]: 'solve: integrate velocities',
  [GpuStage.Prepare]: 'solve: prepare',
  [GpuStage.Colour]: 'solve: colour',
  [GpuStage.Velocity]: 'solve: velocity',
  [GpuStage.Position]: 'solve: position',
  [GpuStage.Sleep]: 'solve: sleep',
  [GpuStage.TimeOfImpact]: 'solve: time of impact',
  [GpuStage.Penetration]: 'solve: penetration',
};

export interface GpuPipelineStepOptions {
  /**
   * true (default): wait for this step's read-back and redo what overflowed before returning.
   * false: return once submitted (the file header).
   */
  wait?: boolean;
  /** Run the solver's stages after collision (default false: collision only, as a step with dt = 0). */
  solve?: boolean;
}

/**
 * Byte layout of the read-back: broad-phase state, narrow-phase state, the solver's colour starts,
 * colours used, penetration and bodies awake (SV_READBACK_WORDS from SV.COLOUR_START), timestamps
 * (8-byte aligned).
 */
const NP_STATE_OFFSET = 64;
const SOLVER_STATE_OFFSET = NP_STATE_OFFSET + 4 * NP_STATE_WORDS;
const SOLVER_STATE_END = SOLVER_STATE_OFFSET + 4 * SV_READBACK_WORDS;
const TIMER_OFFSET = Math.ceil(SOLVER_STATE_END / 8) * 8;

/** What a step's result says of its solver (NarrowPhaseResult). */
type SolverWords = Pick<NarrowPhaseResult, 'coloursUsed' | 'colourItems' | 'penetration' | 'awake'>;
/** A step that did not solve, or whose solver skipped it. */
const NOT_SOLVED: Readonly<SolverWords> = { coloursUsed: -1, colourItems: null, penetration: -1, awake: -1 };

/**
 * The solver words of a step's read-back: SV.COLOURS_USED, the items per colour (the overflow set
 * last), SV.AWAKE and, when the step recorded its stage, SV.PENETRATION.
 */
function solverWords(bytes: ArrayBuffer, last: GpuStage): SolverWords {
  if (last <= GpuStage.Compact) return NOT_SOLVED;
  const w = new Uint32Array(bytes, SOLVER_STATE_OFFSET, SV_READBACK_WORDS);
  const colourItems: number[] = [];
  for (let c = 0; c <= COLOUR_CAP; ++c) colourItems.push(w[c + 1] - w[c]);
  const penetration = last >= GpuStage.Penetration ? new Float32Array(w.buffer, w.byteOffset, SV_READBACK_WORDS)[SV.PENETRATION - SV.COLOUR_START] : -1;
  return { coloursUsed: w[SV.COLOURS_USED - SV.COLOUR_START], colourItems, penetration, awake: w[SV.AWAKE - SV.COLOUR_START] };
}

interface InFlight {
  /** The step's index among the steps recorded. */
  step: number;
  settled: Promise<NarrowPhaseResult>;
  result: NarrowPhaseResult | null;
  /** The broad phase's state words of the step. */
  state: Uint32Array | null;
}

/**
 * Records and submits the GPU step, stage by stage (GpuStage).
 * @internal Advanced: exported for tools, benchmarks and tests; applications use WebGPUBackend
 * through b2World.SetBackend (docs/GPU.md, "The world API on the GPU").
 */
export class GpuPipeline {
  readonly ctx: GpuContext;
  readonly broadPhase: GpuBroadPhase;
  readonly narrowPhase: GpuNarrowPhase;
  readonly solver: GpuSolver | null;
  /** The result of the last step whose counts are known. */
  lastResult: NarrowPhaseResult | null = null;
  /** Steps that overflowed with { wait: false } (their lists were truncated). */
  truncatedSteps = 0;
  /**
   * Whether solving steps record GpuStage.Penetration (NarrowPhaseResult.penetration; -1 without
   * it): off until someone reads the measure (WebGPUBackend.GetPenetration), so that a world
   * without a penetration target does not pay a pass over its contacts.
   */
  measurePenetration = false;
  /**
   * Whether a solving step of a world at rest records nothing (default true). Once a step has run
   * that began with every body asleep (the read-backs of it and of the step before say SV.AWAKE is
   * 0) and no input changed since (inputsChanged), a step would leave every buffer with the bits
   * it has: such a step is skipped, and its result is the last one's (`skipped`).
   */
  skipResting = true;
  /** Steps skipped at rest (skipResting). */
  skippedSteps = 0;
  /** Steps recorded so far: the index of the next one. */
  private recorded = 0;
  /** The index of lastResult's step. */
  private lastResultStep = -1;
  /** The first step of the latest run of results with every body asleep; -1 when the latest is awake. */
  private restingFrom = -1;
  /** The latest step whose inputs changed (inputsChanged). */
  private changedAt = -1;
  private readonly timer: PassTimer;
  private readonly readback: Readback;
  private readonly ring: ReadbackRing;
  private readonly inFlight: InFlight[] = [];
  private givenPairs: GpuArray | null = null;
  private givenState: GPUBuffer | null = null;
  private busy = false;
  // The step being recorded: the pairs the collision stages read and the state that says whether they overflowed.
  private pairs: GPUBuffer | null = null;
  private broadState: GPUBuffer | null = null;

  constructor(ctx: GpuContext, broadPhase: GpuBroadPhase, narrowPhase: GpuNarrowPhase, solver: GpuSolver | null = null) {
    this.ctx = ctx;
    this.broadPhase = broadPhase;
    this.narrowPhase = narrowPhase;
    this.solver = solver;
    this.timer = new PassTimer(ctx, 32);
    this.readback = new Readback(ctx, 'step read-back', TIMER_OFFSET + this.timer.bytes);
    this.ring = new ReadbackRing(ctx, 'step deferred read-back', TIMER_OFFSET + this.timer.bytes, 4);
  }

  /**
   * Records stages `first` to `last` into `pass`, each reading the buffers named here, after the
   * broad phase's and the narrow phase's beginUpdate().
   */
  private record(pass: PassRecorder, mirror: GpuWorld, first: GpuStage, last: GpuStage): void {
    const bp = this.broadPhase;
    const np = this.narrowPhase;
    const solver = this.solver;
    for (let stage = first; stage <= last; ++stage) {
      switch (stage) {
        case GpuStage.BroadPhase:
          this.pairs = bp.encodePasses(pass, bp.lastUpdateInputs);
          this.broadState = bp.state;
          break;
        case GpuStage.Contacts:
          np.bindStep(mirror, this.pairs!, this.broadState!);
          pass(STAGE_PASS[stage], np.encodeContacts);
          break;
        case GpuStage.Collide:
          if (np.timeBins) {
            for (const bin of np.bins) if (np.binInUse(bin)) pass(`collide ${BIN_NAMES[bin]}`, (rec) => np.encodeCollideBin(rec, bin));
          } else {
            pass(STAGE_PASS[stage], np.encodeCollide);
          }
          break;
        case GpuStage.Persist:
          pass(STAGE_PASS[stage], np.encodePersist);
          break;
        case GpuStage.Compact:
          pass(STAGE_PASS[stage], np.encodeCompact);
          break;
        case GpuStage.Islands:
          {
            const io = np.outputs(this.broadState!);
            io.lastSolverCount = this.lastResult === null ? -1 : this.lastResult.solverCount;
            io.lastColourItems = this.lastResult === null ? null : this.lastResult.colourItems;
            solver!.bindStep(mirror, io);
          }
          pass(STAGE_PASS[stage], solver!.encodeIslands);
          break;
        case GpuStage.IntegrateVelocities:
          pass(STAGE_PASS[stage], solver!.encodeIntegrateVelocities);
          break;
        case GpuStage.Prepare:
          pass(STAGE_PASS[stage], solver!.encodePrepare);
          break;
        case GpuStage.Colour:
          pass(STAGE_PASS[stage], solver!.encodeColour);
          break;
        case GpuStage.Velocity:
          pass(STAGE_PASS[stage], solver!.encodeVelocity);
          break;
        case GpuStage.Position:
          pass(STAGE_PASS[stage], solver!.encodePosition);
          break;
        case GpuStage.Sleep:
          pass(STAGE_PASS[stage], solver!.encodeSleep);
          break;
        case GpuStage.TimeOfImpact:
          // Without bullets or static and kinematic bodies no contact is a candidate.
          if (mirror.world.m_continuousPhysics && (mirror.census.bullets > 0 || mirror.census.nonDynamic > 0))
            pass(STAGE_PASS[stage], solver!.encodeTimeOfImpact);
          break;
        case GpuStage.Penetration:
          pass(STAGE_PASS[stage], solver!.encodePenetration);
          break;
      }
    }
  }

  /** Says that the step about to be recorded has inputs that changed: the mirror uploaded something. */
  inputsChanged(): void {
    this.changedAt = this.recorded;
  }

  /** Takes in the result of step `step`, the steps' results coming in the order they were recorded. */
  private take(result: NarrowPhaseResult, step: number): void {
    this.lastResult = result;
    this.lastResultStep = step;
    if (result.awake !== 0) this.restingFrom = -1;
    else if (this.restingFrom < 0) this.restingFrom = step;
  }

  /**
   * Whether the next solving step would change nothing: a step after the first of a run of results
   * at rest has its result in, and was recorded after the last change (and measured the
   * penetration, if that is wanted now).
   */
  private atRest(): boolean {
    return (
      this.skipResting &&
      this.restingFrom >= 0 &&
      this.lastResultStep > this.restingFrom &&
      this.lastResultStep > this.changedAt &&
      (!this.measurePenetration || this.lastResult!.penetration >= 0)
    );
  }

  /** The last stage a step records. */
  private lastStage(solve: boolean): GpuStage {
    if (!solve) return GpuStage.Compact;
    if (this.solver === null) throw new Error('GpuPipeline.step: { solve: true } needs a pipeline made with a solver');
    return this.measurePenetration ? GpuStage.Penetration : GpuStage.TimeOfImpact;
  }

  /**
   * One step on `mirror` (synced): collision, and with { solve: true } the solver (configured for
   * the step). Rejects with GpuDeviceLostError once the device is lost, GpuOutOfMemoryError when a
   * buffer could not be allocated.
   */
  async step(mirror: GpuWorld, options: GpuPipelineStepOptions = {}): Promise<NarrowPhaseResult> {
    const last = this.lastStage(options.solve === true);
    if (this.busy) throw new Error('GpuPipeline.step: the previous step has not finished');
    if (last > GpuStage.Compact && this.atRest()) return this.skip();
    this.busy = true;
    try {
      const step = this.recorded++;
      return options.wait === false ? await this.runDeferred(mirror, last, step) : await this.runWaiting(mirror, last, step);
    } finally {
      this.busy = false;
    }
  }

  /** A step of a world at rest (atRest): nothing recorded, the last result again. */
  private skip(): NarrowPhaseResult {
    this.skippedSteps++;
    const result: NarrowPhaseResult = {
      ...this.lastResult!,
      dispatches: 0,
      gpuTime: null,
      hostMs: { encode: 0, submit: 0, wait: 0 },
      pending: false,
      skipped: true,
    };
    result.settled = Promise.resolve(result);
    return result;
  }

  /** Records a whole step and the copies for its read-back into `rb`. */
  private recordStep(mirror: GpuWorld, last: GpuStage, rb: GPUBuffer): { encoder: GPUCommandEncoder; dispatches: () => number } {
    const bp = this.broadPhase;
    const np = this.narrowPhase;
    bp.beginUpdate(mirror);
    np.beginUpdate(mirror);
    const encoder = this.ctx.device.createCommandEncoder({ label: 'step' });
    this.timer.reset();
    const { pass, dispatches } = passRecorder(encoder, this.ctx.maxWorkgroupsPerDimension, this.timer);
    this.record(pass, mirror, GpuStage.BroadPhase, last);
    this.encodeStateCopies(encoder, last, rb);
    this.timer.resolveTo(encoder, rb, TIMER_OFFSET);
    return { encoder, dispatches };
  }

  /** Copies the state words a step's result reads into `rb` (the solver's when it recorded the solver). */
  private encodeStateCopies(encoder: GPUCommandEncoder, last: GpuStage, rb: GPUBuffer): void {
    this.broadPhase.encodeStateCopy(encoder, rb, 0);
    this.narrowPhase.encodeStateCopy(encoder, rb, NP_STATE_OFFSET);
    if (last > GpuStage.Compact) this.solver!.encodeStateCopy(encoder, rb, SOLVER_STATE_OFFSET);
  }

  private async runWaiting(mirror: GpuWorld, last: GpuStage, index: number): Promise<NarrowPhaseResult> {
    await this.ctx.checkErrors();
    const bp = this.broadPhase;
    const np = this.narrowPhase;
    const queue = this.ctx.device.queue;
    const rb = this.readback;
    let bpRegrows = 0;
    let dispatches = 0;
    let gpuTime: Record<string, number> | null = null;
    let state: Uint32Array;
    let counts: Uint32Array;
    let solved: SolverWords;
    const hostMs = { encode: 0, submit: 0, wait: 0 };
    for (;;) {
      const t0 = performance.now();
      const step = this.recordStep(mirror, last, rb.buffer);
      await this.ctx.checkErrors();
      const t1 = performance.now();
      queue.submit([step.encoder.finish()]);
      const t2 = performance.now();
      const bytes = await rb.read(this.ctx, TIMER_OFFSET + this.timer.bytes);
      const t3 = performance.now();
      hostMs.encode += t1 - t0;
      hostMs.submit += t2 - t1;
      hostMs.wait += t3 - t2;
      dispatches = step.dispatches();
      state = new Uint32Array(bytes, 0, STATE_WORDS);
      counts = new Uint32Array(bytes, NP_STATE_OFFSET, NP_STATE_WORDS);
      solved = solverWords(bytes, last);
      gpuTime = this.timer.parse(bytes, TIMER_OFFSET);
      if ((state[STATE.OVERFLOW] & OVERFLOW_ENTRIES) === 0) break;
      // More sweep entries than room for them: grow, redo everything.
      bpRegrows++;
      bp.growEntries(state[STATE.ENTRY_TOTAL]);
    }
    const before = np.contactRegrows;
    while ((state[STATE.OVERFLOW] & OVERFLOW_PAIRS) !== 0 || (counts[NP.OVERFLOW] & OVERFLOW_CONTACTS) !== 0) {
      const pairOverflow = (state[STATE.OVERFLOW] & OVERFLOW_PAIRS) !== 0;
      if (pairOverflow) {
        bpRegrows++;
        bp.growPairs(state[STATE.PAIR_COUNT]);
        np.growContacts(state[STATE.PAIR_COUNT]);
      } else {
        np.growContacts(counts[NP.PAIRS]);
      }
      np.beginUpdate(mirror);
      await this.ctx.checkErrors();
      const encoder = this.ctx.device.createCommandEncoder({ label: 'step (regrow)' });
      const { pass } = passRecorder(encoder, this.ctx.maxWorkgroupsPerDimension, null, ' (regrow)');
      if (pairOverflow) pass('sweep+pairs', (rec) => (this.pairs = bp.encodeRegrow(rec, bp.lastUpdateInputs)));
      this.record(pass, mirror, GpuStage.Contacts, last);
      this.encodeStateCopies(encoder, last, rb.buffer);
      queue.submit([encoder.finish()]);
      const bytes = await rb.read(this.ctx, SOLVER_STATE_END);
      state = new Uint32Array(bytes, 0, STATE_WORDS);
      counts = new Uint32Array(bytes, NP_STATE_OFFSET, NP_STATE_WORDS);
      solved = solverWords(bytes, last);
    }
    await this.ctx.checkErrors();
    const broad = bp.finishUpdate(state, bpRegrows, dispatches, gpuTime);
    np.endUpdate();
    const result = this.result(broad, counts, solved, np.contactRegrows - before, dispatches, gpuTime, hostMs, false);
    this.take(result, index);
    return result;
  }

  /**
   * The narrow phase alone on a given pair list (proxy slots of `mirror`, a < b, sorted by (a, b),
   * two words per pair), as if the broad phase had found exactly these pairs: for tests of the
   * collide kernels on chosen shape pairs, and for tools. The contact sets persist as in step().
   */
  async collideGivenPairs(mirror: GpuWorld, pairs: Uint32Array): Promise<NarrowPhaseResult> {
    if (this.busy) throw new Error('GpuPipeline.collideGivenPairs: the previous step has not finished');
    const n = pairs.length / 2;
    for (let i = 1; i < n; ++i) {
      const a0 = pairs[2 * i - 2];
      const b0 = pairs[2 * i - 1];
      if (pairs[2 * i] < a0 || (pairs[2 * i] === a0 && pairs[2 * i + 1] <= b0))
        throw new RangeError('collideGivenPairs: pairs must be sorted by (a, b) without duplicates');
    }
    this.busy = true;
    try {
      await this.ctx.checkErrors();
      const np = this.narrowPhase;
      this.givenPairs ??= new GpuArray(this.ctx, 'given pairs', 8, 64);
      this.givenState ??= this.ctx.createBuffer('given pair state', 4 * STATE_WORDS, USAGE.STORAGE | USAGE.COPY_DST);
      this.givenPairs.ensure(Math.max(1, n));
      const queue = this.ctx.device.queue;
      if (n > 0) queue.writeBuffer(this.givenPairs.buffer, 0, pairs.buffer, pairs.byteOffset, 8 * n);
      const words = new Uint32Array(STATE_WORDS);
      words[STATE.PAIR_COUNT] = n;
      words[STATE.PAIR_SORT_COUNT] = n;
      queue.writeBuffer(this.givenState, 0, words);
      np.growContacts(n);
      np.beginUpdate(mirror);
      const rb = this.readback;
      const encoder = this.ctx.device.createCommandEncoder({ label: 'narrow phase on given pairs' });
      this.timer.reset();
      const recorder = passRecorder(encoder, this.ctx.maxWorkgroupsPerDimension, this.timer);
      this.pairs = this.givenPairs.buffer;
      this.broadState = this.givenState;
      this.record(recorder.pass, mirror, GpuStage.Contacts, GpuStage.Compact);
      const dispatches = recorder.dispatches();
      np.encodeStateCopy(encoder, rb.buffer, NP_STATE_OFFSET);
      this.timer.resolveTo(encoder, rb.buffer, TIMER_OFFSET);
      await this.ctx.checkErrors();
      queue.submit([encoder.finish()]);
      const bytes = await rb.read(this.ctx, TIMER_OFFSET + this.timer.bytes);
      const counts = new Uint32Array(bytes, NP_STATE_OFFSET, NP_STATE_WORDS);
      const gpuTime = this.timer.parse(bytes, TIMER_OFFSET);
      await this.ctx.checkErrors();
      np.endUpdate();
      const broad: BroadPhaseResult = { pairCount: n, axis: 0, strips: 0, entries: 0, workItems: 0, regrows: 0, pairCapacity: n, dispatches: 0, gpuTime: null };
      const result = this.result(broad, counts, NOT_SOLVED, 0, dispatches, gpuTime, { encode: 0, submit: 0, wait: 0 }, false);
      this.take(result, this.recorded++);
      return result;
    } finally {
      this.busy = false;
    }
  }

  /** A step's result from its counts and its read-back's solver words (`solved`). */
  private result(
    broad: BroadPhaseResult,
    counts: Uint32Array,
    solved: SolverWords,
    regrows: number,
    dispatches: number,
    gpuTime: Record<string, number> | null,
    hostMs: NarrowPhaseResult['hostMs'],
    pending: boolean,
  ): NarrowPhaseResult {
    const binCounts: number[] = [];
    for (let b = 0; b < BIN_COUNT; ++b) binCounts.push(counts[NP.BINS + b + 1] - counts[NP.BINS + b]);
    return {
      broad,
      contactCount: counts[NP.CONTACTS],
      previousCount: counts[NP.PREV],
      solverCount: counts[NP.SOLVER],
      coloursUsed: solved.coloursUsed,
      colourItems: solved.colourItems,
      penetration: solved.penetration,
      awake: solved.awake,
      eventCount: counts[NP.EVENTS],
      binCounts,
      keptCount: counts[NP.KEPT],
      contactCapacity: this.narrowPhase.contactCapacity,
      contactRegrows: regrows,
      dispatches,
      gpuTime,
      hostMs,
      overflowed: (counts[NP.OVERFLOW] & OVERFLOW_CONTACTS) !== 0 || (broad.pairCount > 0 && counts[NP.PAIRS] === 0),
      pending,
      skipped: false,
    };
  }

  /** Looks at the read-backs that are in, oldest first: counts, and growth after an overflow. */
  private absorbSettled(): void {
    const bp = this.broadPhase;
    const np = this.narrowPhase;
    while (this.inFlight.length > 0 && this.inFlight[0].result !== null) {
      const entry = this.inFlight.shift()!;
      const r = entry.result!;
      const state = entry.state!;
      this.take(r, entry.step);
      const pairsFound = state[STATE.PAIR_COUNT];
      if ((state[STATE.OVERFLOW] & OVERFLOW_ENTRIES) !== 0) bp.growEntries(state[STATE.ENTRY_TOTAL]);
      // Headroom: keep 1.5 x the last counts.
      const want = Math.ceil(1.5 * pairsFound);
      if (want > bp.pairCapacity) bp.growPairs(want);
      if (want > np.contactCapacity) np.growContacts(want);
      if (r.overflowed) this.truncatedSteps++;
    }
  }

  private async runDeferred(mirror: GpuWorld, last: GpuStage, index: number): Promise<NarrowPhaseResult> {
    await this.ctx.checkErrors();
    const bp = this.broadPhase;
    this.absorbSettled();
    const tr = performance.now();
    const rb = await this.ring.next();
    this.absorbSettled();
    const t0 = performance.now();
    const step = this.recordStep(mirror, last, rb.buffer);
    await this.ctx.checkErrors();
    const t1 = performance.now();
    this.ctx.device.queue.submit([step.encoder.finish()]);
    const t2 = performance.now();
    const dispatches = step.dispatches();
    const entry: InFlight = { step: index, settled: null as unknown as Promise<NarrowPhaseResult>, result: null, state: null };
    const capacity = this.narrowPhase.contactCapacity;
    entry.settled = rb.read(this.ctx, TIMER_OFFSET + this.timer.bytes).then((bytes) => {
      const state = new Uint32Array(bytes, 0, STATE_WORDS).slice();
      const counts = new Uint32Array(bytes, NP_STATE_OFFSET, NP_STATE_WORDS);
      const r = this.result(
        bp.resultOf(state, 0, dispatches, null),
        counts,
        solverWords(bytes, last),
        0,
        dispatches,
        null,
        { encode: t1 - t0, submit: t2 - t1, wait: performance.now() - t2 },
        false,
      );
      r.contactCapacity = capacity;
      r.overflowed = r.overflowed || (state[STATE.OVERFLOW] & (OVERFLOW_PAIRS | OVERFLOW_ENTRIES)) !== 0;
      // The solver skipped the step: its colours say nothing of the next steps', and it measured nothing.
      if (r.overflowed) {
        Object.assign(r, NOT_SOLVED);
      }
      entry.state = state;
      entry.result = r;
      return r;
    });
    this.inFlight.push(entry);
    this.narrowPhase.endUpdate();
    const lastResult = this.lastResult;
    const base: NarrowPhaseResult = lastResult
      ? { ...lastResult, hostMs: { encode: t1 - t0, submit: t2 - t1, wait: t0 - tr }, dispatches }
      : this.result(
          { pairCount: 0, axis: 0, strips: 0, entries: 0, workItems: 0, regrows: 0, pairCapacity: bp.pairCapacity, dispatches, gpuTime: null },
          new Uint32Array(NP_STATE_WORDS),
          NOT_SOLVED,
          0,
          dispatches,
          null,
          { encode: t1 - t0, submit: t2 - t1, wait: t0 - tr },
          true,
        );
    return { ...base, pending: true, settled: entry.settled };
  }

  /** Waits for every step in flight ({ wait: false }) and takes in their counts. */
  async settle(): Promise<NarrowPhaseResult | null> {
    await Promise.all(this.inFlight.map((e) => e.settled.catch(() => undefined)));
    this.absorbSettled();
    return this.lastResult;
  }

  /** Destroys the pipeline's own buffers (the phases and the solver are their owners'). */
  destroy(): void {
    this.readback.destroy();
    this.ring.destroy();
    this.timer.destroy();
    this.givenPairs?.destroy();
    this.givenState?.destroy();
  }
}
