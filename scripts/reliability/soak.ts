/*
 * The soak run: long mixed simulations with bodies spawned and destroyed as they go, checking
 * that nothing degrades. `npm run soak` runs 100,000 steps (scripts/reliability/run.mjs);
 * test/reliability/soak.test.ts runs a 2,000-step version.
 *
 * Half the steps run a closed box with rain: random boxes, circles and polygons (some bullets,
 * some joined by revolute, distance, weld or rope joints) spawned at the top, impulses, bodies
 * deactivated and reactivated, destroyed at random or when the population is full. The other
 * half runs the golden scenes in turn, each with small bodies spawned above it and destroyed when
 * they fall away or grow old.
 *
 * Checks, with the bounds they use:
 * - no NaN or infinity and every world invariant (test/support/invariants.ts) every 100 steps;
 * - energy, in the rain box (bodies are spawned and reactivated only where they overlap nothing):
 *   its mechanical energy E = sum(m |v|^2 / 2 + I w^2 / 2 + m g (y - y0))
 *   (y0 below the floor, so every term is >= 0) can only fall, except by what the run puts in.
 *   The run keeps that budget exactly: the energy of each spawned or reactivated body, the rise
 *   of E across each impulse, minus the energy of each body destroyed or deactivated. The check is
 *   E <= 1.02 budget + sum(m g) * 0.05 m + 1 J: 2% and 5 cm of lift for position correction,
 *   which may push overlapping bodies apart (energy the contact solver does not conserve).
 * - energy, in the golden scenes (which have motors, so no budget): every body's kinetic energy
 *   stays below what the solver's per-step limits allow, m (b2_maxTranslation / dt)^2 / 2 +
 *   I (b2_maxRotation / dt)^2 / 2; a blow-up pins bodies there.
 * - growth: contacts at most 8 per proxy; the tree's node pool at most 4 nodes per proxy at the
 *   peak and the island and DFS buffers at most twice the peak bodies and contacts, or the TOI
 *   island's 64 bodies and 32 contacts (+ 16: they double as they grow); in a rain box of 10,000
 *   steps or more (a stationary process once full), after the first quarter, each quarter's peaks of bodies,
 *   contacts, proxies, tree nodes and pool sizes within 1.5 times the second quarter's (+ 16);
 *   the heap, in the rain box's world along the way (after a full GC), never more than 8 MB above
 *   its level at the second sample; after each segment (its world dropped) within 8 MB of the
 *   first segment's.
 */

import { b2AABB } from '../../src/collision/b2Collision';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import type { b2Shape } from '../../src/collision/shapes/b2Shape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2_maxRotation, b2_maxTOIContacts, b2_maxTranslation } from '../../src/common/b2Settings';
import { b2Body, b2BodyDef, b2BodyType } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2DistanceJointDef } from '../../src/dynamics/joints/b2DistanceJoint';
import type { b2Joint } from '../../src/dynamics/joints/b2Joint';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { b2RopeJointDef } from '../../src/dynamics/joints/b2RopeJoint';
import { b2WeldJointDef } from '../../src/dynamics/joints/b2WeldJoint';
import { checkWorldInvariants, poolSizes } from '../../test/support/invariants';
import { goldenSceneNames, loadGoldenScene } from '../../test/support/scene';

export interface SoakOptions {
  steps: number;
  seed?: number;
  /** Golden scenes to visit (default: all, in name order). */
  scenes?: string[];
  log?: (line: string) => void;
}

export interface SegmentReport {
  name: string;
  steps: number;
  spawned: number;
  destroyed: number;
  peakBodies: number;
  peakContacts: number;
  peakProxies: number;
  peakTreeNodes: number;
  /** Highest energy / bound ratio seen (must stay <= 1). */
  peakEnergyRatio: number;
  heapAfterMB: number | null;
  /** The heap with the world alive, sampled along the way (the rain box only). */
  heapSamplesMB?: number[];
}

export interface SoakReport {
  steps: number;
  seed: number;
  milliseconds: number;
  segments: SegmentReport[];
  summary: string[];
  failures: string[];
}

/** mulberry32: a small seeded generator, so a soak run reproduces. */
function makeRandom(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function heapMB(): number | null {
  const gc = (globalThis as { gc?: () => void }).gc;
  if (typeof gc !== 'function') return null;
  gc();
  gc();
  return process.memoryUsage().heapUsed / (1024 * 1024);
}

const kGravity = 10;
const kFloor = -1;

function randomShape(random: () => number, scale: number): b2Shape {
  const kind = random();
  if (kind < 0.35) {
    return new b2PolygonShape().SetAsBox(scale * (0.2 + random()), scale * (0.2 + random()));
  }
  if (kind < 0.7) {
    const c = new b2CircleShape();
    c.m_radius = scale * (0.2 + 0.8 * random());
    return c;
  }
  const n = 3 + Math.floor(random() * 6);
  const r = scale * (0.3 + 0.7 * random());
  const phase = random() * Math.PI;
  const vertices: b2Vec2[] = [];
  for (let k = 0; k < n; ++k) {
    const a = phase + (2 * Math.PI * k) / n;
    vertices.push(new b2Vec2(r * Math.cos(a), r * Math.sin(a)));
  }
  return new b2PolygonShape().Set(vertices);
}

/** Is the box (x, y) +- half free of fixtures (fat AABBs)? Spawning into overlap would add energy. */
function isFree(world: b2World, x: number, y: number, half: number): boolean {
  const aabb = new b2AABB();
  aabb.lowerBound.Set(x - half, y - half);
  aabb.upperBound.Set(x + half, y + half);
  let free = true;
  world.QueryAABB(
    {
      ReportFixture: () => {
        free = false;
        return false;
      },
    },
    aabb,
  );
  return free;
}

/** Mechanical energy of a body: kinetic plus potential above kFloor (gravity kGravity). */
function bodyEnergy(b: b2Body): number {
  if (b.m_type !== b2BodyType.b2_dynamicBody || !b.IsActive()) return 0;
  const v = b.m_linearVelocity;
  return 0.5 * b.m_mass * (v.x * v.x + v.y * v.y) + 0.5 * b.m_I * b.m_angularVelocity * b.m_angularVelocity + b.m_mass * kGravity * (b.m_sweep.c.y - kFloor);
}

/**
 * Counts and pool sizes over a segment, by quarter: after the first quarter (warm-up), each
 * quarter's peaks must stay within 1.5 times the second quarter's (+ 16); and at every sample the
 * pools must stay within what the population needs (capacities double, so twice the peak in use).
 */
class Tracker {
  readonly peaks = { bodies: 0, contacts: 0, proxies: 0, treeNodes: 0 };
  readonly quarters: Map<string, number>[] = [new Map(), new Map(), new Map(), new Map()];

  constructor(
    readonly name: string,
    readonly steps: number,
    readonly failures: string[],
    /** Compare quarters (a stationary run: the rain box, not a golden scene collapsing). */
    readonly stationary: boolean,
  ) {}

  sample(world: b2World, step: number): void {
    const pools = poolSizes(world);
    const counts: Record<string, number> = {
      bodies: world.GetBodyCount(),
      contacts: world.GetContactCount(),
      proxies: world.GetProxyCount(),
      treeNodes: world.m_contactManager.m_broadPhase.m_tree.m_nodeCount,
      ...pools,
    };
    const p = this.peaks;
    p.bodies = Math.max(p.bodies, counts.bodies);
    p.contacts = Math.max(p.contacts, counts.contacts);
    p.proxies = Math.max(p.proxies, counts.proxies);
    p.treeNodes = Math.max(p.treeNodes, counts.treeNodes);
    const where = `${this.name} step ${step}`;
    if (counts.contacts > 8 * counts.proxies + 8) this.failures.push(`${where}: ${counts.contacts} contacts for ${counts.proxies} proxies`);
    // The TOI solve sizes the island for 2 * b2_maxTOIContacts bodies and b2_maxTOIContacts contacts.
    const islandBodies = Math.max(2 * b2_maxTOIContacts, 2 * p.bodies) + 16;
    const limits: [string, number][] = [
      ['treeNodeCapacity', 2 * (2 * p.proxies) + 16],
      ['islandBodies', islandBodies],
      ['islandPositions', islandBodies],
      ['islandVelocities', islandBodies],
      ['islandContacts', Math.max(b2_maxTOIContacts, 2 * p.contacts) + 16],
      ['stack', 2 * p.bodies + 16],
      ['queryWrappers', 4],
      ['rayCastWrappers', 4],
    ];
    for (const [key, limit] of limits) {
      if (counts[key] > limit) this.failures.push(`${where}: ${key} is ${counts[key]}, above its bound ${limit}`);
    }
    const quarter = this.quarters[Math.min(3, Math.floor((4 * step) / this.steps))];
    for (const [key, value] of Object.entries(counts)) quarter.set(key, Math.max(quarter.get(key) ?? 0, value));
  }

  finish(): void {
    if (!this.stationary) return;
    const base = this.quarters[1];
    for (let q = 2; q < 4; ++q) {
      for (const [key, late] of this.quarters[q]) {
        const early = base.get(key);
        if (early !== undefined && late > 1.5 * early + 16) {
          this.failures.push(`${this.name}: ${key} grew from a peak of ${early} in the second quarter to ${late} in quarter ${q + 1}`);
        }
      }
    }
  }
}

function checkWorld(world: b2World, where: string, failures: string[]): boolean {
  const problems = checkWorldInvariants(world);
  if (problems.length === 0) return true;
  failures.push(`${where}: ${problems.slice(0, 3).join('; ')}`);
  return false;
}

/** The closed box with rain (see the header). */
function rainBox(steps: number, random: () => number, failures: string[], log: (line: string) => void): SegmentReport {
  const name = 'rain-box';
  const world = new b2World(new b2Vec2(0, -kGravity));
  const ground = world.CreateBody(new b2BodyDef());
  const walls = new b2ChainShape();
  walls.CreateLoop([new b2Vec2(-20, 0), new b2Vec2(20, 0), new b2Vec2(20, 40), new b2Vec2(-20, 40)]);
  ground.CreateFixture(walls, 0);
  ground.CreateFixture(new b2EdgeShape().Set(new b2Vec2(-10, 8), new b2Vec2(2, 6)), 0);
  const shelf = new b2PolygonShape().SetAsBox(4, 0.25, new b2Vec2(8, 14), -0.2);
  ground.CreateFixture(shelf, 0);

  const dt = 1 / 60;
  const live: b2Body[] = [];
  const inactive: b2Body[] = [];
  const joints: b2Joint[] = [];
  let budget = 0;
  let massWeight = 0;
  let spawned = 0;
  let destroyed = 0;
  let peakRatio = 0;
  // It fills for a few thousand steps; only a long run is stationary enough to compare quarters.
  const tracker = new Tracker(name, steps, failures, steps >= 10_000);
  const heapSamples: number[] = [];

  const destroy = (b: b2Body) => {
    budget -= bodyEnergy(b);
    for (let je = b.m_jointList; je; je = je.next) {
      const k = joints.indexOf(je.joint);
      if (k >= 0) joints.splice(k, 1);
    }
    world.DestroyBody(b);
    ++destroyed;
  };

  for (let step = 0; step < steps; ++step) {
    // Spawn.
    const x = -18 + 36 * random();
    const y = 25 + 13 * random();
    // Shapes reach at most 0.8 * 1.2 * sqrt(2) from their origin.
    if (step % 3 === 0 && live.length < 140 && isFree(world, x, y, 1.5)) {
      const bd = new b2BodyDef();
      bd.type = b2BodyType.b2_dynamicBody;
      bd.position.Set(x, y);
      bd.angle = 6 * random();
      bd.linearVelocity.Set(20 * (random() - 0.5), 20 * (random() - 0.5));
      bd.angularVelocity = 10 * (random() - 0.5);
      bd.bullet = random() < 0.05;
      const b = world.CreateBody(bd);
      const fd = new b2FixtureDef();
      fd.shape = randomShape(random, 0.8);
      fd.density = 0.5 + 1.5 * random();
      fd.friction = 0.6 * random();
      fd.restitution = 0.5 * random();
      b.CreateFixture(fd);
      budget += bodyEnergy(b);
      massWeight += b.m_mass * kGravity;
      live.push(b);
      ++spawned;
      if (random() < 0.15 && live.length > 1) {
        const other = live[Math.floor(random() * (live.length - 1))];
        const pa = b.GetWorldCenter();
        const pb = other.GetWorldCenter();
        const kind = random();
        let joint: b2Joint;
        if (kind < 0.25) {
          const d = new b2RevoluteJointDef();
          d.Initialize(b, other, new b2Vec2(0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y)));
          joint = world.CreateJoint(d);
        } else if (kind < 0.5) {
          const d = new b2DistanceJointDef();
          d.Initialize(b, other, pa, pb);
          d.frequencyHz = random() < 0.5 ? 0 : 3;
          d.dampingRatio = 0.5;
          joint = world.CreateJoint(d);
        } else if (kind < 0.75) {
          const d = new b2WeldJointDef();
          d.Initialize(b, other, pa);
          joint = world.CreateJoint(d);
        } else {
          const d = new b2RopeJointDef();
          d.bodyA = b;
          d.bodyB = other;
          d.maxLength = Math.hypot(pb.x - pa.x, pb.y - pa.y) + 1;
          joint = world.CreateJoint(d);
        }
        joints.push(joint);
      }
    }
    // Churn: destroy, impulse, deactivate or reactivate, destroy a joint.
    const event = random();
    if (live.length > 0 && (event < 0.12 || live.length >= 140)) {
      const k = Math.floor(random() * live.length);
      const b = live[k];
      live.splice(k, 1);
      massWeight -= b.m_mass * kGravity;
      destroy(b);
    } else if (live.length > 0 && event < 0.2) {
      const b = live[Math.floor(random() * live.length)];
      const before = bodyEnergy(b);
      b.ApplyLinearImpulse(new b2Vec2(b.m_mass * 8 * (random() - 0.5), b.m_mass * 8 * random()), b.GetWorldCenter());
      budget += Math.max(0, bodyEnergy(b) - before);
    } else if (live.length > 0 && event < 0.23) {
      const k = Math.floor(random() * live.length);
      const b = live[k];
      budget -= bodyEnergy(b);
      b.SetActive(false);
      live.splice(k, 1);
      inactive.push(b);
    } else if (inactive.length > 0 && event < 0.26) {
      // Only where it overlaps nothing now (position correction would push it out, adding energy).
      const b = inactive[inactive.length - 1];
      if (isFree(world, b.m_sweep.c.x, b.m_sweep.c.y, 1.5)) {
        inactive.pop();
        b.SetActive(true);
        budget += bodyEnergy(b);
        live.push(b);
      }
    } else if (joints.length > 0 && event < 0.28) {
      world.DestroyJoint(joints.splice(Math.floor(random() * joints.length), 1)[0]);
    }
    // Inactive bodies that found no free place to come back to are destroyed (their energy has left the budget).
    if (inactive.length > 10) destroy(inactive.shift() as b2Body);

    world.Step(dt, 8, 3);

    // Bodies that tunnelled out and fell away leave the budget with their energy.
    for (let k = live.length - 1; k >= 0; --k) {
      if (live[k].m_sweep.c.y < -50) {
        const b = live[k];
        live.splice(k, 1);
        massWeight -= b.m_mass * kGravity;
        destroy(b);
      }
    }

    let energy = 0;
    for (const b of live) energy += bodyEnergy(b);
    const bound = 1.02 * budget + 0.05 * massWeight + 1;
    peakRatio = Math.max(peakRatio, energy / bound);
    if (!(energy <= bound)) {
      failures.push(`${name} step ${step}: mechanical energy ${energy.toFixed(1)} J exceeds the bound ${bound.toFixed(1)} J`);
      break;
    }
    if (step % 100 === 99) {
      if (!checkWorld(world, `${name} step ${step}`, failures)) break;
      tracker.sample(world, step);
    }
    // The heap with the world alive, each tenth of the way (after the first): it must not trend up.
    if (steps >= 10_000 && (step + 1) % Math.floor(steps / 10) === 0) {
      const heap = heapMB();
      if (heap !== null) {
        heapSamples.push(heap);
        log(`rain-box step ${step + 1}: ${live.length} live bodies, ${world.GetContactCount()} contacts, heap ${heap.toFixed(1)} MB`);
      }
    }
  }
  tracker.finish();
  if (heapSamples.length >= 4) {
    const settled = heapSamples[1];
    const peak = Math.max(...heapSamples.slice(2));
    if (peak > settled + 8) failures.push(`${name}: the heap grew from ${settled.toFixed(1)} MB to ${peak.toFixed(1)} MB while running (bound 8 MB)`);
  }
  return {
    name,
    steps,
    spawned,
    destroyed,
    peakBodies: tracker.peaks.bodies,
    peakContacts: tracker.peaks.contacts,
    peakProxies: tracker.peaks.proxies,
    peakTreeNodes: tracker.peaks.treeNodes,
    peakEnergyRatio: peakRatio,
    heapAfterMB: null,
    heapSamplesMB: heapSamples,
  };
}

/** A golden scene with small bodies raining on it (see the header). */
function goldenSegment(name: string, steps: number, random: () => number, failures: string[]): SegmentReport {
  const scene = loadGoldenScene(name);
  const world = scene.world;
  const dt = 1 / scene.stepSettings.stepsPerSecond;
  const maxSpeed = b2_maxTranslation / dt;
  const maxSpin = b2_maxRotation / dt;

  // The scene's extent, from its fixtures' AABBs at load.
  const box = new b2AABB();
  box.lowerBound.Set(Infinity, Infinity);
  box.upperBound.Set(-Infinity, -Infinity);
  for (let b = world.GetBodyList(); b; b = b.GetNext()) {
    for (let f = b.GetFixtureList(); f; f = f.GetNext()) {
      for (let c = 0; c < f.m_proxyCount; ++c) box.Combine(f.GetAABB(c));
    }
  }
  if (!Number.isFinite(box.lowerBound.x)) {
    box.lowerBound.Set(-10, -10);
    box.upperBound.Set(10, 10);
  }
  const width = Math.min(40, box.upperBound.x - box.lowerBound.x);
  const centerX = 0.5 * (box.lowerBound.x + box.upperBound.x);
  const top = box.upperBound.y;
  const bottom = box.lowerBound.y - 30;

  const spawnedBodies: { body: b2Body; born: number }[] = [];
  let spawned = 0;
  let destroyed = 0;
  let peakRatio = 0;
  const tracker = new Tracker(name, steps, failures, false);
  for (let step = 0; step < steps; ++step) {
    if (step % 20 === 0 && spawnedBodies.length < 30) {
      const bd = new b2BodyDef();
      bd.type = b2BodyType.b2_dynamicBody;
      bd.position.Set(centerX + width * (random() - 0.5), top + 2 + 5 * random());
      bd.linearVelocity.Set(4 * (random() - 0.5), -5 * random());
      const b = world.CreateBody(bd);
      b.CreateFixture(randomShape(random, 0.4), 0.5 + random());
      spawnedBodies.push({ body: b, born: step });
      ++spawned;
    }
    for (let k = spawnedBodies.length - 1; k >= 0; --k) {
      const { body, born } = spawnedBodies[k];
      if (body.m_sweep.c.y < bottom || step - born > 600) {
        world.DestroyBody(body);
        spawnedBodies.splice(k, 1);
        ++destroyed;
      }
    }
    scene.step();
    for (let b = world.GetBodyList(); b; b = b.GetNext()) {
      if (b.m_type !== b2BodyType.b2_dynamicBody) continue;
      const v = b.m_linearVelocity;
      const ke = 0.5 * b.m_mass * (v.x * v.x + v.y * v.y) + 0.5 * b.m_I * b.m_angularVelocity * b.m_angularVelocity;
      const cap = 0.5 * b.m_mass * maxSpeed * maxSpeed + 0.5 * b.m_I * maxSpin * maxSpin;
      // A little headroom: the cap limits the per-step motion, velocities may exceed it slightly.
      const ratio = ke / (1.01 * cap + 1e-9);
      peakRatio = Math.max(peakRatio, ratio);
      if (!(ratio <= 1)) {
        failures.push(`${name} step ${step}: a body's kinetic energy ${ke} exceeds the solver's limit ${cap}`);
        step = steps;
        break;
      }
    }
    if (step % 100 === 99) {
      if (!checkWorld(world, `${name} step ${step}`, failures)) break;
      tracker.sample(world, step);
    }
  }
  tracker.finish();
  return {
    name,
    steps,
    spawned,
    destroyed,
    peakBodies: tracker.peaks.bodies,
    peakContacts: tracker.peaks.contacts,
    peakProxies: tracker.peaks.proxies,
    peakTreeNodes: tracker.peaks.treeNodes,
    peakEnergyRatio: peakRatio,
    heapAfterMB: null,
  };
}

export function runSoak(options: SoakOptions): SoakReport {
  const seed = options.seed ?? 1;
  const log = options.log ?? (() => {});
  const random = makeRandom(seed);
  const failures: string[] = [];
  const segments: SegmentReport[] = [];
  const start = performance.now();

  const rainSteps = Math.ceil(options.steps / 2);
  const scenes = options.scenes ?? goldenSceneNames();
  const goldenSteps = options.steps - rainSteps;
  const perScene = Math.max(1, Math.floor(goldenSteps / scenes.length));

  const rainReport = rainBox(rainSteps, random, failures, log);
  rainReport.heapAfterMB = heapMB();
  segments.push(rainReport);
  log(
    `rain-box: ${rainSteps} steps, ${rainReport.spawned} spawned, peak ${rainReport.peakBodies} bodies, ${rainReport.peakContacts} contacts, energy <= ${(100 * rainReport.peakEnergyRatio).toFixed(1)}% of its bound`,
  );
  let remaining = goldenSteps;
  for (let i = 0; i < scenes.length && remaining > 0 && failures.length === 0; ++i) {
    const n = i === scenes.length - 1 ? remaining : Math.min(perScene, remaining);
    const report = goldenSegment(scenes[i], n, random, failures);
    report.heapAfterMB = heapMB();
    segments.push(report);
    remaining -= n;
    log(
      `${scenes[i]}: ${n} steps, ${report.spawned} spawned, peak ${report.peakBodies} bodies, ${report.peakContacts} contacts, kinetic energy <= ${(100 * report.peakEnergyRatio).toFixed(2)}% of the solver limit`,
    );
  }

  const heaps = segments.map((s) => s.heapAfterMB).filter((h): h is number => h !== null);
  if (heaps.length > 1) {
    const growth = Math.max(...heaps.slice(1)) - heaps[0];
    if (growth > 8) failures.push(`the heap after a segment grew by ${growth.toFixed(1)} MB over the run (bound 8 MB)`);
  }
  const steps = segments.reduce((n, s) => n + s.steps, 0);
  const milliseconds = performance.now() - start;
  const rain = segments.filter((s) => s.name === 'rain-box');
  const golden = segments.filter((s) => s.name !== 'rain-box');
  const summary = [
    `soak: ${steps} steps (seed ${seed}) in ${(milliseconds / 1000).toFixed(1)} s, ${failures.length === 0 ? 'all checks passed' : `${failures.length} failure(s)`}`,
    `rain box: ${rain.reduce((n, s) => n + s.steps, 0)} steps, ${rain.reduce((n, s) => n + s.spawned, 0)} bodies spawned, ${rain.reduce((n, s) => n + s.destroyed, 0)} destroyed, peak ${Math.max(0, ...rain.map((s) => s.peakBodies))} bodies / ${Math.max(0, ...rain.map((s) => s.peakContacts))} contacts / ${Math.max(0, ...rain.map((s) => s.peakProxies))} proxies, energy at most ${(100 * Math.max(0, ...rain.map((s) => s.peakEnergyRatio))).toFixed(1)}% of its budget bound`,
    `golden scenes: ${golden.length} visited, ${golden.reduce((n, s) => n + s.steps, 0)} steps, ${golden.reduce((n, s) => n + s.spawned, 0)} bodies spawned, kinetic energy at most ${(100 * Math.max(0, ...golden.map((s) => s.peakEnergyRatio))).toFixed(2)}% of the solver limit`,
    heaps.length > 0
      ? `heap after each segment (full GC): first ${heaps[0].toFixed(1)} MB, min ${Math.min(...heaps).toFixed(1)} MB, max ${Math.max(...heaps).toFixed(1)} MB, last ${heaps[heaps.length - 1].toFixed(1)} MB`
      : 'heap not measured (run under node --expose-gc)',
  ];
  return { steps, seed, milliseconds, segments, summary, failures };
}
