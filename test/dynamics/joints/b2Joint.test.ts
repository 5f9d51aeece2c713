import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2DistanceJoint, b2DistanceJointDef } from '../../../src/dynamics/joints/b2DistanceJoint';
import { b2FrictionJoint, b2FrictionJointDef } from '../../../src/dynamics/joints/b2FrictionJoint';
import { b2GearJoint, b2GearJointDef } from '../../../src/dynamics/joints/b2GearJoint';
import {
  b2JointDef,
  b2JointType,
  b2LimitState,
  e_atLowerLimit,
  e_atUpperLimit,
  e_distanceJoint,
  e_equalLimits,
  e_frictionJoint,
  e_gearJoint,
  e_inactiveLimit,
  e_mouseJoint,
  e_prismaticJoint,
  e_pulleyJoint,
  e_revoluteJoint,
  e_ropeJoint,
  e_unknownJoint,
  e_weldJoint,
  e_wheelJoint,
} from '../../../src/dynamics/joints/b2Joint';
import { b2JointFactory } from '../../../src/dynamics/joints/b2JointFactory';
import { b2MouseJoint, b2MouseJointDef } from '../../../src/dynamics/joints/b2MouseJoint';
import { b2PrismaticJoint, b2PrismaticJointDef } from '../../../src/dynamics/joints/b2PrismaticJoint';
import { b2PulleyJoint, b2PulleyJointDef } from '../../../src/dynamics/joints/b2PulleyJoint';
import { b2RevoluteJoint, b2RevoluteJointDef } from '../../../src/dynamics/joints/b2RevoluteJoint';
import { b2RopeJoint, b2RopeJointDef } from '../../../src/dynamics/joints/b2RopeJoint';
import { b2WeldJoint, b2WeldJointDef } from '../../../src/dynamics/joints/b2WeldJoint';
import { b2WheelJoint, b2WheelJointDef } from '../../../src/dynamics/joints/b2WheelJoint';
import { captureLog, makeBox, makeGround, makeWorld } from './jointTestWorld';

describe('b2JointType and b2LimitState', () => {
  it('number the joint types in the order of b2Joint.h', () => {
    expect([
      e_unknownJoint,
      e_revoluteJoint,
      e_prismaticJoint,
      e_distanceJoint,
      e_pulleyJoint,
      e_mouseJoint,
      e_gearJoint,
      e_wheelJoint,
      e_weldJoint,
      e_frictionJoint,
      e_ropeJoint,
    ]).toEqual([0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10]);
    expect(b2JointType.e_ropeJoint).toBe(10);
  });

  it('number the limit states in the order of b2Joint.h', () => {
    expect([e_inactiveLimit, e_atLowerLimit, e_atUpperLimit, e_equalLimits]).toEqual([0, 1, 2, 3]);
    expect(b2LimitState.e_equalLimits).toBe(3);
  });
});

describe('joint definitions', () => {
  it('carry the C++ default values', () => {
    const base = new b2JointDef();
    expect([base.type, base.userData, base.bodyA, base.bodyB, base.collideConnected]).toEqual([e_unknownJoint, null, null, null, false]);

    const pulley = new b2PulleyJointDef();
    expect(pulley.type).toBe(e_pulleyJoint);
    expect(pulley.collideConnected).toBe(true);
    expect([pulley.groundAnchorA.x, pulley.groundAnchorA.y, pulley.groundAnchorB.x, pulley.groundAnchorB.y]).toEqual([-1, 1, 1, 1]);
    expect([pulley.localAnchorA.x, pulley.localAnchorB.x, pulley.ratio]).toEqual([-1, 1, 1]);

    const mouse = new b2MouseJointDef();
    expect([mouse.type, mouse.maxForce, mouse.frequencyHz, mouse.dampingRatio]).toEqual([e_mouseJoint, 0, 5, 0.7]);

    const wheel = new b2WheelJointDef();
    expect([wheel.type, wheel.frequencyHz, wheel.dampingRatio, wheel.localAxisA.x, wheel.localAxisA.y]).toEqual([e_wheelJoint, 2, 0.7, 1, 0]);

    const rope = new b2RopeJointDef();
    expect([rope.type, rope.localAnchorA.x, rope.localAnchorB.x, rope.maxLength]).toEqual([e_ropeJoint, -1, 1, 0]);

    expect(new b2DistanceJointDef().length).toBe(1);
    expect(new b2GearJointDef().ratio).toBe(1);
    expect(new b2PrismaticJointDef().localAxisA.x).toBe(1);
    expect(new b2RevoluteJointDef().type).toBe(e_revoluteJoint);
    expect(new b2WeldJointDef().type).toBe(e_weldJoint);
    expect(new b2FrictionJointDef().type).toBe(e_frictionJoint);
  });
});

describe('b2JointFactory', () => {
  it('constructs the concrete class named by def.type', () => {
    const world = makeWorld();
    const ground = makeGround(world);
    const a = makeBox(world, 0, 5, 0.5, 0.5);
    const b = makeBox(world, 2, 5, 0.5, 0.5);

    const rev = new b2RevoluteJointDef();
    rev.Initialize(ground, a, new b2Vec2(0, 5));
    const pri = new b2PrismaticJointDef();
    pri.Initialize(ground, b, new b2Vec2(2, 5), new b2Vec2(1, 0));
    const revolute = b2JointFactory.Create(rev);
    const prismatic = b2JointFactory.Create(pri);
    const gear = new b2GearJointDef();
    gear.bodyA = a;
    gear.bodyB = b;
    gear.joint1 = revolute;
    gear.joint2 = prismatic;

    const dist = new b2DistanceJointDef();
    dist.Initialize(a, b, a.GetPosition(), b.GetPosition());
    const pulley = new b2PulleyJointDef();
    pulley.Initialize(a, b, new b2Vec2(0, 10), new b2Vec2(2, 10), new b2Vec2(0, 5), new b2Vec2(2, 5), 1);
    const mouse = new b2MouseJointDef();
    mouse.bodyA = ground;
    mouse.bodyB = a;
    mouse.maxForce = 1;
    const wheel = new b2WheelJointDef();
    wheel.Initialize(a, b, b.GetPosition(), new b2Vec2(0, 1));
    const weld = new b2WeldJointDef();
    weld.Initialize(a, b, a.GetPosition());
    const friction = new b2FrictionJointDef();
    friction.Initialize(ground, a, a.GetPosition());
    const rope = new b2RopeJointDef();
    rope.bodyA = a;
    rope.bodyB = b;

    expect(revolute).toBeInstanceOf(b2RevoluteJoint);
    expect(prismatic).toBeInstanceOf(b2PrismaticJoint);
    expect(b2JointFactory.Create(gear)).toBeInstanceOf(b2GearJoint);
    expect(b2JointFactory.Create(dist)).toBeInstanceOf(b2DistanceJoint);
    expect(b2JointFactory.Create(pulley)).toBeInstanceOf(b2PulleyJoint);
    expect(b2JointFactory.Create(mouse)).toBeInstanceOf(b2MouseJoint);
    expect(b2JointFactory.Create(wheel)).toBeInstanceOf(b2WheelJoint);
    expect(b2JointFactory.Create(weld)).toBeInstanceOf(b2WeldJoint);
    expect(b2JointFactory.Create(friction)).toBeInstanceOf(b2FrictionJoint);
    expect(b2JointFactory.Create(rope)).toBeInstanceOf(b2RopeJoint);
  });

  it('rejects an unknown joint type on Create and Destroy', () => {
    const world = makeWorld();
    const def = new b2JointDef();
    def.bodyA = makeGround(world);
    def.bodyB = makeBox(world, 0, 1, 0.5, 0.5);
    expect(() => b2JointFactory.Create(def)).toThrow(/unknown joint type/);

    const rope = new b2RopeJointDef();
    rope.bodyA = def.bodyA;
    rope.bodyB = def.bodyB;
    const joint = b2JointFactory.Create(rope);
    expect(() => b2JointFactory.Destroy(joint)).not.toThrow();
    joint.m_type = e_unknownJoint;
    expect(() => b2JointFactory.Destroy(joint)).toThrow(/unknown joint type/);
  });

  it('refuses a joint whose two bodies are the same or missing', () => {
    const world = makeWorld();
    const a = makeBox(world, 0, 1, 0.5, 0.5);
    const def = new b2RopeJointDef();
    def.bodyA = a;
    def.bodyB = a;
    expect(() => b2JointFactory.Create(def)).toThrow();
    def.bodyB = null;
    expect(() => b2JointFactory.Create(def)).toThrow();
  });
});

describe('b2Joint base API', () => {
  it('exposes type, bodies, user data, collideConnected and the world list links', () => {
    const world = makeWorld();
    const ground = makeGround(world);
    const a = makeBox(world, 0, 5, 0.5, 0.5);
    const b = makeBox(world, 2, 5, 0.5, 0.5);

    const d1 = new b2DistanceJointDef();
    d1.Initialize(ground, a, new b2Vec2(0, 10), a.GetPosition());
    d1.userData = { tag: 'first' };
    d1.collideConnected = true;
    const j1 = world.CreateJoint(d1);

    const d2 = new b2RopeJointDef();
    d2.bodyA = a;
    d2.bodyB = b;
    d2.maxLength = 3;
    const j2 = world.CreateJoint(d2);

    expect(j1.GetType()).toBe(e_distanceJoint);
    expect(j2.GetType()).toBe(e_ropeJoint);
    expect(j1.GetBodyA()).toBe(ground);
    expect(j1.GetBodyB()).toBe(a);
    expect(j1.GetUserData()).toEqual({ tag: 'first' });
    j1.SetUserData(42);
    expect(j1.GetUserData()).toBe(42);
    expect(j1.GetCollideConnected()).toBe(true);
    expect(j2.GetCollideConnected()).toBe(false);

    // The world prepends: the newest joint heads the list.
    expect(world.GetJointList()).toBe(j2);
    expect(j2.GetNext()).toBe(j1);
    expect(j1.GetNext()).toBeNull();

    // Each edge names the joint and the body at the other end.
    expect(j2.m_edgeA.joint).toBe(j2);
    expect(j2.m_edgeA.other).toBe(b);
    expect(j2.m_edgeB.other).toBe(a);
    expect(a.GetJointList()).toBe(j2.m_edgeA);
    expect(a.GetJointList()?.next).toBe(j1.m_edgeB);
  });

  it('is active only while both bodies are active', () => {
    const world = makeWorld();
    const a = makeBox(world, 0, 5, 0.5, 0.5);
    const b = makeBox(world, 2, 5, 0.5, 0.5);
    const def = new b2RopeJointDef();
    def.bodyA = a;
    def.bodyB = b;
    def.maxLength = 3;
    const joint = world.CreateJoint(def);
    expect(joint.IsActive()).toBe(true);
    b.SetActive(false);
    expect(joint.IsActive()).toBe(false);
    b.SetActive(true);
    a.SetActive(false);
    expect(joint.IsActive()).toBe(false);
  });

  it('logs the C++ fallback line from the base Dump and the mouse joint notice', () => {
    const world = makeWorld();
    const ground = makeGround(world);
    const a = makeBox(world, 0, 5, 0.5, 0.5);
    const md = new b2MouseJointDef();
    md.bodyA = ground;
    md.bodyB = a;
    md.target.Set(0, 5);
    md.maxForce = 10;
    const mouse = world.CreateJoint(md);
    expect(captureLog(() => mouse.Dump())).toBe('Mouse joint dumping is not supported.\n');

    const base = Object.getPrototypeOf(b2MouseJoint.prototype) as { Dump(): void };
    expect(captureLog(() => base.Dump.call(mouse))).toBe('// Dump is not supported for this joint type.\n');
  });
});
