/*
 * The GPU solver: b2Island::Solve for the contacts of a step, in float32, as stages that
 * GpuPipeline (pipeline.ts) records after the narrow phase's, in the same command buffer.
 *
 *   begin               solver state: skip when collision overflowed, the contact count  colour.ts
 *   islands             wake (new contacts, touch changes), connected components through
 *                       touching contacts and joints, whole islands woken           islands.ts
 *   integrate velocities  c0 = c; gravity, forces, damping                       integrateVelocities.ts
 *   prepare             solver contacts: masses, world manifold, K, restitution bias    prepareContacts.ts
 *   joints: prepare     the ten joint types' InitVelocityConstraints (no velocity update) solveJoints.ts
 *   colour              Jones-Plassmann colouring of joints and contacts together, colour
 *                       lists (+ overflow set); the last one reused while every item has
 *                       the same dynamic bodies                                          colour.ts
 *   warm start          per large colour (passColours), then the tail pass: its joints'
 *                       and contacts' impulses x dtRatio                                 warmStart.ts
 *   velocity            iterations: per large colour, then the tail pass, its joints,
 *                       then its contacts (friction, then normal: block solver)          solveVelocity.ts
 *   store impulses      into the manifolds' word 3 for the next step                     storeImpulses.ts
 *   integrate positions with b2_maxTranslation / b2_maxRotation                          integratePositions.ts
 *   position            iterations: per large colour, then the tail pass, its contacts,
 *                       then its joints; early exit as zeroed indirect sizes             solvePosition.ts
 *   synchronize         bodyXf from the sweep, cells                                     integratePositions.ts
 *   sleep               sleep timers, islands at rest put to sleep                       islands.ts
 *   time of impact      continuous physics on: b2TimeOfImpact of the contacts 2.2.1 tests
 *                       (bullets; dynamic against static / kinematic), each dynamic body
 *                       moved back to its earliest one; no TOI island solve   timeOfImpact.ts
 *   penetration         the deepest point of the touching contacts after the step, for the
 *                       accuracy target (read back with the step's counts)       penetration.ts
 *
 * In:  the narrow phase's outputs of the step being recorded (solverList, contactRefs, manifolds,
 *      npState) and the broad phase's state (overflow), the mirror's body and fixture tables.
 * Out: bodySweep, bodyVel, bodyXf, bodyCell written in place (the GPU copy is then the authority:
 *      GpuWorld.gpuOwnsMotion), impulses in the manifolds and in the mirror's jointState.
 * Inputs set per step by configure(): dt, dtRatio, warm starting, gravity, iterations. Joints and
 * contacts in a colour's passes are solved in parallel: a colour's items share no dynamic body.
 * Results are the same bits on every run on one device (no float atomics; the colouring depends
 * only on the joints and contacts; the overflow set is solved in item order).
 * Passes per colour: the warm start and each velocity and position iteration dispatch one pass
 * per colour for the first passColours colours (the leading colours of at least
 * TAIL_COLOUR_ITEMS items in the latest step read back; all COLOUR_CAP before one is back), then
 * one tail pass: one workgroup walks the colours left (from the first small one) with barriers
 * between them, then the overflow set. The same items in the same order, so the same bits whatever
 * passColours is (a colour that grew past TAIL_COLOUR_ITEMS since only runs slower, until a
 * read-back raises passColours): passColours + 1 dispatches per pass (COLOUR_CAP + 1 when all
 * have one).
 * A small world (FUSED_SOLVER_ITEMS) runs the colouring rounds, the warm start and the velocity
 * and position iterations each in one dispatch of one workgroup that walks all the colours as the
 * tail passes walk theirs: the same items in the same order, so the same bits, in four dispatches
 * instead of 2 COLOUR_CAP + 1 rounds and the passes per colour. 2.2.1 solves an
 * island's joints, then its contacts, each velocity iteration (contacts, then joints, each
 * position iteration); the GPU analogue is per colour, so across colours the Gauss-Seidel order
 * differs from the engine's.
 * Sleeping bodies are not integrated and their contacts are not solved (islands.ts), nor joints
 * with a sleeping dynamic body (solveJoints.ts).
 * Unlike 2.2.1: no TOI island solve or sub-steps (timeOfImpact.ts), no PreSolve (PostSolve is
 * delivered by WebGPUBackend from the impulses left in the manifolds: events.ts).
 */

import { readBuffer } from '../device/readback';
import type { GpuContext } from '../device/device';
import { GpuArray } from '../device/buffers';
import { Uniform } from '../device/kernel';
import type { Recorder } from '../device/kernel';
import { ColourStage } from './colour';
import type { ColourInputs } from './colour';
import { IntegrateVelocitiesStage } from './integrateVelocities';
import { IntegratePositionsStage } from './integratePositions';
import { PrepareContactsStage } from './prepareContacts';
import type { PrepareInputs } from './prepareContacts';
import { WarmStartStage } from './warmStart';
import type { ColourPassInputs } from './warmStart';
import { SolveVelocityStage } from './solveVelocity';
import { StoreImpulsesStage } from './storeImpulses';
import { SolvePositionStage } from './solvePosition';
import { SolveJointsStage } from './solveJoints';
import { IslandsStage } from './islands';
import { TimeOfImpactStage } from './timeOfImpact';
import { PenetrationStage } from './penetration';
import type { TimeOfImpactInputs } from './timeOfImpact';
import type { IslandInputs } from './islands';
import {
  COLOUR_CAP,
  CONSTRAINT_VEC4,
  FUSED_SOLVER_ITEMS,
  ISLAND_WORDS,
  SV,
  SV_INDIRECT_WORDS,
  SV_READBACK_WORDS,
  SV_STATE_WORDS,
  TAIL_COLOUR_ITEMS,
  USAGE,
} from '../device/layout';
import type { GpuWorld } from '../world/world';

/** The label of the read-backs for tests and tools (readBuffer). */
const DEBUG_READ = 'solver debug read';

/**
 * The leading colours of at least TAIL_COLOUR_ITEMS items in `items` (a step's items per colour,
 * read back): the colours that get a pass of their own; COLOUR_CAP when none were read back.
 */
function largeColours(items: readonly number[] | null): number {
  if (items === null) return COLOUR_CAP;
  let colours = 0;
  while (colours < COLOUR_CAP && items[colours] >= TAIL_COLOUR_ITEMS) ++colours;
  return colours;
}

/** The time step, as b2TimeStep carries it. */
export interface SolverStep {
  dt: number;
  /** dt x the previous step's 1 / dt (0 on a world's first step): scales the warm start. */
  dtRatio: number;
  velocityIterations: number;
  positionIterations: number;
  warmStarting: boolean;
  gravity: { x: number; y: number };
}

/** What the solver reads of the collision step being recorded. */
export interface SolverInputs {
  broadState: GPUBuffer;
  npState: GPUBuffer;
  solverList: GPUBuffer;
  contactRefs: GPUBuffer;
  /** This step's manifolds (the set the narrow phase writes in this submission). */
  manifolds: GPUBuffer;
  /** Contacts the narrow phase's buffers hold (a bound on the solver contacts). */
  contactCapacity: number;
  /** Solver contacts of the latest step whose counts are back; -1 before the first. */
  lastSolverCount: number;
  /** Items per colour of the latest step whose counts are back (NarrowPhaseResult.colourItems); null before the first, or when it did not solve. */
  lastColourItems: readonly number[] | null;
}

export interface GpuSolverOptions {
  /**
   * One workgroup runs the colouring rounds, the warm start and the velocity and position
   * iterations, each in one dispatch (the same bits as the per-colour passes). Default: when the
   * solver's items (the latest known solver contacts, or 3 per body slot before any is known, and
   * the joint slots) are at most FUSED_SOLVER_ITEMS.
   */
  fused?: boolean;
  /**
   * Colours with a pass of their own in the warm start and each velocity and position iteration
   * when not fused (0 to COLOUR_CAP); the tail pass solves the rest, so any value gives the same
   * bits. Default: the leading colours of at least TAIL_COLOUR_ITEMS items in the latest step read
   * back, COLOUR_CAP before one is back.
   */
  passColours?: number;
}

export interface SolverState {
  skipped: boolean;
  contacts: number;
  /** Joint slots coloured with the contacts (0 when skipped). */
  joints: number;
  positionIterations: number;
  positionSolved: boolean;
  /** First entry of each colour in the sorted list (COLOUR_CAP + 2 words, the last is the end). */
  colourStart: number[];
  /** The items were coloured this step (false: the last colouring was reused, colour.ts). */
  recoloured: boolean;
  /** Colours below COLOUR_CAP up to the last non-empty one (SV.COLOURS_USED). */
  coloursUsed: number;
}

/**
 * The GPU solver: its buffers and the stages GpuPipeline records.
 * @internal Advanced: exported for tools, benchmarks and tests; applications use WebGPUBackend
 * through b2World.SetBackend (docs/GPU.md, "The world API on the GPU").
 */
export class GpuSolver {
  readonly ctx: GpuContext;
  /** Solver state words (layout.ts SV). */
  readonly state: GPUBuffer;
  /** Indirect sizes (layout.ts SV_ARGS). */
  readonly indirect: GPUBuffer;
  private readonly params: Uniform;
  private readonly fusedOption: boolean | undefined;
  private readonly passColoursOption: number | undefined;
  private lastSolverCount = -1;
  /** passColours by default: from the latest colour sizes read back (bindStep). */
  private learnedPassColours = COLOUR_CAP;
  /** ColourParams per colour / round: colour c. */
  private readonly colourParams: Uniform[] = [];
  private readonly contactBodiesArray: GpuArray;
  private readonly constraintArray: GpuArray;
  private readonly integrateVelocities: IntegrateVelocitiesStage;
  private readonly prepare: PrepareContactsStage;
  readonly colouring: ColourStage;
  private readonly warmStart: WarmStartStage;
  private readonly solveVelocity: SolveVelocityStage;
  private readonly storeImpulses: StoreImpulsesStage;
  private readonly integratePositions: IntegratePositionsStage;
  private readonly solvePosition: SolvePositionStage;
  private readonly joints: SolveJointsStage;
  readonly islands: IslandsStage;
  readonly timeOfImpact: TimeOfImpactStage;
  private readonly penetration: PenetrationStage;
  private readonly step: SolverStep = { dt: 0, dtRatio: 0, velocityIterations: 8, positionIterations: 3, warmStarting: true, gravity: { x: 0, y: 0 } };
  // The step being recorded (bindStep): filled in place so that recording allocates nothing.
  private mirror: GpuWorld | null = null;
  private readonly colourIo: ColourInputs;
  private readonly passIo: ColourPassInputs;
  private readonly prepareIo: PrepareInputs;
  private readonly islandIo: IslandInputs;
  private readonly toiIo: TimeOfImpactInputs;

  constructor(ctx: GpuContext, options: GpuSolverOptions = {}) {
    this.ctx = ctx;
    this.fusedOption = options.fused;
    if (options.passColours !== undefined && !(Number.isInteger(options.passColours) && options.passColours >= 0 && options.passColours <= COLOUR_CAP))
      throw new RangeError(`GpuSolverOptions.passColours: an integer from 0 to ${COLOUR_CAP}, got ${options.passColours}`);
    this.passColoursOption = options.passColours;
    this.state = ctx.createBuffer('solver state', 4 * SV_STATE_WORDS, USAGE.STORAGE | USAGE.COPY_SRC | USAGE.COPY_DST);
    this.indirect = ctx.createBuffer('solver indirect', 4 * SV_INDIRECT_WORDS, USAGE.STORAGE | USAGE.INDIRECT | USAGE.COPY_DST);
    this.params = new Uniform(ctx, 'solver params', 12);
    for (let c = 0; c <= COLOUR_CAP; ++c) {
      const u = new Uniform(ctx, `solver colour ${c}`, 4);
      u.u32[0] = c;
      u.upload();
      this.colourParams.push(u);
    }
    this.contactBodiesArray = new GpuArray(ctx, 'solver contact bodies', 16, 64);
    this.constraintArray = new GpuArray(ctx, 'solver constraints', 16 * CONSTRAINT_VEC4, 64);
    this.integrateVelocities = new IntegrateVelocitiesStage(ctx);
    this.prepare = new PrepareContactsStage(ctx);
    this.colouring = new ColourStage(ctx);
    this.warmStart = new WarmStartStage(ctx);
    this.solveVelocity = new SolveVelocityStage(ctx);
    this.storeImpulses = new StoreImpulsesStage(ctx);
    this.integratePositions = new IntegratePositionsStage(ctx);
    this.solvePosition = new SolvePositionStage(ctx);
    this.joints = new SolveJointsStage(ctx);
    this.islands = new IslandsStage(ctx);
    this.timeOfImpact = new TimeOfImpactStage(ctx);
    this.penetration = new PenetrationStage(ctx);
    const placeholder = this.state;
    this.colourIo = {
      broadState: placeholder,
      npState: placeholder,
      solverState: this.state,
      solverIndirect: this.indirect,
      contactBodies: this.contactBodiesArray.buffer,
      params: this.params.buffer,
      jointBodies: this.joints.bodies,
      rounds: this.colourParams,
    };
    this.passIo = {
      solverState: this.state,
      solverIndirect: this.indirect,
      colourKeys: this.colouring.keys.buffer,
      contactBodies: this.contactBodiesArray.buffer,
      constraints: this.constraintArray.buffer,
      params: this.params.buffer,
      jointBodies: this.joints.bodies,
      jointConstraints: this.joints.constraints,
      jointParams: placeholder,
      colours: this.colourParams,
    };
    this.prepareIo = {
      params: this.params.buffer,
      solverState: this.state,
      solverIndirect: this.indirect,
      solverList: placeholder,
      contactRefs: placeholder,
      manifolds: placeholder,
      contactBodies: this.contactBodiesArray.buffer,
      constraints: this.constraintArray.buffer,
    };
    this.islandIo = {
      solverState: this.state,
      solverIndirect: this.indirect,
      npState: placeholder,
      contactRefs: placeholder,
      manifolds: placeholder,
      solverList: placeholder,
      contactCapacity: 0,
    };
    this.toiIo = { solverState: this.state, npState: placeholder, contactRefs: placeholder };
  }

  /** Solver contact records per solver contact k (body A, body B, flags, contact index). */
  get contactBodies(): GPUBuffer {
    return this.contactBodiesArray.buffer;
  }

  /** Sets the time step of the steps recorded from now on (uploaded when it changed). */
  configure(step: SolverStep, mirror: GpuWorld): void {
    const own = this.step;
    own.dt = step.dt;
    own.dtRatio = step.dtRatio;
    own.velocityIterations = step.velocityIterations;
    own.positionIterations = step.positionIterations;
    own.warmStarting = step.warmStarting;
    own.gravity.x = step.gravity.x;
    own.gravity.y = step.gravity.y;
    const u = this.params;
    u.f32[0] = step.dt;
    u.f32[1] = step.dtRatio;
    u.f32[2] = step.gravity.x;
    u.f32[3] = step.gravity.y;
    u.f32[4] = mirror.cellSize;
    u.u32[5] = step.warmStarting ? 1 : 0;
    u.u32[6] = mirror.bodySlotCount;
    u.u32[7] = mirror.jointSlotCount;
    u.u32[8] = step.velocityIterations;
    u.u32[9] = step.positionIterations;
    u.upload();
    this.islands.configure(step.dt, mirror);
  }

  /**
   * Names the buffers the stages recorded next read: the collision step's outputs (`io`) and the
   * mirror's tables; makes room for its contacts and joints. Before encodeIslands().
   */
  bindStep(mirror: GpuWorld, io: SolverInputs): void {
    const contacts = Math.max(1, io.contactCapacity);
    this.contactBodiesArray.ensure(contacts);
    this.constraintArray.ensure(contacts);
    this.colouring.reserve(contacts + mirror.jointSlotCount, Math.max(1, mirror.bodySlotCount));
    this.joints.reserve(mirror);
    this.mirror = mirror;
    const c = this.colourIo;
    c.broadState = io.broadState;
    c.npState = io.npState;
    c.contactBodies = this.contactBodiesArray.buffer;
    c.jointBodies = this.joints.bodies;
    const v = this.passIo;
    v.colourKeys = this.colouring.keys.buffer;
    v.contactBodies = this.contactBodiesArray.buffer;
    v.constraints = this.constraintArray.buffer;
    v.jointBodies = this.joints.bodies;
    v.jointConstraints = this.joints.constraints;
    v.jointParams = mirror.jointParams.buffer;
    const p = this.prepareIo;
    p.solverList = io.solverList;
    p.contactRefs = io.contactRefs;
    p.manifolds = io.manifolds;
    p.contactBodies = this.contactBodiesArray.buffer;
    p.constraints = this.constraintArray.buffer;
    const s = this.islandIo;
    s.npState = io.npState;
    s.contactRefs = io.contactRefs;
    s.manifolds = io.manifolds;
    s.solverList = io.solverList;
    s.contactCapacity = io.contactCapacity;
    this.lastSolverCount = io.lastSolverCount;
    this.learnedPassColours = largeColours(io.lastColourItems);
    this.toiIo.npState = io.npState;
    this.toiIo.contactRefs = io.contactRefs;
  }

  /** GpuStage.Islands: the solver state (skipped when collision overflowed), wake-ups, islands. */
  readonly encodeIslands = (rec: Recorder): void => {
    this.colouring.encodeBegin(rec, this.colourIo);
    this.islands.encodeFind(rec, this.islandIo, this.mirror!);
  };

  /** GpuStage.Sleep. */
  readonly encodeSleep = (rec: Recorder): void => this.islands.encodeSleep(rec, this.state, this.mirror!);

  /** GpuStage.TimeOfImpact. */
  readonly encodeTimeOfImpact = (rec: Recorder): void => this.timeOfImpact.encode(rec, this.toiIo, this.mirror!);

  /** GpuStage.Penetration. */
  readonly encodePenetration = (rec: Recorder): void => this.penetration.encode(rec, this.prepareIo, this.mirror!);

  /** GpuStage.IntegrateVelocities. */
  readonly encodeIntegrateVelocities = (rec: Recorder): void => {
    this.integrateVelocities.encode(rec, this.params.buffer, this.state, this.mirror!);
  };

  /** GpuStage.Prepare: contacts, then joints. */
  readonly encodePrepare = (rec: Recorder): void => {
    this.prepare.encode(rec, this.prepareIo, this.mirror!);
    this.joints.encodePrepare(rec, this.params.buffer, this.mirror!);
  };

  /**
   * Whether the step being recorded runs the fused passes (GpuSolverOptions.fused). Both ways give
   * the same bits, so the choice may follow counts read back a few steps late.
   */
  get fused(): boolean {
    if (this.fusedOption !== undefined) return this.fusedOption;
    const mirror = this.mirror!;
    const contacts = this.lastSolverCount >= 0 ? this.lastSolverCount : 3 * mirror.bodySlotCount;
    return contacts + mirror.jointSlotCount <= FUSED_SOLVER_ITEMS;
  }

  /**
   * Colours the step being recorded gives a pass of their own when not fused
   * (GpuSolverOptions.passColours): the leading colours of at least TAIL_COLOUR_ITEMS items in the
   * latest step read back, COLOUR_CAP before one is back; the tail pass walks the others. Any value
   * gives the same bits, so it may follow sizes read back a few steps late.
   */
  get passColours(): number {
    return this.passColoursOption ?? this.learnedPassColours;
  }

  /** GpuStage.Colour. */
  readonly encodeColour = (rec: Recorder): void => this.colouring.encode(rec, this.colourIo, this.fused);

  /** GpuStage.Velocity: warm start, velocity iterations, impulses stored, positions integrated. */
  readonly encodeVelocity = (rec: Recorder): void => {
    const mirror = this.mirror!;
    // Joints need the pass without warm starting too: the mouse joint damps its body there.
    const fused = this.fused;
    if (this.step.warmStarting || mirror.jointSlotCount > 0) {
      if (fused) this.warmStart.encodeFused(rec, this.passIo, mirror.bodyVel.buffer);
      else this.warmStart.encode(rec, this.passIo, mirror.bodyVel.buffer, this.passColours);
    }
    if (fused) this.solveVelocity.encodeFused(rec, this.passIo, mirror.bodyVel.buffer);
    else this.solveVelocity.encode(rec, this.passIo, mirror.bodyVel.buffer, this.step.velocityIterations, this.passColours);
    this.storeImpulses.encode(rec, this.state, this.indirect, this.contactBodiesArray.buffer, this.constraintArray.buffer, this.prepareIo.manifolds);
    this.joints.encodeStore(rec, this.params.buffer, this.state, mirror);
    this.integratePositions.encodeIntegrate(rec, this.params.buffer, this.state, mirror);
  };

  /** GpuStage.Position: position iterations, then the transforms from the sweeps. */
  readonly encodePosition = (rec: Recorder): void => {
    const mirror = this.mirror!;
    if (this.fused) this.solvePosition.encodeFused(rec, this.passIo, mirror.bodySweep.buffer);
    else this.solvePosition.encode(rec, this.passIo, mirror.bodySweep.buffer, this.step.positionIterations, this.passColours);
    this.integratePositions.encodeSynchronize(rec, this.params.buffer, this.state, mirror);
  };

  /**
   * Copies the step's SV.COLOUR_START .. SV.AWAKE words (SV_READBACK_WORDS) into `dst` at
   * `offset`: the pipeline's read-back, whose colour sizes set the next steps' passColours, the
   * step's penetration and the bodies it left awake.
   */
  encodeStateCopy(encoder: GPUCommandEncoder, dst: GPUBuffer, offset: number): void {
    encoder.copyBufferToBuffer(this.state, 4 * SV.COLOUR_START, dst, offset, 4 * SV_READBACK_WORDS);
  }

  // ---- Read-back for tests and tools (not part of a step) ----

  /** The solver state of the last step. */
  async readState(): Promise<SolverState> {
    const w = new Uint32Array(await readBuffer(this.ctx, this.state, 4 * SV_STATE_WORDS, DEBUG_READ));
    return {
      skipped: w[SV.SKIP] !== 0,
      contacts: w[SV.COUNT],
      joints: w[SV.ITEMS] - w[SV.COUNT],
      positionIterations: w[SV.POSITION_ITERATIONS],
      positionSolved: w[SV.POSITION_DONE] !== 0,
      colourStart: Array.from(w.subarray(SV.COLOUR_START, SV.COLOUR_START + COLOUR_CAP + 2)),
      recoloured: w[SV.COLOUR_CHANGED] !== 0,
      coloursUsed: w[SV.COLOURS_USED],
    };
  }

  /**
   * The last step's colouring: per item (joint slots 0 .. joints - 1, then solver contact k as
   * item joints + k) its colour (COLOUR_CAP: overflow set), the contacts' records (contactBodies),
   * the joints' (jointBodies: bodies A, B, C, D | type, dynamic mask, solved, limit state), and
   * the sorted colour list.
   */
  async readColouring(): Promise<{
    joints: number;
    colours: Uint32Array;
    bodies: Uint32Array;
    jointBodies: Uint32Array;
    keys: Uint32Array;
    state: SolverState;
  }> {
    const state = await this.readState();
    const joints = state.joints;
    const n = state.contacts;
    const items = joints + n;
    const read = async (buffer: GPUBuffer, bytes: number): Promise<Uint32Array> =>
      bytes === 0 ? new Uint32Array(0) : new Uint32Array(await readBuffer(this.ctx, buffer, bytes, DEBUG_READ));
    return {
      joints,
      colours: await read(this.colouring.colours.buffer, 4 * items),
      bodies: await read(this.contactBodiesArray.buffer, 16 * n),
      jointBodies: await read(this.joints.bodies, 32 * joints),
      keys: await read(this.colouring.keys.buffer, 8 * items),
      state,
    };
  }

  /**
   * The last step's islands: per body slot its island's label (the island's smallest body slot),
   * NO_ISLAND for static, inactive and dead bodies.
   */
  async readIslands(bodySlots: number): Promise<Uint32Array> {
    const words = new Uint32Array(await readBuffer(this.ctx, this.islands.labels.buffer, 4 * ISLAND_WORDS * bodySlots, DEBUG_READ));
    return Uint32Array.from({ length: bodySlots }, (_, i) => words[ISLAND_WORDS * i]);
  }

  destroy(): void {
    this.state.destroy();
    this.indirect.destroy();
    this.params.destroy();
    for (const u of this.colourParams) u.destroy();
    this.contactBodiesArray.destroy();
    this.constraintArray.destroy();
    this.colouring.destroy();
    this.joints.destroy();
    this.islands.destroy();
    this.timeOfImpact.destroy();
  }
}
