/*
 * The GPU graph colouring (src-gpu/solver/colour.ts) of joints and contacts together, on a pyramid of
 * boxes, on a plate carrying more circles than there are colours, on a 10 x 10 joint grid with
 * contacts, on gear joints (four bodies) and on a hub holding more joints than there are colours:
 * every item (joint slot or solver contact) gets exactly one colour or the overflow set, no two
 * items of a colour share a dynamic body, static bodies block nothing, the colour lists are the
 * items sorted by (colour, item) (a colour's joints, then its contacts), the overflow set is solved
 * (not dropped: contacts keep their circles on the plate, joints keep their lengths), and the
 * colouring and the solved bodies are the same bits run to run. The colours equal a CPU
 * Jones-Plassmann over the same items every step, whether the GPU coloured them again or reused
 * the last colouring (it reuses it while every item keeps its dynamic bodies, colours again when
 * one changes or when its buffers were replaced). The fused passes (one workgroup) and the tail
 * pass that solves the colours past passColours give the bits of a pass per colour, whatever
 * passColours is, and passColours follows the colour sizes read back (the leading colours of at
 * least TAIL_COLOUR_ITEMS items), also across a step whose colouring changes.
 */

import { expect, it } from 'vitest';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2Joint } from '../../src/dynamics/joints/b2Joint';
import { b2DistanceJointDef } from '../../src/dynamics/joints/b2DistanceJoint';
import type { b2DistanceJoint } from '../../src/dynamics/joints/b2DistanceJoint';
import { b2GearJointDef } from '../../src/dynamics/joints/b2GearJoint';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { b2World } from '../../src/dynamics/b2World';
import { COLOUR_CAP, COLOUR_IDLE, FUSED_SOLVER_ITEMS, TAIL_COLOUR_ITEMS } from '../../src-gpu/device/layout';
import type { GpuSolverOptions } from '../../src-gpu/solver/solver';
import { GpuStepper } from '../../src-gpu/stepper';
import { describeGpu } from './support';

const DT = 1 / 60;
const CB_DYNAMIC_A = 0x100;
const CB_DYNAMIC_B = 0x200;

function ground(world: b2World, halfWidth = 40): void {
  const body = world.CreateBody(new b2BodyDef());
  const box = new b2PolygonShape();
  box.SetAsBox(halfWidth, 1, new b2Vec2(0, -1), 0);
  body.CreateFixture(box, 0);
}

/** A pyramid of unit boxes on the ground, centred on x. */
function addPyramid(world: b2World, rows: number, x = 0): void {
  const shape = new b2PolygonShape();
  shape.SetAsBox(0.5, 0.5);
  for (let row = 0; row < rows; ++row) {
    for (let i = 0; i < rows - row; ++i) {
      const def = new b2BodyDef();
      def.type = b2_dynamicBody;
      def.position.Set(x - rows / 2 + i + 0.5 * row + 0.5, 0.5 + row);
      world.CreateBody(def).CreateFixture(shape, 1);
    }
  }
}

function pyramid(rows: number): b2World {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  ground(world);
  addPyramid(world, rows);
  return world;
}

/** `count` pyramids of 20 rows, 22 m apart (bench/gpu-step.ts's layout), the first at x = 22 `first`. */
function addPyramids(world: b2World, count: number, first = 0): void {
  for (let k = first; k < first + count; ++k) addPyramid(world, 20, 22 * k);
}

/** A wide plate on the ground with `n` circles resting on it: every contact shares the plate. */
function crowdedPlate(n: number): b2World {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  ground(world);
  const plateDef = new b2BodyDef();
  plateDef.type = b2_dynamicBody;
  plateDef.position.Set(0, 0.25);
  const plateShape = new b2PolygonShape();
  plateShape.SetAsBox(n * 0.25 + 1, 0.25);
  world.CreateBody(plateDef).CreateFixture(plateShape, 1);
  const circle = new b2CircleShape();
  circle.m_radius = 0.2;
  for (let i = 0; i < n; ++i) {
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(-n * 0.25 + 0.5 * i + 0.25, 0.7);
    const fd = new b2FixtureDef();
    fd.shape = circle;
    fd.density = 1;
    world.CreateBody(def).CreateFixture(fd);
  }
  return world;
}

/**
 * Joints and contacts on the same bodies: a revolute chain of 12 boxes lying on the ground (each
 * box: two joints and its ground contact), and two gears (four bodies each: their discs and the
 * discs' revolute joints to a dynamic carrier hung from the ground).
 */
function jointsAndContacts(): b2World {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  ground(world);
  const groundBody = world.m_bodyList!;
  const shape = new b2PolygonShape();
  shape.SetAsBox(0.5, 0.25);
  let previous: b2Body | null = null;
  for (let i = 0; i < 12; ++i) {
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(-6 + i, 0.25);
    const body = world.CreateBody(def);
    body.CreateFixture(shape, 1);
    if (previous) {
      const jd = new b2RevoluteJointDef();
      jd.Initialize(previous, body, new b2Vec2(-6.5 + i, 0.25));
      world.CreateJoint(jd);
    }
    previous = body;
  }
  const carrierDef = new b2BodyDef();
  carrierDef.type = b2_dynamicBody;
  carrierDef.position.Set(0, 8);
  const carrier = world.CreateBody(carrierDef);
  const plank = new b2PolygonShape();
  plank.SetAsBox(3, 0.1);
  carrier.CreateFixture(plank, 1);
  const hang = new b2RevoluteJointDef();
  hang.Initialize(groundBody, carrier, new b2Vec2(0, 8));
  world.CreateJoint(hang);
  const circle = new b2CircleShape();
  circle.m_radius = 0.5;
  for (const x of [-2, 2]) {
    const discs: b2Joint[] = [];
    for (const dx of [-0.5, 0.5]) {
      const def = new b2BodyDef();
      def.type = b2_dynamicBody;
      def.position.Set(x + dx, 9);
      const fd = new b2FixtureDef();
      fd.shape = circle;
      fd.density = 1;
      fd.filter.groupIndex = -1;
      const disc = world.CreateBody(def);
      disc.CreateFixture(fd);
      const jd = new b2RevoluteJointDef();
      jd.Initialize(carrier, disc, disc.GetPosition());
      discs.push(world.CreateJoint(jd));
    }
    const gear = new b2GearJointDef();
    gear.bodyA = discs[0].m_bodyB;
    gear.bodyB = discs[1].m_bodyB;
    gear.joint1 = discs[0];
    gear.joint2 = discs[1];
    gear.ratio = 2;
    world.CreateJoint(gear);
  }
  return world;
}

/** A dynamic hub hung from the ground with `n` balls on distance joints around it: n + 1 joints on one body. */
function hub(n: number): b2World {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetAllowSleeping(false);
  ground(world);
  const groundBody = world.m_bodyList!;
  const hubDef = new b2BodyDef();
  hubDef.type = b2_dynamicBody;
  hubDef.position.Set(0, 10);
  const centre = world.CreateBody(hubDef);
  const core = new b2CircleShape();
  core.m_radius = 0.5;
  centre.CreateFixture(core, 5);
  const pin = new b2RevoluteJointDef();
  pin.Initialize(groundBody, centre, new b2Vec2(0, 10));
  world.CreateJoint(pin);
  const ball = new b2CircleShape();
  ball.m_radius = 0.1;
  for (let i = 0; i < n; ++i) {
    const angle = (2 * Math.PI * i) / n;
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(3 * Math.cos(angle), 10 + 3 * Math.sin(angle));
    const fd = new b2FixtureDef();
    fd.shape = ball;
    fd.density = 1;
    fd.filter.groupIndex = -1;
    const body = world.CreateBody(def);
    body.CreateFixture(fd);
    const jd = new b2DistanceJointDef();
    jd.Initialize(centre, body, centre.GetPosition(), body.GetPosition());
    world.CreateJoint(jd);
  }
  return world;
}

interface Colouring {
  /** Joint slots: items 0 .. joints - 1; solver contact k is item joints + k. */
  joints: number;
  colours: Uint32Array;
  bodies: Uint32Array;
  jointBodies: Uint32Array;
  keys: Uint32Array;
  colourStart: number[];
}

/** An item's bodies, each with whether it is dynamic (written by the solver). */
function itemBodies(c: Colouring, item: number): [number, boolean][] {
  if (item < c.joints) {
    const mask = c.jointBodies[8 * item + 5];
    const out: [number, boolean][] = [];
    for (let n = 0; n < 4; ++n) if (c.jointBodies[8 * item + n] !== 0xffffffff) out.push([c.jointBodies[8 * item + n], (mask & (1 << n)) !== 0]);
    return out;
  }
  const k = item - c.joints;
  const flags = c.bodies[4 * k + 2];
  return [
    [c.bodies[4 * k], (flags & CB_DYNAMIC_A) !== 0],
    [c.bodies[4 * k + 1], (flags & CB_DYNAMIC_B) !== 0],
  ];
}

function checkColouring(c: Colouring, label: string): { overflow: number; overflowJoints: number; sharedStatic: boolean; used: number } {
  const n = c.colours.length;
  // Exactly one colour (or the overflow set) per item with a dynamic body; COLOUR_IDLE for the others.
  for (let k = 0; k < n; ++k) {
    const solved = itemBodies(c, k).some(([, dynamic]) => dynamic);
    if (solved) expect(c.colours[k], `${label}: item ${k}`).toBeLessThanOrEqual(COLOUR_CAP);
    else expect(c.colours[k], `${label}: item ${k} without a dynamic body`).toBe(COLOUR_IDLE);
  }
  // The lists: (colour, k) sorted by colour then k, each contact once, and the starts agree.
  const seen = new Uint8Array(n);
  for (let e = 0; e < n; ++e) {
    const colour = c.keys[2 * e];
    const k = c.keys[2 * e + 1];
    expect(colour, `${label}: entry ${e}`).toBe(c.colours[k]);
    expect(seen[k], `${label}: contact ${k} listed twice`).toBe(0);
    seen[k] = 1;
    if (e > 0) {
      const before = c.keys[2 * e - 2] * 2 ** 32 + c.keys[2 * e - 1];
      expect(colour * 2 ** 32 + k, `${label}: entry ${e} out of order`).toBeGreaterThan(before);
    }
  }
  for (let colour = 0; colour <= COLOUR_CAP + 1; ++colour) {
    let first = 0;
    while (first < n && c.keys[2 * first] < colour) first++;
    expect(c.colourStart[colour], `${label}: start of colour ${colour}`).toBe(first);
  }
  // No two items of one colour share a dynamic body; static ones may be shared.
  let sharedStatic = false;
  let used = 0;
  for (let colour = 0; colour < COLOUR_CAP; ++colour) {
    const dynamicOwner = new Map<number, number>();
    const staticUsers = new Map<number, number>();
    let size = 0;
    for (let k = 0; k < n; ++k) {
      if (c.colours[k] !== colour) continue;
      size++;
      // A gear may name one body twice (its C and D): one item, one writer.
      for (const [body, dynamic] of itemBodies(c, k)) {
        if (dynamic) {
          const other = dynamicOwner.get(body);
          if (other !== undefined && other !== k) throw new Error(`${label}: items ${other} and ${k} of colour ${colour} share dynamic body ${body}`);
          dynamicOwner.set(body, k);
        } else {
          staticUsers.set(body, (staticUsers.get(body) ?? 0) + 1);
        }
      }
    }
    if (size > 0) used++;
    for (const count of staticUsers.values()) if (count > 1) sharedStatic = true;
  }
  let overflow = 0;
  let overflowJoints = 0;
  for (let k = 0; k < n; ++k) {
    if (c.colours[k] !== COLOUR_CAP) continue;
    overflow++;
    if (k < c.joints) overflowJoints++;
  }
  return { overflow, overflowJoints, sharedStatic, used };
}

/** colour.wgsl's priority: lowbias32 (C. Wellons). */
function priority(item: number): number {
  let x = item >>> 0;
  x ^= x >>> 16;
  x = Math.imul(x, 0x7feb352d) >>> 0;
  x ^= x >>> 15;
  x = Math.imul(x, 0x846ca68b) >>> 0;
  x ^= x >>> 16;
  return x >>> 0;
}

/** Jones-Plassmann as colour.wgsl states it, on the CPU: per round, local maxima of the priority. */
function referenceColours(c: Colouring): number[] {
  const n = c.colours.length;
  const colours = new Array<number>(n).fill(-1);
  const dynamicBodies = Array.from({ length: n }, (_, k) =>
    itemBodies(c, k)
      .filter(([, dynamic]) => dynamic)
      .map(([body]) => body),
  );
  for (let round = 0; round < COLOUR_CAP; ++round) {
    const best = new Map<number, number>();
    for (let k = 0; k < n; ++k) {
      if (colours[k] >= 0) continue;
      for (const body of dynamicBodies[k]) best.set(body, Math.max(best.get(body) ?? 0, priority(k)));
    }
    const winners: number[] = [];
    for (let k = 0; k < n; ++k) if (colours[k] < 0 && dynamicBodies[k].every((body) => best.get(body) === priority(k))) winners.push(k);
    for (const k of winners) colours[k] = round;
  }
  return colours.map((colour, k) => (dynamicBodies[k].length === 0 ? COLOUR_IDLE : colour < 0 ? COLOUR_CAP : colour));
}

type Ctx = Parameters<Parameters<typeof describeGpu>[1]>[0];

/** The bodies' transforms, angles and velocities, in body list order. */
function bodyState(world: b2World): number[] {
  const state: number[] = [];
  for (let b = world.m_bodyList; b; b = b.m_next)
    state.push(b.m_xf.p.x, b.m_xf.p.y, b.m_sweep.a, b.m_linearVelocity.x, b.m_linearVelocity.y, b.m_angularVelocity);
  return state;
}

async function colouringAfter(ctx: Ctx, build: () => b2World, steps: number, solver: GpuSolverOptions = {}) {
  const world = build();
  const stepper = new GpuStepper(ctx, world, { solver });
  let dispatches = 0;
  const positionIterations: number[] = [];
  for (let i = 0; i < steps; ++i) {
    dispatches = (await stepper.step(DT, 8, 3)).dispatches;
    positionIterations.push((await stepper.solver.readState()).positionIterations);
  }
  const c = await stepper.solver.readColouring();
  await stepper.readBodies();
  const state = bodyState(world);
  stepper.destroy();
  return {
    colouring: { joints: c.joints, colours: c.colours, bodies: c.bodies, jointBodies: c.jointBodies, keys: c.keys, colourStart: c.state.colourStart },
    state,
    world,
    dispatches,
    positionIterations,
  };
}

describeGpu('GPU solver: graph colouring', (ctx) => {
  it('colours a 12-row pyramid: one colour per contact, no shared dynamic body in a colour, ground shared, sorted lists', async () => {
    const { colouring } = await colouringAfter(ctx, () => pyramid(12), 5);
    expect(colouring.colours.length).toBeGreaterThan(100);
    const r = checkColouring(colouring, 'pyramid');
    console.log(`pyramid: ${colouring.colours.length} contacts, ${r.used} colours, ${r.overflow} in the overflow set`);
    expect(r.sharedStatic).toBe(true);
    expect(r.overflow).toBe(0);
  });

  it('puts what the colour cap cannot hold in the overflow set and solves it: 40 circles on one plate stay on it', async () => {
    const n = 40;
    const { colouring, world } = await colouringAfter(ctx, () => crowdedPlate(n), 60);
    const r = checkColouring(colouring, 'plate');
    console.log(`plate: ${colouring.colours.length} contacts, ${r.used} colours, ${r.overflow} in the overflow set`);
    // The n circle-plate contacts share the plate, so at most one per colour.
    expect(r.overflow).toBeGreaterThanOrEqual(n - COLOUR_CAP);
    // Solved, not dropped: after one second every circle still rests on the plate (its centre at
    // plate top + radius, within b2_linearSlop + 1 mm; a dropped contact would let its circle sink
    // through), and the plate is not in the ground (centre >= half height - slop - 1 mm).
    let plateY = 0;
    for (let b = world.m_bodyList; b; b = b.m_next) if (b.m_fixtureList!.m_shape.m_type === 2 && b.m_type === b2_dynamicBody) plateY = b.m_xf.p.y;
    expect(plateY).toBeGreaterThan(0.25 - 0.006);
    let circles = 0;
    for (let b = world.m_bodyList; b; b = b.m_next) {
      if (b.m_fixtureList!.m_shape.m_type !== 0) continue;
      circles++;
      expect(Math.abs(b.m_xf.p.y - (plateY + 0.25 + 0.2))).toBeLessThan(0.006);
    }
    expect(circles).toBe(n);
  }, 600_000);

  it('colours joints with the contacts: a chain lying on the ground and gears (four bodies) share no dynamic body in a colour', async () => {
    const { colouring } = await colouringAfter(ctx, jointsAndContacts, 10);
    const r = checkColouring(colouring, 'joints and contacts');
    // 11 chain joints + 1 hanger + 4 disc revolutes + 2 gears.
    expect(colouring.joints).toBe(18);
    expect(colouring.colours.length - colouring.joints).toBeGreaterThanOrEqual(12);
    console.log(
      `joints and contacts: ${colouring.joints} joints, ${colouring.colours.length - colouring.joints} contacts, ${r.used} colours, ${r.overflow} in the overflow set`,
    );
    expect(r.overflow).toBe(0);
    // Colours mix joints and contacts (the lists put a colour's joints first).
    let mixed = false;
    for (let colour = 0; colour < COLOUR_CAP; ++colour) {
      let j = 0;
      let k = 0;
      colouring.colours.forEach((c, item) => {
        if (c === colour) item < colouring.joints ? j++ : k++;
      });
      mixed ||= j > 0 && k > 0;
    }
    expect(mixed).toBe(true);
  }, 600_000);

  it('puts joints the colour cap cannot hold in the overflow set and solves them: 40 distance joints on one hub keep their lengths', async () => {
    const n = 40;
    const { colouring, world } = await colouringAfter(ctx, () => hub(n), 30);
    const r = checkColouring(colouring, 'hub');
    console.log(`hub: ${colouring.joints} joints, ${r.used} colours, ${r.overflowJoints} joints in the overflow set`);
    // n + 1 joints share the hub: at most one per colour.
    expect(r.overflowJoints).toBeGreaterThanOrEqual(n + 1 - COLOUR_CAP);
    // Solved, not dropped: after half a second of swinging under gravity every ball is at its rest
    // length from the hub within 1 cm (a dropped joint lets its ball fall freely: 1.2 m).
    let worst = 0;
    for (let j = world.m_jointList; j; j = j.m_next) {
      if (j.m_type !== 3) continue;
      const a = j.GetAnchorA(new b2Vec2());
      const b = j.GetAnchorB(new b2Vec2());
      worst = Math.max(worst, Math.abs(Math.hypot(a.x - b.x, a.y - b.y) - (j as b2DistanceJoint).m_length));
    }
    console.log(`hub: largest length error ${worst.toExponential(2)} m`);
    expect(worst).toBeLessThan(0.01);
  }, 600_000);

  it('reuses the colouring while the pile keeps its contacts and colours again when they change, each step equal to a CPU Jones-Plassmann', async () => {
    const world = pyramid(8);
    const stepper = new GpuStepper(ctx, world);
    const reused: boolean[] = [];
    const check = async (label: string) => {
      const c = await stepper.solver.readColouring();
      const colouring = { joints: c.joints, colours: c.colours, bodies: c.bodies, jointBodies: c.jointBodies, keys: c.keys, colourStart: c.state.colourStart };
      checkColouring(colouring, label);
      expect(Array.from(c.colours), label).toEqual(referenceColours(colouring));
      return c.state.recoloured;
    };
    for (let i = 0; i < 40; ++i) {
      await stepper.step(DT, 8, 3);
      reused.push(!(await check(`step ${i}`)));
    }
    // The first step colours; once the pyramid rests its contact list stops changing.
    expect(reused[0]).toBe(false);
    const reusedCount = reused.filter(Boolean).length;
    console.log(`pyramid of 8 rows: colouring reused in ${reusedCount} of ${reused.length} steps`);
    expect(reusedCount).toBeGreaterThan(20);
    expect(reused.slice(-5)).toEqual([true, true, true, true, true]);

    // A box lifted off the top ends its contacts: the items change, so the GPU colours again.
    await stepper.readBodies();
    let top = world.m_bodyList!;
    for (let b = world.m_bodyList; b; b = b.m_next) if (b.m_xf.p.y > top.m_xf.p.y) top = b;
    top.SetTransform(new b2Vec2(top.m_xf.p.x + 20, 10), 0);
    await stepper.step(DT, 8, 3);
    expect(await check('after the lift')).toBe(true);
    await stepper.step(DT, 8, 3);
    expect(await check('the step after')).toBe(false);

    // Buffers replaced on the host (room for more items): the last colouring is gone, colour again.
    stepper.solver.colouring.reserve(4 * (await stepper.solver.readState()).contacts + 1024, world.GetBodyCount());
    await stepper.step(DT, 8, 3);
    expect(await check('after the buffers grew')).toBe(true);
    stepper.destroy();
  }, 600_000);

  it('gives the same colours, lists and solved bodies, bit for bit, run to run (contacts, and joints with contacts)', async () => {
    const jointsFirst = await colouringAfter(ctx, jointsAndContacts, 10);
    const jointsSecond = await colouringAfter(ctx, jointsAndContacts, 10);
    expect(Array.from(jointsSecond.colouring.colours)).toEqual(Array.from(jointsFirst.colouring.colours));
    expect(Array.from(jointsSecond.colouring.keys)).toEqual(Array.from(jointsFirst.colouring.keys));
    expect(jointsSecond.state).toEqual(jointsFirst.state);
    const first = await colouringAfter(ctx, () => pyramid(10), 20);
    const second = await colouringAfter(ctx, () => pyramid(10), 20);
    expect(Array.from(second.colouring.colours)).toEqual(Array.from(first.colouring.colours));
    expect(Array.from(second.colouring.keys)).toEqual(Array.from(first.colouring.keys));
    expect(second.state).toEqual(first.state);
  }, 600_000);

  // Scenes whose passes the fused and tail walks must reproduce: contacts, joints, the overflow set.
  const PASS_SCENES: [string, () => b2World][] = [
    ['pyramid', () => pyramid(10)],
    ['joints and contacts', jointsAndContacts],
    ['40 circles on a plate (overflow set)', () => crowdedPlate(40)],
    ['40 joints on a hub (overflow set)', () => hub(40)],
  ];
  // The rounds (2 COLOUR_CAP + 1), warm start (COLOUR_CAP + 1), velocity (8 (COLOUR_CAP + 1)) and
  // position (3 (COLOUR_CAP + 2)) passes with a pass for every colour become four dispatches.
  const FUSED_SAVES = 2 * COLOUR_CAP + 1 + 9 * (COLOUR_CAP + 1) + 3 * (COLOUR_CAP + 2) - 4;

  it('solves a small world in one dispatch per solver pass (fused) to the bits of the per-colour passes: contacts, joints, the overflow set, the early exit', async () => {
    for (const [label, build] of PASS_SCENES) {
      const passes = await colouringAfter(ctx, build, 12, { fused: false, passColours: COLOUR_CAP });
      const fused = await colouringAfter(ctx, build, 12, { fused: true });
      expect(Array.from(fused.colouring.colours), label).toEqual(Array.from(passes.colouring.colours));
      expect(Array.from(fused.colouring.keys), label).toEqual(Array.from(passes.colouring.keys));
      expect(fused.state, label).toEqual(passes.state);
      expect(fused.positionIterations, label).toEqual(passes.positionIterations);
      expect(passes.dispatches - fused.dispatches, label).toBe(FUSED_SAVES);
    }
    // Unless told otherwise, up to FUSED_SOLVER_ITEMS contacts and joints take the fused passes:
    // before any count is back, 3 contacts a body are assumed.
    const byDefault = await colouringAfter(ctx, () => pyramid(10), 1);
    const fused = await colouringAfter(ctx, () => pyramid(10), 1, { fused: true });
    expect(byDefault.dispatches).toBe(fused.dispatches);
    const apart = (): b2World => {
      const world = new b2World(new b2Vec2(0, -10));
      const circle = new b2CircleShape();
      circle.m_radius = 0.25;
      const bodies = Math.ceil(FUSED_SOLVER_ITEMS / 3) + 1;
      for (let i = 0; i < bodies; ++i) {
        const def = new b2BodyDef();
        def.type = b2_dynamicBody;
        def.position.Set(i % 64, Math.floor(i / 64));
        world.CreateBody(def).CreateFixture(circle, 1);
      }
      return world;
    };
    const twoSteps = async (fusedOption?: boolean): Promise<number[]> => {
      const stepper = new GpuStepper(ctx, apart(), { solver: { fused: fusedOption } });
      const out = [(await stepper.step(DT, 8, 3)).dispatches, (await stepper.step(DT, 8, 3)).dispatches];
      stepper.destroy();
      return out;
    };
    const [first, second] = await twoSteps();
    expect(first, 'per-colour passes first').toBe((await twoSteps(false))[0]);
    expect(second, 'fused once no contact is known to touch').toBe((await twoSteps(true))[1]);
  }, 600_000);
  // Dispatches a colour's pass of its own costs a step: the warm start and each velocity and
  // position iteration (8 and 3 here) record one per colour below passColours, then the tail.
  const PASSES_PER_COLOUR = 1 + 8 + 3;

  it('solves the colours past passColours in one tail pass to the bits of a pass per colour: contacts, joints, the overflow set, the early exit', async () => {
    for (const [label, build] of PASS_SCENES) {
      const all = await colouringAfter(ctx, build, 12, { fused: false, passColours: COLOUR_CAP });
      for (const passColours of [0, 2]) {
        const few = await colouringAfter(ctx, build, 12, { fused: false, passColours });
        const what = `${label}, passColours ${passColours}`;
        expect(Array.from(few.colouring.colours), what).toEqual(Array.from(all.colouring.colours));
        expect(few.state, what).toEqual(all.state);
        expect(few.positionIterations, what).toEqual(all.positionIterations);
        expect(all.dispatches - few.dispatches, what).toBe((COLOUR_CAP - passColours) * PASSES_PER_COLOUR);
      }
    }
  }, 600_000);

  /** Items per colour (the overflow set last) from a solver state's colour starts. */
  const itemsPerColour = (colourStart: number[]): number[] => colourStart.slice(1).map((end, c) => end - colourStart[c]);
  /** The colours of a pass of their own after a step with these items per colour: the leading ones of at least TAIL_COLOUR_ITEMS. */
  const largeColours = (items: number[]): number => {
    const small = items.slice(0, COLOUR_CAP).findIndex((n) => n < TAIL_COLOUR_ITEMS);
    return small < 0 ? COLOUR_CAP : small;
  };

  type Step = {
    dispatches: number;
    passColours: number;
    items: number[];
    coloursUsed: number;
    recoloured: boolean;
    readBack: number[] | null;
    readBackUsed: number;
  };

  it('records a pass for each leading colour of at least TAIL_COLOUR_ITEMS items in the latest read-back step, every colour before one is back, to the bits of a pass per colour as the colouring changes', async () => {
    // Five pyramids of 20 rows, then at step 3 five more: the colouring changes and its colours
    // grow past TAIL_COLOUR_ITEMS.
    const run = async (passColours?: number) => {
      const world = new b2World(new b2Vec2(0, -10));
      world.SetAllowSleeping(false);
      ground(world, 230);
      addPyramids(world, 5);
      const stepper = new GpuStepper(ctx, world, { solver: { fused: false, passColours } });
      const steps: Step[] = [];
      for (let i = 0; i < 6; ++i) {
        if (i === 3) addPyramids(world, 5, 5);
        const r = await stepper.step(DT, 8, 3);
        const state = await stepper.solver.readState();
        steps.push({
          dispatches: r.dispatches,
          passColours: stepper.solver.passColours,
          items: itemsPerColour(state.colourStart),
          coloursUsed: state.coloursUsed,
          recoloured: state.recoloured,
          readBack: r.colourItems,
          readBackUsed: r.coloursUsed,
        });
      }
      await stepper.readBodies();
      const state = bodyState(world);
      // Steps in flight ({ wait: false }): the colour sizes come back with each step's counts.
      for (let i = 0; i < 3; ++i) await stepper.step(DT, 8, 3, { wait: false });
      const settled = await stepper.pipeline.settle();
      const last = await stepper.solver.readState();
      const inFlight = {
        readBack: settled!.colourItems,
        readBackUsed: settled!.coloursUsed,
        items: itemsPerColour(last.colourStart),
        coloursUsed: last.coloursUsed,
      };
      stepper.destroy();
      return { steps, state, inFlight };
    };
    const learned = await run();
    const all = await run(COLOUR_CAP);
    expect(learned.state).toEqual(all.state);
    expect(learned.inFlight.readBack).toEqual(learned.inFlight.items);
    expect(learned.inFlight.readBackUsed).toBe(learned.inFlight.coloursUsed);
    learned.steps.forEach((step, i) => {
      expect(step.readBack, `step ${i}: read back`).toEqual(step.items);
      expect(step.readBackUsed, `step ${i}: read back`).toBe(step.coloursUsed);
      expect(step.items, `step ${i}: the same colouring`).toEqual(all.steps[i].items);
      const expected = i === 0 ? COLOUR_CAP : largeColours(learned.steps[i - 1].items);
      expect(step.passColours, `step ${i}: passColours`).toBe(expected);
      expect(all.steps[i].dispatches - step.dispatches, `step ${i}: dispatches`).toBe((COLOUR_CAP - expected) * PASSES_PER_COLOUR);
    });
    const perStep = (steps: { dispatches: number }[]) => steps.map((step) => step.dispatches).join(', ');
    const sizes = (step: Step) => step.items.slice(0, step.coloursUsed).join(' ');
    console.log(
      `5 pyramids of 20 rows, then 10: items per colour ${sizes(learned.steps[0])}, then ${sizes(learned.steps[3])}; ` +
        `passColours per step ${learned.steps.map((step) => step.passColours).join(', ')}; ` +
        `dispatches per step ${perStep(learned.steps)} (${perStep(all.steps)} with a pass for every colour)`,
    );
    // The pyramids have colours on both sides of TAIL_COLOUR_ITEMS: some colours get passes of
    // their own, the small ones go to the tail, and more get passes once the colours grew.
    const [before, after] = [learned.steps[1], learned.steps[4]];
    expect(before.passColours).toBeGreaterThan(0);
    expect(before.passColours).toBeLessThan(before.coloursUsed);
    expect(after.passColours).toBeGreaterThan(before.passColours);
    expect(after.passColours).toBeLessThan(after.coloursUsed);
    expect(learned.steps[3].recoloured, 'the pyramids added are coloured').toBe(true);
    expect(learned.steps[4].recoloured).toBe(false);
  }, 600_000);

  it('solves a step that needs more passes than it has (a pyramid added after one large colour was learned) to the bits of a pass per colour', async () => {
    const run = async (passColours?: number) => {
      const world = new b2World(new b2Vec2(0, -10));
      world.SetAllowSleeping(false);
      ground(world, 470);
      const box = new b2PolygonShape();
      box.SetAsBox(0.5, 0.5);
      // One colour of TAIL_COLOUR_ITEMS + 44 contacts (every box on the ground alone).
      for (let i = 0; i < TAIL_COLOUR_ITEMS + 44; ++i) {
        const def = new b2BodyDef();
        def.type = b2_dynamicBody;
        def.position.Set(-460 + 1.5 * i, 0.5);
        world.CreateBody(def).CreateFixture(box, 1);
      }
      const stepper = new GpuStepper(ctx, world, { solver: { fused: false, passColours } });
      const passes: number[] = [];
      const beyond: number[] = [];
      for (let i = 0; i < 10; ++i) {
        if (i === 4) addPyramid(world, 10, 10);
        await stepper.step(DT, 8, 3);
        passes.push(stepper.solver.passColours);
        beyond.push((await stepper.solver.readState()).coloursUsed - stepper.solver.passColours);
      }
      await stepper.readBodies();
      const state = bodyState(world);
      stepper.destroy();
      return { state, passes, beyond };
    };
    const learned = await run();
    const all = await run(COLOUR_CAP);
    console.log(`boxes, then a pyramid: passColours ${learned.passes.join(', ')}; colours used past them ${learned.beyond.join(', ')}`);
    // The boxes on the ground need one colour, large: the step that adds the pyramid has one
    // pass, and the tail solves the colours past it.
    expect(learned.passes.slice(1, 5)).toEqual([1, 1, 1, 1]);
    expect(learned.beyond[4]).toBeGreaterThan(0);
    expect(learned.state).toEqual(all.state);
  }, 600_000);
});
