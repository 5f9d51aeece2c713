/*
 * Not in the C++: accuracy targets (b2World.SetAccuracyTarget, docs/ACCURACY.md, "Accuracy
 * targets"). A world given a target in the accuracy study's own units (maximum penetration and
 * joint error in metres, resting jitter in m/s) picks its velocity / position iterations and
 * sub-steps from a ladder of step settings ordered by cost, starting at the rung the accuracy
 * study measured to meet the target, and corrects the choice from the errors it measures in the
 * world after every step.
 *
 * The ladder and its numbers are the study's (bench/results/accuracy/accuracy.md, the JavaScript
 * engine's rows): 2/1, 4/2, 8/3 and 16/6 iterations, then 8/3 iterations in 2, 4 and 8 sub-steps.
 * 32/12 iterations is left out: it costs what 8/3 in 2 sub-steps costs and measures a larger error
 * in every measure but the chain's joint error, where the two are close; past 16/6, iterations no
 * longer reduce the mechanisms' joint error (the pulley's heavy box landing) and sub-steps do.
 *
 * The controller (b2AccuracyController), after every step:
 *  - measures what the target names, from the world's state only: penetration, the deepest point
 *    of the touching, enabled contacts' manifolds at the bodies' transforms (as
 *    b2PositionSolverManifold computes the separation); joint error, the largest linear position
 *    error of the joints (per joint type, as bench/accuracy/measures.mjs defines it); jitter, the
 *    root mean square linear speed of the awake dynamic bodies. No allocation.
 *  - moves up a rung when a measure exceeds its target and is not being corrected at this rung
 *    (then holds b2_accuracyUpHold steps, so that the new settings show before the next move up).
 *    The largest error of each block of b2_accuracyBlock checks since the last move tells: an
 *    error over its target is left to the rung while the current block's largest is not above the
 *    last block's, the last block's is below the one before, and at that fall per block the excess
 *    over the target is gone within b2_accuracyHorizon checks (2 s at 60 Hz). Until two blocks are
 *    complete the rung waits, unless the second block already rose above the first (a level error
 *    climbs after 30 checks, a rising one when the hold allows). Why: a scene that starts
 *    overlapping (the study's stack: the boxes' skins overlap 0.02 m) has an error that the
 *    position solver removes at any rung, over seconds that iterations hardly shorten (the stack's
 *    overlap falls under 0.01 m after 9 s at 4/2, 5 s at 32/12 and 1 s at 8 sub-steps), so
 *    chasing it up the ladder costs much and buys little; an error that rises, stays level or
 *    falls too slowly to reach the target within the horizon is under-iteration and climbs as
 *    before. Block maxima, not single steps: the stack's penetration jumps by a third from step to
 *    step while its blocks' maxima fall steadily.
 *  - moves down a rung when, for `downWait` consecutive steps (b2_accuracyDownWait at first),
 *    every measure would stay below half its target one rung down: the measured excess over the
 *    measure's floor (b2_linearSlop for penetration, which contacts settle into by design; 0
 *    otherwise) times the study's largest growth of that excess from this rung to the one below,
 *    over its scenes. A descent that the next move up undoes doubles downWait (at most
 *    b2_accuracyDownWaitMax), so the choice settles instead of oscillating.
 * Everything is integer counters and the world's own numbers: the same scene and target make the
 * same choices on every run. Sub-steps take the frame's dt in equal parts with the forces applied
 * through the whole frame (the world's force clearing is held until the last sub-step).
 *
 * On a backend (b2World.SetBackend) the chosen iterations go to the backend's Step; the ladder
 * stops at its last rung without sub-steps (each sub-step would be a step queued on the backend,
 * beyond its queue's limit). The measures read the backend's last synchronisation (the world's
 * PullState), so they lag the steps by the read-back, and are taken only when a synchronisation
 * (or a step on this engine) brought a new state. A backend that keeps the contacts (the world's
 * contact list is then empty) measures penetration itself, by the same definition, for the step
 * its last synchronisation shows (b2WorldBackend.GetPenetration: the WebGPU backend computes it on
 * the GPU after the step, in float32, and reads it back with the step's counts). One that does not
 * leaves penetration unmeasured, and its target holds the rung at or above the study's rung.
 */

import type { b2Contact } from './contacts/b2Contact';
import type { b2World } from './b2World';
import type { b2Joint } from './joints/b2Joint';
import type { b2DistanceJoint } from './joints/b2DistanceJoint';
import type { b2GearJoint } from './joints/b2GearJoint';
import type { b2PrismaticJoint } from './joints/b2PrismaticJoint';
import type { b2PulleyJoint } from './joints/b2PulleyJoint';
import type { b2RopeJoint } from './joints/b2RopeJoint';
import type { b2WheelJoint } from './joints/b2WheelJoint';
import type { b2Body } from './b2Body';
import type { b2Vec2 } from '../common/b2Math';
import { b2_linearSlop } from '../common/b2Settings';
import { b2ArgumentError, b2DescribeNumber } from '../common/b2ArgumentError';
import { b2BodyFlags, b2BodyType, b2ContactFlags, b2JointType, b2ManifoldType, b2WorldFlags } from '../common/b2Constants';

/** An accuracy target: at least one of the study's measures, each the largest error allowed. */
export interface b2AccuracyTargetDef {
  /** Maximum penetration of touching shapes, metres (contacts rest b2_linearSlop deep by design). */
  penetration?: number;
  /** Maximum linear position error of a joint, metres. */
  jointError?: number;
  /** Root mean square linear speed of the awake dynamic bodies, m/s (for scenes that should rest). */
  jitter?: number;
}

/** The measures of a target, in the order the controller checks them. */
export const b2AccuracyMeasures = ['penetration', 'jointError', 'jitter'] as const;
export type b2AccuracyMeasure = (typeof b2AccuracyMeasures)[number];

/** The measures' units, for messages. */
const UNIT: Readonly<Record<b2AccuracyMeasure, string>> = { penetration: 'm', jointError: 'm', jitter: 'm/s' };

/**
 * One rung of the ladder: step settings and what the accuracy study measured with them
 * (bench/results/accuracy/accuracy.md, the JavaScript engine's rows): per measure, the error on each
 * of the study's scenes that measure it; `msPerSecond`, the pyramid's stepping time per simulated
 * second (its largest scene), which orders the ladder.
 */
export interface b2AccuracyRung {
  readonly velocityIterations: number;
  readonly positionIterations: number;
  readonly substeps: number;
  readonly label: string;
  readonly study: {
    readonly penetration: { readonly stack: number; readonly pyramid: number };
    readonly jointError: { readonly chain: number; readonly mechanisms: number };
    readonly jitter: { readonly stack: number; readonly pyramid: number };
  };
  readonly msPerSecond: number;
}

function rung(
  velocityIterations: number,
  positionIterations: number,
  substeps: number,
  penetration: [number, number],
  jointError: [number, number],
  jitter: [number, number],
  msPerSecond: number,
): b2AccuracyRung {
  const label = `${velocityIterations}/${positionIterations} iterations${substeps > 1 ? `, ${substeps} substeps` : ''}`;
  return Object.freeze({
    velocityIterations,
    positionIterations,
    substeps,
    label,
    study: Object.freeze({
      penetration: Object.freeze({ stack: penetration[0], pyramid: penetration[1] }),
      jointError: Object.freeze({ chain: jointError[0], mechanisms: jointError[1] }),
      jitter: Object.freeze({ stack: jitter[0], pyramid: jitter[1] }),
    }),
    msPerSecond,
  });
}

/**
 * The ladder, cheapest first. The numbers are the study's (bench/results/accuracy/accuracy.md), to
 * its three significant digits: penetration max (stack, pyramid), joint error (chain,
 * mechanisms), jitter (stack, pyramid), and the pyramid's ms per simulated second.
 */
export const b2_accuracyLadder: readonly b2AccuracyRung[] = Object.freeze([
  rung(2, 1, 1, [0.0152, 0.00569], [0.128, 0.059], [0.0202, 2.77e-5], 5.4),
  rung(4, 2, 1, [0.00973, 0.00539], [0.0673, 0.059], [9.25e-5, 2.24e-7], 6.15),
  rung(8, 3, 1, [0.00882, 0.00531], [0.0367, 0.059], [3.13e-5, 1.73e-7], 7.49),
  rung(16, 6, 1, [0.00823, 0.00527], [0.0186, 0.059], [5.14e-5, 8.55e-8], 10.1),
  rung(8, 3, 2, [0.00615, 0.00501], [0.0109, 0.0321], [1.04e-6, 2.12e-9], 14.7),
  rung(8, 3, 4, [0.00511, 0.00501], [0.00402, 0.00773], [3.15e-6, 6.3e-13], 28.7),
  rung(8, 3, 8, [0.005, 0.00501], [0.00173, 0.00133], [2.97e-7, 3.26e-17], 57.6),
]);

/** The last rung a backend takes: the last one without sub-steps. */
const BACKEND_TOP = b2_accuracyLadder.reduce((top, r, i) => (r.substeps === 1 ? i : top), 0);

/** Steps after a move before the next move up. */
export const b2_accuracyUpHold = 15;
/** Checks (measured steps) in a block: the controller compares consecutive blocks' largest errors to tell a falling error. */
export const b2_accuracyBlock = 15;
/**
 * A falling error over its target stays with the current rung while, falling as fast as it fell
 * from the block before to the last block, it would be under the target within this many checks.
 */
export const b2_accuracyHorizon = 120;
/** Consecutive steps with room to spare before the first move down. */
export const b2_accuracyDownWait = 60;
/** The longest wait before a move down, however often descents were undone. */
export const b2_accuracyDownWaitMax = 60 * 64;

/** The error a measure shows even when fully converged: contacts settle b2_linearSlop deep. */
const FLOOR: Readonly<Record<b2AccuracyMeasure, number>> = { penetration: b2_linearSlop, jointError: 0, jitter: 0 };
/** The study's resolution (three significant digits) near each floor: the smallest excess it can tell. */
const RESOLUTION: Readonly<Record<b2AccuracyMeasure, number>> = { penetration: 1e-5, jointError: 1e-5, jitter: 1e-18 };

function studyValues(r: b2AccuracyRung, m: b2AccuracyMeasure): number[] {
  return Object.values(r.study[m]);
}

/** The study's largest error of measure `m` at rung `i`, over its scenes. */
export function b2AccuracyStudyError(i: number, m: b2AccuracyMeasure): number {
  return Math.max(...studyValues(b2_accuracyLadder[i], m));
}

/**
 * GROWTH[m][i]: for rung i > 0, the largest factor by which the study's excess error of measure m
 * over its floor grew from rung i to rung i - 1, over the study's scenes (at least 1).
 */
const GROWTH: Readonly<Record<b2AccuracyMeasure, readonly number[]>> = (() => {
  const out = {} as Record<b2AccuracyMeasure, number[]>;
  for (const m of b2AccuracyMeasures) {
    out[m] = b2_accuracyLadder.map((r, i) => {
      if (i === 0) return Infinity;
      const below = studyValues(b2_accuracyLadder[i - 1], m);
      const here = studyValues(r, m);
      let g = 1;
      for (let s = 0; s < here.length; ++s) {
        const ratio = Math.max(below[s] - FLOOR[m], RESOLUTION[m]) / Math.max(here[s] - FLOOR[m], RESOLUTION[m]);
        if (ratio > g) g = ratio;
      }
      return g;
    });
  }
  return out;
})();

/** The study's growth factor of measure `m`'s excess from rung `i` to rung `i - 1` (see the file comment). */
export function b2AccuracyGrowth(i: number, m: b2AccuracyMeasure): number {
  return GROWTH[m][i];
}

/**
 * Checks an accuracy target: an object with at least one of penetration, jointError and jitter,
 * each a finite number > 0, and no other key. Returns a frozen copy; throws a b2ArgumentError
 * naming the argument and the rule otherwise.
 */
export function b2CheckAccuracyTarget(method: string, target: unknown): Readonly<b2AccuracyTargetDef> {
  if (typeof target !== 'object' || target === null || Array.isArray(target)) {
    throw new b2ArgumentError(
      method,
      'target',
      `must be an object { penetration?, jointError?, jitter? } or null, got ${Array.isArray(target) ? 'an array' : b2DescribeNumber(target)}`,
    );
  }
  const t = target as Record<string, unknown>;
  for (const key of Object.keys(t)) {
    if (!(b2AccuracyMeasures as readonly string[]).includes(key)) {
      throw new b2ArgumentError(method, `target.${key}`, `is not a measure of an accuracy target (penetration, jointError, jitter)`);
    }
  }
  const out: b2AccuracyTargetDef = {};
  for (const m of b2AccuracyMeasures) {
    const v = t[m];
    if (v === undefined) continue;
    if (typeof v !== 'number' || !Number.isFinite(v) || !(v > 0)) {
      throw new b2ArgumentError(method, `target.${m}`, `must be a finite number > 0 (${UNIT[m]}), got ${b2DescribeNumber(v)}`);
    }
    out[m] = v;
  }
  if (Object.keys(out).length === 0) {
    throw new b2ArgumentError(method, 'target', 'must give at least one of penetration (m), jointError (m), jitter (m/s)');
  }
  return Object.freeze(out);
}

/** The cheapest rung at or below `top` whose study error of `m` is below `target`; -1 when none is. */
export function b2AccuracyStudyRung(m: b2AccuracyMeasure, target: number, top = b2_accuracyLadder.length - 1): number {
  for (let i = 0; i <= top; ++i) if (b2AccuracyStudyError(i, m) < target) return i;
  return -1;
}

/** What b2World.GetAccuracy returns: the target, the step settings in use, the measured errors and why. */
export interface b2Accuracy {
  readonly target: Readonly<b2AccuracyTargetDef>;
  readonly velocityIterations: number;
  readonly positionIterations: number;
  readonly substeps: number;
  /**
   * The errors measured after the last measured step (null: not in the target, not measured yet,
   * or not measurable here: penetration on a backend that keeps the contacts without
   * b2WorldBackend.GetPenetration, or whose last synchronised step did not solve).
   */
  readonly measured: { readonly penetration: number | null; readonly jointError: number | null; readonly jitter: number | null };
  /** The largest error of each measure since the current rung was chosen (null as for `measured`). */
  readonly worst: { readonly penetration: number | null; readonly jointError: number | null; readonly jitter: number | null };
  /** Steps taken under the target (World.Step calls with dt > 0), and rung changes among them. */
  readonly steps: number;
  readonly changes: number;
  /** Whether every measured error is at or below its target after the last measured step. */
  readonly met: boolean;
  /** Why these settings, in words and numbers. */
  readonly reason: string;
}

function num(x: number): string {
  return Number(x.toPrecision(3)).toString();
}

function describeMeasure(m: b2AccuracyMeasure, v: number): string {
  return `${num(v)} ${UNIT[m]}`;
}

const NAME: Readonly<Record<b2AccuracyMeasure, string>> = { penetration: 'penetration', jointError: 'joint error', jitter: 'jitter' };

const { e_touchingFlag, e_enabledFlag } = b2ContactFlags;
const { e_awakeFlag } = b2BodyFlags;
const { e_clearForces } = b2WorldFlags;

/** Index of a measure in the controller's arrays. */
const PEN = 0;
const JOINT = 1;
const JIT = 2;

/**
 * The controller of one world's accuracy target (b2World.SetAccuracyTarget makes one; see the
 * file comment for its rules). Step(world, dt) takes the world's Step under the target.
 */
export class b2AccuracyController {
  readonly target: Readonly<b2AccuracyTargetDef>;
  private readonly targets = new Float64Array(3);
  private readonly wanted = [false, false, false];
  /** The study's rung for each measure (-1: none of the study's rungs meets it). */
  private readonly studyRungs = [0, 0, 0];
  private rungIndex: number;
  /** Last measured values; NaN when not measured. */
  private readonly measured = new Float64Array([NaN, NaN, NaN]);
  private readonly worstHere = new Float64Array([NaN, NaN, NaN]);
  /** The largest error of each measure in the current block of checks, the last complete block and the one before (NaN: none). */
  private readonly blockMax = new Float64Array([NaN, NaN, NaN]);
  private readonly lastBlock = new Float64Array([NaN, NaN, NaN]);
  private readonly prevBlock = new Float64Array([NaN, NaN, NaN]);
  /** Checks in the current block, and complete blocks, since the last move. */
  private blockChecks = 0;
  private blocks = 0;
  private measuredAny = false;
  private steps = 0;
  private changes = 0;
  private sinceMove = 0;
  private calm = 0;
  private downWait = b2_accuracyDownWait;
  private lastMove: 'set' | 'up' | 'down' = 'set';
  /** The last move: at which step, from which rung, for which measure, with which value and bound. */
  private moveStep = 0;
  private moveFrom = -1;
  private moveMeasure = -1;
  private moveValue = 0;
  private moveBound = 0;
  /** The world's state the last measure read: its synchronisation epoch and engine steps under a backend. */
  private seenEpoch = -1;
  private seenEngineSteps = -1;

  constructor(target: Readonly<b2AccuracyTargetDef>) {
    this.target = target;
    let start = 0;
    b2AccuracyMeasures.forEach((m, k) => {
      const t = target[m];
      if (t === undefined) return;
      this.wanted[k] = true;
      this.targets[k] = t;
      const r = b2AccuracyStudyRung(m, t);
      this.studyRungs[k] = r;
      start = Math.max(start, r < 0 ? b2_accuracyLadder.length - 1 : r);
    });
    this.rungIndex = start;
  }

  /** The highest rung on `world` now: the whole ladder on this engine, the rungs without sub-steps on a backend. */
  private top(world: b2World): number {
    return world.GetBackend() === null ? b2_accuracyLadder.length - 1 : BACKEND_TOP;
  }

  /** The rung in use on `world`. */
  rung(world: b2World): number {
    return Math.min(this.rungIndex, this.top(world));
  }

  /**
   * b2World.Step under the target (its arguments already checked): the chosen rung's sub-steps of
   * dt / substeps at its iterations, then the measures and the next choice.
   */
  Step(world: b2World, dt: number): void {
    const r = b2_accuracyLadder[this.rung(world)];
    const k = dt > 0 ? r.substeps : 1;
    if (k === 1) {
      world.StepDirect(dt, r.velocityIterations, r.positionIterations);
    } else {
      // The forces act through the whole frame: cleared after the last sub-step only.
      const clear = world.m_flags & e_clearForces;
      const h = dt / k;
      try {
        world.m_flags &= ~clear;
        for (let i = 0; i < k - 1; ++i) world.StepDirect(h, r.velocityIterations, r.positionIterations);
      } finally {
        world.m_flags |= clear;
      }
      world.StepDirect(h, r.velocityIterations, r.positionIterations);
    }
    if (dt > 0) this.update(world);
  }

  /** Measures the world (when it shows a new state) and moves up or down the ladder. */
  private update(world: b2World): void {
    this.steps++;
    this.sinceMove++;
    const onBackend = world.GetBackend() !== null;
    let contacts = true;
    if (onBackend) {
      // The state of the last synchronisation, or of a step a backend let this engine take.
      const epoch = world.m_stateEpoch;
      const engineSteps = world.m_engineStepsOnBackend;
      if (epoch === this.seenEpoch && engineSteps === this.seenEngineSteps) return;
      // The world's contacts are this engine's only after a step it took (not at the first look);
      // otherwise penetration is the backend's own measure (measure()).
      contacts = this.seenEngineSteps >= 0 && engineSteps !== this.seenEngineSteps;
      this.seenEpoch = epoch;
      this.seenEngineSteps = engineSteps;
      world.PullState();
    }
    this.measure(world, contacts);
    this.decide(world);
  }

  /** `contacts`: the world's contact list holds the step's contacts (else a backend keeps them). */
  private measure(world: b2World, contacts: boolean): void {
    // Written into the array, not returned: a returned double would be boxed, an allocation a step.
    const v = this.measured;
    if (!this.wanted[PEN]) v[PEN] = NaN;
    else if (contacts) measurePenetration(world.m_contactManager.m_contactList, v, PEN);
    else v[PEN] = world.GetBackend()!.GetPenetration?.() ?? NaN;
    if (this.wanted[JOINT]) measureJointError(world.m_jointList, v, JOINT);
    else v[JOINT] = NaN;
    if (this.wanted[JIT]) measureJitter(world.m_bodyList, v, JIT);
    else v[JIT] = NaN;
    this.measuredAny = true;
    for (let k = 0; k < 3; ++k) {
      if (v[k] === v[k] && !(v[k] <= this.worstHere[k])) this.worstHere[k] = v[k];
      if (v[k] === v[k] && !(v[k] <= this.blockMax[k])) this.blockMax[k] = v[k];
    }
    if (++this.blockChecks === b2_accuracyBlock) {
      this.prevBlock.set(this.lastBlock);
      this.lastBlock.set(this.blockMax);
      this.blockMax.fill(NaN);
      this.blockChecks = 0;
      this.blocks++;
    }
  }

  /**
   * Whether measure k, over its target, is being corrected at the current rung (see the file
   * comment): with two complete blocks of checks since the last move, the current block's largest
   * error is not above the last block's, the last block's is below the one before, and at that fall
   * per block the excess over the target is gone within b2_accuracyHorizon checks. With fewer
   * blocks, the rung waits for the second unless the current block already rose above the first.
   */
  private corrected(k: number): boolean {
    const now = this.blockMax[k];
    const last = this.lastBlock[k];
    if (this.blocks < 2) return !(this.blocks === 1 && now > last);
    const prev = this.prevBlock[k];
    return !(now > last) && last < prev && (last - this.targets[k]) * b2_accuracyBlock <= b2_accuracyHorizon * (prev - last);
  }

  private decide(world: b2World): void {
    const v = this.measured;
    const top = this.top(world);
    const here = Math.min(this.rungIndex, top);
    // Up: the first measure over its target that is not being corrected here.
    let over = false;
    for (let k = 0; k < 3; ++k) {
      if (!(v[k] > this.targets[k])) continue;
      over = true;
      if (here < top && this.sinceMove >= b2_accuracyUpHold && !this.corrected(k)) {
        if (this.lastMove === 'down') this.downWait = Math.min(2 * this.downWait, b2_accuracyDownWaitMax);
        this.move(here, here + 1, 'up', k, v[k], this.targets[k]);
        return;
      }
    }
    if (over) {
      this.calm = 0;
      return;
    }
    // Down: every measure would keep below half its target one rung down.
    if (here === 0) {
      this.calm = 0;
      return;
    }
    let room = true;
    let slack = Infinity;
    let slackMeasure = -1;
    for (let k = 0; k < 3 && room; ++k) {
      if (!this.wanted[k]) continue;
      const m = b2AccuracyMeasures[k];
      if (v[k] !== v[k]) {
        // Not measured here: the study's rung is the floor.
        room = here - 1 >= this.studyRungs[k];
        continue;
      }
      const predicted = FLOOR[m] + Math.max(v[k] - FLOOR[m], 0) * GROWTH[m][here];
      const bound = FLOOR[m] + 0.5 * (this.targets[k] - FLOOR[m]);
      room = predicted < bound;
      if (bound - predicted < slack) {
        slack = bound - predicted;
        slackMeasure = k;
      }
    }
    if (!room) {
      this.calm = 0;
      return;
    }
    if (++this.calm >= this.downWait) {
      const k = slackMeasure;
      this.move(here, here - 1, 'down', k, k < 0 ? 0 : v[k], k < 0 ? 0 : this.targets[k]);
    }
  }

  private move(from: number, to: number, how: 'up' | 'down', measure: number, value: number, bound: number): void {
    this.rungIndex = to;
    this.lastMove = how;
    this.moveStep = this.steps;
    this.moveFrom = from;
    this.moveMeasure = measure;
    this.moveValue = value;
    this.moveBound = bound;
    this.sinceMove = 0;
    this.calm = 0;
    this.changes++;
    this.worstHere.fill(NaN);
    this.blockMax.fill(NaN);
    this.lastBlock.fill(NaN);
    this.prevBlock.fill(NaN);
    this.blockChecks = 0;
    this.blocks = 0;
  }

  /** b2World.GetAccuracy's answer (allocates; not called by the step). */
  report(world: b2World): b2Accuracy {
    const here = this.rung(world);
    const r = b2_accuracyLadder[here];
    const top = this.top(world);
    const value = (a: Float64Array, k: number): number | null => (this.wanted[k] && a[k] === a[k] ? a[k] : null);
    const measured = { penetration: value(this.measured, PEN), jointError: value(this.measured, JOINT), jitter: value(this.measured, JIT) };
    const worst = { penetration: value(this.worstHere, PEN), jointError: value(this.worstHere, JOINT), jitter: value(this.worstHere, JIT) };
    const over: string[] = [];
    const within: string[] = [];
    b2AccuracyMeasures.forEach((m, k) => {
      if (!this.wanted[k]) return;
      const t = this.targets[k];
      const x = this.measured[k];
      if (x !== x) {
        const where = !this.measuredAny
          ? 'yet'
          : world.GetBackend()?.GetPenetration === undefined
            ? 'here (the backend keeps the contacts)'
            : 'in the last synchronisation (no step it shows solved)';
        within.push(`${NAME[m]} not measured ${where}, target ${describeMeasure(m, t)}`);
      } else if (x > t) {
        const falling = here < top && this.corrected(k) ? (this.blocks < 2 ? ', watched for a fall' : ', falling: left to this rung') : '';
        over.push(`${NAME[m]} ${describeMeasure(m, x)} over the target ${describeMeasure(m, t)}${falling}`);
      } else {
        within.push(`${NAME[m]} ${describeMeasure(m, x)} within ${describeMeasure(m, t)}`);
      }
    });
    const parts: string[] = [r.label];
    if (this.lastMove === 'set') {
      const why = b2AccuracyMeasures
        .filter((_, k) => this.wanted[k])
        .map((m) => {
          const k = b2AccuracyMeasures.indexOf(m);
          const s = this.studyRungs[k];
          return s < 0
            ? `no rung of the study gets ${NAME[m]} below ${describeMeasure(m, this.targets[k])} (its best: ${describeMeasure(m, b2AccuracyStudyError(b2_accuracyLadder.length - 1, m))})`
            : `${NAME[m]} ${describeMeasure(m, b2AccuracyStudyError(s, m))} at ${b2_accuracyLadder[s].label} is the study's cheapest below ${describeMeasure(m, this.targets[k])}`;
        });
      parts.push(`chosen from the accuracy study: ${why.join('; ')}`);
    } else {
      const m = this.moveMeasure >= 0 ? b2AccuracyMeasures[this.moveMeasure] : null;
      const from = b2_accuracyLadder[this.moveFrom].label;
      if (this.lastMove === 'up') {
        parts.push(
          `up from ${from} at step ${this.moveStep}: ${NAME[m!]} ${describeMeasure(m!, this.moveValue)} over the target ${describeMeasure(m!, this.moveBound)}`,
        );
      } else {
        const tail =
          m === null
            ? "the measures not taken here stay at or above the study's rungs"
            : `${NAME[m]} ${describeMeasure(m, this.moveValue)} would stay below half the target ${describeMeasure(m, this.moveBound)}${FLOOR[m] > 0 ? ` above the ${describeMeasure(m, FLOOR[m])} contacts rest at` : ''} with the study's growth from rung to rung`;
        parts.push(
          `down from ${from} at step ${this.moveStep} after ${this.downWait === b2_accuracyDownWait ? b2_accuracyDownWait : `${this.downWait} (doubled: a descent was undone)`} steps with room: ${tail}`,
        );
      }
    }
    const onTop = here === top;
    if (!this.measuredAny) parts.push('nothing measured yet');
    else if (over.length > 0)
      parts.push(`${onTop ? 'target NOT met at the top rung' : 'target not met yet'}: ${over.join(', ')}${within.length > 0 ? `; ${within.join(', ')}` : ''}`);
    else parts.push(`target met: ${within.join(', ')}`);
    if (onTop && world.GetBackend() !== null && top < b2_accuracyLadder.length - 1)
      parts.push('on a backend the ladder ends at its last rung without sub-steps');
    return {
      target: this.target,
      velocityIterations: r.velocityIterations,
      positionIterations: r.positionIterations,
      substeps: r.substeps,
      measured,
      worst,
      steps: this.steps,
      changes: this.changes,
      met: this.measuredAny && over.length === 0,
      reason: parts.join('; '),
    };
  }
}

/**
 * The deepest penetration (m, >= 0) of the touching, enabled contacts' manifold points at the
 * bodies' current transforms, each point's separation as b2PositionSolverManifold computes it.
 */
export function penetrationOf(list: b2Contact | null): number {
  measurePenetration(list, scratch, 0);
  return scratch[0];
}

const scratch = new Float64Array(1);

/** penetrationOf(list) into out[slot]. */
function measurePenetration(list: b2Contact | null, out: Float64Array, slot: number): void {
  let deepest = 0;
  for (let c = list; c; c = c.m_next) {
    if ((c.m_flags & (e_touchingFlag | e_enabledFlag)) !== (e_touchingFlag | e_enabledFlag)) continue;
    const m = c.m_manifold;
    const n = m.pointCount;
    if (n === 0) continue;
    const fA = c.m_fixtureA;
    const fB = c.m_fixtureB;
    const xfA = fA.m_body.m_xf;
    const xfB = fB.m_body.m_xf;
    const radii = fA.m_shape.m_radius + fB.m_shape.m_radius;
    if (m.type === b2ManifoldType.e_circles) {
      const lp = m.localPoint;
      const ax = xfA.q.c * lp.x - xfA.q.s * lp.y + xfA.p.x;
      const ay = xfA.q.s * lp.x + xfA.q.c * lp.y + xfA.p.y;
      const bp = m.points[0].localPoint;
      const bx = xfB.q.c * bp.x - xfB.q.s * bp.y + xfB.p.x;
      const by = xfB.q.s * bp.x + xfB.q.c * bp.y + xfB.p.y;
      const s = Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay)) - radii;
      if (-s > deepest) deepest = -s;
      continue;
    }
    const faceA = m.type === b2ManifoldType.e_faceA;
    const xfF = faceA ? xfA : xfB;
    const xfC = faceA ? xfB : xfA;
    const ln = m.localNormal;
    const nx = xfF.q.c * ln.x - xfF.q.s * ln.y;
    const ny = xfF.q.s * ln.x + xfF.q.c * ln.y;
    const lp = m.localPoint;
    const px = xfF.q.c * lp.x - xfF.q.s * lp.y + xfF.p.x;
    const py = xfF.q.s * lp.x + xfF.q.c * lp.y + xfF.p.y;
    for (let i = 0; i < n; ++i) {
      const cp = m.points[i].localPoint;
      const cx = xfC.q.c * cp.x - xfC.q.s * cp.y + xfC.p.x;
      const cy = xfC.q.s * cp.x + xfC.q.c * cp.y + xfC.p.y;
      const s = (cx - px) * nx + (cy - py) * ny - radii;
      if (-s > deepest) deepest = -s;
    }
  }
  out[slot] = deepest;
}

/**
 * The helpers below leave their result in G[0] rather than return it: a double returned from a
 * call the optimiser does not inline is boxed, an allocation a joint and a step.
 */
const G = new Float64Array(1);

/** |b.xf(lb) - a.xf(la)|, the distance between two bodies' local points in the world. */
function anchorGap(a: b2Body, la: Readonly<b2Vec2>, b: b2Body, lb: Readonly<b2Vec2>): void {
  const dx = b.m_xf.q.c * lb.x - b.m_xf.q.s * lb.y + b.m_xf.p.x - (a.m_xf.q.c * la.x - a.m_xf.q.s * la.y + a.m_xf.p.x);
  const dy = b.m_xf.q.s * lb.x + b.m_xf.q.c * lb.y + b.m_xf.p.y - (a.m_xf.q.s * la.x + a.m_xf.q.c * la.y + a.m_xf.p.y);
  G[0] = Math.sqrt(dx * dx + dy * dy);
}

/** The distance from a body's local point in the world to a world point. */
function pointGap(a: b2Body, la: Readonly<b2Vec2>, p: Readonly<b2Vec2>): void {
  const dx = a.m_xf.q.c * la.x - a.m_xf.q.s * la.y + a.m_xf.p.x - p.x;
  const dy = a.m_xf.q.s * la.x + a.m_xf.q.c * la.y + a.m_xf.p.y - p.y;
  G[0] = Math.sqrt(dx * dx + dy * dy);
}

/** (b.xf(lb) - a.xf(la)) · (a's rotation of axis). */
function alongAxis(a: b2Body, la: Readonly<b2Vec2>, b: b2Body, lb: Readonly<b2Vec2>, axis: Readonly<b2Vec2>): void {
  const dx = b.m_xf.q.c * lb.x - b.m_xf.q.s * lb.y + b.m_xf.p.x - (a.m_xf.q.c * la.x - a.m_xf.q.s * la.y + a.m_xf.p.x);
  const dy = b.m_xf.q.s * lb.x + b.m_xf.q.c * lb.y + b.m_xf.p.y - (a.m_xf.q.s * la.x + a.m_xf.q.c * la.y + a.m_xf.p.y);
  G[0] = dx * (a.m_xf.q.c * axis.x - a.m_xf.q.s * axis.y) + dy * (a.m_xf.q.s * axis.x + a.m_xf.q.c * axis.y);
}

/**
 * The largest linear position error (m) of the joints, per type as bench/accuracy/measures.mjs
 * defines it; soft joints (a distance joint with a frequency), limits, motors, mouse and friction
 * joints are not errors, and a gear between two revolute joints has an angular error only.
 */
export function jointErrorOf(list: b2Joint | null): number {
  measureJointError(list, scratch, 0);
  return scratch[0];
}

/** jointErrorOf(list) into out[slot]. */
function measureJointError(list: b2Joint | null, out: Float64Array, slot: number): void {
  let largest = 0;
  for (let j = list; j; j = j.m_next) {
    const a = j.m_bodyA;
    const b = j.m_bodyB;
    let e = 0;
    switch (j.m_type) {
      case b2JointType.e_revoluteJoint:
      case b2JointType.e_weldJoint: {
        const r = j as unknown as { m_localAnchorA: b2Vec2; m_localAnchorB: b2Vec2 };
        anchorGap(a, r.m_localAnchorA, b, r.m_localAnchorB);
        e = G[0];
        break;
      }
      case b2JointType.e_prismaticJoint:
      case b2JointType.e_wheelJoint: {
        const p = j as unknown as b2PrismaticJoint | b2WheelJoint;
        alongAxis(a, p.m_localAnchorA, b, p.m_localAnchorB, p.m_localYAxisA);
        e = Math.abs(G[0]);
        break;
      }
      case b2JointType.e_distanceJoint: {
        const d = j as unknown as b2DistanceJoint;
        if (d.m_frequencyHz > 0) break;
        anchorGap(a, d.m_localAnchorA, b, d.m_localAnchorB);
        e = Math.abs(G[0] - d.m_length);
        break;
      }
      case b2JointType.e_ropeJoint: {
        const r = j as unknown as b2RopeJoint;
        anchorGap(a, r.m_localAnchorA, b, r.m_localAnchorB);
        e = Math.max(0, G[0] - r.m_maxLength);
        break;
      }
      case b2JointType.e_pulleyJoint: {
        const p = j as unknown as b2PulleyJoint;
        pointGap(a, p.m_localAnchorA, p.m_groundAnchorA);
        const lengthA = G[0];
        pointGap(b, p.m_localAnchorB, p.m_groundAnchorB);
        e = Math.abs(lengthA + p.m_ratio * G[0] - p.m_constant);
        break;
      }
      case b2JointType.e_gearJoint: {
        const g = j as unknown as b2GearJoint;
        if (g.m_typeA === b2JointType.e_revoluteJoint && g.m_typeB === b2JointType.e_revoluteJoint) break;
        // Each coordinate as b2GearJoint defines it: an angle for a revolute joint, a translation for a prismatic one.
        let ca = a.m_sweep.a - g.m_bodyC.m_sweep.a - g.m_referenceAngleA;
        if (g.m_typeA !== b2JointType.e_revoluteJoint) {
          alongAxis(g.m_bodyC, g.m_localAnchorC, a, g.m_localAnchorA, g.m_localAxisC);
          ca = G[0];
        }
        let cb = b.m_sweep.a - g.m_bodyD.m_sweep.a - g.m_referenceAngleB;
        if (g.m_typeB !== b2JointType.e_revoluteJoint) {
          alongAxis(g.m_bodyD, g.m_localAnchorD, b, g.m_localAnchorB, g.m_localAxisD);
          cb = G[0];
        }
        e = Math.abs(ca + g.m_ratio * cb - g.m_constant);
        break;
      }
      default:
        break;
    }
    if (e > largest) largest = e;
  }
  out[slot] = largest;
}

/** The root mean square linear speed (m/s) of the awake dynamic bodies; 0 when there is none. */
export function jitterOf(list: b2Body | null): number {
  measureJitter(list, scratch, 0);
  return scratch[0];
}

/** jitterOf(list) into out[slot]. */
function measureJitter(list: b2Body | null, out: Float64Array, slot: number): void {
  let sum = 0;
  let n = 0;
  for (let b = list; b; b = b.m_next) {
    if (b.m_type !== b2BodyType.b2_dynamicBody || (b.m_flags & e_awakeFlag) === 0) continue;
    const v = b.m_linearVelocity;
    sum += v.x * v.x + v.y * v.y;
    n++;
  }
  out[slot] = n === 0 ? 0 : Math.sqrt(sum / n);
}
