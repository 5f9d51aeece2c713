// b2ChangeListener (an addition to 2.2.1): which API calls report a change, and with what.
import { describe, expect, it } from 'vitest';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2_dynamicBody, b2_kinematicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2Filter, b2FixtureDef } from '../../src/dynamics/b2Fixture';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2ChangeListener } from '../../src/dynamics/b2WorldCallbacks';
import { b2MouseJointDef } from '../../src/dynamics/joints/b2MouseJoint';
import type { b2MouseJoint } from '../../src/dynamics/joints/b2MouseJoint';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import type { b2RevoluteJoint } from '../../src/dynamics/joints/b2RevoluteJoint';

class Recorder extends b2ChangeListener {
  readonly events: string[] = [];
  /** BodyWoken's reports, apart from the others. */
  readonly woken: string[] = [];
  constructor(private readonly names: Map<object, string>) {
    super();
  }
  override BodyChanged(body: b2Body, motion: boolean): void {
    this.events.push(`body ${this.names.get(body)} ${motion ? 'motion' : 'state'}`);
  }
  override BodyWoken(body: b2Body): void {
    this.woken.push(`${this.names.get(body)}`);
  }
  override FixtureChanged(fixture: b2Fixture): void {
    this.events.push(`fixture ${this.names.get(fixture)}`);
  }
  override StructureChanged(): void {
    this.events.push('structure');
  }
  take(): string[] {
    return this.events.splice(0);
  }
}

function setup(): { world: b2World; a: b2Body; ground: b2Body; log: Recorder } {
  const world = new b2World(new b2Vec2(0, -10));
  const ground = world.CreateBody(new b2BodyDef());
  const bd = new b2BodyDef();
  bd.type = b2_dynamicBody;
  bd.position.Set(0, 2);
  const a = world.CreateBody(bd);
  const shape = new b2PolygonShape();
  shape.SetAsBox(0.5, 0.5);
  const fd = new b2FixtureDef();
  fd.shape = shape;
  fd.density = 1;
  a.CreateFixture(fd);
  ground.CreateFixture(fd);
  const log = new Recorder(
    new Map<object, string>([
      [a, 'a'],
      [ground, 'ground'],
      [a.GetFixtureList()!, 'fa'],
    ]),
  );
  world.SetChangeListener(log);
  return { world, a, ground, log };
}

describe('b2ChangeListener', () => {
  it('reports motion set through the API as motion, and forces, damping and flags as state', () => {
    const { a, log } = setup();
    a.SetLinearVelocity(new b2Vec2(1, 0));
    a.SetAngularVelocity(2);
    a.SetTransform(new b2Vec2(1, 1), 0.5);
    a.ApplyLinearImpulse(new b2Vec2(0, 1), a.GetWorldCenter());
    a.ApplyAngularImpulse(0.1);
    a.ResetMassData();
    expect(log.take()).toEqual(Array(6).fill('body a motion'));

    a.ApplyForce(new b2Vec2(1, 0), a.GetWorldCenter());
    a.ApplyForceToCenter(new b2Vec2(1, 0));
    a.ApplyTorque(1);
    a.SetLinearDamping(0.1);
    a.SetAngularDamping(0.1);
    a.SetGravityScale(2);
    a.SetBullet(true);
    a.SetAwake(false);
    expect(log.take()).toEqual(Array(8).fill('body a state'));
    // Waking from sleep is reported once; waking an awake body changes nothing and says nothing.
    a.SetAwake(true);
    a.SetAwake(true);
    expect(log.take()).toEqual(['body a state']);
  });

  it('reports every wake the API asks for, of an awake body too: SetAwake(true), forces, impulses, non-zero velocities, a mouse target, a motor', () => {
    const { world, a, ground, log } = setup();
    a.SetAwake(true);
    a.ApplyForce(new b2Vec2(1, 0), a.GetWorldCenter());
    a.ApplyForceToCenter(new b2Vec2(1, 0));
    a.ApplyTorque(1);
    a.ApplyLinearImpulse(new b2Vec2(0, 1), a.GetWorldCenter());
    a.ApplyAngularImpulse(0.1);
    a.SetLinearVelocity(new b2Vec2(1, 0));
    a.SetAngularVelocity(2);
    const md = new b2MouseJointDef();
    md.bodyA = ground;
    md.bodyB = a;
    md.target.Set(0, 2);
    md.maxForce = 10;
    const mouse = world.CreateJoint(md) as b2MouseJoint;
    mouse.SetTarget(new b2Vec2(0, 3));
    expect(log.woken.splice(0)).toEqual(Array(9).fill('a'));
    const jd = new b2RevoluteJointDef();
    jd.Initialize(ground, a, new b2Vec2(0, 2));
    (world.CreateJoint(jd) as b2RevoluteJoint).SetMotorSpeed(1);
    expect(log.woken.splice(0)).toEqual(['ground', 'a']);
    // What does not wake in 2.2.1 says nothing.
    a.SetLinearVelocity(new b2Vec2(0, 0));
    a.SetAngularVelocity(0);
    a.SetLinearDamping(0.1);
    a.SetAwake(false);
    expect(log.woken).toEqual([]);
  });

  it('says nothing when a setter changes nothing (a static body has no velocity)', () => {
    const { ground, log } = setup();
    ground.SetLinearVelocity(new b2Vec2(1, 0));
    ground.ApplyForceToCenter(new b2Vec2(1, 0));
    expect(log.take()).toEqual([]);
  });

  it('reports fixture sensors, filters and materials', () => {
    const { a, log } = setup();
    const f = a.GetFixtureList()!;
    f.SetFriction(0.1);
    f.SetRestitution(0.1);
    f.SetDensity(2);
    f.SetSensor(true);
    f.SetFilterData(new b2Filter());
    expect(log.take().filter((e) => e.startsWith('fixture'))).toEqual(Array(5).fill('fixture fa'));
  });

  it('reports bodies, fixtures and joints coming and going, body types and activity as structure', () => {
    const { world, a, ground, log } = setup();
    const b = world.CreateBody(new b2BodyDef());
    const shape = new b2PolygonShape();
    shape.SetAsBox(1, 1);
    const f = b.CreateFixture(shape, 1);
    b.DestroyFixture(f);
    const jd = new b2RevoluteJointDef();
    jd.Initialize(ground, a, new b2Vec2(0, 2));
    const j = world.CreateJoint(jd);
    world.DestroyJoint(j);
    world.DestroyBody(b);
    // (adding and removing a fixture also resets b's mass: motion, reported too)
    expect(log.take().filter((e) => e === 'structure')).toEqual(Array(6).fill('structure'));
    a.SetType(b2_kinematicBody);
    expect(log.take()).toContain('structure');
    a.SetType(b2_staticBody);
    log.take();
    a.SetActive(false);
    expect(log.take()).toContain('structure');
  });

  it('is told nothing once unregistered', () => {
    const { world, a, log } = setup();
    world.SetChangeListener(null);
    a.SetLinearVelocity(new b2Vec2(1, 0));
    world.CreateBody(new b2BodyDef());
    expect(log.take()).toEqual([]);
  });
});
