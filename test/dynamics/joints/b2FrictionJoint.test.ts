import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2FrictionJoint, b2FrictionJointDef } from '../../../src/dynamics/joints/b2FrictionJoint';
import { captureLog, h, inv_h, makeBox, makeGround, makeWorld, step } from './jointTestWorld';

/** A top-down 1 kg box at (2, 1) held to the ground by a friction joint at its centre. */
function slidingBox(maxForce: number, maxTorque: number) {
  const world = makeWorld(0, 0);
  const ground = makeGround(world);
  const box = makeBox(world, 2, 1, 0.5, 0.5);
  const def = new b2FrictionJointDef();
  def.Initialize(ground, box, box.GetPosition());
  def.maxForce = maxForce;
  def.maxTorque = maxTorque;
  const joint = world.CreateJoint(def) as b2FrictionJoint;
  return { world, ground, box, joint, def };
}

describe('b2FrictionJointDef.Initialize', () => {
  it('stores the anchor in each body frame', () => {
    const { def } = slidingBox(1, 1);
    expect([def.localAnchorA.x, def.localAnchorA.y]).toEqual([2, 1]);
    expect([def.localAnchorB.x, def.localAnchorB.y]).toEqual([0, 0]);
  });
});

describe('b2FrictionJoint', () => {
  it('slows a sliding body at maxForce / m along its velocity, then holds it at rest', () => {
    const { world, box, joint } = slidingBox(2, 0);
    box.SetLinearVelocity(new b2Vec2(3, 4));

    step(world, 60);
    const v = box.GetLinearVelocity();
    expect(Math.hypot(v.x, v.y)).toBeCloseTo(5 - 60 * h * 2, 9);
    expect(v.x / v.y).toBeCloseTo(3 / 4, 12);
    const force = joint.GetReactionForce(inv_h, new b2Vec2());
    expect(force.x).toBeCloseTo(-2 * 0.6, 9);
    expect(force.y).toBeCloseTo(-2 * 0.8, 9);

    // 5 m/s at 2 m/s^2 stops after 2.5 s = 150 steps.
    step(world, 100);
    expect(box.GetLinearVelocity().Length()).toBeLessThan(1e-12);
    const p = box.GetPosition();
    step(world, 30);
    expect(box.GetPosition().x).toBeCloseTo(p.x, 12);
  });

  it('slows a spinning body at maxTorque / I', () => {
    const { world, box, joint } = slidingBox(0, 0.5);
    box.SetAngularVelocity(4);
    step(world, 30);
    const I = box.GetInertia();
    expect(box.GetAngularVelocity()).toBeCloseTo(4 - (30 * h * 0.5) / I, 9);
    expect(joint.GetReactionTorque(inv_h)).toBeCloseTo(-0.5, 9);
  });

  it('does nothing with zero maximum force and torque', () => {
    const { world, box } = slidingBox(0, 0);
    box.SetLinearVelocity(new b2Vec2(1, 0));
    box.SetAngularVelocity(1);
    step(world, 20);
    expect(box.GetLinearVelocity().x).toBe(1);
    expect(box.GetAngularVelocity()).toBe(1);
  });

  it('validates and exposes its limits', () => {
    const { joint } = slidingBox(1, 2);
    expect([joint.GetMaxForce(), joint.GetMaxTorque()]).toEqual([1, 2]);
    joint.SetMaxForce(3);
    joint.SetMaxTorque(4);
    expect([joint.GetMaxForce(), joint.GetMaxTorque()]).toEqual([3, 4]);
    expect(() => joint.SetMaxForce(-1)).toThrow();
    expect(() => joint.SetMaxTorque(Infinity)).toThrow();
    expect([joint.GetLocalAnchorA().x, joint.GetLocalAnchorB().x]).toEqual([2, 0]);
  });

  it('dumps a b2FrictionJointDef with the C++ format', () => {
    const { ground, box, joint } = slidingBox(1.5, 0.25);
    ground.m_islandIndex = 0;
    box.m_islandIndex = 1;
    joint.m_index = 5;
    expect(captureLog(() => joint.Dump())).toBe(
      '  b2FrictionJointDef jd;\n' +
        '  jd.bodyA = bodies[0];\n' +
        '  jd.bodyB = bodies[1];\n' +
        '  jd.collideConnected = bool(0);\n' +
        '  jd.localAnchorA.Set(2.000000000000000e+00f, 1.000000000000000e+00f);\n' +
        '  jd.localAnchorB.Set(0.000000000000000e+00f, 0.000000000000000e+00f);\n' +
        '  jd.maxForce = 1.500000000000000e+00f;\n' +
        '  jd.maxTorque = 2.500000000000000e-01f;\n' +
        '  joints[5] = m_world->CreateJoint(&jd);\n',
    );
  });
});
