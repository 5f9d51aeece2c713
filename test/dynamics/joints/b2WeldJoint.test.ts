import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2_angularSlop, b2_linearSlop } from '../../../src/common/b2Settings';
import { b2WeldJoint, b2WeldJointDef } from '../../../src/dynamics/joints/b2WeldJoint';
import { captureLog, inv_h, makeBox, makeGround, makeWorld, step } from './jointTestWorld';

function anchorGap(joint: b2WeldJoint): number {
  const a = joint.GetAnchorA(new b2Vec2());
  const b = joint.GetAnchorB(new b2Vec2());
  return Math.hypot(b.x - a.x, b.y - a.y);
}

function relativeAngle(joint: b2WeldJoint): number {
  return joint.GetBodyB().GetAngle() - joint.GetBodyA().GetAngle() - joint.GetReferenceAngle();
}

/** A 2 x 0.5 plank (1 kg) welded by its left end to the ground at (0, 10). */
function cantilever(frequencyHz: number, dampingRatio: number) {
  const world = makeWorld();
  const ground = makeGround(world);
  const plank = makeBox(world, 1, 10, 1, 0.25, { density: 1 });
  const def = new b2WeldJointDef();
  def.Initialize(ground, plank, new b2Vec2(0, 10));
  def.frequencyHz = frequencyHz;
  def.dampingRatio = dampingRatio;
  const joint = world.CreateJoint(def) as b2WeldJoint;
  return { world, plank, joint };
}

describe('b2WeldJointDef.Initialize', () => {
  it('stores the anchor in each body frame and the relative angle', () => {
    const world = makeWorld();
    const a = makeBox(world, 0, 0, 0.5, 0.5, { angle: -0.25 });
    const b = makeBox(world, 1, 0, 0.5, 0.5, { angle: 0.5 });
    const def = new b2WeldJointDef();
    def.Initialize(a, b, new b2Vec2(1, 0));
    expect([def.localAnchorB.x, def.localAnchorB.y]).toEqual([0, 0]);
    expect(def.referenceAngle).toBe(0.5 - -0.25);
  });
});

describe('b2WeldJoint', () => {
  it('holds a rigid cantilever in its welded pose', () => {
    const { world, joint } = cantilever(0, 0);
    let worstGap = 0;
    let worstAngle = 0;
    step(world, 120, () => {
      worstGap = Math.max(worstGap, anchorGap(joint));
      worstAngle = Math.max(worstAngle, Math.abs(relativeAngle(joint)));
    });
    expect(worstGap).toBeLessThan(b2_linearSlop);
    expect(worstAngle).toBeLessThan(b2_angularSlop);
  });

  it('reacts with m*g and the torque m*g*lever on a rigid cantilever at rest', () => {
    const { world, plank, joint } = cantilever(0, 0);
    step(world, 120);
    expect(plank.GetMass()).toBe(1);
    const force = joint.GetReactionForce(inv_h, new b2Vec2());
    expect(force.x).toBeCloseTo(0, 6);
    expect(force.y).toBeCloseTo(10, 6);
    // The anchor is 1 m left of the centre of mass.
    expect(joint.GetReactionTorque(inv_h)).toBeCloseTo(10 * 1, 6);
  });

  it('lets a soft weld bend in rotation only, far more than a rigid one', () => {
    const rigid = cantilever(0, 0);
    const soft = cantilever(2, 0.1);
    let rigidAngle = 0;
    let softAngle = 0;
    let softGap = 0;
    step(rigid.world, 60, () => {
      rigidAngle = Math.max(rigidAngle, Math.abs(relativeAngle(rigid.joint)));
    });
    step(soft.world, 60, () => {
      softAngle = Math.max(softAngle, Math.abs(relativeAngle(soft.joint)));
      softGap = Math.max(softGap, anchorGap(soft.joint));
    });
    expect(softAngle).toBeGreaterThan(0.05);
    expect(softAngle).toBeGreaterThan(20 * rigidAngle);
    expect(softGap).toBeLessThan(b2_linearSlop);
  });

  it('keeps two free bodies in their relative pose while they tumble', () => {
    const world = makeWorld(0, 0);
    const a = makeBox(world, 0, 0, 0.5, 0.5);
    const b = makeBox(world, 1, 0.5, 0.5, 0.25, { angle: 0.3 });
    const def = new b2WeldJointDef();
    def.Initialize(a, b, new b2Vec2(0.5, 0.25));
    const joint = world.CreateJoint(def) as b2WeldJoint;
    a.SetAngularVelocity(4);
    b.SetLinearVelocity(new b2Vec2(1, -2));

    let worstAngle = 0;
    let worstGap = 0;
    step(world, 90, () => {
      worstAngle = Math.max(worstAngle, Math.abs(relativeAngle(joint)));
      worstGap = Math.max(worstGap, anchorGap(joint));
    });
    expect(Math.abs(a.GetAngle())).toBeGreaterThan(0.2);
    expect(worstAngle).toBeLessThan(b2_angularSlop);
    expect(worstGap).toBeLessThan(b2_linearSlop);
  });

  it('exposes its parameters through the getters and setters', () => {
    const { joint } = cantilever(3, 0.5);
    expect([joint.GetFrequency(), joint.GetDampingRatio(), joint.GetReferenceAngle()]).toEqual([3, 0.5, 0]);
    joint.SetFrequency(1);
    joint.SetDampingRatio(0.2);
    expect([joint.GetFrequency(), joint.GetDampingRatio()]).toEqual([1, 0.2]);
    expect([joint.GetLocalAnchorA().x, joint.GetLocalAnchorA().y]).toEqual([0, 10]);
    expect([joint.GetLocalAnchorB().x, joint.GetLocalAnchorB().y]).toEqual([-1, 0]);
  });

  it('dumps a b2WeldJointDef with the C++ format', () => {
    const { joint } = cantilever(5, 0.7);
    joint.GetBodyA().m_islandIndex = 0;
    joint.GetBodyB().m_islandIndex = 1;
    joint.m_index = 3;
    expect(captureLog(() => joint.Dump())).toBe(
      '  b2WeldJointDef jd;\n' +
        '  jd.bodyA = bodies[0];\n' +
        '  jd.bodyB = bodies[1];\n' +
        '  jd.collideConnected = bool(0);\n' +
        '  jd.localAnchorA.Set(0.000000000000000e+00f, 1.000000000000000e+01f);\n' +
        '  jd.localAnchorB.Set(-1.000000000000000e+00f, 0.000000000000000e+00f);\n' +
        '  jd.referenceAngle = 0.000000000000000e+00f;\n' +
        '  jd.frequencyHz = 5.000000000000000e+00f;\n' +
        '  jd.dampingRatio = 7.000000000000000e-01f;\n' +
        '  joints[3] = m_world->CreateJoint(&jd);\n',
    );
  });
});
