import { describe, expect, it } from 'vitest';
import { b2MassData } from '../../src/collision/shapes/b2Shape';
import { b2Abs, b2Clamp, b2Rot, b2Vec2 } from '../../src/common/b2Math';
import { b2_maxRotation, b2_maxRotationSquared, b2_maxTranslation, b2_timeToSleep } from '../../src/common/b2Settings';
import { b2Body, b2BodyDef, b2BodyType } from '../../src/dynamics/b2Body';
import { b2Island } from '../../src/dynamics/b2Island';
import { b2Profile, b2TimeStep } from '../../src/dynamics/b2TimeStep';
import { b2World } from '../../src/dynamics/b2World';
import { b2ContactImpulse, b2ContactListener } from '../../src/dynamics/b2WorldCallbacks';
import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { b2ContactVelocityConstraint } from '../../src/dynamics/contacts/b2ContactSolver';

const h = 1.0 / 60.0;
const gravity = new b2Vec2(0.0, -10.0);

function makeStep(dt: number, positionIterations = 3): b2TimeStep {
  const step = new b2TimeStep();
  step.dt = dt;
  step.inv_dt = 1.0 / dt;
  step.dtRatio = 1.0;
  step.velocityIterations = 8;
  step.positionIterations = positionIterations;
  step.warmStarting = true;
  return step;
}

function createBody(world: b2World, setup: (bd: b2BodyDef) => void): b2Body {
  const bd = new b2BodyDef();
  bd.type = b2BodyType.b2_dynamicBody;
  setup(bd);
  return world.CreateBody(bd);
}

function setMass(body: b2Body, mass: number, I: number): void {
  const md = new b2MassData();
  md.mass = mass;
  md.I = I;
  body.SetMassData(md);
}

describe('b2Island bookkeeping', () => {
  it('numbers bodies by island position and enforces the capacities', () => {
    const world = new b2World(gravity);
    const a = createBody(world, () => {});
    const b = createBody(world, () => {});
    const island = new b2Island(2, 0, 0, null);
    island.Add(b);
    island.Add(a);
    expect(b.m_islandIndex).toBe(0);
    expect(a.m_islandIndex).toBe(1);
    expect(island.m_bodies.slice(0, island.m_bodyCount)).toEqual([b, a]);
    expect(() => island.Add(a)).toThrow();
    expect(() => island.AddContact({} as b2Contact)).toThrow();

    island.Clear();
    expect([island.m_bodyCount, island.m_contactCount, island.m_jointCount]).toEqual([0, 0, 0]);
  });

  it('re-initialises with new capacities and listener, growing its state buffers to fit', () => {
    const island = new b2Island(2, 1, 0, null);
    expect(island.m_positions.length).toBeGreaterThanOrEqual(2);
    const listener = new b2ContactListener();
    island.Initialize(64, 32, 5, listener);
    expect([island.m_bodyCapacity, island.m_contactCapacity, island.m_jointCapacity]).toEqual([64, 32, 5]);
    expect([island.m_bodyCount, island.m_contactCount, island.m_jointCount]).toEqual([0, 0, 0]);
    expect(island.m_listener).toBe(listener);
    expect(island.m_positions.length).toBeGreaterThanOrEqual(64);
    expect(island.m_velocities.length).toBe(island.m_positions.length);
    const positions = island.m_positions[0];
    island.Initialize(3, 0, 0, null);
    expect(island.m_bodyCapacity).toBe(3);
    expect(island.m_positions[0]).toBe(positions);
  });
});

describe('b2Island.Solve', () => {
  it('integrates gravity (scaled), force, torque and damping, then positions, in the C++ order', () => {
    // Many bodies with irregular values, so that any re-association of the C++ expressions
    // changes some result in the last bit.
    let seed = 12345;
    const random = (lo: number, hi: number): number => {
      seed = (Math.imul(seed, 1103515245) + 12345) >>> 0;
      return lo + ((seed >>> 8) / 16777216) * (hi - lo);
    };
    const g = new b2Vec2(0.3, -9.8);
    const world = new b2World(g);
    const count = 32;
    const island = new b2Island(count, 0, 0, null);
    const cases = [];
    for (let i = 0; i < count; ++i) {
      const c = {
        x: random(-5, 5),
        y: random(-5, 5),
        angle: random(-3, 3),
        vx: random(-5, 5),
        vy: random(-5, 5),
        w: random(-2, 2),
        // Up to 80/s, so that 1 - h * damping sometimes clamps to 0.
        linearDamping: random(0, 80),
        angularDamping: random(0, 80),
        gravityScale: random(-1, 2),
        mass: random(0.5, 3),
        I: random(0.5, 3),
        fx: random(-20, 20),
        fy: random(-20, 20),
        torque: random(-20, 20),
      };
      const body = createBody(world, (bd) => {
        bd.position.Set(c.x, c.y);
        bd.angle = c.angle;
        bd.linearVelocity.Set(c.vx, c.vy);
        bd.angularVelocity = c.w;
        bd.linearDamping = c.linearDamping;
        bd.angularDamping = c.angularDamping;
        bd.gravityScale = c.gravityScale;
      });
      setMass(body, c.mass, c.I);
      body.ApplyForceToCenter(new b2Vec2(c.fx, c.fy));
      body.ApplyTorque(c.torque);
      // A stale start-of-step pose, as a previous step leaves it.
      body.m_sweep.c0.Set(99.0, 99.0);
      body.m_sweep.a0 = 99.0;
      island.Add(body);
      cases.push({ c, body });
    }

    const profile = new b2Profile();
    island.Solve(profile, makeStep(h), g, false);

    for (const { c, body } of cases) {
      const invMass = 1.0 / c.mass;
      const invI = 1.0 / c.I;
      expect([body.m_invMass, body.m_invI]).toEqual([invMass, invI]);
      let vx = c.vx + h * (c.gravityScale * g.x + invMass * c.fx);
      let vy = c.vy + h * (c.gravityScale * g.y + invMass * c.fy);
      let w = c.w + h * invI * c.torque;
      const linear = b2Clamp(1.0 - h * c.linearDamping, 0.0, 1.0);
      vx *= linear;
      vy *= linear;
      w *= b2Clamp(1.0 - h * c.angularDamping, 0.0, 1.0);
      const cx = c.x + h * vx;
      const cy = c.y + h * vy;
      const a = c.angle + h * w;

      expect([body.m_linearVelocity.x, body.m_linearVelocity.y, body.m_angularVelocity]).toEqual([vx, vy, w]);
      expect([body.m_sweep.c.x, body.m_sweep.c.y, body.m_sweep.a]).toEqual([cx, cy, a]);
      // The start-of-step pose is kept for continuous collision.
      expect([body.m_sweep.c0.x, body.m_sweep.c0.y, body.m_sweep.a0]).toEqual([c.x, c.y, c.angle]);
      // The transform is synchronised from the sweep (the center of mass is the origin here).
      const q = new b2Rot(a);
      expect([body.m_xf.q.s, body.m_xf.q.c]).toEqual([q.s, q.c]);
      expect([body.m_xf.p.x, body.m_xf.p.y]).toEqual([cx - (q.c * 0.0 - q.s * 0.0), cy - (q.s * 0.0 + q.c * 0.0)]);
    }
    expect(profile.solveInit).toBeGreaterThanOrEqual(0.0);
    expect(profile.solveVelocity).toBeGreaterThanOrEqual(0.0);
    expect(profile.solvePosition).toBeGreaterThanOrEqual(0.0);
  });

  it('moves kinematic bodies with their velocity but applies no gravity or damping to them', () => {
    const world = new b2World(gravity);
    const body = createBody(world, (bd) => {
      bd.type = b2BodyType.b2_kinematicBody;
      bd.linearVelocity.Set(1.0, 2.0);
      bd.angularVelocity = -0.5;
      bd.linearDamping = 3.0;
    });
    const island = new b2Island(1, 0, 0, null);
    island.Add(body);
    island.Solve(new b2Profile(), makeStep(h), gravity, false);
    expect([body.m_linearVelocity.x, body.m_linearVelocity.y, body.m_angularVelocity]).toEqual([1.0, 2.0, -0.5]);
    expect([body.m_sweep.c.x, body.m_sweep.c.y, body.m_sweep.a]).toEqual([0.0 + h * 1.0, 0.0 + h * 2.0, 0.0 + h * -0.5]);
  });

  it('clamps large translations and rotations and keeps the clamped velocities', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, (bd) => {
      bd.linearVelocity.Set(300.0, -400.0);
      bd.angularVelocity = 200.0;
    });
    setMass(body, 1.0, 1.0);
    const island = new b2Island(1, 0, 0, null);
    island.Add(body);
    island.Solve(new b2Profile(), makeStep(h), new b2Vec2(0.0, 0.0), false);

    const tx = h * 300.0;
    const ty = h * -400.0;
    const ratio = b2_maxTranslation / Math.sqrt(tx * tx + ty * ty);
    const vx = 300.0 * ratio;
    const vy = -400.0 * ratio;
    const rotation = h * 200.0;
    expect(rotation * rotation).toBeGreaterThan(b2_maxRotationSquared);
    const w = 200.0 * (b2_maxRotation / b2Abs(rotation));
    expect([body.m_linearVelocity.x, body.m_linearVelocity.y, body.m_angularVelocity]).toEqual([vx, vy, w]);
    expect([body.m_sweep.c.x, body.m_sweep.c.y, body.m_sweep.a]).toEqual([0.0 + h * vx, 0.0 + h * vy, 0.0 + h * w]);
  });

  it('puts the island to sleep once every body has rested b2_timeToSleep and the positions are solved', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, () => {});
    const b = createBody(world, (bd) => bd.linearVelocity.Set(0.005, 0.0));
    const ground = createBody(world, (bd) => (bd.type = b2BodyType.b2_staticBody));
    const island = new b2Island(3, 0, 0, null);
    const step = makeStep(h);

    let solves = 0;
    let sleepTime = 0.0;
    while (a.IsAwake()) {
      island.Clear();
      island.Add(a);
      island.Add(b);
      island.Add(ground);
      island.Solve(new b2Profile(), step, new b2Vec2(0.0, 0.0), true);
      sleepTime += h;
      ++solves;
      if (a.IsAwake()) {
        expect(sleepTime).toBeLessThan(b2_timeToSleep);
        expect(a.m_sleepTime).toBe(sleepTime);
        expect(ground.m_sleepTime).toBe(0.0);
      }
      expect(solves).toBeLessThan(100);
    }
    expect(sleepTime).toBeGreaterThanOrEqual(b2_timeToSleep);
    expect(b.IsAwake()).toBe(false);
    expect([b.m_linearVelocity.x, b.m_sleepTime]).toEqual([0.0, 0.0]);
  });

  it('keeps the island awake while a body moves faster than the sleep tolerance or may not sleep', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const still = createBody(world, () => {});
    const fast = createBody(world, (bd) => (bd.angularVelocity = 0.1));
    const insomniac = createBody(world, (bd) => (bd.allowSleep = false));
    for (const other of [fast, insomniac]) {
      const island = new b2Island(2, 0, 0, null);
      for (let i = 0; i < 60; ++i) {
        island.Clear();
        island.Add(still);
        island.Add(other);
        island.Solve(new b2Profile(), makeStep(h), new b2Vec2(0.0, 0.0), true);
      }
      expect(still.IsAwake()).toBe(true);
      expect(other.IsAwake()).toBe(true);
      expect(other.m_sleepTime).toBe(0.0);
      expect(still.m_sleepTime).toBeGreaterThan(b2_timeToSleep);
      still.SetAwake(false);
      still.SetAwake(true);
    }
  });

  it('does not sleep when the position iterations did not confirm a solved state', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, () => {});
    const island = new b2Island(1, 0, 0, null);
    for (let i = 0; i < 60; ++i) {
      island.Clear();
      island.Add(body);
      island.Solve(new b2Profile(), makeStep(h, 0), new b2Vec2(0.0, 0.0), true);
    }
    expect(body.IsAwake()).toBe(true);
    expect(body.m_sleepTime).toBeGreaterThan(b2_timeToSleep);
  });
});

describe('b2Island.SolveTOI', () => {
  it('re-bases the sweeps of the TOI pair and integrates the sub-step without gravity or damping', () => {
    const world = new b2World(gravity);
    const a = createBody(world, (bd) => {
      bd.position.Set(1.0, 1.0);
      bd.linearVelocity.Set(2.0, -3.0);
      bd.angularVelocity = 1.0;
      bd.linearDamping = 1.0;
    });
    const b = createBody(world, (bd) => {
      bd.position.Set(-4.0, 0.5);
      bd.angle = 0.25;
      bd.linearVelocity.Set(-1.0, 0.0);
    });
    // Sweeps that an earlier TOI event left behind: SolveTOI re-bases c0/a0 of the pair.
    a.m_sweep.c0.Set(99.0, 99.0);
    a.m_sweep.a0 = 9.0;
    b.m_sweep.c0.Set(-99.0, 99.0);
    b.m_sweep.a0 = -9.0;
    const island = new b2Island(64, 32, 0, null);
    island.Add(b);
    island.Add(a);
    const subStep = makeStep(0.01, 20);
    subStep.warmStarting = false;
    island.SolveTOI(subStep, 1, 0);

    expect([a.m_sweep.c0.x, a.m_sweep.c0.y, a.m_sweep.a0]).toEqual([1.0, 1.0, 0.0]);
    expect([b.m_sweep.c0.x, b.m_sweep.c0.y, b.m_sweep.a0]).toEqual([-4.0, 0.5, 0.25]);
    expect([a.m_sweep.c.x, a.m_sweep.c.y, a.m_sweep.a]).toEqual([1.0 + 0.01 * 2.0, 1.0 + 0.01 * -3.0, 0.0 + 0.01 * 1.0]);
    expect([b.m_sweep.c.x, b.m_sweep.c.y, b.m_sweep.a]).toEqual([-4.0 + 0.01 * -1.0, 0.5 + 0.01 * 0.0, 0.25 + 0.01 * 0.0]);
    expect([a.m_linearVelocity.x, a.m_linearVelocity.y, a.m_angularVelocity]).toEqual([2.0, -3.0, 1.0]);
    const q = new b2Rot(0.01);
    expect([a.m_xf.q.s, a.m_xf.q.c]).toEqual([q.s, q.c]);
  });
});

describe('b2Island.Report', () => {
  it('calls PostSolve for each island contact with its constraint impulses', () => {
    const calls: { contact: unknown; count: number; normal: number[]; tangent: number[] }[] = [];
    class Listener extends b2ContactListener {
      override PostSolve(contact: b2Contact, impulse: b2ContactImpulse): void {
        calls.push({
          contact,
          count: impulse.count,
          normal: impulse.normalImpulses.slice(0, impulse.count),
          tangent: impulse.tangentImpulses.slice(0, impulse.count),
        });
      }
    }
    const island = new b2Island(0, 2, 0, new Listener());
    const contact1 = { id: 1 } as unknown as b2Contact;
    const contact2 = { id: 2 } as unknown as b2Contact;
    island.AddContact(contact1);
    island.AddContact(contact2);

    const vc1 = new b2ContactVelocityConstraint();
    vc1.pointCount = 2;
    vc1.points[0].normalImpulse = 1.5;
    vc1.points[0].tangentImpulse = -0.25;
    vc1.points[1].normalImpulse = 2.5;
    vc1.points[1].tangentImpulse = 0.125;
    const vc2 = new b2ContactVelocityConstraint();
    vc2.pointCount = 1;
    vc2.points[0].normalImpulse = 7.0;
    vc2.points[0].tangentImpulse = 3.0;

    island.Report([vc1, vc2]);
    expect(calls).toEqual([
      { contact: contact1, count: 2, normal: [1.5, 2.5], tangent: [-0.25, 0.125] },
      { contact: contact2, count: 1, normal: [7.0], tangent: [3.0] },
    ]);
  });

  it('reports nothing without a listener', () => {
    const island = new b2Island(0, 1, 0, null);
    island.AddContact({} as b2Contact);
    expect(() => island.Report([])).not.toThrow();
  });
});
