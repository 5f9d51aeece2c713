import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2MassData } from '../../src/collision/shapes/b2Shape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Body, b2BodyDef, b2BodyType, b2_dynamicBody, b2_kinematicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2ContactListener } from '../../src/dynamics/b2WorldCallbacks';
import { b2Contact } from '../../src/dynamics/contacts/b2Contact';

const dt = 1.0 / 60.0;

function box(hx: number, hy: number, center?: b2Vec2, angle = 0.0): b2PolygonShape {
  return new b2PolygonShape().SetAsBox(hx, hy, center, angle);
}

function createBody(world: b2World, type: b2BodyType, x = 0.0, y = 0.0, angle = 0.0): b2Body {
  const bd = new b2BodyDef();
  bd.type = type;
  bd.position.Set(x, y);
  bd.angle = angle;
  return world.CreateBody(bd);
}

/** A static ground box (top face at y = 0) and a dynamic 1x1 box resting on it after `steps` steps. */
function restingBox(world: b2World, steps: number): { ground: b2Body; body: b2Body } {
  const ground = createBody(world, b2_staticBody, 0.0, -1.0);
  ground.CreateFixture(box(10.0, 1.0), 0.0);
  const body = createBody(world, b2_dynamicBody, 0.0, 0.5);
  body.CreateFixture(box(0.5, 0.5), 1.0);
  for (let i = 0; i < steps; ++i) {
    world.Step(dt, 8, 3);
  }
  return { ground, body };
}

describe('b2BodyDef', () => {
  it('has the C++ defaults', () => {
    const bd = new b2BodyDef();
    expect(bd.type).toBe(b2_staticBody);
    expect([bd.position.x, bd.position.y, bd.angle]).toEqual([0, 0, 0]);
    expect([bd.linearVelocity.x, bd.linearVelocity.y, bd.angularVelocity]).toEqual([0, 0, 0]);
    expect([bd.linearDamping, bd.angularDamping, bd.gravityScale]).toEqual([0, 0, 1]);
    expect([bd.allowSleep, bd.awake, bd.fixedRotation, bd.bullet, bd.active]).toEqual([true, true, false, false, true]);
    expect(bd.userData).toBeNull();
  });
});

describe('b2Body construction', () => {
  it('copies the definition into the flags, transform and sweep', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const bd = new b2BodyDef();
    bd.type = b2_dynamicBody;
    bd.position.Set(1.0, 2.0);
    bd.angle = 0.5;
    bd.linearVelocity.Set(3.0, 4.0);
    bd.angularVelocity = 5.0;
    bd.bullet = true;
    bd.fixedRotation = true;
    bd.allowSleep = false;
    bd.awake = false;
    bd.userData = 'user';
    const b = world.CreateBody(bd);

    expect(b.m_flags).toBe(b2Body.e_bulletFlag | b2Body.e_fixedRotationFlag | b2Body.e_activeFlag);
    expect(b.GetPosition()).toEqual(new b2Vec2(1.0, 2.0));
    expect(b.GetAngle()).toBe(0.5);
    expect(b.m_sweep.c0).toEqual(new b2Vec2(1.0, 2.0));
    expect(b.m_sweep.a0).toBe(0.5);
    expect(b.GetLinearVelocity()).toEqual(new b2Vec2(3.0, 4.0));
    expect(b.GetAngularVelocity()).toBe(5.0);
    expect(b.GetMass()).toBe(1.0);
    expect(b.GetUserData()).toBe('user');
    expect(b.GetWorld()).toBe(world);
  });

  it('rejects a non-finite position or a negative damping', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const bd = new b2BodyDef();
    bd.position.Set(Number.NaN, 0.0);
    expect(() => world.CreateBody(bd)).toThrow();
    const bd2 = new b2BodyDef();
    bd2.linearDamping = -1.0;
    expect(() => world.CreateBody(bd2)).toThrow();
  });
});

describe('b2Body mass', () => {
  it('gives a 2x2 box of density 1 mass 4 and inertia 8/3 about its center', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    b.CreateFixture(box(1.0, 1.0), 1.0);

    expect(b.GetMass()).toBe(4.0);
    expect(b.m_invMass).toBe(0.25);
    expect(b.m_I).toBeCloseTo(8.0 / 3.0, 14);
    expect(b.m_invI).toBeCloseTo(3.0 / 8.0, 14);
    expect(b.GetLocalCenter().x).toBeCloseTo(0.0, 15);
    expect(b.GetLocalCenter().y).toBeCloseTo(0.0, 15);
    expect(b.GetInertia()).toBeCloseTo(8.0 / 3.0, 14);
  });

  it('moves the center of mass to an offset fixture and reports inertia about the origin', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody, 1.0, 1.0);
    b.CreateFixture(box(1.0, 1.0, new b2Vec2(2.0, 0.0)), 1.0);

    expect(b.GetMass()).toBe(4.0);
    expect(b.GetLocalCenter().x).toBeCloseTo(2.0, 14);
    expect(b.GetLocalCenter().y).toBeCloseTo(0.0, 14);
    expect(b.GetWorldCenter().x).toBeCloseTo(3.0, 14);
    expect(b.GetWorldCenter().y).toBeCloseTo(1.0, 14);
    expect(b.m_I).toBeCloseTo(8.0 / 3.0, 12);
    expect(b.GetInertia()).toBeCloseTo(8.0 / 3.0 + 16.0, 12);

    const data = new b2MassData();
    expect(b.GetMassData(data)).toBe(data);
    expect(data.mass).toBe(4.0);
    expect(data.I).toBe(b.GetInertia());
    expect(data.center).toEqual(b.GetLocalCenter());
  });

  it('sums several fixtures and skips zero-density ones', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    b.CreateFixture(box(1.0, 1.0, new b2Vec2(-1.0, 0.0)), 1.0);
    b.CreateFixture(box(1.0, 1.0, new b2Vec2(1.0, 0.0)), 3.0);
    b.CreateFixture(box(5.0, 5.0, new b2Vec2(9.0, 9.0)), 0.0);

    // Masses 4 at x = -1 and 12 at x = +1: center at x = 0.5.
    expect(b.GetMass()).toBe(16.0);
    expect(b.GetLocalCenter().x).toBeCloseTo(0.5, 14);
    expect(b.GetLocalCenter().y).toBeCloseTo(0.0, 14);
    // Each box: 8/3 per unit density about its own center, plus m d^2 about the origin.
    const aboutOrigin = (8.0 / 3.0 + 4.0) * 1.0 + (8.0 / 3.0 + 4.0) * 3.0;
    expect(b.GetInertia()).toBeCloseTo(aboutOrigin, 12);
    expect(b.m_I).toBeCloseTo(aboutOrigin - 16.0 * 0.25, 12);
  });

  it('gives static and kinematic bodies zero mass and a dynamic body without density mass 1', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const s = createBody(world, b2_staticBody);
    s.CreateFixture(box(1.0, 1.0), 1.0);
    const k = createBody(world, b2_kinematicBody);
    k.CreateFixture(box(1.0, 1.0), 1.0);
    const d = createBody(world, b2_dynamicBody);
    d.CreateFixture(box(1.0, 1.0), 0.0);

    expect([s.GetMass(), s.m_invMass, s.m_I, s.m_invI]).toEqual([0, 0, 0, 0]);
    expect([k.GetMass(), k.m_invMass, k.m_I, k.m_invI]).toEqual([0, 0, 0, 0]);
    expect([d.GetMass(), d.m_invMass, d.m_I, d.m_invI]).toEqual([1, 1, 0, 0]);
  });

  it('SetMassData overrides the fixtures, moves the center and keeps the origin velocity', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    b.CreateFixture(box(1.0, 1.0), 1.0);
    b.SetAngularVelocity(2.0);

    const data = new b2MassData();
    data.mass = 2.0;
    data.center.Set(1.0, 0.0);
    data.I = 3.0;
    b.SetMassData(data);

    expect(b.GetMass()).toBe(2.0);
    expect(b.m_invMass).toBe(0.5);
    // I about the center = I - m |c|^2 = 3 - 2.
    expect(b.m_I).toBe(1.0);
    expect(b.m_invI).toBe(1.0);
    expect(b.GetInertia()).toBe(3.0);
    expect(b.GetWorldCenter()).toEqual(new b2Vec2(1.0, 0.0));
    expect(b.m_sweep.c0).toEqual(new b2Vec2(1.0, 0.0));
    // v += cross(w, c - oldCenter) = cross(2, (1, 0)) = (0, 2)
    expect(b.GetLinearVelocity()).toEqual(new b2Vec2(0.0, 2.0));

    b.ResetMassData();
    expect(b.GetMass()).toBe(4.0);
    expect(b.GetLocalCenter().x).toBeCloseTo(0.0, 15);
    expect(b.m_I).toBeCloseTo(8.0 / 3.0, 14);
  });

  it('SetMassData turns a non-positive mass into 1 and is ignored on non-dynamic bodies', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    const data = new b2MassData();
    data.mass = -5.0;
    data.I = 0.0;
    b.SetMassData(data);
    expect([b.GetMass(), b.m_invMass, b.m_I, b.m_invI]).toEqual([1, 1, 0, 0]);

    const s = createBody(world, b2_staticBody);
    data.mass = 7.0;
    s.SetMassData(data);
    expect(s.GetMass()).toBe(0.0);
  });

  it('fixed rotation zeroes the rotational inertia and releasing it restores the inertia', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    b.CreateFixture(box(1.0, 1.0), 1.0);

    b.SetFixedRotation(true);
    expect(b.IsFixedRotation()).toBe(true);
    expect(b.m_I).toBe(0.0);
    expect(b.m_invI).toBe(0.0);
    expect(b.GetMass()).toBe(4.0);

    const data = new b2MassData();
    data.mass = 2.0;
    data.I = 3.0;
    b.SetMassData(data);
    expect(b.m_invI).toBe(0.0);

    b.SetFixedRotation(false);
    expect(b.m_I).toBeCloseTo(8.0 / 3.0, 14);
  });

  it('DestroyFixture unlinks the fixture, destroys its contacts and resets the mass', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const { body } = restingBox(world, 2);
    const extra = body.CreateFixture(box(0.25, 0.25, new b2Vec2(0.0, 2.0)), 2.0);
    const first = extra.GetNext();
    expect(body.GetFixtureList()).toBe(extra);
    expect(body.m_fixtureCount).toBe(2);
    expect(body.GetMass()).toBe(1.0 + 0.5);
    expect(world.GetContactCount()).toBe(1);

    // The contact belongs to the original fixture: destroying it removes the contact.
    body.DestroyFixture(first!);
    expect(body.GetFixtureList()).toBe(extra);
    expect(extra.GetNext()).toBeNull();
    expect(body.m_fixtureCount).toBe(1);
    expect(world.GetContactCount()).toBe(0);
    expect(body.GetContactList()).toBeNull();
    expect(body.GetMass()).toBe(0.5);
    expect(body.GetLocalCenter().y).toBeCloseTo(2.0, 14);
    expect(first!.m_proxyCount).toBe(0);
  });
});

describe('b2Body forces and impulses', () => {
  it('ApplyForce at an off-center point accumulates force and torque and wakes the body', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const bd = new b2BodyDef();
    bd.type = b2_dynamicBody;
    bd.awake = false;
    const b = world.CreateBody(bd);
    b.CreateFixture(box(1.0, 1.0), 1.0);
    expect(b.IsAwake()).toBe(false);

    b.ApplyForce(new b2Vec2(0.0, 10.0), new b2Vec2(1.0, 0.0));
    expect(b.IsAwake()).toBe(true);
    expect(b.m_force).toEqual(new b2Vec2(0.0, 10.0));
    // cross((1, 0) - c, (0, 10)) = 10
    expect(b.m_torque).toBe(10.0);

    const invI = b.m_invI;
    const invMass = b.m_invMass;
    world.Step(dt, 8, 3);
    // b2Island: v += h * (gravityScale * gravity + invMass * force); w += h * invI * torque.
    expect(Object.is(b.GetLinearVelocity().y, dt * (1.0 * 0.0 + invMass * 10.0))).toBe(true);
    expect(Object.is(b.GetAngularVelocity(), 0.0 + dt * invI * 10.0)).toBe(true);
    // Forces are cleared after the step.
    expect(b.m_force).toEqual(new b2Vec2(0.0, 0.0));
    expect(b.m_torque).toBe(0.0);
  });

  it('ApplyForceToCenter and ApplyTorque add to the accumulators; non-dynamic bodies ignore them', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    b.ApplyForceToCenter(new b2Vec2(1.0, 2.0));
    b.ApplyForceToCenter(new b2Vec2(1.0, 2.0));
    b.ApplyTorque(3.0);
    expect(b.m_force).toEqual(new b2Vec2(2.0, 4.0));
    expect(b.m_torque).toBe(3.0);

    const k = createBody(world, b2_kinematicBody);
    k.ApplyForce(new b2Vec2(1.0, 0.0), new b2Vec2(0.0, 1.0));
    k.ApplyForceToCenter(new b2Vec2(1.0, 0.0));
    k.ApplyTorque(1.0);
    k.ApplyLinearImpulse(new b2Vec2(1.0, 0.0), new b2Vec2(0.0, 1.0));
    k.ApplyAngularImpulse(1.0);
    expect(k.m_force).toEqual(new b2Vec2(0.0, 0.0));
    expect(k.m_torque).toBe(0.0);
    expect(k.GetLinearVelocity()).toEqual(new b2Vec2(0.0, 0.0));
    expect(k.GetAngularVelocity()).toBe(0.0);
  });

  it('ApplyLinearImpulse changes the velocity by impulse / mass at once', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    b.CreateFixture(box(1.0, 1.0), 1.0);

    b.ApplyLinearImpulse(new b2Vec2(8.0, -4.0), b.GetWorldCenter());
    expect(b.GetLinearVelocity()).toEqual(new b2Vec2(2.0, -1.0));
    expect(b.GetAngularVelocity()).toBe(0.0);

    // Off-center: w += invI * cross(r, impulse) with r = (0, 1): cross = -8.
    b.ApplyLinearImpulse(new b2Vec2(8.0, 0.0), new b2Vec2(0.0, 1.0));
    expect(b.GetLinearVelocity()).toEqual(new b2Vec2(4.0, -1.0));
    expect(Object.is(b.GetAngularVelocity(), 0.0 + b.m_invI * -8.0)).toBe(true);

    const w = b.GetAngularVelocity();
    b.ApplyAngularImpulse(2.0);
    expect(Object.is(b.GetAngularVelocity(), w + b.m_invI * 2.0)).toBe(true);
  });

  it('SetLinearVelocity and SetAngularVelocity wake a moving body and are ignored on static bodies', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const bd = new b2BodyDef();
    bd.type = b2_dynamicBody;
    bd.awake = false;
    const b = world.CreateBody(bd);
    b.SetLinearVelocity(new b2Vec2(0.0, 0.0));
    expect(b.IsAwake()).toBe(false);
    b.SetLinearVelocity(new b2Vec2(1.0, 0.0));
    expect(b.IsAwake()).toBe(true);
    b.SetAwake(false);
    b.SetAngularVelocity(1.0);
    expect(b.IsAwake()).toBe(true);
    expect(b.GetAngularVelocity()).toBe(1.0);

    const s = createBody(world, b2_staticBody);
    s.SetLinearVelocity(new b2Vec2(1.0, 0.0));
    s.SetAngularVelocity(1.0);
    expect(s.GetLinearVelocity()).toEqual(new b2Vec2(0.0, 0.0));
    expect(s.GetAngularVelocity()).toBe(0.0);
  });

  it('GetLinearVelocity returns a copy, written to out when given', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    b.SetLinearVelocity(new b2Vec2(1.0, 2.0));
    const copy = b.GetLinearVelocity();
    copy.x = 99.0;
    expect(b.m_linearVelocity.x).toBe(1.0);
    const out = new b2Vec2();
    expect(b.GetLinearVelocity(out)).toBe(out);
    expect(out).toEqual(new b2Vec2(1.0, 2.0));
  });

  it('SetAwake(false) zeroes velocity, force and sleep time; SetAwake(true) keeps them', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    b.SetLinearVelocity(new b2Vec2(1.0, 2.0));
    b.SetAngularVelocity(3.0);
    b.ApplyForceToCenter(new b2Vec2(1.0, 0.0));
    b.ApplyTorque(1.0);
    b.m_sleepTime = 0.25;
    b.SetAwake(true);
    expect(b.m_sleepTime).toBe(0.25);
    b.SetAwake(false);
    expect(b.IsAwake()).toBe(false);
    expect([b.m_linearVelocity.x, b.m_linearVelocity.y, b.m_angularVelocity]).toEqual([0, 0, 0]);
    expect([b.m_force.x, b.m_force.y, b.m_torque, b.m_sleepTime]).toEqual([0, 0, 0, 0]);
  });

  it('SetSleepingAllowed(false) wakes the body', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    b.SetAwake(false);
    b.SetSleepingAllowed(false);
    expect(b.IsSleepingAllowed()).toBe(false);
    expect(b.IsAwake()).toBe(true);
    b.SetSleepingAllowed(true);
    expect(b.IsSleepingAllowed()).toBe(true);
  });

  it('SetBullet toggles the bullet flag only', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    const flags = b.m_flags;
    b.SetBullet(true);
    expect(b.IsBullet()).toBe(true);
    expect(b.m_flags).toBe(flags | b2Body.e_bulletFlag);
    b.SetBullet(false);
    expect(b.m_flags).toBe(flags);
  });
});

describe('b2Body coordinates', () => {
  it('converts points and vectors between world and local frames and back', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody, 3.0, 4.0, 0.7);
    const local = new b2Vec2(1.25, -2.5);

    const wp = b.GetWorldPoint(local);
    const c = Math.cos(0.7);
    const s = Math.sin(0.7);
    expect(wp.x).toBeCloseTo(c * 1.25 - s * -2.5 + 3.0, 14);
    expect(wp.y).toBeCloseTo(s * 1.25 + c * -2.5 + 4.0, 14);
    const back = b.GetLocalPoint(wp);
    expect(back.x).toBeCloseTo(local.x, 14);
    expect(back.y).toBeCloseTo(local.y, 14);

    const wv = b.GetWorldVector(local);
    expect(wv.x).toBeCloseTo(c * 1.25 - s * -2.5, 14);
    expect(wv.y).toBeCloseTo(s * 1.25 + c * -2.5, 14);
    const lv = b.GetLocalVector(wv);
    expect(lv.x).toBeCloseTo(local.x, 14);
    expect(lv.y).toBeCloseTo(local.y, 14);
  });

  it('is exact for an unrotated body and writes into out, even when out aliases the input', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody, 3.0, 4.0);
    const p = new b2Vec2(1.0, 2.0);
    expect(b.GetWorldPoint(p, p)).toBe(p);
    expect(p).toEqual(new b2Vec2(4.0, 6.0));
    expect(b.GetLocalPoint(p, p)).toEqual(new b2Vec2(1.0, 2.0));
    expect(b.GetWorldVector(p, p)).toEqual(new b2Vec2(1.0, 2.0));
    expect(b.GetLocalVector(p, p)).toEqual(new b2Vec2(1.0, 2.0));
  });

  it('gives the velocity of a point as v + w x (p - c)', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody, 3.0, 4.0);
    b.SetLinearVelocity(new b2Vec2(1.0, 0.0));
    b.SetAngularVelocity(2.0);
    // p - c = (0, 1): w x r = (-2, 0)
    expect(b.GetLinearVelocityFromWorldPoint(new b2Vec2(3.0, 5.0))).toEqual(new b2Vec2(-1.0, 0.0));
    // local (1, 0) is world (4, 4): w x r = (0, 2)
    const out = new b2Vec2();
    expect(b.GetLinearVelocityFromLocalPoint(new b2Vec2(1.0, 0.0), out)).toBe(out);
    expect(out).toEqual(new b2Vec2(1.0, 2.0));
  });
});

describe('b2Body transform, type and activity', () => {
  it('SetTransform moves the body, its proxies and keeps its velocity', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    const f = b.CreateFixture(box(1.0, 1.0, new b2Vec2(1.0, 0.0)), 1.0);
    b.SetLinearVelocity(new b2Vec2(1.0, 2.0));
    b.SetAngularVelocity(3.0);

    b.SetTransform(new b2Vec2(10.0, 5.0), 0.0);
    expect(b.GetPosition()).toEqual(new b2Vec2(10.0, 5.0));
    expect(b.GetAngle()).toBe(0.0);
    expect(b.GetWorldCenter().x).toBeCloseTo(11.0, 14);
    expect(b.m_sweep.c0).toEqual(b.m_sweep.c);
    expect(b.GetLinearVelocity()).toEqual(new b2Vec2(1.0, 2.0));
    expect(b.GetAngularVelocity()).toBe(3.0);

    // The proxy AABB is the shape's AABB at the new transform (polygon radius included).
    const aabb = f.GetAABB(0);
    expect(aabb.lowerBound.x).toBeCloseTo(10.0 - 0.01, 14);
    expect(aabb.upperBound.x).toBeCloseTo(12.0 + 0.01, 14);
    expect(aabb.lowerBound.y).toBeCloseTo(4.0 - 0.01, 14);
    expect(aabb.upperBound.y).toBeCloseTo(6.0 + 0.01, 14);
    const fat = world.m_contactManager.m_broadPhase.GetFatAABB(f.m_proxies[0].proxyId);
    expect(fat.lowerBound.x).toBeLessThanOrEqual(aabb.lowerBound.x);
    expect(fat.upperBound.x).toBeGreaterThanOrEqual(aabb.upperBound.x);
  });

  it('SetTransform onto another body creates the contact at once', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2_dynamicBody);
    a.CreateFixture(box(1.0, 1.0), 1.0);
    const b = createBody(world, b2_dynamicBody, 20.0, 0.0);
    b.CreateFixture(box(1.0, 1.0), 1.0);
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(0);

    b.SetTransform(new b2Vec2(1.0, 0.0), 0.0);
    expect(world.GetContactCount()).toBe(1);
  });

  it('SetType(static) zeroes velocity and mass, and the next step destroys contacts with static bodies', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const { body } = restingBox(world, 5);
    expect(world.GetContactCount()).toBe(1);
    expect(world.GetContactList()!.IsTouching()).toBe(true);

    body.SetLinearVelocity(new b2Vec2(1.0, 2.0));
    body.ApplyForceToCenter(new b2Vec2(1.0, 1.0));
    body.SetType(b2_staticBody);
    expect(body.GetType()).toBe(b2_staticBody);
    expect(body.GetLinearVelocity()).toEqual(new b2Vec2(0.0, 0.0));
    expect(body.GetAngularVelocity()).toBe(0.0);
    expect(body.GetMass()).toBe(0.0);
    expect(body.m_force).toEqual(new b2Vec2(0.0, 0.0));
    // 2.2.1 flags the contacts for filtering; Collide destroys them on the next step.
    const contact = world.GetContactList()!;
    expect(contact.m_flags & b2Contact.e_filterFlag).toBe(b2Contact.e_filterFlag);

    const position = body.GetPosition().Clone();
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(0);
    expect(body.GetContactList()).toBeNull();
    expect(body.GetPosition()).toEqual(position);

    body.SetType(b2_dynamicBody);
    expect(body.GetMass()).toBe(1.0);
    expect(body.IsAwake()).toBe(true);
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(1);
  });

  it('SetActive(false) removes proxies and contacts; SetActive(true) restores them', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const { body } = restingBox(world, 5);
    const f = body.GetFixtureList()!;
    const proxies = world.GetProxyCount();
    expect(world.GetContactCount()).toBe(1);

    body.SetActive(false);
    expect(body.IsActive()).toBe(false);
    expect(f.m_proxyCount).toBe(0);
    expect(world.GetProxyCount()).toBe(proxies - 1);
    expect(world.GetContactCount()).toBe(0);
    expect(body.GetContactList()).toBeNull();

    // An inactive body does not move.
    const position = body.GetPosition().Clone();
    world.Step(dt, 8, 3);
    expect(body.GetPosition()).toEqual(position);
    expect(world.GetContactCount()).toBe(0);

    body.SetActive(true);
    expect(body.IsActive()).toBe(true);
    expect(f.m_proxyCount).toBe(1);
    expect(world.GetProxyCount()).toBe(proxies);
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(1);
  });

  it('an inactive body gets no proxies for new fixtures until activated', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const bd = new b2BodyDef();
    bd.active = false;
    const b = world.CreateBody(bd);
    const circle = new b2CircleShape();
    circle.m_radius = 0.5;
    const f = b.CreateFixture(circle, 0.0);
    expect(f.m_proxyCount).toBe(0);
    expect(world.GetProxyCount()).toBe(0);
    b.SetActive(true);
    expect(world.GetProxyCount()).toBe(1);
  });

  it('throws instead of editing a locked world, and leaves the body unchanged', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const { body } = restingBox(world, 0);
    const errors: string[] = [];
    class Editor extends b2ContactListener {
      override BeginContact(): void {
        const b = body;
        const attempts: [string, () => void][] = [
          ['CreateFixture', () => b.CreateFixture(box(1.0, 1.0), 1.0)],
          ['DestroyFixture', () => b.DestroyFixture(b.GetFixtureList()!)],
          ['SetTransform', () => b.SetTransform(new b2Vec2(5.0, 5.0), 1.0)],
          ['SetType', () => b.SetType(b.GetType() === b2_staticBody ? b2_dynamicBody : b2_staticBody)],
          ['SetActive', () => b.SetActive(false)],
          ['SetMassData', () => b.SetMassData(new b2MassData())],
        ];
        for (const [name, attempt] of attempts) {
          try {
            attempt();
          } catch (e) {
            errors.push(`${name}: ${(e as Error).message}`);
          }
        }
      }
    }
    world.SetContactListener(new Editor());
    const fixtures = [body.m_fixtureCount, body.GetMass(), body.GetType(), body.IsActive()];
    world.Step(dt, 8, 3);

    expect(errors).toHaveLength(6);
    for (const [i, name] of ['CreateFixture', 'DestroyFixture', 'SetTransform', 'SetType', 'SetActive', 'SetMassData'].entries()) {
      expect(errors[i]).toContain(`b2Body.${name}: the world is locked`);
    }
    expect([body.m_fixtureCount, body.GetMass(), body.GetType(), body.IsActive()]).toEqual(fixtures);
  });
});

describe('b2Body lists and filtering', () => {
  it('CreateFixture prepends, accepts a def or a shape, clones the shape and flags the world', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    const circle = new b2CircleShape();
    circle.m_radius = 0.5;
    const f1 = b.CreateFixture(circle, 2.0);
    world.m_flags &= ~b2World.e_newFixture;
    const fd = new b2FixtureDef();
    fd.shape = box(1.0, 1.0);
    fd.friction = 0.7;
    const f2 = b.CreateFixture(fd);

    expect(b.GetFixtureList()).toBe(f2);
    expect(f2.GetNext()).toBe(f1);
    expect(b.m_fixtureCount).toBe(2);
    expect(f1.GetShape()).not.toBe(circle);
    expect(f1.GetShape().m_radius).toBe(0.5);
    expect(f1.GetDensity()).toBe(2.0);
    expect(f2.GetFriction()).toBe(0.7);
    expect(f2.GetBody()).toBe(b);
    expect(world.m_flags & b2World.e_newFixture).toBe(b2World.e_newFixture);
  });

  it('ShouldCollide needs a dynamic body and no joint that forbids collision', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const s1 = createBody(world, b2_staticBody);
    const s2 = createBody(world, b2_staticBody);
    const k = createBody(world, b2_kinematicBody);
    const d = createBody(world, b2_dynamicBody);
    expect(s1.ShouldCollide(s2)).toBe(false);
    expect(s1.ShouldCollide(k)).toBe(false);
    expect(k.ShouldCollide(d)).toBe(true);
    expect(s1.ShouldCollide(d)).toBe(true);
  });

  it('SynchronizeTransform and Advance rebuild the transform from the sweep', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const b = createBody(world, b2_dynamicBody);
    const data = new b2MassData();
    data.mass = 1.0;
    data.center.Set(1.0, 0.0);
    data.I = 2.0;
    b.SetMassData(data);

    b.m_sweep.c.Set(5.0, 0.0);
    b.m_sweep.a = 0.0;
    b.SynchronizeTransform();
    expect(b.GetPosition()).toEqual(new b2Vec2(4.0, 0.0));

    b.m_sweep.c0.Set(1.0, 0.0);
    b.m_sweep.a0 = 0.0;
    b.m_sweep.alpha0 = 0.0;
    b.Advance(0.5);
    expect(b.m_sweep.c).toEqual(new b2Vec2(3.0, 0.0));
    expect(b.m_sweep.c0).toEqual(new b2Vec2(3.0, 0.0));
    expect(b.m_sweep.alpha0).toBe(0.5);
    expect(b.GetPosition()).toEqual(new b2Vec2(2.0, 0.0));
  });
});
