import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2WheelJoint, b2WheelJointDef } from '../../../src/dynamics/joints/b2WheelJoint';
import { captureLog, h, inv_h, makeBox, makeCircle, makeGround, makeWorld, step } from './jointTestWorld';

/** A 0.5 m circle wheel of mass m on a vertical wheel joint to the ground, anchored at its centre. */
function suspendedWheel(frequencyHz: number, dampingRatio: number, gy = -10, configure?: (def: b2WheelJointDef) => void) {
  const world = makeWorld(0, gy);
  const ground = makeGround(world);
  const wheel = makeCircle(world, 0, 1, 0.5);
  const def = new b2WheelJointDef();
  def.Initialize(ground, wheel, wheel.GetPosition(), new b2Vec2(0, 1));
  def.frequencyHz = frequencyHz;
  def.dampingRatio = dampingRatio;
  configure?.(def);
  const joint = world.CreateJoint(def) as b2WheelJoint;
  return { world, ground, wheel, joint };
}

describe('b2WheelJointDef.Initialize and the constructor', () => {
  it('stores the axis in body A without normalising it', () => {
    const world = makeWorld();
    const ground = makeGround(world);
    const wheel = makeCircle(world, 2, 1, 0.5);
    const def = new b2WheelJointDef();
    def.Initialize(ground, wheel, new b2Vec2(2, 1), new b2Vec2(0, 2));
    expect([def.localAnchorA.x, def.localAnchorA.y]).toEqual([2, 1]);
    expect([def.localAnchorB.x, def.localAnchorB.y]).toEqual([0, 0]);
    expect([def.localAxisA.x, def.localAxisA.y]).toEqual([0, 2]);

    const joint = world.CreateJoint(def) as b2WheelJoint;
    expect([joint.GetLocalAxisA().x, joint.GetLocalAxisA().y]).toEqual([0, 2]);
    expect([joint.m_localYAxisA.x, joint.m_localYAxisA.y]).toEqual([-2, 0]);
  });
});

describe('b2WheelJoint.GetDefinition', () => {
  it('fills a def that rebuilds an equivalent joint, reflecting later setter calls', () => {
    const { world, ground, wheel, joint } = suspendedWheel(3, 0.4, -10, (def) => {
      def.enableMotor = true;
      def.motorSpeed = 2;
      def.maxMotorTorque = 7;
      def.collideConnected = true;
      def.userData = 'wheel';
    });
    joint.SetMotorSpeed(-4);
    joint.SetSpringFrequencyHz(5);

    const def = new b2WheelJointDef();
    joint.GetDefinition(def);
    expect(def.type).toBe(joint.GetType());
    expect(def.bodyA).toBe(ground);
    expect(def.bodyB).toBe(wheel);
    expect(def.collideConnected).toBe(true);
    expect(def.userData).toBe('wheel');
    expect([def.localAnchorA.x, def.localAnchorA.y]).toEqual([joint.GetLocalAnchorA().x, joint.GetLocalAnchorA().y]);
    expect([def.localAnchorB.x, def.localAnchorB.y]).toEqual([0, 0]);
    expect([def.localAxisA.x, def.localAxisA.y]).toEqual([0, 1]);
    expect([def.enableMotor, def.motorSpeed, def.maxMotorTorque]).toEqual([true, -4, 7]);
    expect([def.frequencyHz, def.dampingRatio]).toEqual([5, 0.4]);
    // The def owns copies, not the joint's vectors.
    expect(def.localAxisA).not.toBe(joint.GetLocalAxisA());

    const copy = world.CreateJoint(def) as b2WheelJoint;
    expect(copy.GetMotorSpeed()).toBe(-4);
    expect(copy.GetSpringFrequencyHz()).toBe(5);
    expect(copy.GetJointTranslation()).toBe(joint.GetJointTranslation());
  });
});

describe('b2WheelJoint', () => {
  it('sags to the static spring deflection g / omega^2 and carries m*g through the spring', () => {
    const hz = 4;
    const { world, wheel, joint } = suspendedWheel(hz, 0.7);
    step(world, 240);
    const omega = 2 * Math.PI * hz;
    expect(joint.GetJointTranslation()).toBeCloseTo(-10 / (omega * omega), 4);
    expect(wheel.GetPosition().x).toBeCloseTo(0, 12);

    const force = joint.GetReactionForce(inv_h, new b2Vec2());
    expect(force.x).toBeCloseTo(0, 9);
    expect(force.y).toBeCloseTo(wheel.GetMass() * 10, 6);
  });

  it('bounces on an undamped spring', () => {
    const { world, joint } = suspendedWheel(2, 0);
    const translations: number[] = [];
    step(world, 120, () => translations.push(joint.GetJointTranslation()));
    const lowest = Math.min(...translations);
    const omega = 2 * Math.PI * 2;
    // Released at the unstretched length, it swings to about twice the static deflection.
    expect(lowest).toBeLessThan(-1.5 * (10 / (omega * omega)));
    expect(Math.max(...translations.slice(10))).toBeGreaterThan(-0.5 * (10 / (omega * omega)));
  });

  it('slides freely along the axis when the spring is disabled, but never across it', () => {
    const { world, wheel, joint } = suspendedWheel(0, 0);
    wheel.SetLinearVelocity(new b2Vec2(3, 0));
    step(world, 30, () => wheel.ApplyForceToCenter(new b2Vec2(-7, 0)));
    let vy = 0;
    let y = 1;
    for (let k = 0; k < 30; ++k) {
      vy = vy + h * -10;
      y = y + h * vy;
    }
    expect(wheel.GetPosition().y).toBeCloseTo(y, 12);
    expect(joint.GetJointTranslation()).toBeCloseTo(y - 1, 12);
    expect(wheel.GetPosition().x).toBeCloseTo(0, 9);
  });

  it('spins the wheel at the motor speed and limits the motor torque', () => {
    const fast = suspendedWheel(4, 0.7, 0, (def) => {
      def.enableMotor = true;
      def.motorSpeed = -5;
      def.maxMotorTorque = 100;
    });
    step(fast.world, 20);
    expect(fast.joint.GetJointSpeed()).toBeCloseTo(-5, 12);
    expect(fast.wheel.GetAngularVelocity()).toBeCloseTo(-5, 12);

    const weak = suspendedWheel(4, 0.7, 0, (def) => {
      def.enableMotor = true;
      def.motorSpeed = -50;
      def.maxMotorTorque = 0.1;
    });
    step(weak.world, 20);
    const I = weak.wheel.GetInertia();
    expect(weak.joint.GetJointSpeed()).toBeCloseTo((-20 * h * 0.1) / I, 10);
    expect(weak.joint.GetMotorTorque(inv_h)).toBeCloseTo(-0.1, 10);
    expect(weak.joint.GetReactionTorque(inv_h)).toBeCloseTo(-0.1, 10);
  });

  it('wakes both bodies from the motor setters and exposes the spring parameters', () => {
    const world = makeWorld();
    const chassis = makeBox(world, 0, 2, 1, 0.25);
    const wheel = makeCircle(world, 0, 1, 0.5);
    const def = new b2WheelJointDef();
    def.Initialize(chassis, wheel, wheel.GetPosition(), new b2Vec2(0, 1));
    const joint = world.CreateJoint(def) as b2WheelJoint;

    for (const set of [() => joint.EnableMotor(true), () => joint.SetMotorSpeed(2), () => joint.SetMaxMotorTorque(3)]) {
      chassis.SetAwake(false);
      wheel.SetAwake(false);
      set();
      expect([chassis.IsAwake(), wheel.IsAwake()]).toEqual([true, true]);
    }
    expect([joint.IsMotorEnabled(), joint.GetMotorSpeed(), joint.GetMaxMotorTorque()]).toEqual([true, 2, 3]);

    joint.SetSpringFrequencyHz(6);
    joint.SetSpringDampingRatio(0.3);
    expect([joint.GetSpringFrequencyHz(), joint.GetSpringDampingRatio()]).toEqual([6, 0.3]);
  });

  it('dumps a b2WheelJointDef with the C++ format', () => {
    const { ground, wheel, joint } = suspendedWheel(4, 0.5);
    ground.m_islandIndex = 0;
    wheel.m_islandIndex = 1;
    joint.m_index = 4;
    expect(captureLog(() => joint.Dump())).toBe(
      '  b2WheelJointDef jd;\n' +
        '  jd.bodyA = bodies[0];\n' +
        '  jd.bodyB = bodies[1];\n' +
        '  jd.collideConnected = bool(0);\n' +
        '  jd.localAnchorA.Set(0.000000000000000e+00f, 1.000000000000000e+00f);\n' +
        '  jd.localAnchorB.Set(0.000000000000000e+00f, 0.000000000000000e+00f);\n' +
        '  jd.localAxisA.Set(0.000000000000000e+00f, 1.000000000000000e+00f);\n' +
        '  jd.enableMotor = bool(0);\n' +
        '  jd.motorSpeed = 0.000000000000000e+00f;\n' +
        '  jd.maxMotorTorque = 0.000000000000000e+00f;\n' +
        '  jd.frequencyHz = 4.000000000000000e+00f;\n' +
        '  jd.dampingRatio = 5.000000000000000e-01f;\n' +
        '  joints[4] = m_world->CreateJoint(&jd);\n',
    );
  });
});
