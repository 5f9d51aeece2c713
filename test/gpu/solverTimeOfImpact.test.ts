/*
 * Continuous collision on the GPU (src-gpu/solver/timeOfImpact.ts, swept and predicted AABBs in
 * src-gpu/broadphase/bounds.ts): fast bodies stop at thin static walls where the engine without continuous
 * physics lets them through; the GPU's b2TimeOfImpact gives the engine's answer on hand-built
 * sweeps; the stage records nothing when continuous physics is off; slow pairs are not tested, with
 * the results of testing them; runs repeat bit for bit.
 */

import { expect, it } from 'vitest';
import { b2Distance, b2DistanceInput, b2DistanceOutput, b2SimplexCache } from '../../src/collision/b2Distance';
import { b2TOIInput, b2TOIOutput, b2TimeOfImpact } from '../../src/collision/b2TimeOfImpact';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import type { b2Shape } from '../../src/collision/shapes/b2Shape';
import { b2Transform, b2Vec2 } from '../../src/common/b2Math';
import { b2_linearSlop } from '../../src/common/b2Settings';
import { b2BodyDef, b2_dynamicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { GpuStepper } from '../../src-gpu/stepper';
import { TimeOfImpactStage } from '../../src-gpu/solver/timeOfImpact';
import { GpuWorld } from '../../src-gpu/world/world';
import { pyramid, restingWorld } from './resting';
import { describeGpu } from './support';

const DT = 1 / 60;
const WALL_X = 5;
/** Steps of the bullet scenes: the bullet reaches the wall in the third (2 m a step at most). */
const STEPS = 15;

type WallKind = 'edge' | 'thin box';
type BulletKind = 'circle' | 'box';

/**
 * A bullet fired at 300 m/s along x from the origin at a wall 5 m away, no gravity: a 0.2 m circle
 * or box against an edge or a 0.05 m thick static box.
 */
function bulletScene(wall: WallKind, bullet: BulletKind, continuous: boolean): { world: b2World; bullet: b2Body } {
  const world = new b2World(new b2Vec2(0, 0));
  world.SetContinuousPhysics(continuous);
  const ground = world.CreateBody(new b2BodyDef());
  if (wall === 'edge') {
    const edge = new b2EdgeShape();
    edge.Set(new b2Vec2(WALL_X, -5), new b2Vec2(WALL_X, 5));
    ground.CreateFixture(edge, 0);
  } else {
    const box = new b2PolygonShape();
    box.SetAsBox(0.025, 5, new b2Vec2(WALL_X, 0), 0);
    ground.CreateFixture(box, 0);
  }
  const def = new b2BodyDef();
  def.type = b2_dynamicBody;
  def.bullet = true;
  def.linearVelocity.Set(300, 0);
  const body = world.CreateBody(def);
  if (bullet === 'circle') {
    const circle = new b2CircleShape();
    circle.m_radius = 0.1;
    body.CreateFixture(circle, 1);
  } else {
    const box = new b2PolygonShape();
    box.SetAsBox(0.1, 0.1);
    body.CreateFixture(box, 1);
  }
  return { world, bullet: body };
}

function motion(w: b2World): number[] {
  const out: number[] = [];
  for (let b = w.m_bodyList; b; b = b.m_next) out.push(b.m_xf.p.x, b.m_xf.p.y, b.m_sweep.a, b.m_linearVelocity.x, b.m_linearVelocity.y, b.m_angularVelocity);
  return out;
}

/**
 * GPU against engine at rest against the wall: the engine's TOI island solve leaves the bullet
 * about b2_linearSlop into the wall's skin; the GPU stops it 3 b2_linearSlop deep (b2TimeOfImpact's
 * target) and leaves the rest to the next steps' position correction, which stops at about
 * b2_linearSlop too. 3 b2_linearSlop covers the whole gap between the two stops (measured: at most
 * 1e-3 m, bullets and the falling box).
 */
const REST_TOLERANCE = 3 * b2_linearSlop;

describeGpu('GPU continuous collision', (ctx) => {
  for (const wall of ['edge', 'thin box'] as WallKind[]) {
    for (const kind of ['circle', 'box'] as BulletKind[]) {
      it(`a ${kind} bullet at 300 m/s stops at a thin static wall (${wall}) as the engine's does, where the engine without continuous physics lets it through`, async () => {
        const off = bulletScene(wall, kind, false);
        const on = bulletScene(wall, kind, true);
        const gpu = bulletScene(wall, kind, true);
        const stepper = new GpuStepper(ctx, gpu.world);
        for (let i = 0; i < STEPS; ++i) {
          off.world.Step(DT, 8, 3);
          on.world.Step(DT, 8, 3);
          await stepper.step(DT, 8, 3);
        }
        await stepper.readBodies();
        const xOff = off.bullet.GetPosition().x;
        const xOn = on.bullet.GetPosition().x;
        const xGpu = gpu.bullet.GetPosition().x;
        console.log(
          `${kind} bullet, ${wall}: x after ${STEPS} steps: engine without continuous physics ${xOff.toFixed(3)}, with it ${xOn.toFixed(5)}, GPU ${xGpu.toFixed(5)} m`,
        );
        expect(xOff).toBeGreaterThan(WALL_X + 10);
        expect(xOn).toBeLessThan(WALL_X);
        expect(xGpu).toBeLessThan(WALL_X);
        expect(Math.abs(xGpu - xOn)).toBeLessThan(REST_TOLERANCE);
        stepper.destroy();
      });
    }
  }

  it('a fast non-bullet box falling onto a thin static edge stops on it with continuous physics on, and falls through with it off', async () => {
    const scene = (continuous: boolean) => {
      const world = new b2World(new b2Vec2(0, -10));
      world.SetContinuousPhysics(continuous);
      const ground = world.CreateBody(new b2BodyDef());
      const edge = new b2EdgeShape();
      edge.Set(new b2Vec2(-10, 0), new b2Vec2(10, 0));
      ground.CreateFixture(edge, 0);
      const def = new b2BodyDef();
      def.type = b2_dynamicBody;
      // 2 m a step (b2_maxTranslation) from 7 m: the discrete steps jump from 1 m to -1 m.
      def.position.Set(0, 7);
      def.linearVelocity.Set(0, -200);
      const body = world.CreateBody(def);
      const box = new b2PolygonShape();
      box.SetAsBox(0.25, 0.25);
      body.CreateFixture(box, 1);
      return { world, body };
    };
    const js = scene(true);
    const gpuOn = scene(true);
    const gpuOff = scene(false);
    const on = new GpuStepper(ctx, gpuOn.world);
    const off = new GpuStepper(ctx, gpuOff.world);
    let dispatchesOn = 0;
    let dispatchesOff = 0;
    for (let i = 0; i < 15; ++i) {
      js.world.Step(DT, 8, 3);
      dispatchesOn = (await on.step(DT, 8, 3)).dispatches;
      dispatchesOff = (await off.step(DT, 8, 3)).dispatches;
    }
    await on.readBodies();
    await off.readBodies();
    console.log(
      `falling box: y after 15 steps: engine ${js.body.GetPosition().y.toFixed(5)}, GPU ${gpuOn.body.GetPosition().y.toFixed(5)}, GPU without continuous physics ${gpuOff.body.GetPosition().y.toFixed(3)} m; dispatches per step ${dispatchesOn} / ${dispatchesOff}`,
    );
    expect(js.body.GetPosition().y).toBeGreaterThan(0);
    expect(gpuOn.body.GetPosition().y).toBeGreaterThan(0);
    expect(Math.abs(gpuOn.body.GetPosition().y - js.body.GetPosition().y)).toBeLessThan(REST_TOLERANCE);
    expect(gpuOff.body.GetPosition().y).toBeLessThan(-10);
    // The stage's three dispatches (begin, candidates, advance) are recorded only when continuous
    // physics is on; with it off, nothing of it is in the command buffer.
    expect(dispatchesOn - dispatchesOff).toBe(3);
    on.destroy();
    off.destroy();
  });

  it('leaves the time of impact to fast pairs: a resting pyramid and slow boxes are not tested, with the same bits as testing them, and a bullet the filter skipped would tunnel', async () => {
    // A 6-row pyramid at rest on static ground (its bottom row's contacts are dynamic against
    // static: 2.2.1 tests each every step), a box sliding slowly along the ground, and a box
    // falling fast from 4 m.
    const scene = () => {
      const { world } = restingWorld(pyramid(6), false);
      world.SetContinuousPhysics(true);
      const add = (x: number, y: number, vx: number, vy: number) => {
        const def = new b2BodyDef();
        def.type = b2_dynamicBody;
        def.position.Set(x, y);
        def.linearVelocity.Set(vx, vy);
        const body = world.CreateBody(def);
        const box = new b2PolygonShape();
        box.SetAsBox(0.5, 0.5);
        body.CreateFixture(box, 1);
      };
      add(12, 0.5, 0.1, 0);
      add(-12, 4, 0, -30);
      return world;
    };
    const filtered = scene();
    const unfiltered = scene();
    const a = new GpuStepper(ctx, filtered);
    const b = new GpuStepper(ctx, unfiltered);
    b.solver.timeOfImpact.minMotion = 0;
    const testedA: number[] = [];
    const testedB: number[] = [];
    for (let i = 0; i < 20; ++i) {
      await a.step(DT, 8, 3);
      await b.step(DT, 8, 3);
      testedA.push(await a.solver.timeOfImpact.testedContacts());
      testedB.push(await b.solver.timeOfImpact.testedContacts());
    }
    await a.readBodies();
    await b.readBodies();
    console.log(`contacts run through b2TimeOfImpact per step: filtered ${testedA.join(' ')}; unfiltered ${testedB.join(' ')}`);
    expect(motion(filtered)).toEqual(motion(unfiltered));
    // Unfiltered: the pyramid's 6 bottom boxes and the sliding box, and the falling box once its
    // AABB meets the ground. Filtered: the bottom boxes the first step's position correction
    // moves (the pyramid's boxes start with their skins overlapping), then only the falling box,
    // and nothing once it has landed.
    expect(Math.min(...testedB)).toBeGreaterThanOrEqual(7);
    expect(Math.max(...testedA.slice(1))).toBeLessThanOrEqual(1);
    expect(testedA.some((n) => n === 1)).toBe(true);
    expect(testedA[testedA.length - 1]).toBe(0);
    a.destroy();
    b.destroy();

    const bullet = bulletScene('edge', 'circle', true);
    const none = new GpuStepper(ctx, bullet.world);
    none.solver.timeOfImpact.minMotion = Infinity;
    for (let i = 0; i < STEPS; ++i) await none.step(DT, 8, 3);
    await none.readBodies();
    expect(bullet.bullet.GetPosition().x).toBeGreaterThan(WALL_X + 10);
    none.destroy();
  });

  it('runs twice to the same bits (bullets, walls, a falling box)', async () => {
    const run = async () => {
      const { world } = bulletScene('thin box', 'box', true);
      const def = new b2BodyDef();
      def.type = b2_dynamicBody;
      def.bullet = true;
      def.position.Set(0, 1);
      def.linearVelocity.Set(250, 3);
      def.angularVelocity = 20;
      const body = world.CreateBody(def);
      const circle = new b2CircleShape();
      circle.m_radius = 0.15;
      body.CreateFixture(circle, 1);
      const stepper = new GpuStepper(ctx, world);
      for (let i = 0; i < 12; ++i) await stepper.step(DT, 8, 3);
      await stepper.readBodies();
      stepper.destroy();
      return motion(world);
    };
    const a = await run();
    const b = await run();
    expect(a).toEqual(b);
    expect(a.every(Number.isFinite)).toBe(true);
  });

  it("gives the engine's b2TimeOfImpact (state, and t within 1e-4) on hand-built sweeps, at a separation within its tolerance of the target", async () => {
    const world = new b2World(new b2Vec2(0, 0));
    const make = (
      shape: b2Shape,
      type: number,
      c0: [number, number, number],
      c: [number, number, number],
      localCenter: [number, number] = [0, 0],
    ): b2Fixture => {
      const def = new b2BodyDef();
      def.type = type;
      const body = world.CreateBody(def);
      const fixture = body.CreateFixture(shape, 1);
      const s = body.m_sweep;
      s.localCenter.Set(localCenter[0], localCenter[1]);
      s.c0.Set(c0[0], c0[1]);
      s.a0 = c0[2];
      s.c.Set(c[0], c[1]);
      s.a = c[2];
      s.alpha0 = 0;
      body.m_xf.q.Set(s.a);
      body.m_xf.p.Set(
        s.c.x - (body.m_xf.q.c * localCenter[0] - body.m_xf.q.s * localCenter[1]),
        s.c.y - (body.m_xf.q.s * localCenter[0] + body.m_xf.q.c * localCenter[1]),
      );
      return fixture;
    };
    const circle = (r: number) => {
      const s = new b2CircleShape();
      s.m_radius = r;
      return s;
    };
    const box = (hx: number, hy: number, angle = 0) => {
      const s = new b2PolygonShape();
      s.SetAsBox(hx, hy, new b2Vec2(0, 0), angle);
      return s;
    };
    const edge = (x1: number, y1: number, x2: number, y2: number) => {
      const s = new b2EdgeShape();
      s.Set(new b2Vec2(x1, y1), new b2Vec2(x2, y2));
      return s;
    };
    const cases: { name: string; a: b2Fixture; b: b2Fixture }[] = [
      // A circle crossing an edge: touching part way.
      {
        name: 'edge / circle',
        a: make(edge(5, -5, 5, 5), b2_staticBody, [0, 0, 0], [0, 0, 0]),
        b: make(circle(0.1), b2_dynamicBody, [2, 0.3, 0], [8, 0.3, 0]),
      },
      // A spinning box through a thin box, off centre (face and vertex axes, the root finder).
      {
        name: 'box / spinning box',
        a: make(box(0.025, 3), b2_staticBody, [10, 0, 0], [10, 0, 0]),
        b: make(box(0.2, 0.1), b2_dynamicBody, [8.5, 0.5, 0.3], [11.5, 0.2, 2.1], [0.05, -0.02]),
      },
      // Two moving boxes meeting corner first.
      {
        name: 'box / box, both moving',
        a: make(box(0.5, 0.5, 0.4), b2_dynamicBody, [-3, 0, 0], [0.5, 0.2, 0.5]),
        b: make(box(0.3, 0.6), b2_dynamicBody, [3, 0.4, 1], [-0.5, 0.1, 0.2]),
      },
      // Passing by: separated at the end.
      { name: 'circle / box, missing', a: make(box(1, 1), b2_staticBody, [0, 0, 0], [0, 0, 0]), b: make(circle(0.25), b2_dynamicBody, [-4, 2, 0], [4, 2, 0]) },
      // Close at the start (touching at t = 0).
      {
        name: 'edge / box, touching at the start',
        a: make(edge(-5, 0, 5, 0), b2_staticBody, [0, 0, 0], [0, 0, 0]),
        b: make(box(0.5, 0.5), b2_dynamicBody, [0, 0.505, 0], [0, -1, 0]),
      },
      // A circle and a polygon across a cell boundary (the sweep of B is moved into A's cell).
      {
        name: 'polygon / circle across cells',
        a: make(box(0.5, 0.5), b2_staticBody, [15.8, 0, 0], [15.8, 0, 0]),
        b: make(circle(0.2), b2_dynamicBody, [18.5, 0.1, 0], [16.3, 0.1, 0]),
      },
    ];
    const mirror = new GpuWorld(ctx, world);
    mirror.sync();
    const refs = new Uint32Array(8 * cases.length);
    cases.forEach(({ a, b }, k) => {
      refs.set([mirror.fixtureSlot(a), 0, mirror.bodySlot(a.m_body), 0, mirror.fixtureSlot(b), 0, mirror.bodySlot(b.m_body), 0], 8 * k);
    });
    const stage = new TimeOfImpactStage(ctx);
    const got = await stage.evaluate(mirror, refs);
    const states = new Set<number>();
    cases.forEach(({ name, a, b }, k) => {
      const input = new b2TOIInput();
      input.proxyA.Set(a.m_shape, 0);
      input.proxyB.Set(b.m_shape, 0);
      input.sweepA.Assign(a.m_body.m_sweep);
      input.sweepB.Assign(b.m_body.m_sweep);
      input.tMax = 1;
      const output = new b2TOIOutput();
      b2TimeOfImpact(output, input);
      console.log(`${name}: engine state ${output.state} t ${output.t}, GPU state ${got[k].state} t ${got[k].t}`);
      expect(got[k].state, name).toBe(output.state);
      // Float32 against float64 in up to 20 x 50 root-finder steps (measured: at most 1.2e-5);
      // 1e-4 leaves room for a different but valid stopping point of the root finder.
      expect(Math.abs(got[k].t - output.t), name).toBeLessThan(1e-4);
      states.add(output.state);
      if (output.state !== b2TOIOutput.e_touching) return;
      // The GPU's t by the engine's own criterion: the cores' distance is within the tolerance of
      // the target (b2TimeOfImpact: target = max(slop, radii - 3 slop), tolerance slop / 4).
      const xfA = new b2Transform();
      const xfB = new b2Transform();
      input.sweepA.GetTransform(xfA, got[k].t);
      input.sweepB.GetTransform(xfB, got[k].t);
      const di = new b2DistanceInput();
      di.proxyA.Assign(input.proxyA);
      di.proxyB.Assign(input.proxyB);
      di.transformA.Assign(xfA);
      di.transformB.Assign(xfB);
      di.useRadii = false;
      const dout = new b2DistanceOutput();
      const cache = new b2SimplexCache();
      cache.count = 0;
      b2Distance(dout, cache, di);
      const target = Math.max(b2_linearSlop, input.proxyA.m_radius + input.proxyB.m_radius - 3 * b2_linearSlop);
      if (got[k].t > 0) expect(Math.abs(dout.distance - target), name).toBeLessThan(0.25 * b2_linearSlop + 1e-5);
      else expect(dout.distance, name).toBeLessThan(target + 0.25 * b2_linearSlop);
    });
    // The cases reach both outcomes a step depends on.
    expect(states.has(b2TOIOutput.e_touching)).toBe(true);
    expect(states.has(b2TOIOutput.e_separated)).toBe(true);
    stage.destroy();
    mirror.destroy();
  });
});
