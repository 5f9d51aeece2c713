import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2GearJoint, b2GearJointDef } from '../../../src/dynamics/joints/b2GearJoint';
import { b2PrismaticJoint, b2PrismaticJointDef } from '../../../src/dynamics/joints/b2PrismaticJoint';
import { b2RevoluteJoint, b2RevoluteJointDef } from '../../../src/dynamics/joints/b2RevoluteJoint';
import { captureLog, inv_h, makeBox, makeCircle, makeGround, makeWorld, step } from './jointTestWorld';

/** Two wheels on revolute joints to the ground, coupled by a gear of the given ratio. */
function gearedWheels(ratio: number, configure1: (def: b2RevoluteJointDef) => void = () => {}) {
  const world = makeWorld(0, 0);
  const ground = makeGround(world);
  const wheel1 = makeCircle(world, 0, 0, 1);
  const wheel2 = makeCircle(world, 3, 0, 0.5);

  const rd1 = new b2RevoluteJointDef();
  rd1.Initialize(ground, wheel1, wheel1.GetPosition());
  configure1(rd1);
  const joint1 = world.CreateJoint(rd1) as b2RevoluteJoint;
  const rd2 = new b2RevoluteJointDef();
  rd2.Initialize(ground, wheel2, wheel2.GetPosition());
  const joint2 = world.CreateJoint(rd2) as b2RevoluteJoint;

  const gd = new b2GearJointDef();
  gd.bodyA = wheel1;
  gd.bodyB = wheel2;
  gd.joint1 = joint1;
  gd.joint2 = joint2;
  gd.ratio = ratio;
  const gear = world.CreateJoint(gd) as b2GearJoint;
  return { world, ground, wheel1, wheel2, joint1, joint2, gear };
}

describe('b2GearJoint', () => {
  it('takes its four bodies from the two joints', () => {
    const { ground, wheel1, wheel2, joint1, joint2, gear } = gearedWheels(2);
    expect(gear.GetBodyA()).toBe(wheel1);
    expect(gear.GetBodyB()).toBe(wheel2);
    expect(gear.m_bodyC).toBe(ground);
    expect(gear.m_bodyD).toBe(ground);
    expect(gear.GetJoint1()).toBe(joint1);
    expect(gear.GetJoint2()).toBe(joint2);
    expect(gear.GetRatio()).toBe(2);
    expect(gear.m_constant).toBe(0);
  });

  it('couples two revolute joints: angle1 + ratio * angle2 stays constant', () => {
    const { world, joint1, joint2 } = gearedWheels(2, (def) => {
      def.enableMotor = true;
      def.motorSpeed = 1.5;
      def.maxMotorTorque = 1000;
    });
    let worst = 0;
    step(world, 90, () => {
      worst = Math.max(worst, Math.abs(joint1.GetJointAngle() + 2 * joint2.GetJointAngle()));
    });
    expect(joint1.GetJointAngle()).toBeGreaterThan(2);
    expect(worst).toBeLessThan(1e-9);
    expect(joint2.GetJointSpeed()).toBeCloseTo(-1.5 / 2, 9);
  });

  it('transmits a load torque divided by the ratio', () => {
    const { world, wheel2, joint1, gear } = gearedWheels(2, (def) => {
      def.enableMotor = true;
      def.motorSpeed = 0;
      def.maxMotorTorque = 1000;
    });
    step(world, 30, () => wheel2.ApplyTorque(3));
    expect(wheel2.GetAngularVelocity()).toBeCloseTo(0, 9);
    expect(gear.GetReactionTorque(inv_h)).toBeCloseTo(-3 / 2, 9);
    expect(joint1.GetMotorTorque(inv_h)).toBeCloseTo(3 / 2, 9);
    // Revolute-revolute gears have no linear Jacobian, hence no reaction force.
    const force = gear.GetReactionForce(inv_h, new b2Vec2());
    expect([Math.abs(force.x), Math.abs(force.y)]).toEqual([0, 0]);
  });

  it('couples a revolute and a prismatic joint: angle + ratio * translation stays constant', () => {
    const world = makeWorld(0, 0);
    const ground = makeGround(world);
    const wheel = makeCircle(world, 0, 0, 1);
    const rack = makeBox(world, 0, -1.5, 2, 0.25);

    const rd = new b2RevoluteJointDef();
    rd.Initialize(ground, wheel, wheel.GetPosition());
    rd.enableMotor = true;
    rd.motorSpeed = -1;
    rd.maxMotorTorque = 1000;
    const revolute = world.CreateJoint(rd) as b2RevoluteJoint;
    const pd = new b2PrismaticJointDef();
    pd.Initialize(ground, rack, rack.GetPosition(), new b2Vec2(1, 0));
    const prismatic = world.CreateJoint(pd) as b2PrismaticJoint;

    const gd = new b2GearJointDef();
    gd.bodyA = wheel;
    gd.bodyB = rack;
    gd.joint1 = revolute;
    gd.joint2 = prismatic;
    gd.ratio = -1;
    const gear = world.CreateJoint(gd) as b2GearJoint;
    expect(gear.m_constant).toBe(0);

    let worst = 0;
    step(world, 60, () => {
      worst = Math.max(worst, Math.abs(revolute.GetJointAngle() - prismatic.GetJointTranslation()));
    });
    // With ratio -1 the translation follows the angle one for one.
    expect(revolute.GetJointAngle()).toBeLessThan(-0.9);
    expect(worst).toBeLessThan(1e-6);
    expect(prismatic.GetJointSpeed()).toBeCloseTo(-1, 6);
  });

  it('validates the ratio and the joint types', () => {
    const { world, wheel1, wheel2, gear } = gearedWheels(1);
    gear.SetRatio(-3);
    expect(gear.GetRatio()).toBe(-3);
    expect(() => gear.SetRatio(NaN)).toThrow();

    const gd = new b2GearJointDef();
    gd.bodyA = wheel1;
    gd.bodyB = wheel2;
    gd.joint1 = gear;
    gd.joint2 = gear.GetJoint2();
    expect(() => world.CreateJoint(gd)).toThrow();
    gd.joint1 = null;
    expect(() => world.CreateJoint(gd)).toThrow();
  });

  it('dumps a b2GearJointDef with the C++ format', () => {
    const { wheel1, wheel2, joint1, joint2, gear } = gearedWheels(2.5);
    wheel1.m_islandIndex = 1;
    wheel2.m_islandIndex = 2;
    joint1.m_index = 0;
    joint2.m_index = 1;
    gear.m_index = 2;
    expect(captureLog(() => gear.Dump())).toBe(
      '  b2GearJointDef jd;\n' +
        '  jd.bodyA = bodies[1];\n' +
        '  jd.bodyB = bodies[2];\n' +
        '  jd.collideConnected = bool(0);\n' +
        '  jd.joint1 = joints[0];\n' +
        '  jd.joint2 = joints[1];\n' +
        '  jd.ratio = 2.500000000000000e+00f;\n' +
        '  joints[2] = m_world->CreateJoint(&jd);\n',
    );
  });
});
