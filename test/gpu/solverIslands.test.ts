/*
 * Islands and sleeping on the GPU (src-gpu/solver/islands.ts, shaders/solver/islands.wgsl) against the engine:
 *   - the islands: for golden scenes at several steps, the GPU's connected components (labels per
 *     body slot) are the islands b2World::Solve's DFS builds from the same world (the engine's
 *     positions, its contacts updated by b2ContactManager::Collide as its next step would), as a
 *     partition of the non-static active bodies. The DFS here seeds from every non-static body,
 *     awake or not, since the GPU labels sleeping islands too; static bodies end no island.
 *   - sleeping: stacks placed at rest fall asleep on the GPU within SLEEP_STEP_TOLERANCE steps of
 *     the step at which the engine's do, and then have zero velocity and sleep time and keep
 *     every bit of their transforms;
 *   - waking: a box dropped onto one of two sleeping columns wakes that column, all of it at once,
 *     and never the other; SetAllowSleeping(false) and a body without autoSleep keep bodies awake;
 *     SetAwake from JavaScript after the GPU put a body to sleep reaches the GPU;
 *   - determinism: two runs give the same bits (motion, awake flags, labels).
 */

import { expect, it } from 'vitest';
import { b2_angularSleepTolerance, b2_linearSleepTolerance, b2_timeToSleep } from '../../src/common/b2Settings';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2Body, b2BodyDef, b2_dynamicBody, b2_kinematicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import type { b2Joint } from '../../src/dynamics/joints/b2Joint';
import type { GpuContext } from '../../src-gpu/device/device';
import { ISLAND_WORDS, MAP_READ, NO_ISLAND, USAGE } from '../../src-gpu/device/layout';
import { SHADERS } from '../../src-gpu/device/shaders';
import { GpuStepper } from '../../src-gpu/stepper';
import type { GpuWorld } from '../../src-gpu/world/world';
import { loadGoldenScene } from '../support/scene';
import { describeGpu } from './support';
import { allAsleep, allAwake, column, DT, motion, POSITION_ITERATIONS, pyramid, restingWorld, stepUntilAsleep, VELOCITY_ITERATIONS } from './resting';

/**
 * Steps between the engine's and the GPU's falling asleep. The sleep timer starts when every
 * body of the island is below b2_linearSleepTolerance (0.01 m/s) and b2_angularSleepTolerance:
 * the residual velocities of a settling stack are float32 and colour-ordered on the GPU, float64
 * and island-ordered in the engine, so the step at which the last body drops below the tolerance
 * may differ by a few steps; the timer itself (30 steps of 1/60 s) is the same.
 */
const SLEEP_STEP_TOLERANCE = 5;

/** The label per body slot of the islands b2World::Solve's DFS builds (the island's smallest slot). */
function engineIslands(world: b2World, mirror: GpuWorld): Uint32Array {
  const labels = new Uint32Array(mirror.bodySlotCount).fill(NO_ISLAND);
  const inIsland = new Set<b2Body>();
  const contacts = new Set<b2Contact>();
  const joints = new Set<b2Joint>();
  for (let seed = world.m_bodyList; seed; seed = seed.m_next) {
    if (inIsland.has(seed) || !seed.IsActive() || seed.GetType() === b2_staticBody) continue;
    const island: b2Body[] = [];
    const stack = [seed];
    inIsland.add(seed);
    while (stack.length > 0) {
      const b = stack.pop()!;
      island.push(b);
      if (b.GetType() === b2_staticBody) continue;
      for (let ce = b.m_contactList; ce; ce = ce.next) {
        const c = ce.contact;
        if (contacts.has(c) || !c.IsEnabled() || !c.IsTouching() || c.m_fixtureA.m_isSensor || c.m_fixtureB.m_isSensor) continue;
        contacts.add(c);
        if (inIsland.has(ce.other)) continue;
        stack.push(ce.other);
        inIsland.add(ce.other);
      }
      for (let je = b.m_jointList; je; je = je.next) {
        if (joints.has(je.joint) || !je.other.IsActive()) continue;
        joints.add(je.joint);
        if (inIsland.has(je.other)) continue;
        stack.push(je.other);
        inIsland.add(je.other);
      }
    }
    const slots: number[] = [];
    for (const b of island) {
      // Static bodies may join other islands (b2World::Solve clears their flag after each island).
      if (b.GetType() === b2_staticBody) inIsland.delete(b);
      else slots.push(mirror.bodySlot(b));
    }
    const label = Math.min(...slots);
    for (const s of slots) labels[s] = label;
  }
  return labels;
}

/** The GPU's awake words, read without writing anything into the world. */
async function gpuAwake(ctx: GpuContext, mirror: GpuWorld): Promise<Uint32Array> {
  const bytes = 4 * mirror.bodySlotCount;
  const staging = ctx.createBuffer('test awake read', Math.max(16, Math.ceil(bytes / 16) * 16), USAGE.MAP_READ | USAGE.COPY_DST);
  const encoder = ctx.device.createCommandEncoder();
  encoder.copyBufferToBuffer(mirror.bodyAwake.buffer, 0, staging, 0, staging.size);
  ctx.device.queue.submit([encoder.finish()]);
  await staging.mapAsync(MAP_READ);
  const out = new Uint32Array(staging.getMappedRange().slice(0, bytes));
  staging.unmap();
  staging.destroy();
  return out;
}

it("compiles the islands stage with b2Settings' sleep constants and the islands layout the host uses", () => {
  const source = SHADERS.islands;
  const c = new Map<string, number>();
  for (const m of source.matchAll(/^const (\w+): (?:u32|f32) = (0x[0-9a-fA-F]+|[0-9.]+)u?;/gm)) c.set(m[1], Number(m[2]));
  const f32 = Math.fround;
  expect(f32(c.get('TIME_TO_SLEEP')!)).toBe(f32(b2_timeToSleep));
  expect(f32(c.get('LINEAR_SLEEP_TOLERANCE')!)).toBe(f32(b2_linearSleepTolerance));
  expect(f32(c.get('ANGULAR_SLEEP_TOLERANCE')!)).toBe(f32(b2_angularSleepTolerance));
  expect(c.get('BODY_AUTO_SLEEP')).toBe(b2Body.e_autoSleepFlag);
  expect(c.get('ISLAND_WORDS')).toBe(ISLAND_WORDS);
  expect(c.get('NO_ISLAND')).toBe(NO_ISLAND);
});

/** Golden scenes and the steps at which their islands are compared. */
const ISLAND_SCENES: Record<string, number[]> = {
  pyramid: [1, 40, 120],
  'vertical-stack': [1, 60],
  bridge: [1, 60],
  chain: [1, 60],
  'mixed-rain': [1, 30, 90],
  'varying-restitution': [1, 60],
};

describeGpu('GPU islands: the engine partition', (ctx) => {
  for (const [name, checkpoints] of Object.entries(ISLAND_SCENES)) {
    it(`${name}: the GPU's islands are b2World::Solve's at steps ${checkpoints.join(', ')}`, async () => {
      const scene = loadGoldenScene(name);
      const settings = scene.stepSettings;
      let step = 0;
      const summary: string[] = [];
      for (const checkpoint of checkpoints) {
        while (step < checkpoint) {
          scene.step();
          step++;
        }
        const stepper = new GpuStepper(ctx, scene.world);
        // The engine's next step starts by updating its contacts at these positions.
        scene.world.m_contactManager.Collide();
        const expected = engineIslands(scene.world, stepper.mirror);
        await stepper.step(1 / settings.stepsPerSecond, settings.velocityIterations, settings.positionIterations);
        const labels = await stepper.solver.readIslands(stepper.mirror.bodySlotCount);
        stepper.destroy();
        expect(Array.from(labels)).toEqual(Array.from(expected));
        const islands = new Set(Array.from(expected).filter((l) => l !== NO_ISLAND)).size;
        summary.push(`step ${checkpoint}: ${islands} islands`);
      }
      console.log(`${name}: ${summary.join(', ')}`);
    });
  }

  it('a kinematic body joins islands, a static one does not, sensors join nothing, joints do', async () => {
    const world = new b2World(new b2Vec2(0, -10));
    const ground = world.CreateBody(new b2BodyDef());
    const groundShape = new b2PolygonShape();
    groundShape.SetAsBox(40, 1, new b2Vec2(0, -1), 0);
    ground.CreateFixture(groundShape, 0);
    const make = (type: number, x: number, y: number, halfWidth = 0.5, sensor = false) => {
      const def = new b2BodyDef();
      def.type = type;
      def.position.Set(x, y);
      const body = world.CreateBody(def);
      const shape = new b2PolygonShape();
      shape.SetAsBox(halfWidth, 0.5);
      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 1;
      fd.isSensor = sensor;
      body.CreateFixture(fd);
      return body;
    };
    // Two boxes on the ground, touching it only: two islands (the ground does not join them).
    const a = make(b2_dynamicBody, -10, 0.5);
    const b = make(b2_dynamicBody, -8, 0.5);
    // A kinematic plank with a box on each end: one island through the kinematic body.
    make(b2_kinematicBody, 0, 3.5, 3);
    make(b2_dynamicBody, -2, 4.5);
    make(b2_dynamicBody, 2, 4.5);
    // A sensor box overlapping a box on the ground: separate islands.
    make(b2_dynamicBody, 8, 0.5);
    make(b2_dynamicBody, 8.5, 0.5, 0.5, true);
    // Two circles joined by a revolute joint in the air, and one jointed to the ground: the joint
    // to the ground joins nothing.
    const circle = new b2CircleShape();
    circle.m_radius = 0.25;
    const ball = (x: number) => {
      const def = new b2BodyDef();
      def.type = b2_dynamicBody;
      def.position.Set(x, 10);
      const body = world.CreateBody(def);
      body.CreateFixture(circle, 1);
      return body;
    };
    const c1 = ball(12);
    const c2 = ball(13);
    const c3 = ball(15);
    const joint = new b2RevoluteJointDef();
    joint.Initialize(c1, c2, new b2Vec2(12.5, 10));
    world.CreateJoint(joint);
    joint.Initialize(ground, c3, new b2Vec2(15, 10));
    world.CreateJoint(joint);
    world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    const stepper = new GpuStepper(ctx, world);
    world.m_contactManager.Collide();
    const expected = engineIslands(world, stepper.mirror);
    await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    const labels = await stepper.solver.readIslands(stepper.mirror.bodySlotCount);
    const slot = (body: b2Body) => stepper.mirror.bodySlot(body);
    stepper.destroy();
    expect(Array.from(labels)).toEqual(Array.from(expected));
    // The scene does what it was built for: 7 islands (a, b, plank + 2 boxes, box, sensor, c1 + c2, c3).
    expect(new Set(Array.from(labels).filter((l) => l !== NO_ISLAND)).size).toBe(7);
    expect(labels[slot(a)]).not.toBe(labels[slot(b)]);
    expect(labels[slot(c1)]).toBe(labels[slot(c2)]);
    expect(labels[slot(ground)]).toBe(NO_ISLAND);
  });
});

describeGpu('GPU sleeping against the engine', (ctx) => {
  const cases: Record<string, number[][]> = {
    'a column of 4 boxes': column(0, 4),
    'a 6-row pyramid': pyramid(6),
  };
  for (const [name, at] of Object.entries(cases)) {
    it(`${name} placed at rest falls asleep within ${SLEEP_STEP_TOLERANCE} steps of the engine's, then has zero velocity and does not move`, async () => {
      const js = restingWorld(at);
      const gpu = restingWorld(at);
      const stepper = new GpuStepper(ctx, gpu.world);
      let jsStep = -1;
      let gpuStep = -1;
      for (let step = 1; step <= 200 && (jsStep < 0 || gpuStep < 0); ++step) {
        js.world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
        await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
        await stepper.readBodies();
        if (jsStep < 0 && allAsleep(js.boxes)) jsStep = step;
        if (gpuStep < 0 && allAsleep(gpu.boxes)) gpuStep = step;
        // Islands sleep as a whole.
        expect(allAsleep(gpu.boxes) || allAwake(gpu.boxes)).toBe(true);
      }
      console.log(`${name}: asleep at step ${jsStep} in the engine, ${gpuStep} on the GPU`);
      expect(jsStep).toBeGreaterThan(0);
      expect(gpuStep).toBeGreaterThan(0);
      expect(Math.abs(gpuStep - jsStep)).toBeLessThanOrEqual(SLEEP_STEP_TOLERANCE);
      const before = motion(gpu.boxes);
      for (const row of before) expect(row.slice(7)).toEqual([0, 0, 0, 0]);
      for (let step = 0; step < 30; ++step) await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
      await stepper.readBodies();
      stepper.destroy();
      expect(allAsleep(gpu.boxes)).toBe(true);
      expect(motion(gpu.boxes)).toEqual(before);
    });
  }
});

describeGpu('GPU waking', (ctx) => {
  it('a box dropped onto one of two sleeping columns wakes that whole column and never the other', async () => {
    const { world, boxes } = restingWorld([...column(-10, 2), ...column(10, 2)]);
    const left = boxes.slice(0, 2);
    const right = boxes.slice(2);
    const stepper = new GpuStepper(ctx, world);
    await stepUntilAsleep(stepper, boxes);
    const rightAtRest = motion(right);
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(-10, 3);
    const dropped = world.CreateBody(def);
    const box = new b2PolygonShape();
    box.SetAsBox(0.5, 0.5);
    dropped.CreateFixture(box, 1);
    let woke = -1;
    for (let step = 1; step <= 40; ++step) {
      await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
      await stepper.readBodies();
      expect(allAsleep(right)).toBe(true);
      expect(allAsleep(left) || allAwake(left)).toBe(true);
      if (woke < 0 && allAwake(left)) woke = step;
    }
    const landed = dropped.m_xf.p.y;
    stepper.destroy();
    console.log(`dropped box: the left column woke at step ${woke}; the box rests at y = ${landed.toFixed(3)}`);
    // It falls 0.5 m (0.32 s, 19 steps): the column wakes before the box lands on it (when their
    // AABBs, extended by b2_aabbExtension, first overlap: b2ContactManager::AddPair), and holds it.
    expect(woke).toBeGreaterThan(0);
    expect(woke).toBeLessThan(19);
    expect(landed).toBeGreaterThan(2.4);
    expect(landed).toBeLessThan(2.6);
    expect(motion(right)).toEqual(rightAtRest);
  });

  it('SetAllowSleeping(false) keeps everything awake and wakes what the GPU put to sleep', async () => {
    // Asleep on the GPU while the world's flags still say awake (woken from JavaScript, asleep
    // again on the GPU, no read-back since): SetAllowSleeping(false) must reach the GPU anyway.
    const on = restingWorld(column(0, 2));
    const stepper = new GpuStepper(ctx, on.world);
    const asleepAfter = await stepUntilAsleep(stepper, on.boxes);
    for (const b of on.boxes) b.SetAwake(true);
    for (let step = 0; step < asleepAfter + 5; ++step) await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    const words = await gpuAwake(ctx, stepper.mirror);
    expect(on.boxes.map((b) => words[stepper.mirror.bodySlot(b)])).toEqual([0, 0]);
    expect(allAwake(on.boxes)).toBe(true);
    on.world.SetAllowSleeping(false);
    for (let step = 0; step < 10; ++step) await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    await stepper.readBodies();
    stepper.destroy();
    expect(allAwake(on.boxes)).toBe(true);

    // Without sleeping from the start: awake past the step at which the same column slept, and
    // no sleep time kept (2.2.1 leaves it alone).
    const off = restingWorld(column(0, 2), false);
    const offStepper = new GpuStepper(ctx, off.world);
    for (let step = 0; step < asleepAfter + 5; ++step) await offStepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    await offStepper.readBodies();
    offStepper.destroy();
    expect(allAwake(off.boxes)).toBe(true);
    expect(off.boxes.every((b) => b.m_sleepTime === 0)).toBe(true);
  });

  it('a body without autoSleep keeps its island awake, and only its island', async () => {
    const { world, boxes } = restingWorld([...column(-5, 2), ...column(5, 2)]);
    boxes[1].SetSleepingAllowed(false);
    const stepper = new GpuStepper(ctx, world);
    const asleepAfter = await stepUntilAsleep(stepper, boxes.slice(2));
    for (let step = 0; step < asleepAfter; ++step) await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    await stepper.readBodies();
    stepper.destroy();
    expect(allAwake(boxes.slice(0, 2))).toBe(true);
    expect(allAsleep(boxes.slice(2))).toBe(true);
  });

  it('SetAwake from JavaScript after the GPU stepped reaches the GPU: a sleeping column wakes, a falling box stops', async () => {
    const { world, boxes } = restingWorld(column(0, 2));
    const def = new b2BodyDef();
    def.type = b2_dynamicBody;
    def.position.Set(20, 50);
    const faller = world.CreateBody(def);
    const box = new b2PolygonShape();
    box.SetAsBox(0.5, 0.5);
    faller.CreateFixture(box, 1);
    const stepper = new GpuStepper(ctx, world);
    await stepUntilAsleep(stepper, boxes);
    expect(faller.IsAwake()).toBe(true);
    // Waking the top box wakes its island on the GPU: the whole column, with its sleep time reset.
    boxes[1].SetAwake(true);
    faller.SetAwake(false);
    const frozenAt = faller.m_xf.p.y;
    await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    await stepper.readBodies();
    expect(allAwake(boxes)).toBe(true);
    expect(boxes.every((b) => b.m_sleepTime <= Math.fround(DT))).toBe(true);
    for (let step = 0; step < 10; ++step) await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
    await stepper.readBodies();
    stepper.destroy();
    // The box put to sleep from JavaScript stays where it was, without velocity.
    expect(faller.IsAwake()).toBe(false);
    expect(faller.m_xf.p.y).toBe(frozenAt);
    expect([faller.m_linearVelocity.x, faller.m_linearVelocity.y, faller.m_angularVelocity, faller.m_sleepTime]).toEqual([0, 0, 0, 0]);
    // The column's sleep timer started again: it is still awake b2_timeToSleep / 3 later.
    expect(allAwake(boxes)).toBe(true);
  });
});

describeGpu('GPU islands: determinism', (ctx) => {
  it('two runs give the same bits (motion, sleep times, awake flags, islands) while islands form, sleep and wake', async () => {
    const run = async () => {
      // A pyramid and a column at rest (they fall asleep near step 35), a box dropped beside the
      // column onto the ground (asleep later), and a box dropped onto the column at step 40.
      const { world, boxes } = restingWorld([...pyramid(4), ...column(10, 2), [12, 3]]);
      const stepper = new GpuStepper(ctx, world);
      const out: number[][] = [];
      const awake: number[] = [];
      for (let step = 1; step <= 60; ++step) {
        if (step === 40) {
          const def = new b2BodyDef();
          def.type = b2_dynamicBody;
          def.position.Set(10, 2.6);
          const body = world.CreateBody(def);
          const box = new b2PolygonShape();
          box.SetAsBox(0.5, 0.5);
          body.CreateFixture(box, 1);
          boxes.push(body);
        }
        await stepper.step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS);
        if (step % 10 !== 0) continue;
        await stepper.readBodies();
        out.push(Array.from(await stepper.solver.readIslands(stepper.mirror.bodySlotCount)));
        out.push(...motion(boxes));
        out.push(boxes.map((b) => (b.IsAwake() ? 1 : 0)));
        awake.push(boxes.filter((b) => b.IsAwake()).length);
      }
      stepper.destroy();
      return { out, awake };
    };
    const first = await run();
    const second = await run();
    console.log(`awake bodies at steps 10, 20, ..., 60: ${first.awake.join(', ')}`);
    // The run does what it is for: everything awake at first, bodies asleep later.
    expect(first.awake[0]).toBe(13);
    expect(Math.min(...first.awake)).toBeLessThan(13);
    expect(second.out).toEqual(first.out);
  });
});
