// The accuracy study's measures (bench/accuracy/): each on a case whose answer is known, with the
// engine itself; and the limit search on synthetic tests whose limit is known.
import { mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { describe, expect, it } from 'vitest';
import * as b2 from '../../src/index';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Rot, b2Vec2 } from '../../src/common/b2Math';
import { b2_linearSlop, b2_polygonRadius } from '../../src/common/b2Settings';
import { b2BodyDef, b2_dynamicBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { b2WeldJointDef } from '../../src/dynamics/joints/b2WeldJoint';
import { agm, freeFall, pendulumPeriod, projectileRange } from '../../bench/accuracy/analytic.mjs';
import { bisectLimit } from '../../bench/accuracy/limits.mjs';
import { mergeStudies } from '../../bench/accuracy/merge.mjs';
import { loadPeers, peerLimits, runAccuracy, writeAccuracy } from '../../bench/accuracy/run.mjs';
import { energyAndMomentum, jointErrors, penetration, restingDrift, trajectoryError } from '../../bench/accuracy/measures.mjs';
import { buildScene } from '../../bench/accuracy/scenes.mjs';

const DT = 1 / 60;

function body(world: b2World, x: number, y: number, dynamic: boolean, angle = 0): b2Body {
  const def = new b2BodyDef();
  if (dynamic) def.type = b2_dynamicBody;
  def.position.Set(x, y);
  def.angle = angle;
  return world.CreateBody(def);
}

function box(b: b2Body, hx: number, hy: number): void {
  const s = new b2PolygonShape();
  s.SetAsBox(hx, hy);
  b.CreateFixture(s, 1);
}

function circle(b: b2Body, radius: number): void {
  const s = new b2CircleShape();
  s.m_radius = radius;
  b.CreateFixture(s, 1);
}

describe('analytic answers', () => {
  it('free fall: n steps of the engine are semi-implicit Euler to rounding, and its error against the exact fall is g dt t / 2', () => {
    const world = new b2World(new b2Vec2(0, -10));
    const ball = body(world, 0, 100, true);
    circle(ball, 0.5);
    ball.SetLinearVelocity(new b2Vec2(0, 3));
    for (let n = 1; n <= 60; ++n) {
      world.Step(DT, 8, 3);
      const { steps, exact } = freeFall(100, 3, -10, DT, n);
      expect(ball.GetPosition().y).toBeCloseTo(steps.y, 10);
      expect(ball.GetLinearVelocity().y).toBeCloseTo(steps.v, 10);
      expect(steps.y - exact.y).toBeCloseTo((-10 * DT * n * DT) / 2, 12);
    }
  });

  it('the pendulum period: the arithmetic-geometric mean gives K(k) (the small-angle limit 2 pi sqrt(L / g); 60 degrees 7.32 % longer)', () => {
    expect(agm(1, 1)).toBe(1);
    expect(agm(24, 6)).toBeCloseTo(13.458171481725615, 12);
    const small = pendulumPeriod(1, 9.81, 1e-6);
    expect(small).toBeCloseTo(2 * Math.PI * Math.sqrt(1 / 9.81), 9);
    expect(pendulumPeriod(1, 9.81, Math.PI / 3) / small).toBeCloseTo(1.07318, 5);
  });

  it("the engine's pendulum converges to the exact elliptic period at first order in dt (1 % short at 60 Hz, under 0.1 % at 960 Hz)", () => {
    const L = 2;
    const r = 0.1;
    const amplitude = Math.PI / 3;
    // A disc of radius r whose centre is L from the pivot: I_pivot = m (r² / 2 + L²).
    const expected = pendulumPeriod((r * r) / 2 / L + L, 10, amplitude);
    const relativeError = (hz: number): number => {
      const dt = 1 / hz;
      const world = new b2World(new b2Vec2(0, -10));
      const ground = body(world, 0, 0, false);
      const q = new b2Rot(amplitude);
      const bob = body(world, L * q.s, -L * q.c, true);
      circle(bob, r);
      const jd = new b2RevoluteJointDef();
      jd.Initialize(ground, bob, new b2Vec2(0, 0));
      world.CreateJoint(jd);
      // Crossings of x = 0 moving right, interpolated within the step.
      const crossings: number[] = [];
      let prev = bob.GetPosition().x;
      for (let n = 1; n <= 20 * hz && crossings.length < 3; ++n) {
        world.Step(dt, 8, 3);
        const x = bob.GetPosition().x;
        if (prev < 0 && x >= 0) crossings.push((n - 1 + -prev / (x - prev)) * dt);
        prev = x;
      }
      expect(crossings.length).toBe(3);
      expect(jointErrors(world).linear).toBeLessThan(b2_linearSlop);
      return ((crossings[2] - crossings[0]) / 2 - expected) / expected;
    };
    const e60 = relativeError(60);
    const e240 = relativeError(240);
    const e960 = relativeError(960);
    expect(Math.abs(e60)).toBeLessThan(0.015);
    expect(e60 / e240).toBeGreaterThan(3);
    expect(e60 / e240).toBeLessThan(5);
    expect(e240 / e960).toBeGreaterThan(3);
    expect(e240 / e960).toBeLessThan(5);
    expect(Math.abs(e960)).toBeLessThan(0.001);
  });

  it('free flight without gravity or damping conserves kinetic energy and linear momentum exactly, and angular momentum to rounding', () => {
    const world = new b2World(new b2Vec2(0, 0));
    const a = body(world, 0, 0, true, 0.3);
    box(a, 0.5, 0.25);
    a.SetLinearVelocity(new b2Vec2(1.5, -0.25));
    a.SetAngularVelocity(2);
    const b = body(world, 30, 5, true);
    circle(b, 0.4);
    b.SetLinearVelocity(new b2Vec2(-0.5, 0.75));
    const before = energyAndMomentum(world);
    for (let n = 0; n < 600; ++n) world.Step(DT, 8, 3);
    const after = energyAndMomentum(world);
    expect(after.kinetic).toBe(before.kinetic);
    expect(after.momentum).toEqual(before.momentum);
    expect(after.angular).toBeCloseTo(before.angular, 9);
    expect(before.kinetic).toBeGreaterThan(0.5);
  });

  it("a projectile lands short by v_x dt of the exact range v² sin(2θ) / g (semi-implicit Euler's lag: 1.18 % at 60 Hz), a quarter of that with 4 sub-steps", async () => {
    expect(projectileRange(10, Math.PI / 4, 10)).toBeCloseTo(10, 12);
    const run = await runAccuracy(b2, { scenes: ['projectile'], methods: ['iter-8-3', 'substeps-4'], limits: false, rounds: 1 });
    const [frame, substeps] = run.scenes[0].results.map((r) => r.measures['range error']);
    const lag = (10 / Math.sqrt(2)) * DT;
    expect(frame).toBeCloseTo(lag / 10, 4);
    expect(substeps).toBeCloseTo(lag / 4 / 10, 4);
  });
});

describe('the collision scene in free space', () => {
  it('conserves linear momentum to rounding on the engine, and reports the energy and angular momentum drifts', async () => {
    const run = await runAccuracy(b2, { scenes: ['collide'], methods: ['iter-8-3'], limits: false, rounds: 1 });
    const m = run.scenes[0].results[0].measures;
    expect(m['momentum drift']).toBeLessThan(1e-12);
    expect(m['energy drift']).toBeGreaterThan(0);
    expect(m['energy drift']).toBeLessThan(0.01);
    expect(m['angular momentum drift']).toBeLessThan(1e-3);
  });
});

describe('the mechanisms scene', () => {
  it('builds every joint kind with a position constraint but the wheel and rope, and its joint errors fall with sub-steps', async () => {
    const { world } = buildScene(b2, 'mechanisms');
    const kinds = new Map<number, number>();
    for (let j = world.GetJointList(); j !== null; j = j.GetNext()) kinds.set(j.GetType(), (kinds.get(j.GetType()) ?? 0) + 1);
    expect(Object.fromEntries(kinds)).toEqual({
      [b2.b2JointType.e_revoluteJoint]: 20,
      [b2.b2JointType.e_gearJoint]: 1,
      [b2.b2JointType.e_prismaticJoint]: 1,
      [b2.b2JointType.e_pulleyJoint]: 1,
      [b2.b2JointType.e_weldJoint]: 3,
    });
    const run = await runAccuracy(b2, { scenes: ['mechanisms'], methods: ['iter-8-3', 'substeps-4'], limits: false, rounds: 1 });
    const [frame, substeps] = run.scenes[0].results.map((r) => r.measures);
    expect(frame['joint error']).toBeGreaterThan(0);
    expect(substeps['joint error']).toBeLessThan(frame['joint error'] / 2);
    expect(substeps['joint angle error']).toBeLessThan(frame['joint angle error'] / 2);
  });
});

describe('measures on states whose answer is known', () => {
  it("penetration, from the shapes alone: two circles 0.1 m into each other, two boxes 0.05 m (plus the polygons' skins), a ball on a chain", () => {
    const world = new b2World(new b2Vec2(0, 0));
    circle(body(world, 0, 0, true), 0.5);
    circle(body(world, 0.9, 0, true), 0.5);
    box(body(world, 10, 0, true), 0.5, 0.5);
    box(body(world, 10.95, 0, true), 0.5, 0.5);
    // Apart: a box and a circle 0.2 m from each other, a static pair overlapping (not counted).
    box(body(world, 20, 0, true), 0.5, 0.5);
    circle(body(world, 21, 0, true), 0.3);
    box(body(world, 30, 0, false), 1, 1);
    box(body(world, 30.5, 0, false), 1, 1);
    const p = penetration(b2, world);
    // Circles: one point at 0.1; boxes: two points at 0.05 + 2 b2_polygonRadius (the radius skin).
    expect(p.points).toBe(3);
    expect(p.max).toBeCloseTo(0.1, 12);
    expect(p.mean).toBeCloseTo((0.1 + 2 * (0.05 + 2 * b2_polygonRadius)) / 3, 12);
    // A ball sunk 0.05 m into a chain's second edge.
    const chainWorld = new b2World(new b2Vec2(0, 0));
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(-2, 0), new b2Vec2(0, 0), new b2Vec2(2, 0)], 3);
    body(chainWorld, 0, 0, false).CreateFixture(chain, 0);
    circle(body(chainWorld, 1, 0.45, true), 0.5);
    const q = penetration(b2, chainWorld);
    expect(q.points).toBe(1);
    expect(q.max).toBeCloseTo(0.05 + b2_polygonRadius, 12);
  });

  it('penetration of a box resting on the ground settles to what Box2D allows (b2_linearSlop into the skins)', () => {
    const world = new b2World(new b2Vec2(0, -10));
    box(body(world, 0, 0, false), 10, 0.5);
    box(body(world, 0, 1.2, true), 0.5, 0.5);
    for (let n = 0; n < 180; ++n) world.Step(DT, 8, 3);
    const p = penetration(b2, world);
    expect(p.points).toBe(2);
    expect(p.max).toBeGreaterThan(0.5 * b2_linearSlop);
    expect(p.max).toBeLessThan(1.5 * b2_linearSlop);
  });

  it('joint error: a revolute joint whose anchors are 0.1 m apart and a weld 0.2 rad off its reference angle', () => {
    const world = new b2World(new b2Vec2(0, 0));
    const a = body(world, 0, 0, false);
    const b = body(world, 1, 0, true);
    circle(b, 0.2);
    const rev = new b2RevoluteJointDef();
    rev.Initialize(a, b, new b2Vec2(1, 0));
    rev.localAnchorB.Set(0.1, 0);
    world.CreateJoint(rev);
    expect(jointErrors(world)).toEqual({ linear: expect.closeTo(0.1, 12), angular: 0, joints: 1 });
    const c = body(world, 5, 0, true, 0.2);
    circle(c, 0.2);
    const weld = new b2WeldJointDef();
    weld.bodyA = a;
    weld.bodyB = c;
    weld.localAnchorA.Set(5, 0);
    world.CreateJoint(weld);
    const e = jointErrors(world);
    expect(e.angular).toBeCloseTo(0.2, 12);
    expect(e.linear).toBeCloseTo(0.1, 12);
    expect(e.joints).toBe(2);
  });

  it('trajectory error and resting drift between snapshots of the same bodies', () => {
    const world = new b2World(new b2Vec2(0, 0));
    const a = body(world, 0, 0, true);
    circle(a, 0.5);
    const b = body(world, 3, 4, true);
    circle(b, 0.5);
    const snapshot = () => Float64Array.from([a, b].flatMap((body) => [body.GetPosition().x, body.GetPosition().y]));
    const before = snapshot();
    a.SetTransform(new b2Vec2(0.3, 0.4), 0);
    const after = snapshot();
    expect(trajectoryError(before, after).max).toBeCloseTo(0.5, 12);
    expect(trajectoryError(before, after).rms).toBeCloseTo(Math.sqrt(0.25 / 2), 12);
    expect(restingDrift(before, before)).toBe(0);
    expect(() => trajectoryError(before, new Float64Array(2))).toThrow(/snapshots of 2 and 1 bodies/);
  });
});

describe('bisectLimit', () => {
  it('finds the largest passing value of a monotone test to the tolerance', async () => {
    const r = await bisectLimit((x: number) => x <= 7.3, 0, 100, { tolerance: 1e-6 });
    expect(r.outside).toBeNull();
    expect(r.limit).toBeLessThanOrEqual(7.3);
    expect(7.3 - r.limit!).toBeLessThan(1e-6);
    expect(r.tests).toBeLessThan(40);
  });

  it('finds an integer limit exactly, largest or smallest, in about log2(range) tests', async () => {
    const largest = await bisectLimit((n: number) => n <= 42, 1, 1000, { integer: true });
    expect(largest.limit).toBe(42);
    expect(largest.bracket).toEqual([42, 43]);
    expect(largest.tests).toBeLessThanOrEqual(12);
    const smallest = await bisectLimit(async (n: number) => n >= 5, 0, 100, { integer: true, smallest: true });
    expect(smallest.limit).toBe(5);
    expect(smallest.bracket).toEqual([5, 4]);
  });

  it('says when the limit lies outside the range, and rejects a bad range', async () => {
    expect(await bisectLimit(() => false, 0, 10)).toMatchObject({ limit: null, outside: 'below' });
    expect(await bisectLimit(() => true, 0, 10)).toMatchObject({ limit: 10, outside: 'above' });
    await expect(bisectLimit(() => true, 5, 5)).rejects.toThrow(/lo \(5\) must be finite and below hi \(5\)/);
  });
});

describe('runAccuracy --quick', () => {
  it('measures each scene under each method, marks the Pareto front, finds the stability limits, and writes JSON, Markdown and one chart per measure', async () => {
    const run = await runAccuracy(b2, { quick: true });
    expect(run.schema).toBe('webphysics-accuracy/1');
    expect(run.scenes.map((s) => s.id)).toEqual(['pendulum', 'bounce', 'slide', 'chain']);
    for (const scene of run.scenes) {
      expect(scene.results.map((r) => r.method)).toEqual(['iter-2-1', 'iter-8-3', 'substeps-2']);
      for (const r of scene.results) expect(r.msPerSecond).toBeGreaterThan(0);
      for (const measure of scene.measures) {
        // The front gets cheaper-to-dearer and better at each point.
        const front = scene.fronts[measure].map((key) => scene.results.find((r) => r.key === key)!);
        expect(front.length).toBeGreaterThan(0);
        for (let i = 1; i < front.length; ++i) {
          expect(front[i].msPerSecond).toBeGreaterThanOrEqual(front[i - 1].msPerSecond!);
          expect(front[i].measures[measure]).toBeLessThan(front[i - 1].measures[measure]);
        }
      }
    }
    // The pendulum at 8/3 and 60 Hz: 1.05 % short, as the analytic test above finds; 2 substeps halve it.
    const pendulum = run.scenes[0].results;
    expect(pendulum[1].measures['period error']).toBeCloseTo(0.0105, 3);
    expect(pendulum[2].measures['period error']).toBeLessThan(0.6 * pendulum[1].measures['period error']);
    const limit = (id: string) => run.limits.find((l) => l.id === id)!;
    // Without continuous physics a 0.05 m plate stops a 0.1 m ball only while no step can land past its middle.
    expect(limit('tunnelling speed').limit).toBeGreaterThan(6);
    expect(limit('tunnelling speed').limit).toBeLessThan(16);
    expect(limit('tunnelling speed (continuous)').outside).toBe('above');
    const dir = mkdtempSync(path.join(tmpdir(), 'accuracy-'));
    try {
      const files = writeAccuracy(run, dir).map((f) => path.basename(f));
      expect(files).toContain('accuracy.json');
      expect(files).toContain('accuracy-pendulum-period-error.svg');
      expect(JSON.parse(readFileSync(path.join(dir, 'accuracy.json'), 'utf8')).scenes).toHaveLength(4);
      expect(readFileSync(path.join(dir, 'accuracy.md'), 'utf8')).toMatch(/## Stability limits/);
      expect(readFileSync(path.join(dir, 'accuracy-chain-joint-error.svg'), 'utf8')).toMatch(/^<svg[\s\S]*<polyline[\s\S]*<\/svg>\n$/);
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
});

describe('merging parts of a study run apart', () => {
  it("puts another run's scenes and limits in place of the same scenes' and methods', and names the device a GPU limit was found on", () => {
    const limit = (method: string, value: number) => ({
      id: 'stack height',
      test: 'a column',
      unit: 'boxes',
      method,
      range: [2, 80] as [number, number],
      smallest: false,
      limit: value,
      tests: 7,
      bracket: [value, value + 1] as [number, number],
      outside: null,
    });
    const scene = (id: string, drift: number) => ({
      id,
      title: id,
      seconds: 1,
      measures: ['drift'],
      results: [{ key: 'iter-8-3', method: 'iter-8-3', backend: 'js', msPerSecond: 1, measures: { drift } }],
      fronts: { drift: ['iter-8-3'] },
    });
    const run = (gpu: object | null, limits: ReturnType<typeof limit>[], scenes: ReturnType<typeof scene>[] = []) => ({
      schema: 's',
      date: 'd',
      quick: false,
      machine: { cpus: 1, cpuModel: 'cpu', node: 'v20', gpu },
      methods: [],
      peers: [],
      scenes,
      limits,
    });
    const base = run({ device: 'swiftshader', software: true }, [limit('iter-8-3', 31), limit('webgpu iter-8-3', 19)], [scene('stack', 1), scene('chain', 2)]);
    const h100 = run({ device: 'nvidia-h100' }, [limit('webgpu iter-8-3', 20), limit('webgpu iter-4-2', 15)]);
    const newScenes = run(null, [], [scene('chain', 3), scene('projectile', 4)]);
    const merged = mergeStudies(base, [h100, newScenes]);
    expect(merged.scenes.map((s) => [s.id, s.results[0].measures.drift])).toEqual([
      ['stack', 1],
      ['chain', 3],
      ['projectile', 4],
    ]);
    expect(merged.limits.map((l) => [l.method, l.limit, l.device])).toEqual([
      ['iter-8-3', 31, undefined],
      ['webgpu iter-8-3', 20, 'nvidia-h100'],
      ['webgpu iter-4-2', 15, 'nvidia-h100'],
    ]);
    expect(base.limits).toHaveLength(2);
    const dir = mkdtempSync(path.join(tmpdir(), 'accuracy-'));
    try {
      writeAccuracy(merged, dir);
      expect(readFileSync(path.join(dir, 'accuracy.md'), 'utf8')).toMatch(/\| WebGPU, iter-8-3[^|]* \(on nvidia-h100\) \| 20\.0 \|/);
    } finally {
      rmSync(dir, { recursive: true, force: true });
    }
  });
});

describe('peers in the accuracy study', () => {
  it("measures a peer engine at its own settings where positions suffice: planck's pendulum period, and no energy for its elastic balls", async () => {
    const peers = await loadPeers(['planck'], '');
    const run = await runAccuracy(b2, { scenes: ['pendulum', 'elastic'], methods: ['iter-8-3'], limits: false, peers, rounds: 1 });
    expect(run.peers.map((p) => p.id)).toEqual(['planck']);
    const [pendulum, elastic] = run.scenes.map((s) => s.results.find((r) => r.backend === 'planck')!);
    expect(pendulum.key).toBe('planck');
    expect(pendulum.msPerSecond).toBeGreaterThan(0);
    // planck is Box2D 2.x too: its period is short by about what WebPhysics' is at 60 Hz.
    expect(pendulum.measures['period error']).toBeGreaterThan(0.001);
    expect(pendulum.measures['period error']).toBeLessThan(0.05);
    expect(elastic.measures).toEqual({});
    expect(run.scenes[1].fronts['energy drift']).toEqual(['iter-8-3']);
    // Its limits, by the same tests: Box2D 2.x stacks, and stops a ball at any speed with its continuous collision.
    const limits = await peerLimits(peers[0].engine, peers[0].api);
    expect(limits.map((l) => l.id)).toEqual(['stack height', 'frame time', 'tunnelling speed']);
    expect(limits[0].limit).toBeGreaterThan(10);
    expect(limits[0].outside).toBeNull();
    expect(limits[2].outside).toBe('above');
  }, 120_000);
});
