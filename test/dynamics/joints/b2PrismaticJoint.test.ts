import { describe, expect, it } from 'vitest';
import { b2Rot, b2Vec2 } from '../../../src/common/b2Math';
import { b2_linearSlop } from '../../../src/common/b2Settings';
import { b2LimitState } from '../../../src/dynamics/joints/b2Joint';
import { b2PrismaticJoint, b2PrismaticJointDef } from '../../../src/dynamics/joints/b2PrismaticJoint';
import { captureLog, h, inv_h, makeBox, makeGround, makeWorld, step } from './jointTestWorld';

function slider(axis: b2Vec2, gy: number, configure: (def: b2PrismaticJointDef) => void = () => {}) {
  const world = makeWorld(0, gy);
  const ground = makeGround(world);
  // 1 x 1 box of density 3: mass 3 kg.
  const box = makeBox(world, 0, 0, 0.5, 0.5, { density: 3 });
  const def = new b2PrismaticJointDef();
  def.Initialize(ground, box, new b2Vec2(0, 0), axis);
  configure(def);
  const joint = world.CreateJoint(def) as b2PrismaticJoint;
  return { world, ground, box, joint, def };
}

describe('b2PrismaticJointDef.Initialize and the constructor', () => {
  it('stores anchors, the axis in body A and the relative angle; the joint normalises the axis', () => {
    const world = makeWorld();
    const a = makeBox(world, 1, 1, 0.5, 0.5, { angle: 0.3 });
    const b = makeBox(world, 2, 3, 0.5, 0.5, { angle: 0.8 });
    const def = new b2PrismaticJointDef();
    def.Initialize(a, b, new b2Vec2(2, 3), new b2Vec2(2, 1));

    const q = new b2Rot(0.3);
    expect(def.localAxisA.x).toBe(q.c * 2 + q.s * 1);
    expect(def.localAxisA.y).toBe(-q.s * 2 + q.c * 1);
    expect(def.localAnchorB.x).toBe(0);
    expect(def.localAnchorB.y).toBe(0);
    expect(def.referenceAngle).toBe(0.8 - 0.3);

    const joint = world.CreateJoint(def) as b2PrismaticJoint;
    const axis = joint.GetLocalAxisA();
    expect(Math.hypot(axis.x, axis.y)).toBeCloseTo(1, 15);
    const len = Math.sqrt(def.localAxisA.x * def.localAxisA.x + def.localAxisA.y * def.localAxisA.y);
    expect(axis.x).toBe(def.localAxisA.x * (1 / len));
    expect(joint.m_localYAxisA.x).toBe(-axis.y);
    expect(joint.m_localYAxisA.y).toBe(axis.x);
    expect(joint.GetReferenceAngle()).toBe(0.8 - 0.3);
  });
});

describe('b2PrismaticJoint', () => {
  it('lets the body slide along the axis only', () => {
    const { world, box, joint } = slider(new b2Vec2(1, 0), 0);
    box.SetLinearVelocity(new b2Vec2(2, 1));
    box.SetAngularVelocity(3);
    step(world, 60, () => box.ApplyForceToCenter(new b2Vec2(0, 5)));

    expect(box.GetPosition().y).toBeCloseTo(0, 9);
    expect(box.GetAngle()).toBeCloseTo(0, 9);
    expect(joint.GetJointTranslation()).toBeCloseTo(box.GetPosition().x, 12);
    expect(joint.GetJointTranslation()).toBeCloseTo(2, 6);
    expect(joint.GetJointSpeed()).toBeCloseTo(2, 9);
  });

  it('clamps the translation at the lower limit under gravity and carries m*g along the axis', () => {
    const { world, box, joint } = slider(new b2Vec2(0, 1), -10, (def) => {
      def.enableLimit = true;
      def.lowerTranslation = -1;
      def.upperTranslation = 2;
    });

    let minT = Infinity;
    let maxSpeed = 0;
    let lateMin = Infinity;
    step(world, 180, (k) => {
      minT = Math.min(minT, joint.GetJointTranslation());
      maxSpeed = Math.max(maxSpeed, Math.abs(joint.GetJointSpeed()));
      if (k > 120) lateMin = Math.min(lateMin, joint.GetJointTranslation());
    });

    expect(joint.m_limitState).toBe(b2LimitState.e_atLowerLimit);
    // The limit engages once crossed, so the first contact may overshoot by one step.
    expect(minT).toBeGreaterThanOrEqual(-1 - maxSpeed * h - b2_linearSlop);
    expect(lateMin).toBeGreaterThanOrEqual(-1 - b2_linearSlop - 1e-12);
    expect(joint.GetJointTranslation()).toBeLessThan(-1 + b2_linearSlop);

    const force = joint.GetReactionForce(inv_h, new b2Vec2());
    expect(force.x).toBeCloseTo(0, 6);
    expect(force.y).toBeCloseTo(3 * 10, 6);
    expect(box.GetLinearVelocity().y).toBeCloseTo(0, 9);
  });

  it('clamps the translation at the upper limit when pushed up the axis', () => {
    const { world, box, joint } = slider(new b2Vec2(0, 1), -10, (def) => {
      def.enableLimit = true;
      def.lowerTranslation = -1;
      def.upperTranslation = 0.5;
    });
    step(world, 120, () => box.ApplyForceToCenter(new b2Vec2(0, 60)));
    expect(joint.m_limitState).toBe(b2LimitState.e_atUpperLimit);
    expect(joint.GetJointTranslation()).toBeGreaterThan(0.5 - b2_linearSlop);
    expect(joint.GetJointTranslation()).toBeLessThanOrEqual(0.5 + b2_linearSlop + 1e-12);
  });

  it('locks the translation with equal limits (e_equalLimits), carrying m*g and ignoring the motor', () => {
    const { world, box, joint } = slider(new b2Vec2(0, 1), -10, (def) => {
      def.enableLimit = true;
      def.lowerTranslation = 0;
      def.upperTranslation = 0;
      def.enableMotor = true;
      def.motorSpeed = 5;
      def.maxMotorForce = 1000;
    });
    let maxAbs = 0;
    step(world, 120, () => (maxAbs = Math.max(maxAbs, Math.abs(joint.GetJointTranslation()))));
    expect(joint.m_limitState).toBe(b2LimitState.e_equalLimits);
    expect(maxAbs).toBeLessThan(b2_linearSlop);
    expect(box.GetLinearVelocity().y).toBeCloseTo(0, 9);
    expect(joint.GetMotorForce(inv_h)).toBe(0);
    expect(joint.GetReactionForce(inv_h, new b2Vec2()).y).toBeCloseTo(3 * 10, 6);
  });

  it('lets a motor drive the body into its upper limit, where the limit holds the saturated motor force', () => {
    const { world, joint } = slider(new b2Vec2(1, 0), 0, (def) => {
      def.enableLimit = true;
      def.lowerTranslation = -1;
      def.upperTranslation = 1;
      def.enableMotor = true;
      def.motorSpeed = 2;
      def.maxMotorForce = 50;
    });
    step(world, 120);
    expect(joint.m_limitState).toBe(b2LimitState.e_atUpperLimit);
    expect(joint.GetJointTranslation()).toBeGreaterThan(1 - b2_linearSlop);
    expect(joint.GetJointTranslation()).toBeLessThanOrEqual(1 + b2_linearSlop);
    expect(Math.abs(joint.GetJointSpeed())).toBeLessThan(1e-9);
    expect(joint.GetMotorForce(inv_h)).toBeCloseTo(50, 9);
    // The limit impulse cancels the motor's, so the axial reaction (motor + limit) is zero.
    expect(inv_h * joint.m_impulse.z).toBeCloseTo(-50, 6);
    expect(joint.GetReactionForce(inv_h, new b2Vec2()).x).toBeCloseTo(0, 6);
  });

  it('drives the motor to its speed when the force allows it', () => {
    const { world, joint } = slider(new b2Vec2(1, 0), 0, (def) => {
      def.enableMotor = true;
      def.motorSpeed = 3;
      def.maxMotorForce = 1000;
    });
    step(world, 10);
    expect(joint.GetJointSpeed()).toBeCloseTo(3, 12);
    expect(joint.GetMotorForce(inv_h)).toBeCloseTo(0, 9);
  });

  it('accelerates by maxMotorForce / m per step when the force is too small', () => {
    const { world, joint } = slider(new b2Vec2(1, 0), 0, (def) => {
      def.enableMotor = true;
      def.motorSpeed = 100;
      def.maxMotorForce = 6;
    });
    step(world, 30);
    expect(joint.GetJointSpeed()).toBeCloseTo((30 * h * 6) / 3, 10);
    expect(joint.GetMotorForce(inv_h)).toBeCloseTo(6, 10);
  });

  it('holds a load against gravity with a zero-speed motor, using m*g of motor force', () => {
    const { world, box, joint } = slider(new b2Vec2(0, 1), -10, (def) => {
      def.enableMotor = true;
      def.motorSpeed = 0;
      def.maxMotorForce = 1000;
    });
    step(world, 60);
    expect(box.GetPosition().y).toBeCloseTo(0, 9);
    expect(joint.GetMotorForce(inv_h)).toBeCloseTo(30, 9);
  });

  it('wakes both bodies from the setters and resets the limit impulse when the limit changes', () => {
    const { world, box, joint } = slider(new b2Vec2(1, 0), -10);
    step(world, 1);

    joint.m_impulse.z = 2;
    box.SetAwake(false);
    joint.EnableLimit(false);
    expect(box.IsAwake()).toBe(false);
    joint.EnableLimit(true);
    expect(box.IsAwake()).toBe(true);
    expect([joint.IsLimitEnabled(), joint.m_impulse.z]).toEqual([true, 0]);

    joint.m_impulse.z = 2;
    box.SetAwake(false);
    joint.SetLimits(0, 0);
    expect(box.IsAwake()).toBe(false);
    joint.SetLimits(-2, 3);
    expect(box.IsAwake()).toBe(true);
    expect([joint.GetLowerLimit(), joint.GetUpperLimit(), joint.m_impulse.z]).toEqual([-2, 3, 0]);
    expect(() => joint.SetLimits(3, -2)).toThrow();

    box.SetAwake(false);
    joint.EnableMotor(true);
    expect(box.IsAwake()).toBe(true);
    box.SetAwake(false);
    joint.SetMotorSpeed(-1);
    expect(box.IsAwake()).toBe(true);
    box.SetAwake(false);
    joint.SetMaxMotorForce(9);
    expect(box.IsAwake()).toBe(true);
    expect([joint.IsMotorEnabled(), joint.GetMotorSpeed(), joint.GetMaxMotorForce()]).toEqual([true, -1, 9]);
  });

  it('dumps a b2PrismaticJointDef with the C++ format', () => {
    const { ground, box, joint } = slider(new b2Vec2(0, 2), -10, (def) => {
      def.enableMotor = true;
      def.maxMotorForce = 12.5;
      def.lowerTranslation = -1;
      def.upperTranslation = 1;
    });
    ground.m_islandIndex = 1;
    box.m_islandIndex = 0;
    joint.m_index = 2;
    expect(captureLog(() => joint.Dump())).toBe(
      '  b2PrismaticJointDef jd;\n' +
        '  jd.bodyA = bodies[1];\n' +
        '  jd.bodyB = bodies[0];\n' +
        '  jd.collideConnected = bool(0);\n' +
        '  jd.localAnchorA.Set(0.000000000000000e+00f, 0.000000000000000e+00f);\n' +
        '  jd.localAnchorB.Set(0.000000000000000e+00f, 0.000000000000000e+00f);\n' +
        '  jd.localAxisA.Set(0.000000000000000e+00f, 1.000000000000000e+00f);\n' +
        '  jd.referenceAngle = 0.000000000000000e+00f;\n' +
        '  jd.enableLimit = bool(0);\n' +
        '  jd.lowerTranslation = -1.000000000000000e+00f;\n' +
        '  jd.upperTranslation = 1.000000000000000e+00f;\n' +
        '  jd.enableMotor = bool(1);\n' +
        '  jd.motorSpeed = 0.000000000000000e+00f;\n' +
        '  jd.maxMotorForce = 1.250000000000000e+01f;\n' +
        '  joints[2] = m_world->CreateJoint(&jd);\n',
    );
  });
});
