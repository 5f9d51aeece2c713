/*
 * Leak checks: create and destroy worlds, bodies, fixtures and joints many times (10,000 cycles
 * each by default) and check that
 * - the objects destroyed early on are collected (WeakRefs to the first 200 cycles' objects are
 *   all cleared after a full GC; the check yields to the event loop first, since a WeakRef keeps
 *   its target alive until the end of the job that made it);
 * - the heap after a full GC at the end is within 2 MB of its level after the first 1,000 cycles
 *   (a leak of 200 bytes a cycle would exceed it; V8's own noise is a few hundred KB), and no
 *   sample taken every 1,000 cycles after that rises above it by more;
 * - the world's pools (tree nodes, move and pair buffers, island and solver arrays, DFS stack,
 *   query and ray-cast wrappers) are the same size at the end as after the first 1,000 cycles
 *   where the population is the same at each cycle's end, and otherwise (the churning pile)
 *   within twice what the population can use.
 * The scenarios: worlds (each cycle a new world with bodies, joints, steps, queries, dropped),
 * bodies (a body with two fixtures and a joint, created, stepped and destroyed in a world),
 * churn (a pile of 60 bodies, one dropped in and another destroyed each step: contacts end all
 * the time), fixtures (created and destroyed on one body) and joints (every type, created and
 * destroyed between two bodies).
 * Run under node --expose-gc (scripts/reliability/run.mjs leak), as test/reliability/leak.test.ts does.
 */

import { b2AABB } from '../../src/collision/b2Collision';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2Body, b2BodyDef, b2BodyType } from '../../src/dynamics/b2Body';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2DistanceJointDef } from '../../src/dynamics/joints/b2DistanceJoint';
import { b2FrictionJointDef } from '../../src/dynamics/joints/b2FrictionJoint';
import { b2GearJointDef } from '../../src/dynamics/joints/b2GearJoint';
import type { b2Joint, b2JointDef } from '../../src/dynamics/joints/b2Joint';
import { b2MouseJointDef } from '../../src/dynamics/joints/b2MouseJoint';
import { b2PrismaticJointDef } from '../../src/dynamics/joints/b2PrismaticJoint';
import { b2PulleyJointDef } from '../../src/dynamics/joints/b2PulleyJoint';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { b2RopeJointDef } from '../../src/dynamics/joints/b2RopeJoint';
import { b2WeldJointDef } from '../../src/dynamics/joints/b2WeldJoint';
import { b2WheelJointDef } from '../../src/dynamics/joints/b2WheelJoint';
import { checkWorldInvariants, poolSizes } from '../../test/support/invariants';

export interface LeakScenarioReport {
  name: string;
  cycles: number;
  heapAfterWarmupMB: number;
  heapEndMB: number;
  growthKB: number;
  maxSampleMB: number;
  sampled: number;
  collected: number;
  poolsAfterWarmup: Record<string, number> | null;
  poolsEnd: Record<string, number> | null;
}

export interface LeakReport {
  scenarios: LeakScenarioReport[];
  summary: string[];
  failures: string[];
}

const kWarmup = 1000;
const kHeapBoundMB = 2;
/** Objects destroyed in the first cycles are watched with WeakRefs (the churn scenario destroys from cycle 61 on). */
const kSampled = 300;

function gc(): void {
  const collect = (globalThis as { gc?: () => void }).gc;
  if (typeof collect !== 'function') throw new Error('run under node --expose-gc');
  collect();
  collect();
}

function heapMB(): number {
  gc();
  return process.memoryUsage().heapUsed / (1024 * 1024);
}

/** Let the current job end, so WeakRef targets made in it may be collected. */
function nextTask(): Promise<void> {
  return new Promise((resolve) => setImmediate(resolve));
}

function box(hx: number, hy: number): b2PolygonShape {
  return new b2PolygonShape().SetAsBox(hx, hy);
}

function circle(r: number): b2CircleShape {
  const c = new b2CircleShape();
  c.m_radius = r;
  return c;
}

function dynamicBody(world: b2World, x: number, y: number): b2Body {
  const bd = new b2BodyDef();
  bd.type = b2BodyType.b2_dynamicBody;
  bd.position.Set(x, y);
  return world.CreateBody(bd);
}

function groundOf(world: b2World): b2Body {
  const ground = world.CreateBody(new b2BodyDef());
  ground.CreateFixture(new b2EdgeShape().Set(new b2Vec2(-40, 0), new b2Vec2(40, 0)), 0);
  const chain = new b2ChainShape();
  chain.CreateChain([new b2Vec2(-40, 0), new b2Vec2(-40, 20), new b2Vec2(-30, 25)]);
  ground.CreateFixture(chain, 0);
  return ground;
}

const s_query = new b2AABB();

/** Query and ray-cast the world, nesting a query inside each callback (the wrappers must stay bounded). */
function probe(world: b2World): void {
  s_query.lowerBound.Set(-5, -1);
  s_query.upperBound.Set(5, 10);
  world.QueryAABB(
    {
      ReportFixture: (f: b2Fixture) => {
        world.QueryAABB({ ReportFixture: () => true }, f.GetAABB(0));
        return true;
      },
    },
    s_query,
  );
  world.RayCast({ ReportFixture: (_f: b2Fixture, _p: b2Vec2, _n: b2Vec2, fraction: number) => fraction }, new b2Vec2(-10, 5), new b2Vec2(10, 0.5));
}

interface Scenario {
  name: string;
  /** Set up once; returns the world whose pools are watched, or null (a fresh world per cycle). */
  setup(): b2World | null;
  /** One create/step/destroy cycle; returns the objects it destroyed (or dropped). */
  cycle(i: number): object[];
  /**
   * True when the world's population is the same at every cycle's end, so its pools must not
   * change after warm-up; otherwise they must stay within what the population needs.
   */
  stablePools?: boolean;
}

function worldsScenario(): Scenario {
  return {
    name: 'worlds',
    setup: () => null,
    cycle(i) {
      const world = new b2World(new b2Vec2(0, -10));
      const ground = groundOf(world);
      const a = dynamicBody(world, 0, 2);
      a.CreateFixture(box(0.5, 0.5), 1);
      const b = dynamicBody(world, 1.5, 2);
      b.CreateFixture(circle(0.5), 1);
      const c = dynamicBody(world, -1.5, 2 + (i % 3));
      c.CreateFixture(new b2PolygonShape().Set([new b2Vec2(0, 0), new b2Vec2(1, 0), new b2Vec2(0.5, 0.8)]), 1);
      const rd = new b2RevoluteJointDef();
      rd.Initialize(ground, a, new b2Vec2(0, 3));
      world.CreateJoint(rd);
      const dd = new b2DistanceJointDef();
      dd.Initialize(a, b, a.GetWorldCenter(), b.GetWorldCenter());
      world.CreateJoint(dd);
      for (let k = 0; k < 3; ++k) world.Step(1 / 60, 8, 3);
      probe(world);
      return [world, a, b, c];
    },
  };
}

function bodiesScenario(): Scenario {
  let world: b2World;
  let ground: b2Body;
  const resident: b2Body[] = [];
  return {
    name: 'bodies',
    stablePools: true,
    setup() {
      world = new b2World(new b2Vec2(0, -10));
      ground = groundOf(world);
      for (let k = 0; k < 20; ++k) {
        const b = dynamicBody(world, -10 + k, 0.5);
        b.CreateFixture(box(0.45, 0.45), 1);
        resident.push(b);
      }
      return world;
    },
    cycle(i) {
      const b = dynamicBody(world, -10 + (i % 20), 1.6);
      const f1 = b.CreateFixture(box(0.3, 0.3), 1);
      const f2 = b.CreateFixture(circle(0.25), 1);
      const rd = new b2RevoluteJointDef();
      rd.Initialize(ground, b, b.GetWorldCenter());
      const j = world.CreateJoint(rd);
      world.Step(1 / 60, 8, 3);
      if (i % 2 === 0) world.DestroyJoint(j);
      world.DestroyBody(b);
      if (i % 50 === 0) probe(world);
      return [b, f1, f2, j];
    },
  };
}

/** A pile kept at 60 bodies: each cycle drops one in and destroys another, so contacts come and go all the time. */
function churnScenario(): Scenario {
  let world: b2World;
  const live: b2Body[] = [];
  let seed = 12345;
  const random = () => {
    seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
    return seed / 4294967296;
  };
  return {
    name: 'churn',
    setup() {
      world = new b2World(new b2Vec2(0, -10));
      const ground = groundOf(world);
      ground.CreateFixture(new b2EdgeShape().Set(new b2Vec2(6, 0), new b2Vec2(6, 10)), 0);
      ground.CreateFixture(new b2EdgeShape().Set(new b2Vec2(-6, 0), new b2Vec2(-6, 10)), 0);
      return world;
    },
    cycle() {
      const b = dynamicBody(world, -5 + 10 * random(), 8 + 2 * random());
      b.CreateFixture(random() < 0.5 ? circle(0.3) : box(0.3, 0.25), 1);
      live.push(b);
      const dropped: object[] = [];
      if (live.length > 60) {
        const victim = live.splice(Math.floor(random() * live.length), 1)[0];
        world.DestroyBody(victim);
        dropped.push(victim);
      }
      world.Step(1 / 60, 8, 3);
      return dropped;
    },
  };
}

function fixturesScenario(): Scenario {
  let world: b2World;
  let body: b2Body;
  return {
    name: 'fixtures',
    stablePools: true,
    setup() {
      world = new b2World(new b2Vec2(0, -10));
      groundOf(world);
      body = dynamicBody(world, 0, 1);
      body.CreateFixture(box(0.5, 0.5), 1);
      return world;
    },
    cycle(i) {
      const shapes = [box(0.2, 0.2), circle(0.3), new b2EdgeShape().Set(new b2Vec2(0, 0), new b2Vec2(1, 0.2))];
      const f = body.CreateFixture(shapes[i % 3], i % 3 === 2 ? 0 : 1);
      world.Step(1 / 60, 8, 3);
      body.DestroyFixture(f);
      if (i % 100 === 0) body.SetTransform(new b2Vec2(0, 1), 0);
      return [f];
    },
  };
}

function jointsScenario(): Scenario {
  let world: b2World;
  let ground: b2Body;
  let a: b2Body;
  let b: b2Body;
  let r1: b2Joint;
  let r2: b2Joint;
  return {
    name: 'joints',
    stablePools: true,
    setup() {
      world = new b2World(new b2Vec2(0, -10));
      ground = groundOf(world);
      a = dynamicBody(world, -1, 3);
      a.CreateFixture(box(0.5, 0.5), 1);
      b = dynamicBody(world, 1, 3);
      b.CreateFixture(circle(0.5), 1);
      const ra = new b2RevoluteJointDef();
      ra.Initialize(ground, a, a.GetWorldCenter());
      r1 = world.CreateJoint(ra);
      const rb = new b2RevoluteJointDef();
      rb.Initialize(ground, b, b.GetWorldCenter());
      r2 = world.CreateJoint(rb);
      return world;
    },
    cycle(i) {
      const pa = a.GetWorldCenter();
      const pb = b.GetWorldCenter();
      let def: b2JointDef;
      switch (i % 10) {
        case 0: {
          const d = new b2RevoluteJointDef();
          d.Initialize(a, b, pa);
          def = d;
          break;
        }
        case 1: {
          const d = new b2PrismaticJointDef();
          d.Initialize(a, b, pa, new b2Vec2(1, 0));
          def = d;
          break;
        }
        case 2: {
          const d = new b2DistanceJointDef();
          d.Initialize(a, b, pa, pb);
          def = d;
          break;
        }
        case 3: {
          const d = new b2PulleyJointDef();
          d.Initialize(a, b, new b2Vec2(pa.x, 6), new b2Vec2(pb.x, 6), pa, pb, 1);
          def = d;
          break;
        }
        case 4: {
          const d = new b2MouseJointDef();
          d.bodyA = ground;
          d.bodyB = b;
          d.target.Assign(pb);
          d.maxForce = 10;
          def = d;
          break;
        }
        case 5: {
          const d = new b2GearJointDef();
          d.bodyA = a;
          d.bodyB = b;
          d.joint1 = r1;
          d.joint2 = r2;
          def = d;
          break;
        }
        case 6: {
          const d = new b2WheelJointDef();
          d.Initialize(a, b, pb, new b2Vec2(0, 1));
          def = d;
          break;
        }
        case 7: {
          const d = new b2WeldJointDef();
          d.Initialize(a, b, pa);
          def = d;
          break;
        }
        case 8: {
          const d = new b2FrictionJointDef();
          d.Initialize(a, b, pa);
          def = d;
          break;
        }
        default: {
          const d = new b2RopeJointDef();
          d.bodyA = a;
          d.bodyB = b;
          d.maxLength = 3;
          def = d;
        }
      }
      const j = world.CreateJoint(def);
      world.Step(1 / 60, 8, 3);
      world.DestroyJoint(j);
      return [j];
    },
  };
}

function runCycle(scenario: Scenario, i: number, refs: WeakRef<object>[]): void {
  const dropped = scenario.cycle(i);
  if (i < kSampled) for (const object of dropped) refs.push(new WeakRef(object));
}

async function runScenario(scenario: Scenario, cycles: number, failures: string[], log: (line: string) => void): Promise<LeakScenarioReport> {
  const world = scenario.setup();
  const refs: WeakRef<object>[] = [];
  let heapAfterWarmup = 0;
  let poolsAfterWarmup: Record<string, number> | null = null;
  let maxSample = 0;
  const warmup = Math.min(kWarmup, Math.floor(cycles / 2));
  for (let i = 0; i < cycles; ++i) {
    // In a plain function: a suspended async frame may keep its last loop values alive.
    runCycle(scenario, i, refs);
    if (i + 1 === warmup) {
      await nextTask();
      heapAfterWarmup = heapMB();
      poolsAfterWarmup = world === null ? null : poolSizes(world);
    } else if (i + 1 > warmup && (i + 1) % 1000 === 0) {
      await nextTask();
      maxSample = Math.max(maxSample, heapMB());
    }
  }
  await nextTask();
  const heapEnd = heapMB();
  maxSample = Math.max(maxSample, heapEnd);
  const collected = refs.filter((r) => r.deref() === undefined).length;
  const poolsEnd = world === null ? null : poolSizes(world);
  const name = scenario.name;
  const growthKB = (heapEnd - heapAfterWarmup) * 1024;
  if (collected !== refs.length) failures.push(`${name}: ${refs.length - collected} of ${refs.length} destroyed objects were not collected`);
  if (heapEnd - heapAfterWarmup > kHeapBoundMB)
    failures.push(`${name}: the heap grew by ${growthKB.toFixed(0)} KB after warm-up (bound ${kHeapBoundMB * 1024} KB)`);
  if (maxSample - heapAfterWarmup > kHeapBoundMB)
    failures.push(
      `${name}: the heap reached ${maxSample.toFixed(2)} MB, ${((maxSample - heapAfterWarmup) * 1024).toFixed(0)} KB above its level after warm-up`,
    );
  if (world !== null && poolsAfterWarmup !== null && poolsEnd !== null) {
    if (scenario.stablePools === true) {
      for (const key of Object.keys(poolsEnd)) {
        if (poolsEnd[key] !== poolsAfterWarmup[key]) failures.push(`${name}: ${key} grew from ${poolsAfterWarmup[key]} to ${poolsEnd[key]}`);
      }
    } else {
      // Capacities double as they grow: at most twice what the population can use (plus the TOI island's 64).
      const bodies = world.GetBodyCount();
      const proxies = world.GetProxyCount();
      const limits: Record<string, number> = {
        treeNodeCapacity: 4 * proxies,
        islandBodies: 2 * bodies + 64,
        islandPositions: 2 * bodies + 64,
        islandVelocities: 2 * bodies + 64,
        islandContacts: 16 * proxies,
        stack: bodies,
        queryWrappers: 2,
        rayCastWrappers: 1,
      };
      for (const [key, limit] of Object.entries(limits)) {
        if (poolsEnd[key] > limit) failures.push(`${name}: ${key} is ${poolsEnd[key]}, above ${limit} for ${bodies} bodies and ${proxies} proxies`);
      }
    }
  }
  if (world !== null) {
    const problems = checkWorldInvariants(world);
    if (problems.length > 0) failures.push(`${name}: ${problems.slice(0, 3).join('; ')}`);
  }
  const report: LeakScenarioReport = {
    name,
    cycles,
    heapAfterWarmupMB: heapAfterWarmup,
    heapEndMB: heapEnd,
    growthKB,
    maxSampleMB: maxSample,
    sampled: refs.length,
    collected,
    poolsAfterWarmup,
    poolsEnd,
  };
  log(
    `${name}: ${cycles} cycles, heap ${heapAfterWarmup.toFixed(2)} MB after warm-up, ${heapEnd.toFixed(2)} MB at the end (${growthKB >= 0 ? '+' : ''}${growthKB.toFixed(0)} KB), ${collected}/${refs.length} sampled objects collected` +
      (poolsEnd === null ? '' : `, pools ${JSON.stringify(poolsEnd)}`),
  );
  return report;
}

export async function runLeakChecks(options: { cycles: number; log?: (line: string) => void }): Promise<LeakReport> {
  const log = options.log ?? (() => {});
  const failures: string[] = [];
  const scenarios: LeakScenarioReport[] = [];
  for (const scenario of [worldsScenario(), bodiesScenario(), churnScenario(), fixturesScenario(), jointsScenario()]) {
    scenarios.push(await runScenario(scenario, options.cycles, failures, log));
  }
  const summary = scenarios.map(
    (s) =>
      `${s.name}: ${s.cycles} cycles, heap ${s.growthKB >= 0 ? '+' : ''}${s.growthKB.toFixed(0)} KB after warm-up (max sample ${((s.maxSampleMB - s.heapAfterWarmupMB) * 1024).toFixed(0)} KB above), ${s.collected}/${s.sampled} destroyed objects collected`,
  );
  summary.push(failures.length === 0 ? 'leak checks: all passed' : `leak checks: ${failures.length} failure(s)`);
  return { scenarios, summary, failures };
}
