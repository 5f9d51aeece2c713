import { describe, expect, it } from 'vitest';
import { b2Rot, b2Vec2 } from '../../../src/common/b2Math';
import { b2_angularSlop } from '../../../src/common/b2Settings';
import { b2SolverData } from '../../../src/dynamics/b2TimeStep';
import { b2LimitState } from '../../../src/dynamics/joints/b2Joint';
import { b2RevoluteJoint, b2RevoluteJointDef } from '../../../src/dynamics/joints/b2RevoluteJoint';
import { captureLog, h, inv_h, makeBox, makeCircle, makeGround, makeWorld, step } from './jointTestWorld';

describe('b2RevoluteJointDef.Initialize', () => {
  it('stores the anchor in each body frame and the relative angle', () => {
    const world = makeWorld();
    const a = makeBox(world, 1, 2, 0.5, 0.5);
    const b = makeBox(world, 3, 4, 0.5, 0.5, { angle: 0.5 });
    const def = new b2RevoluteJointDef();
    def.Initialize(a, b, new b2Vec2(2, 3));

    expect(def.bodyA).toBe(a);
    expect(def.bodyB).toBe(b);
    expect(def.localAnchorA.x).toBe(2 - 1);
    expect(def.localAnchorA.y).toBe(3 - 2);
    // Inverse rotation of (2,3) - (3,4) = (-1,-1) by 0.5 rad.
    const q = new b2Rot(0.5);
    expect(def.localAnchorB.x).toBe(q.c * -1 + q.s * -1);
    expect(def.localAnchorB.y).toBe(-q.s * -1 + q.c * -1);
    expect(def.referenceAngle).toBe(0.5 - 0.0);
  });
});

describe('b2RevoluteJoint', () => {
  function hangingBox() {
    const world = makeWorld();
    const ground = makeGround(world);
    // 1 x 1 box of density 2: mass 2 kg.
    const box = makeBox(world, 0, 5, 0.5, 0.5, { density: 2 });
    const def = new b2RevoluteJointDef();
    def.Initialize(ground, box, new b2Vec2(0, 6));
    const joint = world.CreateJoint(def) as b2RevoluteJoint;
    return { world, ground, box, joint };
  }

  it('keeps the anchors together and reacts with m*g on a hanging body at rest', () => {
    const { world, box, joint } = hangingBox();
    step(world, 120);

    const pA = joint.GetAnchorA(new b2Vec2());
    const pB = joint.GetAnchorB(new b2Vec2());
    expect(pA.x).toBe(0);
    expect(pA.y).toBe(6);
    expect(Math.hypot(pB.x - pA.x, pB.y - pA.y)).toBeLessThan(1e-9);
    expect(box.GetPosition().y).toBeCloseTo(5, 9);

    const force = joint.GetReactionForce(inv_h, new b2Vec2());
    expect(box.GetMass()).toBe(2);
    expect(force.x).toBeCloseTo(0, 9);
    expect(force.y).toBeCloseTo(2 * 10, 9);
    expect(joint.GetReactionTorque(inv_h)).toBe(0);
  });

  function limitedBar(lower: number, upper: number, enableLimit = true) {
    const world = makeWorld(0, 0);
    const ground = makeGround(world);
    const bar = makeBox(world, 1, 0, 1, 0.1);
    const def = new b2RevoluteJointDef();
    def.Initialize(ground, bar, new b2Vec2(0, 0));
    def.enableLimit = enableLimit;
    def.lowerAngle = lower;
    def.upperAngle = upper;
    const joint = world.CreateJoint(def) as b2RevoluteJoint;
    return { world, bar, joint };
  }

  // The 2.2.1 limit is not predictive: it engages on the step after the angle crosses it, so
  // the bar may overshoot by one step of rotation before the position solver pulls it back.
  it('holds the angle inside [lower, upper] while a torque pushes against the upper limit', () => {
    const upper = 0.25 * Math.PI;
    const { world, bar, joint } = limitedBar(-upper, upper);

    let maxAngle = -Infinity;
    let maxSpeed = 0;
    let lateMax = -Infinity;
    step(world, 180, (k) => {
      maxAngle = Math.max(maxAngle, joint.GetJointAngle());
      maxSpeed = Math.max(maxSpeed, Math.abs(joint.GetJointSpeed()));
      if (k > 120) lateMax = Math.max(lateMax, joint.GetJointAngle());
      bar.ApplyTorque(5);
    });

    expect(joint.m_limitState).toBe(b2LimitState.e_atUpperLimit);
    expect(maxAngle).toBeLessThanOrEqual(upper + maxSpeed * h + b2_angularSlop);
    // The position solver aims at the limit plus the allowed slop.
    expect(lateMax).toBeLessThanOrEqual(upper + b2_angularSlop + 1e-12);
    expect(joint.GetJointAngle()).toBeGreaterThan(upper - b2_angularSlop);
    // The limit carries the whole applied torque once the bar rests on it (the torque applied
    // after the last step above acts in this one).
    step(world, 1);
    expect(joint.GetReactionTorque(inv_h)).toBeCloseTo(-5, 6);
  });

  it('lets the same torque swing the bar far past the angle when the limit is off', () => {
    const upper = 0.25 * Math.PI;
    const { world, bar, joint } = limitedBar(-upper, upper, false);
    step(world, 60, () => bar.ApplyTorque(5));
    expect(joint.m_limitState).toBe(b2LimitState.e_inactiveLimit);
    expect(joint.GetJointAngle()).toBeGreaterThan(2 * upper);
  });

  it('holds the angle at the lower limit under the opposite torque', () => {
    const { world, bar, joint } = limitedBar(-0.5, 1.0);

    let minAngle = Infinity;
    let maxSpeed = 0;
    let lateMin = Infinity;
    step(world, 180, (k) => {
      minAngle = Math.min(minAngle, joint.GetJointAngle());
      maxSpeed = Math.max(maxSpeed, Math.abs(joint.GetJointSpeed()));
      if (k > 120) lateMin = Math.min(lateMin, joint.GetJointAngle());
      bar.ApplyTorque(-5);
    });

    expect(joint.m_limitState).toBe(b2LimitState.e_atLowerLimit);
    expect(minAngle).toBeGreaterThanOrEqual(-0.5 - maxSpeed * h - b2_angularSlop);
    expect(lateMin).toBeGreaterThanOrEqual(-0.5 - b2_angularSlop - 1e-12);
    expect(joint.GetJointAngle()).toBeLessThan(-0.5 + b2_angularSlop);
  });

  it('locks the angle with equal limits (e_equalLimits), carrying the torque and ignoring the motor', () => {
    const { world, bar, joint } = limitedBar(0.0, 0.0);
    joint.EnableMotor(true);
    joint.SetMotorSpeed(10);
    joint.SetMaxMotorTorque(1000);
    let maxAbsAngle = 0;
    step(world, 120, () => {
      maxAbsAngle = Math.max(maxAbsAngle, Math.abs(joint.GetJointAngle()));
      bar.ApplyTorque(5);
    });
    expect(joint.m_limitState).toBe(b2LimitState.e_equalLimits);
    expect(maxAbsAngle).toBeLessThan(b2_angularSlop);
    expect(Math.abs(joint.GetJointSpeed())).toBeLessThan(1e-9);
    expect(joint.GetMotorTorque(inv_h)).toBe(0);
    step(world, 1);
    expect(joint.GetReactionTorque(inv_h)).toBeCloseTo(-5, 6);
  });

  it('lets a motor drive the bar into its upper limit, where the limit holds the saturated motor torque', () => {
    const { world, joint } = limitedBar(-0.5, 0.5);
    joint.EnableMotor(true);
    joint.SetMotorSpeed(2);
    joint.SetMaxMotorTorque(10);
    step(world, 120);
    expect(joint.m_limitState).toBe(b2LimitState.e_atUpperLimit);
    expect(joint.GetJointAngle()).toBeGreaterThan(0.5 - b2_angularSlop);
    expect(joint.GetJointAngle()).toBeLessThanOrEqual(0.5 + b2_angularSlop);
    expect(Math.abs(joint.GetJointSpeed())).toBeLessThan(1e-9);
    // The motor pushes with its maximum torque and the limit pushes back as hard.
    expect(joint.GetMotorTorque(inv_h)).toBeCloseTo(10, 9);
    expect(joint.GetReactionTorque(inv_h)).toBeCloseTo(-10, 6);
  });

  it('drives the motor to its speed when the torque allows it', () => {
    const world = makeWorld(0, 0);
    const ground = makeGround(world);
    const wheel = makeCircle(world, 0, 0, 1);
    const def = new b2RevoluteJointDef();
    def.Initialize(ground, wheel, new b2Vec2(0, 0));
    def.enableMotor = true;
    def.motorSpeed = 2;
    def.maxMotorTorque = 1000;
    const joint = world.CreateJoint(def) as b2RevoluteJoint;

    step(world, 30);
    expect(joint.GetJointSpeed()).toBeCloseTo(2, 12);
    expect(wheel.GetAngularVelocity()).toBeCloseTo(2, 12);
    // An unloaded motor needs no torque once it turns at speed.
    expect(joint.GetMotorTorque(inv_h)).toBeCloseTo(0, 9);
    expect(joint.GetJointAngle()).toBeCloseTo(wheel.GetAngle(), 15);
  });

  it('accelerates by maxMotorTorque / I per step when the torque is too small', () => {
    const world = makeWorld(0, 0);
    const ground = makeGround(world);
    const wheel = makeCircle(world, 0, 0, 1);
    const def = new b2RevoluteJointDef();
    def.Initialize(ground, wheel, new b2Vec2(0, 0));
    def.enableMotor = true;
    def.motorSpeed = 100;
    def.maxMotorTorque = 1;
    const joint = world.CreateJoint(def) as b2RevoluteJoint;

    const I = wheel.GetInertia();
    expect(I).toBeCloseTo(Math.PI / 2, 10);
    step(world, 20);
    expect(joint.GetJointSpeed()).toBeCloseTo((20 * h * 1) / I, 10);
    expect(joint.GetMotorTorque(inv_h)).toBeCloseTo(1, 10);
  });

  it('wakes both bodies from the motor and limit setters and resets the limit impulse', () => {
    const { world, box, joint } = hangingBox();
    step(world, 1);
    joint.m_impulse.z = 3;

    box.SetAwake(false);
    joint.EnableLimit(false);
    expect(box.IsAwake()).toBe(false);
    expect(joint.m_impulse.z).toBe(3);
    joint.EnableLimit(true);
    expect(box.IsAwake()).toBe(true);
    expect(joint.IsLimitEnabled()).toBe(true);
    expect(joint.m_impulse.z).toBe(0);

    joint.m_impulse.z = 3;
    box.SetAwake(false);
    joint.SetLimits(0, 0);
    expect(box.IsAwake()).toBe(false);
    joint.SetLimits(-1, 2);
    expect(box.IsAwake()).toBe(true);
    expect([joint.GetLowerLimit(), joint.GetUpperLimit(), joint.m_impulse.z]).toEqual([-1, 2, 0]);
    expect(() => joint.SetLimits(1, -1)).toThrow();

    box.SetAwake(false);
    joint.EnableMotor(true);
    expect(box.IsAwake()).toBe(true);
    box.SetAwake(false);
    joint.SetMotorSpeed(3);
    expect(box.IsAwake()).toBe(true);
    box.SetAwake(false);
    joint.SetMaxMotorTorque(4);
    expect(box.IsAwake()).toBe(true);
    expect([joint.IsMotorEnabled(), joint.GetMotorSpeed(), joint.GetMaxMotorTorque()]).toEqual([true, 3, 4]);
  });

  it('dumps a b2RevoluteJointDef with the C++ format', () => {
    const { ground, box, joint } = hangingBox();
    ground.m_islandIndex = 0;
    box.m_islandIndex = 1;
    joint.m_index = 7;
    joint.SetLimits(-0.5, 0.25);
    joint.EnableLimit(true);
    joint.SetMotorSpeed(-2);
    expect(captureLog(() => joint.Dump())).toBe(
      '  b2RevoluteJointDef jd;\n' +
        '  jd.bodyA = bodies[0];\n' +
        '  jd.bodyB = bodies[1];\n' +
        '  jd.collideConnected = bool(0);\n' +
        '  jd.localAnchorA.Set(0.000000000000000e+00f, 6.000000000000000e+00f);\n' +
        '  jd.localAnchorB.Set(0.000000000000000e+00f, 1.000000000000000e+00f);\n' +
        '  jd.referenceAngle = 0.000000000000000e+00f;\n' +
        '  jd.enableLimit = bool(1);\n' +
        '  jd.lowerAngle = -5.000000000000000e-01f;\n' +
        '  jd.upperAngle = 2.500000000000000e-01f;\n' +
        '  jd.enableMotor = bool(0);\n' +
        '  jd.motorSpeed = -2.000000000000000e+00f;\n' +
        '  jd.maxMotorTorque = 0.000000000000000e+00f;\n' +
        '  joints[7] = m_world->CreateJoint(&jd);\n',
    );
  });
});

describe('b2RevoluteJoint solver records', () => {
  it('lie one after another in the island joint records, in the order the island initialises the joints', () => {
    const world = makeWorld();
    const ground = makeGround(world);
    const joints: b2RevoluteJoint[] = [];
    let previous = ground;
    for (let i = 0; i < 5; ++i) {
      const link = makeBox(world, 0.5 + i, 5, 0.5, 0.1);
      const def = new b2RevoluteJointDef();
      def.Initialize(previous, link, new b2Vec2(i, 5));
      joints.push(world.CreateJoint(def) as b2RevoluteJoint);
      previous = link;
    }
    step(world, 3);
    const records = joints[0].m_solverRecord;
    const offsets = joints.map((j) => j.m_recordOffset).sort((a, b) => a - b);
    for (const j of joints) expect(j.m_solverRecord).toBe(records);
    const size = offsets[1] - offsets[0];
    expect(size).toBeGreaterThan(0);
    expect(offsets).toEqual([0, size, 2 * size, 3 * size, 4 * size]);
  });

  it('AllocateJointRecord hands out consecutive offsets, growing into a new array that later joints get', () => {
    const data = new b2SolverData();
    const a = data.AllocateJointRecord(31);
    const first = data.jointRecords;
    first[a] = 7;
    const b = data.AllocateJointRecord(31);
    expect([a, b]).toEqual([0, 31]);
    expect(data.jointRecords).toBe(first);
    const c = data.AllocateJointRecord(31);
    expect(c).toBe(62);
    expect(data.jointRecords).not.toBe(first);
    expect(data.jointRecords.length).toBeGreaterThanOrEqual(93);
    // A joint given the first array keeps its record there.
    expect(first[a]).toBe(7);
    expect(data.jointRecordCount).toBe(93);
  });
});
