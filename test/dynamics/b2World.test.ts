import { describe, expect, it } from 'vitest';
import { b2AABB } from '../../src/collision/b2Collision';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Color, b2Draw } from '../../src/common/b2Draw';
import { b2Transform, b2Vec2 } from '../../src/common/b2Math';
import { b2SetLogSink, b2_maxTranslation, b2_timeToSleep } from '../../src/common/b2Settings';
import { b2Body, b2BodyDef, b2BodyType } from '../../src/dynamics/b2Body';
import { b2Fixture, b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2ContactImpulse, b2ContactListener, b2DestructionListener, b2QueryCallback, b2RayCastCallback } from '../../src/dynamics/b2WorldCallbacks';
import { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { b2DistanceJointDef } from '../../src/dynamics/joints/b2DistanceJoint';
import type { b2Joint } from '../../src/dynamics/joints/b2Joint';
import { motionDigest } from '../support/invariants';

const h = 1.0 / 60.0;

function createBody(world: b2World, type: b2BodyType, x: number, y: number, userData: any = null): b2Body {
  const bd = new b2BodyDef();
  bd.type = type;
  bd.position.Set(x, y);
  bd.userData = userData;
  return world.CreateBody(bd);
}

function addBox(body: b2Body, hx: number, hy: number, density: number, userData: any = null): b2Fixture {
  const shape = new b2PolygonShape();
  shape.SetAsBox(hx, hy);
  const fd = new b2FixtureDef();
  fd.shape = shape;
  fd.density = density;
  fd.userData = userData;
  return body.CreateFixture(fd);
}

function addCircle(body: b2Body, radius: number, density: number): b2Fixture {
  const shape = new b2CircleShape();
  shape.m_radius = radius;
  return body.CreateFixture(shape, density);
}

function bodyList(world: b2World): b2Body[] {
  const bodies: b2Body[] = [];
  for (let b = world.GetBodyList(); b; b = b.GetNext()) bodies.push(b);
  return bodies;
}

function jointList(world: b2World): b2Joint[] {
  const joints: b2Joint[] = [];
  for (let j = world.GetJointList(); j; j = j.GetNext()) joints.push(j);
  return joints;
}

function contactList(world: b2World): b2Contact[] {
  const contacts: b2Contact[] = [];
  for (let c = world.GetContactList(); c; c = c.GetNext()) contacts.push(c);
  return contacts;
}

function distanceJointDef(bodyA: b2Body, bodyB: b2Body, collideConnected = false): b2DistanceJointDef {
  const jd = new b2DistanceJointDef();
  jd.bodyA = bodyA;
  jd.bodyB = bodyB;
  jd.length = 2.0;
  jd.collideConnected = collideConnected;
  return jd;
}

/** A ground box (static, 20 x 1, top at y = 0.5) and a 1 x 1 dynamic box resting on it. */
function restingBox(): { world: b2World; ground: b2Body; box: b2Body } {
  const world = new b2World(new b2Vec2(0.0, -10.0));
  const ground = createBody(world, b2BodyType.b2_staticBody, 0.0, 0.0);
  addBox(ground, 10.0, 0.5, 0.0);
  const box = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 1.0);
  addBox(box, 0.5, 0.5, 1.0);
  return { world, ground, box };
}

function stepUntilAsleep(world: b2World, body: b2Body, maxSteps: number): number {
  for (let i = 1; i <= maxSteps; ++i) {
    world.Step(h, 8, 3);
    if (!body.IsAwake()) return i;
  }
  return -1;
}

describe('b2World construction and settings', () => {
  it('starts with the C++ defaults: empty lists, sleep, warm starting, continuous on, sub-stepping off, auto-clear on', () => {
    const world = new b2World(new b2Vec2(1.5, -9.5));
    expect(world.GetBodyList()).toBeNull();
    expect(world.GetJointList()).toBeNull();
    expect(world.GetContactList()).toBeNull();
    expect(world.GetBodyCount()).toBe(0);
    expect(world.GetJointCount()).toBe(0);
    expect(world.GetContactCount()).toBe(0);
    expect(world.GetProxyCount()).toBe(0);
    expect(world.GetAllowSleeping()).toBe(true);
    expect(world.GetWarmStarting()).toBe(true);
    expect(world.GetContinuousPhysics()).toBe(true);
    expect(world.GetSubStepping()).toBe(false);
    expect(world.GetAutoClearForces()).toBe(true);
    expect(world.IsLocked()).toBe(false);
    const g = world.GetGravity(new b2Vec2());
    expect([g.x, g.y]).toEqual([1.5, -9.5]);
  });

  it('sets and reads back gravity and the solver switches', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const gravity = new b2Vec2(2.0, 3.0);
    world.SetGravity(gravity);
    gravity.Set(7.0, 7.0);
    const g = world.GetGravity(new b2Vec2());
    expect([g.x, g.y]).toEqual([2.0, 3.0]);
    world.SetWarmStarting(false);
    world.SetContinuousPhysics(false);
    world.SetSubStepping(true);
    world.SetAutoClearForces(false);
    expect(world.GetWarmStarting()).toBe(false);
    expect(world.GetContinuousPhysics()).toBe(false);
    expect(world.GetSubStepping()).toBe(true);
    expect(world.GetAutoClearForces()).toBe(false);
  });
});

describe('b2World.Step integration', () => {
  it('moves a free body along the explicit-Euler trajectory v += h*g, x += h*v', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const body = createBody(world, b2BodyType.b2_dynamicBody, 1.0, 20.0);
    addCircle(body, 0.5, 1.0);

    let vy = 0.0;
    let y = 20.0;
    for (let k = 1; k <= 6; ++k) {
      world.Step(h, 8, 3);
      vy = vy + h * -10.0;
      y = y + h * vy;
      const p = body.GetPosition();
      const v = body.GetLinearVelocity(new b2Vec2());
      expect(p.y, `y after step ${k}`).toBe(y);
      expect(v.y, `vy after step ${k}`).toBe(vy);
      expect(p.x).toBe(1.0);
      expect(v.x).toBe(0.0);
      expect(body.GetAngle()).toBe(0.0);
    }
  });

  it('scales gravity by the body gravity scale and divides forces by the mass', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const body = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.0);
    addCircle(body, 0.5, 2.0);
    body.SetGravityScale(0.5);
    body.ApplyForceToCenter(new b2Vec2(3.0, 0.0));
    const invMass = body.m_invMass;
    world.Step(h, 8, 3);
    const v = body.GetLinearVelocity(new b2Vec2());
    expect(v.x).toBe(0.0 + h * (0.5 * 0.0 + invMass * 3.0));
    expect(v.y).toBe(0.0 + h * (0.5 * -10.0 + invMass * 0.0));
  });

  it('does not integrate when dt is zero', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const body = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 5.0);
    addCircle(body, 0.5, 1.0);
    world.Step(0.0, 8, 3);
    expect(body.GetPosition().y).toBe(5.0);
    expect(body.GetLinearVelocity(new b2Vec2()).y).toBe(0.0);
  });

  it('clamps the per-step translation to b2_maxTranslation', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const bd = new b2BodyDef();
    bd.type = b2BodyType.b2_dynamicBody;
    bd.linearVelocity.Set(600.0, 0.0);
    const body = world.CreateBody(bd);
    addCircle(body, 0.5, 1.0);
    world.Step(h, 8, 3);
    const tx = h * 600.0;
    const ty = h * 0.0;
    const vx = 600.0 * (b2_maxTranslation / Math.sqrt(tx * tx + ty * ty));
    expect(body.GetLinearVelocity(new b2Vec2()).x).toBe(vx);
    expect(body.GetPosition().x).toBe(0.0 + h * vx);
  });
});

describe('b2World forces', () => {
  it('clears forces after each step by default', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.0);
    addCircle(body, 0.5, 1.0);
    const invMass = body.m_invMass;
    body.ApplyForceToCenter(new b2Vec2(3.0, 0.0));
    body.ApplyTorque(2.0);
    world.Step(h, 8, 3);
    const v1 = h * (invMass * 3.0);
    expect(body.GetLinearVelocity(new b2Vec2()).x).toBe(v1);
    expect([body.m_force.x, body.m_force.y, body.m_torque]).toEqual([0.0, 0.0, 0.0]);
    world.Step(h, 8, 3);
    expect(body.GetLinearVelocity(new b2Vec2()).x).toBe(v1);
  });

  it('keeps forces across steps when auto-clear is off, until ClearForces', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    world.SetAutoClearForces(false);
    const body = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.0);
    addCircle(body, 0.5, 1.0);
    const invMass = body.m_invMass;
    body.ApplyForceToCenter(new b2Vec2(3.0, 0.0));
    world.Step(h, 8, 3);
    world.Step(h, 8, 3);
    let vx = 0.0;
    vx = vx + h * (0.0 + invMass * 3.0);
    vx = vx + h * (0.0 + invMass * 3.0);
    expect(body.GetLinearVelocity(new b2Vec2()).x).toBe(vx);
    expect(body.m_force.x).toBe(3.0);

    body.ApplyTorque(1.0);
    world.ClearForces();
    expect([body.m_force.x, body.m_force.y, body.m_torque]).toEqual([0.0, 0.0, 0.0]);
    world.Step(h, 8, 3);
    expect(body.GetLinearVelocity(new b2Vec2()).x).toBe(vx);
  });
});

describe('b2World sleeping', () => {
  it('puts a resting box to sleep after b2_timeToSleep and zeroes its velocity', () => {
    const { world, box } = restingBox();
    const steps = stepUntilAsleep(world, box, 240);
    expect(steps).toBeGreaterThan(0);
    expect(steps * h).toBeGreaterThanOrEqual(b2_timeToSleep);
    expect(box.GetLinearVelocity(new b2Vec2())).toEqual(new b2Vec2(0.0, 0.0));
    expect(box.GetAngularVelocity()).toBe(0.0);

    // A sleeping body does not move.
    const y = box.GetPosition().y;
    world.Step(h, 8, 3);
    expect(box.GetPosition().y).toBe(y);
    expect(box.IsAwake()).toBe(false);
  });

  it('wakes a sleeping box on ApplyForce and on SetAwake(true)', () => {
    const { world, box } = restingBox();
    expect(stepUntilAsleep(world, box, 240)).toBeGreaterThan(0);

    box.ApplyForce(new b2Vec2(0.0, 50.0), box.GetWorldCenter());
    expect(box.IsAwake()).toBe(true);
    world.Step(h, 8, 3);
    expect(box.IsAwake()).toBe(true);

    expect(stepUntilAsleep(world, box, 240)).toBeGreaterThan(0);
    box.SetAwake(true);
    expect(box.IsAwake()).toBe(true);
    world.Step(h, 8, 3);
    expect(box.IsAwake()).toBe(true);
  });

  it('never sleeps with sleeping disallowed, and disallowing wakes every body', () => {
    const { world, box } = restingBox();
    expect(stepUntilAsleep(world, box, 240)).toBeGreaterThan(0);
    world.SetAllowSleeping(false);
    expect(world.GetAllowSleeping()).toBe(false);
    expect(box.IsAwake()).toBe(true);
    expect(stepUntilAsleep(world, box, 120)).toBe(-1);
  });
});

describe('b2World waking by contact', () => {
  it("wakes a sleeping box when a falling ball's contact with it is created (2.2.1 AddPair), and both then sleep together", () => {
    const { world, box } = restingBox();
    expect(stepUntilAsleep(world, box, 240)).toBeGreaterThan(0);
    const ball = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 2.5);
    addCircle(ball, 0.25, 1.0);

    const ballContact = (): b2Contact | null => {
      for (let ce = ball.GetContactList(); ce; ce = ce.next) if (ce.other === box) return ce.contact;
      return null;
    };
    const history: { contact: boolean; touching: boolean; boxAwake: boolean }[] = [];
    for (let k = 0; k < 60 && !(history.length > 0 && history[history.length - 1].touching); ++k) {
      world.Step(h, 8, 3);
      const c = ballContact();
      history.push({ contact: c !== null, touching: c !== null && c.IsTouching(), boxAwake: box.IsAwake() });
    }
    const created = history.findIndex((s) => s.contact);
    const touched = history.findIndex((s) => s.touching);
    expect(created).toBeGreaterThan(0);
    // The fat AABBs overlap before the shapes touch.
    expect(touched).toBeGreaterThan(created);
    // Asleep until the contact exists, awake from then on.
    expect(history.map((s) => s.boxAwake)).toEqual(history.map((_, i) => i >= created));

    // Touching, the two form one island: they fall asleep in the same step.
    let asleepAt = -1;
    for (let k = 1; k <= 300 && asleepAt < 0; ++k) {
      world.Step(h, 8, 3);
      expect(ball.IsAwake()).toBe(box.IsAwake());
      if (!box.IsAwake()) asleepAt = k;
    }
    expect(asleepAt).toBeGreaterThan(0);
    expect(ballContact()!.IsTouching()).toBe(true);
  });

  it('keeps a jointed pair in one island: waking one body wakes the other in the next step', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.0);
    addCircle(a, 0.5, 1.0);
    const b = createBody(world, b2BodyType.b2_dynamicBody, 3.0, 0.0);
    addCircle(b, 0.5, 1.0);
    const jd = new b2DistanceJointDef();
    jd.Initialize(a, b, a.GetPosition(), b.GetPosition());
    world.CreateJoint(jd);
    expect(stepUntilAsleep(world, a, 120)).toBeGreaterThan(0);
    expect(b.IsAwake()).toBe(false);

    a.SetAwake(true);
    expect(b.IsAwake()).toBe(false);
    world.Step(h, 8, 3);
    expect([a.IsAwake(), b.IsAwake()]).toEqual([true, true]);
  });
});

describe('b2World.QueryAABB', () => {
  function threeCircles(): { world: b2World; fixtures: b2Fixture[] } {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const fixtures: b2Fixture[] = [];
    for (const x of [0.0, 3.0, 6.0]) {
      fixtures.push(addCircle(createBody(world, b2BodyType.b2_staticBody, x, 0.0), 0.5, 0.0));
    }
    return { world, fixtures };
  }

  function aabb(x1: number, y1: number, x2: number, y2: number): b2AABB {
    const box = new b2AABB();
    box.lowerBound.Set(x1, y1);
    box.upperBound.Set(x2, y2);
    return box;
  }

  class Collector extends b2QueryCallback {
    readonly found: b2Fixture[] = [];
    constructor(private readonly stopAfter = Infinity) {
      super();
    }
    ReportFixture(fixture: b2Fixture): boolean {
      this.found.push(fixture);
      return this.found.length < this.stopAfter;
    }
  }

  it('reports fixtures whose fat AABB (shape AABB + b2_aabbExtension) overlaps the query box', () => {
    const { world, fixtures } = threeCircles();
    // The circle at the origin spans [-0.5, 0.5]; its fat AABB spans [-0.6, 0.6].
    const inFatMargin = new Collector();
    world.QueryAABB(inFatMargin, aabb(0.55, -0.1, 0.58, 0.1));
    expect(inFatMargin.found).toEqual([fixtures[0]]);

    const outside = new Collector();
    world.QueryAABB(outside, aabb(0.65, -0.1, 0.7, 0.1));
    expect(outside.found).toEqual([]);

    const all = new Collector();
    world.QueryAABB(all, aabb(-1.0, -1.0, 7.0, 1.0));
    expect(new Set(all.found)).toEqual(new Set(fixtures));
    expect(all.found.length).toBe(3);
  });

  it('stops the query when the callback returns false', () => {
    const { world } = threeCircles();
    const first = new Collector(1);
    world.QueryAABB(first, aabb(-1.0, -1.0, 7.0, 1.0));
    expect(first.found.length).toBe(1);
  });

  it('accepts a plain object callback and allows a nested query from inside the callback', () => {
    const { world, fixtures } = threeCircles();
    const outer: b2Fixture[] = [];
    const inner: b2Fixture[] = [];
    world.QueryAABB(
      {
        ReportFixture(fixture: b2Fixture): boolean {
          outer.push(fixture);
          world.QueryAABB(
            {
              ReportFixture(f: b2Fixture): boolean {
                inner.push(f);
                return true;
              },
            },
            aabb(2.9, -0.1, 3.1, 0.1),
          );
          return true;
        },
      },
      aabb(-1.0, -1.0, 7.0, 1.0),
    );
    expect(new Set(outer)).toEqual(new Set(fixtures));
    expect(inner).toEqual([fixtures[1], fixtures[1], fixtures[1]]);
  });
});

describe('b2World.RayCast', () => {
  // Static 1 x 1 boxes centred at x = 2, 4, 6 on the ray from (-1, 0.13) to (11, -0.29): the ray
  // enters each through its left face, at fraction (cx + 0.5) / 12, with normal (-1, 0).
  const centers = [2.0, 4.0, 6.0];
  const tags = ['A', 'B', 'C'];

  function boxRow(): b2World {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    centers.forEach((cx, i) => addBox(createBody(world, b2BodyType.b2_staticBody, cx, 0.0), 0.5, 0.5, 0.0, tags[i]));
    return world;
  }

  interface Hit {
    tag: string;
    point: [number, number];
    normal: [number, number];
    fraction: number;
  }

  class Recorder extends b2RayCastCallback {
    readonly hits: Hit[] = [];
    constructor(private readonly reply: (tag: string, fraction: number) => number) {
      super();
    }
    ReportFixture(fixture: b2Fixture, point: b2Vec2, normal: b2Vec2, fraction: number): number {
      const tag = fixture.GetUserData() as string;
      this.hits.push({ tag, point: [point.x, point.y], normal: [normal.x, normal.y], fraction });
      return this.reply(tag, fraction);
    }
  }

  const p1 = new b2Vec2(-1.0, 0.13);
  const p2 = new b2Vec2(11.0, -0.29);

  function expectedHit(i: number): Hit {
    const fraction = (centers[i] + 0.5) / 12.0;
    return {
      tag: tags[i],
      point: [(1.0 - fraction) * p1.x + fraction * p2.x, (1.0 - fraction) * p1.y + fraction * p2.y],
      normal: [-1.0, 0.0],
      fraction,
    };
  }

  it('reports every fixture with its point, normal and fraction when the callback returns 1', () => {
    const world = boxRow();
    const recorder = new Recorder(() => 1.0);
    world.RayCast(recorder, p1, p2);
    const hits = [...recorder.hits].sort((a, b) => a.fraction - b.fraction);
    expect(hits).toEqual([expectedHit(0), expectedHit(1), expectedHit(2)]);
  });

  it('terminates after the first report when the callback returns 0', () => {
    const world = boxRow();
    const recorder = new Recorder(() => 0.0);
    world.RayCast(recorder, p1, p2);
    expect(recorder.hits.length).toBe(1);
  });

  it('clips the ray to the returned fraction, so the last report is the closest hit', () => {
    const world = boxRow();
    const recorder = new Recorder((_tag, fraction) => fraction);
    world.RayCast(recorder, p1, p2);
    expect(recorder.hits[recorder.hits.length - 1]).toEqual(expectedHit(0));
    // Once clipped, nothing beyond the clip point is reported.
    for (let i = 1; i < recorder.hits.length; ++i) {
      expect(recorder.hits[i].fraction).toBeLessThan(recorder.hits[i - 1].fraction);
    }
  });

  it('ignores a fixture when the callback returns -1 and keeps the ray unclipped', () => {
    const world = boxRow();
    const recorder = new Recorder((tag, fraction) => (tag === 'A' ? -1.0 : fraction));
    world.RayCast(recorder, p1, p2);
    // A is still reported (once) but does not clip: B, behind it, is found as the closest.
    expect(recorder.hits.filter((hit) => hit.tag === 'A')).toEqual([expectedHit(0)]);
    const closest = recorder.hits.filter((hit) => hit.tag !== 'A').sort((a, b) => a.fraction - b.fraction)[0];
    expect(closest).toEqual(expectedHit(1));
  });
});

describe('b2World continuous collision', () => {
  // A small ball 1 m above a thin static plate moving down 2 m in one step (the clamped maximum).
  function fastBall(continuous: boolean, subStepping = false): { world: b2World; ball: b2Body } {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    world.SetContinuousPhysics(continuous);
    world.SetSubStepping(subStepping);
    const plate = createBody(world, b2BodyType.b2_staticBody, 0.0, 0.0);
    addBox(plate, 2.0, 0.05, 0.0);
    const bd = new b2BodyDef();
    bd.type = b2BodyType.b2_dynamicBody;
    bd.position.Set(0.0, 1.0);
    bd.linearVelocity.Set(0.0, -120.0);
    const ball = world.CreateBody(bd);
    addCircle(ball, 0.1, 1.0);
    return { world, ball };
  }

  it('tunnels through a thin plate without continuous physics', () => {
    const { world, ball } = fastBall(false);
    world.Step(h, 8, 3);
    expect(ball.GetPosition().y).toBeLessThan(-0.5);
  });

  it('stops at the plate at the time of impact with continuous physics', () => {
    const { world, ball } = fastBall(true);
    world.Step(h, 8, 3);
    const y = ball.GetPosition().y;
    expect(y).toBeGreaterThan(0.05);
    expect(y).toBeLessThan(0.2);
    expect(world.m_stepComplete).toBe(true);
  });

  it('handles one TOI event per Step with sub-stepping, skipping the next discrete solve', () => {
    const { world, ball } = fastBall(true, true);
    // A free body far away moves only in the discrete solve.
    const bd = new b2BodyDef();
    bd.type = b2BodyType.b2_dynamicBody;
    bd.position.Set(50.0, 0.0);
    bd.linearVelocity.Set(1.0, 0.0);
    const witness = world.CreateBody(bd);
    addCircle(witness, 0.1, 1.0);

    world.Step(h, 8, 3);
    expect(world.m_stepComplete).toBe(false);
    expect(ball.GetPosition().y).toBeGreaterThan(0.05);
    expect(witness.GetPosition().x).toBe(50.0 + h * 1.0);

    world.Step(h, 8, 3);
    expect(world.m_stepComplete).toBe(true);
    expect(ball.GetPosition().y).toBeGreaterThan(0.05);
    expect(witness.GetPosition().x).toBe(50.0 + h * 1.0);

    world.Step(h, 8, 3);
    expect(witness.GetPosition().x).toBe(50.0 + h * 1.0 + h * 1.0);
  });
});

describe('b2World continuous collision: bullets (2.2.1 SolveTOI rules)', () => {
  // A ball of radius 0.1 at y = 1 moving down 2 m in one step, through a 0.1 m thick plate at
  // y = 0: neither end of the step overlaps the plate, so only a TOI event can catch it.
  function ballAndPlate(plateType: b2BodyType, bullet: boolean, continuous = true) {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    world.SetContinuousPhysics(continuous);
    const plate = createBody(world, plateType, 0.0, 0.0);
    addBox(plate, 2.0, 0.05, 1.0);
    const bd = new b2BodyDef();
    bd.type = b2BodyType.b2_dynamicBody;
    bd.position.Set(0.0, 1.0);
    bd.linearVelocity.Set(0.0, -120.0);
    bd.bullet = bullet;
    const ball = world.CreateBody(bd);
    addCircle(ball, 0.1, 1.0);
    return { world, plate, ball };
  }

  it('stops a fast small bullet at a thin static wall, at the time of impact', () => {
    const { world, plate, ball } = ballAndPlate(b2BodyType.b2_staticBody, true);
    expect(ball.IsBullet()).toBe(true);
    world.Step(h, 8, 3);
    // Stopped on the upper face (0.05 + radius 0.1), within the TOI target tolerance.
    expect(ball.GetPosition().y).toBeGreaterThan(0.05 + 0.1 - 3.0 * 0.005);
    expect(ball.GetPosition().y).toBeLessThan(0.2);
    for (let k = 0; k < 30; ++k) world.Step(h, 8, 3);
    expect(ball.GetPosition().y).toBeGreaterThan(0.1);
    expect(plate.GetPosition().y).toBe(0.0);
  });

  it('lets even a bullet tunnel through the wall when continuous physics is off', () => {
    const { world, ball } = ballAndPlate(b2BodyType.b2_staticBody, true, false);
    world.Step(h, 8, 3);
    expect(ball.GetPosition().y).toBe(1.0 + h * -120.0);
  });

  it('lets a fast non-bullet dynamic body tunnel through a thin dynamic plate: no TOI between two non-bullets', () => {
    const { world, plate, ball } = ballAndPlate(b2BodyType.b2_dynamicBody, false);
    world.Step(h, 8, 3);
    expect(ball.GetPosition().y).toBe(1.0 + h * -120.0);
    expect(ball.GetLinearVelocity().y).toBe(-120.0);
    // The plate never felt it.
    expect(plate.GetLinearVelocity()).toEqual(new b2Vec2(0.0, 0.0));
    expect(plate.GetPosition().y).toBe(0.0);
  });

  it('stops the same body at the thin dynamic plate when it is a bullet, and pushes the plate', () => {
    const { world, plate, ball } = ballAndPlate(b2BodyType.b2_dynamicBody, true);
    world.Step(h, 8, 3);
    expect(ball.GetPosition().y).toBeGreaterThan(plate.GetPosition().y + 0.05 + 0.1 - 3.0 * 0.005);
    expect(ball.GetPosition().y).toBeLessThan(0.2);
    expect(plate.GetLinearVelocity().y).toBeLessThan(0.0);
    for (let k = 0; k < 30; ++k) world.Step(h, 8, 3);
    expect(ball.GetPosition().y).toBeGreaterThan(plate.GetPosition().y + 0.1);
  });

  it('stops a non-bullet dynamic body at a thin kinematic plate: only dynamic pairs need a bullet', () => {
    const { world, plate, ball } = ballAndPlate(b2BodyType.b2_kinematicBody, false);
    world.Step(h, 8, 3);
    expect(ball.GetPosition().y).toBeGreaterThan(0.05 + 0.1 - 3.0 * 0.005);
    expect(ball.GetPosition().y).toBeLessThan(0.2);
    expect(plate.GetPosition().y).toBe(0.0);
  });

  // SolveTOI's searches after the first visit only the contacts that can have a TOI (see
  // b2World.IsTOICandidate). A callback inside SolveTOI can turn a skipped contact into a candidate
  // with SetBullet or SetSensor; the search must then see it in the same step, as the C++'s full
  // walk does.
  function bulletFromCallback(everyContactACandidate: boolean, setBullet: boolean) {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    if (everyContactACandidate) {
      (b2World as unknown as { IsTOICandidate: () => boolean }).IsTOICandidate = () => true;
    }
    const wall = createBody(world, b2BodyType.b2_staticBody, -10.0, 0.0);
    addBox(wall, 2.0, 0.05, 1.0);
    const plate = createBody(world, b2BodyType.b2_dynamicBody, 10.0, 0.0);
    addBox(plate, 2.0, 0.05, 1.0);
    const balls = [-10.0, 10.0].map((x) => {
      const bd = new b2BodyDef();
      bd.type = b2BodyType.b2_dynamicBody;
      bd.position.Set(x, 1.0);
      bd.linearVelocity.Set(0.0, -120.0);
      const ball = world.CreateBody(bd);
      addCircle(ball, 0.1, 1.0);
      return ball;
    });
    const listener = new b2ContactListener();
    let calls = 0;
    listener.BeginContact = () => {
      // The left ball reaches the static wall in SolveTOI: make the right ball a bullet then.
      if (setBullet) balls[1].SetBullet(true);
      calls++;
    };
    world.SetContactListener(listener);
    world.Step(h, 8, 3);
    return { y: balls[1].GetPosition().y, plateY: plate.GetPosition().y, digest: motionDigest(world), calls };
  }

  it('sees a contact that a callback inside SolveTOI made a bullet contact, in the same step, as the C++ full search', () => {
    const original = (b2World as unknown as { IsTOICandidate: unknown }).IsTOICandidate;
    try {
      const skipped = bulletFromCallback(false, false);
      // Without the callback the right ball tunnels through the dynamic plate.
      expect(skipped.y).toBe(1.0 + h * -120.0);
      const fast = bulletFromCallback(false, true);
      expect(fast.calls).toBeGreaterThan(0);
      expect(fast.y).toBeGreaterThan(fast.plateY + 0.05 + 0.1 - 3.0 * 0.005);
      const full = bulletFromCallback(true, true);
      expect(fast.digest).toBe(full.digest);
    } finally {
      (b2World as unknown as { IsTOICandidate: unknown }).IsTOICandidate = original;
    }
  });
});

// SolveTOI keeps its candidates (the contacts b2World.IsTOICandidate lets through, which are the
// only ones with a TOI) from step to step and brings them up to date before each search.
describe('b2World SolveTOI candidates kept between steps', () => {
  type CandidateState = { m_toiCandidates: b2Contact[]; m_toiCandidateCount: number };
  const everyContactACandidate = () => true;
  function withEveryContactACandidate<T>(run: () => T): T {
    const statics = b2World as unknown as { IsTOICandidate: unknown };
    const original = statics.IsTOICandidate;
    statics.IsTOICandidate = everyContactACandidate;
    try {
      return run();
    } finally {
      statics.IsTOICandidate = original;
    }
  }

  // A ball resting close above a thin plate (their contact exists after one step), then shot
  // through it after `change`: the plate's type, the ball's bullet flag or its sensor flag.
  function shootThroughPlate(change: 'none' | 'SetType' | 'SetBullet' | 'SetSensor') {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const plate = createBody(world, change === 'SetSensor' ? b2BodyType.b2_staticBody : b2BodyType.b2_dynamicBody, 0.0, 0.0);
    addBox(plate, 2.0, 0.05, 1.0);
    const ball = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.25);
    const fixture = addCircle(ball, 0.1, 1.0);
    if (change === 'SetSensor' || change === 'none') fixture.SetSensor(change === 'SetSensor');
    world.Step(h, 8, 3);
    expect(world.GetContactCount()).toBe(1);
    if (change === 'SetType') plate.SetType(b2BodyType.b2_staticBody);
    if (change === 'SetBullet') ball.SetBullet(true);
    if (change === 'SetSensor') fixture.SetSensor(false);
    ball.SetLinearVelocity(new b2Vec2(0.0, -120.0));
    world.Step(h, 8, 3);
    return { y: ball.GetPosition().y, plateY: plate.GetPosition().y };
  }

  it('sees a contact that SetType, SetBullet or SetSensor made a TOI contact between steps', () => {
    // Unchanged, the ball tunnels through the dynamic plate.
    expect(shootThroughPlate('none').y).toBe(0.25 + h * -120.0);
    for (const change of ['SetType', 'SetBullet', 'SetSensor'] as const) {
      const { y, plateY } = shootThroughPlate(change);
      expect(y, change).toBeGreaterThan(plateY + 0.05 + 0.1 - 3.0 * 0.005);
      expect(y, change).toBeLessThan(plateY + 0.25);
    }
  });

  // Bullets and balls bouncing on a static floor and a dynamic shelf: contacts with a TOI end and
  // begin again every few steps, their objects reused by the contact allocator.
  function bouncingRain(steps: number, check: (world: b2World) => void): string {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const floor = createBody(world, b2BodyType.b2_staticBody, 0.0, 0.0);
    addBox(floor, 20.0, 0.1, 0.0);
    const shelf = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 3.0);
    addBox(shelf, 4.0, 0.05, 1.0);
    for (let i = 0; i < 24; ++i) {
      const bd = new b2BodyDef();
      bd.type = b2BodyType.b2_dynamicBody;
      bd.position.Set(-9.0 + 0.75 * i, 6.0 + (i % 5));
      bd.linearVelocity.Set(i % 2 === 0 ? 3.0 : -3.0, -40.0 - i);
      bd.bullet = i % 3 === 0;
      const body = world.CreateBody(bd);
      const fd = new b2FixtureDef();
      if (i % 2 === 0) {
        const circle = new b2CircleShape();
        circle.m_radius = 0.15;
        fd.shape = circle;
      } else {
        const box = new b2PolygonShape();
        box.SetAsBox(0.15, 0.1);
        fd.shape = box;
      }
      fd.density = 1.0;
      fd.restitution = 0.8;
      body.CreateFixture(fd);
    }
    for (let k = 0; k < steps; ++k) {
      world.Step(h, 8, 3);
      check(world);
    }
    return motionDigest(world);
  }

  it('keeps exactly the contacts with a TOI, in contact list order, as contacts end and begin', () => {
    let checked = 0;
    let ended = 0;
    let neverCandidates = 0;
    let previous = new Set<b2Contact>();
    const digest = bouncingRain(240, (world) => {
      const state = world as unknown as CandidateState;
      const kept = state.m_toiCandidates.slice(0, state.m_toiCandidateCount).reverse();
      const expected: b2Contact[] = [];
      const now = new Set<b2Contact>();
      for (let c = world.GetContactList(); c; c = c.GetNext()) {
        now.add(c);
        if ((b2World as unknown as { IsTOICandidate: (c: b2Contact) => boolean }).IsTOICandidate(c)) expected.push(c);
      }
      expect(kept).toEqual(expected);
      // Only candidates hold a TOI, so only they get its storage (b2ContactScalars).
      for (const c of kept) expect(c.m_scalars).not.toBeNull();
      for (const c of now) if (c.m_scalars === null) neverCandidates++;
      for (const c of previous) if (!now.has(c)) ended++;
      previous = now;
      checked += expected.length;
    });
    expect(checked).toBeGreaterThan(0);
    expect(ended).toBeGreaterThan(0);
    expect(neverCandidates).toBeGreaterThan(0);
    // The same trajectory as a search over every contact, as the C++'s.
    expect(withEveryContactACandidate(() => bouncingRain(240, () => {}))).toBe(digest);
  });
});

describe('b2World bodies, joints and destruction', () => {
  it('prepends bodies and joints, counts them and unlinks them on destruction', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const a = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.0);
    const b = createBody(world, b2BodyType.b2_dynamicBody, 5.0, 0.0);
    const c = createBody(world, b2BodyType.b2_dynamicBody, 10.0, 0.0);
    expect(bodyList(world)).toEqual([c, b, a]);
    expect(world.GetBodyCount()).toBe(3);

    const j1 = world.CreateJoint(distanceJointDef(a, b));
    const j2 = world.CreateJoint(distanceJointDef(b, c));
    expect(jointList(world)).toEqual([j2, j1]);
    expect(world.GetJointCount()).toBe(2);
    expect(b.GetJointList()?.joint).toBe(j2);
    expect(b.GetJointList()?.next?.joint).toBe(j1);
    expect(b.GetJointList()?.other).toBe(c);

    world.DestroyJoint(j2);
    expect(jointList(world)).toEqual([j1]);
    expect(world.GetJointCount()).toBe(1);
    expect(c.GetJointList()).toBeNull();
    expect(b.GetJointList()?.joint).toBe(j1);
    expect(b.GetJointList()?.prev).toBeNull();

    world.DestroyBody(b);
    expect(bodyList(world)).toEqual([c, a]);
    expect(c.m_prev).toBeNull();
    expect(a.m_prev).toBe(c);
    expect(world.GetBodyCount()).toBe(2);
    expect(world.GetJointCount()).toBe(0);
    expect(a.GetJointList()).toBeNull();
  });

  it("gives each joint an island slot on both edges, reuses a destroyed joint's slot, and solves every joint of a chain longer than the first slot array", () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const bodies = [createBody(world, b2BodyType.b2_staticBody, 0.0, 0.0)];
    for (let i = 1; i <= 20; ++i) {
      const b = createBody(world, b2BodyType.b2_dynamicBody, 2.0 * i, 0.0);
      addBox(b, 0.25, 0.25, 1.0);
      bodies.push(b);
    }
    const joints: b2Joint[] = [];
    for (let i = 0; i < 20; ++i) joints.push(world.CreateJoint(distanceJointDef(bodies[i], bodies[i + 1])));
    const slots = joints.map((j) => j.m_edgeA.islandSlot);
    expect(joints.every((j) => j.m_edgeB.islandSlot === j.m_edgeA.islandSlot)).toBe(true);
    expect([...slots].sort((x, y) => x - y)).toEqual([...Array(20).keys()]);

    const removed = joints[7];
    const slot = removed.m_edgeA.islandSlot;
    world.DestroyJoint(removed);
    expect(removed.m_edgeA.islandSlot).toBe(-1);
    expect(removed.m_edgeB.islandSlot).toBe(-1);
    joints[7] = world.CreateJoint(distanceJointDef(bodies[7], bodies[8]));
    expect(joints[7].m_edgeA.islandSlot).toBe(slot);

    // A joint left out of its island would let the chain stretch as it swings down.
    for (let i = 0; i < 120; ++i) world.Step(h, 8, 3);
    for (let i = 0; i < 20; ++i) {
      const d = bodies[i + 1].GetPosition().Clone().Subtract(bodies[i].GetPosition()).Length();
      expect(Math.abs(d - 2.0)).toBeLessThan(0.05);
    }
  });

  it('calls the destruction listener for the joints, then the fixtures, of a destroyed body', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.0);
    const f1 = addBox(a, 0.5, 0.5, 1.0);
    const f2 = addCircle(a, 0.3, 1.0);
    const b = createBody(world, b2BodyType.b2_dynamicBody, 4.0, 0.0);
    addBox(b, 0.5, 0.5, 1.0);
    const c = createBody(world, b2BodyType.b2_staticBody, 8.0, 0.0);
    addBox(c, 0.5, 0.5, 0.0);
    const d = createBody(world, b2BodyType.b2_dynamicBody, 0.5, 0.0);
    addBox(d, 0.5, 0.5, 1.0);

    const j1 = world.CreateJoint(distanceJointDef(a, b));
    const j2 = world.CreateJoint(distanceJointDef(c, a));
    const j3 = world.CreateJoint(distanceJointDef(b, c));

    world.Step(h, 8, 3);
    expect(world.GetContactCount()).toBe(2);
    const proxies = world.GetProxyCount();

    const calls: [string, unknown][] = [];
    class Listener extends b2DestructionListener {
      SayGoodbyeJoint(joint: b2Joint): void {
        calls.push(['joint', joint]);
      }
      SayGoodbyeFixture(fixture: b2Fixture): void {
        calls.push(['fixture', fixture]);
      }
    }
    world.SetDestructionListener(new Listener());

    world.DestroyBody(a);
    // Joint and fixture lists are prepended, so the newest comes first.
    expect(calls).toEqual([
      ['joint', j2],
      ['joint', j1],
      ['fixture', f2],
      ['fixture', f1],
    ]);
    expect(world.GetProxyCount()).toBe(proxies - 2);
    expect(world.GetContactCount()).toBe(0);
    expect(contactList(world)).toEqual([]);
    expect(d.GetContactList()).toBeNull();
    expect(jointList(world)).toEqual([j3]);
    expect(b.GetJointList()?.joint).toBe(j3);
    expect(b.GetJointList()?.next).toBeNull();

    // DestroyJoint called directly says no goodbye.
    calls.length = 0;
    world.DestroyJoint(j3);
    expect(calls).toEqual([]);
  });

  it('flags existing contacts for filtering when a joint forbids collision, so the next step drops them', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.0);
    addBox(a, 0.5, 0.5, 1.0);
    const b = createBody(world, b2BodyType.b2_dynamicBody, 0.8, 0.0);
    addBox(b, 0.5, 0.5, 1.0);
    world.Step(h, 8, 3);
    expect(world.GetContactCount()).toBe(1);
    const contact = world.GetContactList() as b2Contact;
    expect(contact.m_flags & b2Contact.e_filterFlag).toBe(0);

    world.CreateJoint(distanceJointDef(a, b, false));
    expect(contact.m_flags & b2Contact.e_filterFlag).toBe(b2Contact.e_filterFlag);
    world.Step(h, 8, 3);
    expect(world.GetContactCount()).toBe(0);
  });

  it('keeps contacts when the joint allows collision', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 0.0);
    addBox(a, 0.5, 0.5, 1.0);
    const b = createBody(world, b2BodyType.b2_dynamicBody, 0.8, 0.0);
    addBox(b, 0.5, 0.5, 1.0);
    world.Step(h, 8, 3);
    const contact = world.GetContactList() as b2Contact;
    world.CreateJoint(distanceJointDef(a, b, true));
    expect(contact.m_flags & b2Contact.e_filterFlag).toBe(0);
    world.Step(h, 8, 3);
    expect(world.GetContactCount()).toBe(1);
  });
});

describe('b2World locking', () => {
  const lockedMessage = /^b2World\.(CreateBody|DestroyBody|CreateJoint|DestroyJoint): the world is locked/;

  it('throws from CreateBody, DestroyBody, CreateJoint and DestroyJoint inside a callback, changing nothing', () => {
    const { world, ground, box } = restingBox();
    const other = createBody(world, b2BodyType.b2_dynamicBody, 5.0, 5.0);
    const joint = world.CreateJoint(distanceJointDef(other, ground));
    const errors: string[] = [];
    let lockedInCallback = false;
    class Listener extends b2ContactListener {
      override BeginContact(): void {
        lockedInCallback = world.IsLocked();
        const attempts = [
          () => world.CreateBody(new b2BodyDef()),
          () => world.DestroyBody(box),
          () => world.CreateJoint(distanceJointDef(box, ground)),
          () => world.DestroyJoint(joint),
        ];
        for (const attempt of attempts) {
          try {
            attempt();
          } catch (e) {
            errors.push((e as Error).message);
          }
        }
      }
    }
    world.SetContactListener(new Listener());
    world.Step(h, 8, 3);

    expect(lockedInCallback).toBe(true);
    expect(errors.length).toBe(4);
    for (const message of errors) expect(message).toMatch(lockedMessage);
    expect(errors[0]).toContain('CreateBody');
    expect(errors[1]).toContain('DestroyBody');
    expect(errors[2]).toContain('CreateJoint');
    expect(errors[3]).toContain('DestroyJoint');
    expect(world.IsLocked()).toBe(false);
    expect(bodyList(world)).toEqual([other, box, ground]);
    expect(jointList(world)).toEqual([joint]);

    // Usable afterwards.
    world.SetContactListener(null);
    const extra = world.CreateBody(new b2BodyDef());
    expect(world.GetBodyCount()).toBe(4);
    world.DestroyBody(extra);
    world.DestroyJoint(joint);
    world.Step(h, 8, 3);
    expect(world.GetBodyCount()).toBe(3);
  });

  it('unlocks the world when a callback error escapes Step', () => {
    const { world, box } = restingBox();
    class Listener extends b2ContactListener {
      override BeginContact(): void {
        world.CreateBody(new b2BodyDef());
      }
    }
    world.SetContactListener(new Listener());
    expect(() => world.Step(h, 8, 3)).toThrow(lockedMessage);
    expect(world.IsLocked()).toBe(false);

    world.SetContactListener(null);
    world.CreateBody(new b2BodyDef());
    expect(world.GetBodyCount()).toBe(3);
    const y = box.GetPosition().y;
    world.Step(h, 8, 3);
    expect(box.GetPosition().y).not.toBe(y);
  });
});

describe('b2World contacts, listener and profile', () => {
  it('walks the contact list in step with GetContactCount and reports PostSolve impulses for a resting box', () => {
    const { world, box } = restingBox();
    const impulses: { count: number; normal: number[] }[] = [];
    class Listener extends b2ContactListener {
      override PostSolve(contact: b2Contact, impulse: b2ContactImpulse): void {
        expect(contact.GetFixtureA().GetBody() === box || contact.GetFixtureB().GetBody() === box).toBe(true);
        impulses.push({ count: impulse.count, normal: impulse.normalImpulses.slice(0, impulse.count) });
      }
    }
    world.SetContactListener(new Listener());
    for (let i = 0; i < 60; ++i) world.Step(h, 8, 3);
    expect(world.GetContactCount()).toBe(1);
    expect(contactList(world).length).toBe(world.GetContactCount());
    expect(contactList(world)[0].IsTouching()).toBe(true);
    expect(impulses.length).toBeGreaterThan(0);
    const last = impulses[impulses.length - 1];
    expect(last.count).toBe(2);
    // The two points together carry the box's weight over one step.
    expect(last.normal[0] + last.normal[1]).toBeCloseTo(box.GetMass() * 10.0 * h, 3);
  });

  it('leaves the profile at zero unless profiling is on (each clock reading allocates)', () => {
    const { world } = restingBox();
    expect(world.GetProfiling()).toBe(false);
    for (let i = 0; i < 5; ++i) world.Step(h, 8, 3);
    const profile = world.GetProfile();
    for (const key of Object.keys(profile) as (keyof typeof profile)[]) {
      if (typeof profile[key] === 'number') expect(profile[key], key).toBe(0.0);
    }
  });

  it('fills every profile field with a non-negative time while profiling is on', () => {
    const { world } = restingBox();
    world.SetProfiling(true);
    expect(world.GetProfiling()).toBe(true);
    for (let i = 0; i < 5; ++i) world.Step(h, 8, 3);
    const profile = world.GetProfile();
    for (const key of ['step', 'collide', 'solve', 'solveInit', 'solveVelocity', 'solvePosition', 'broadphase', 'solveTOI'] as const) {
      expect(Number.isFinite(profile[key]), key).toBe(true);
      expect(profile[key], key).toBeGreaterThanOrEqual(0.0);
    }
    expect(profile.step).toBeGreaterThanOrEqual(profile.collide);
  });

  it('reports the broad-phase proxy count and tree metrics', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    expect(world.GetTreeHeight()).toBe(0);
    for (let i = 0; i < 8; ++i) {
      addCircle(createBody(world, b2BodyType.b2_dynamicBody, 3.0 * i, 0.0), 0.5, 1.0);
    }
    expect(world.GetProxyCount()).toBe(8);
    expect(world.GetTreeHeight()).toBeGreaterThanOrEqual(3);
    expect(world.GetTreeBalance()).toBeGreaterThanOrEqual(0);
    expect(world.GetTreeQuality()).toBeGreaterThanOrEqual(1.0);
    expect(world.GetContactManager().m_broadPhase.GetProxyCount()).toBe(8);
  });
});

describe('b2World.DrawDebugData', () => {
  class Recorder extends b2Draw {
    readonly calls: unknown[][] = [];
    DrawPolygon(vertices: readonly b2Vec2[], vertexCount: number, color: b2Color): void {
      this.calls.push(['polygon', vertices.slice(0, vertexCount).map((v) => [v.x, v.y]), [color.r, color.g, color.b]]);
    }
    DrawSolidPolygon(vertices: readonly b2Vec2[], vertexCount: number, color: b2Color): void {
      this.calls.push(['solidPolygon', vertices.slice(0, vertexCount).map((v) => [v.x, v.y]), [color.r, color.g, color.b]]);
    }
    DrawCircle(center: b2Vec2, radius: number, color: b2Color): void {
      this.calls.push(['circle', [center.x, center.y], radius, [color.r, color.g, color.b]]);
    }
    DrawSolidCircle(center: b2Vec2, radius: number, axis: b2Vec2, color: b2Color): void {
      this.calls.push(['solidCircle', [center.x, center.y], radius, [axis.x, axis.y], [color.r, color.g, color.b]]);
    }
    DrawSegment(p1: b2Vec2, p2: b2Vec2, color: b2Color): void {
      this.calls.push(['segment', [p1.x, p1.y], [p2.x, p2.y], [color.r, color.g, color.b]]);
    }
    DrawTransform(xf: b2Transform): void {
      this.calls.push(['transform', [xf.p.x, xf.p.y], [xf.q.s, xf.q.c]]);
    }
  }

  it('draws shapes in the body-state colors, joints, fat AABBs and centers of mass', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const ground = createBody(world, b2BodyType.b2_staticBody, 1.0, 2.0);
    addBox(ground, 1.0, 0.5, 0.0);
    const ball = createBody(world, b2BodyType.b2_dynamicBody, 4.0, 5.0);
    addCircle(ball, 0.25, 1.0);
    const jd = distanceJointDef(ground, ball);
    jd.localAnchorB.Set(0.0, 0.25);
    world.CreateJoint(jd);

    const draw = new Recorder();
    world.SetDebugDraw(draw);
    world.DrawDebugData();
    expect(draw.calls).toEqual([]);

    draw.SetFlags(b2Draw.e_shapeBit | b2Draw.e_jointBit);
    world.DrawDebugData();
    expect(draw.calls).toEqual([
      ['solidCircle', [4.0, 5.0], 0.25, [1.0, 0.0], [0.9, 0.7, 0.7]],
      [
        'solidPolygon',
        [
          [0.0, 1.5],
          [2.0, 1.5],
          [2.0, 2.5],
          [0.0, 2.5],
        ],
        [0.5, 0.9, 0.5],
      ],
      ['segment', [1.0, 2.0], [4.0, 5.25], [0.5, 0.8, 0.8]],
    ]);

    draw.calls.length = 0;
    ball.SetAwake(false);
    draw.SetFlags(b2Draw.e_shapeBit | b2Draw.e_aabbBit | b2Draw.e_centerOfMassBit);
    world.DrawDebugData();
    const fat = world.GetContactManager().m_broadPhase.GetFatAABB(ball.GetFixtureList()!.m_proxies[0].proxyId);
    expect(draw.calls[0]).toEqual(['solidCircle', [4.0, 5.0], 0.25, [1.0, 0.0], [0.6, 0.6, 0.6]]);
    expect(draw.calls[2]).toEqual([
      'polygon',
      [
        [fat.lowerBound.x, fat.lowerBound.y],
        [fat.upperBound.x, fat.lowerBound.y],
        [fat.upperBound.x, fat.upperBound.y],
        [fat.lowerBound.x, fat.upperBound.y],
      ],
      [0.9, 0.3, 0.9],
    ]);
    expect(draw.calls.slice(4)).toEqual([
      ['transform', [4.0, 5.0], [0.0, 1.0]],
      ['transform', [1.0, 2.0], [0.0, 1.0]],
    ]);
  });
});

describe('b2World.Dump', () => {
  it('logs the gravity, the allocation lines and the closing lines with the C++ formats', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    let text = '';
    b2SetLogSink((s) => {
      text += s;
    });
    try {
      world.Dump();
    } finally {
      b2SetLogSink((s) => process.stdout.write(s));
    }
    expect(text).toBe(
      'b2Vec2 g(0.000000000000000e+00f, -1.000000000000000e+01f);\n' +
        'm_world->SetGravity(g);\n' +
        'b2Body** bodies = (b2Body**)b2Alloc(0 * sizeof(b2Body*));\n' +
        'b2Joint** joints = (b2Joint**)b2Alloc(0 * sizeof(b2Joint*));\n' +
        'b2Free(joints);\n' +
        'b2Free(bodies);\n' +
        'joints = NULL;\n' +
        'bodies = NULL;\n',
    );
  });
});
