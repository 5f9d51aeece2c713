import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2_linearSlop } from '../../../src/common/b2Settings';
import { b2PulleyJoint, b2PulleyJointDef, b2_minPulleyLength } from '../../../src/dynamics/joints/b2PulleyJoint';
import { captureLog, inv_h, makeBox, makeGround, makeWorld, step } from './jointTestWorld';

/**
 * Two boxes hanging 5 m below ground anchors at (-2, 10) and (2, 10). Box A is 1 x 1 (density
 * massA), box B is 1 x 1 (density massB).
 */
function pulley(massA: number, massB: number, ratio: number) {
  const world = makeWorld();
  const ground = makeGround(world);
  const a = makeBox(world, -2, 5, 0.5, 0.5, { density: massA });
  const b = makeBox(world, 2, 5, 0.5, 0.5, { density: massB });
  const def = new b2PulleyJointDef();
  def.Initialize(a, b, new b2Vec2(-2, 10), new b2Vec2(2, 10), new b2Vec2(-2, 5.5), new b2Vec2(2, 5.5), ratio);
  const joint = world.CreateJoint(def) as b2PulleyJoint;
  return { world, ground, a, b, joint, def };
}

describe('b2PulleyJointDef.Initialize', () => {
  it('stores ground anchors, local anchors, segment lengths and the ratio', () => {
    const { def } = pulley(1, 1, 1.5);
    expect([def.groundAnchorA.x, def.groundAnchorA.y, def.groundAnchorB.x, def.groundAnchorB.y]).toEqual([-2, 10, 2, 10]);
    expect([def.localAnchorA.x, def.localAnchorA.y]).toEqual([0, 0.5]);
    expect([def.localAnchorB.x, def.localAnchorB.y]).toEqual([0, 0.5]);
    expect([def.lengthA, def.lengthB, def.ratio]).toEqual([4.5, 4.5, 1.5]);
    expect(b2_minPulleyLength).toBe(2);
  });

  it('rejects a ratio that is not positive', () => {
    const world = makeWorld();
    const a = makeBox(world, 0, 0, 0.5, 0.5);
    const b = makeBox(world, 1, 0, 0.5, 0.5);
    const def = new b2PulleyJointDef();
    expect(() => def.Initialize(a, b, new b2Vec2(0, 1), new b2Vec2(1, 1), a.GetPosition(), b.GetPosition(), 0)).toThrow();
  });
});

describe('b2PulleyJoint', () => {
  it('conserves lengthA + ratio * lengthB while the heavier side drops', () => {
    const { world, joint } = pulley(1, 3, 1);
    const total = joint.GetLengthA() + joint.GetRatio() * joint.GetLengthB();
    let worst = 0;
    step(world, 60, () => {
      worst = Math.max(worst, Math.abs(joint.GetLengthA() + joint.GetRatio() * joint.GetLengthB() - total));
    });
    expect(worst).toBeLessThan(b2_linearSlop);
    // a = (mB - mA) g / (mA + mB) = 5 m/s^2: about 2.5 m in one second.
    expect(joint.GetLengthB() - 4.5).toBeCloseTo(2.5, 1);
    expect(4.5 - joint.GetLengthA()).toBeCloseTo(2.5, 1);
  });

  it('moves side A ratio times as far as side B', () => {
    const { world, joint } = pulley(1, 4, 2);
    const total = joint.GetLengthA() + 2 * joint.GetLengthB();
    step(world, 45);
    const dA = joint.GetLengthA() - 4.5;
    const dB = joint.GetLengthB() - 4.5;
    expect(dB).toBeGreaterThan(0.1);
    expect(dA + 2 * dB).toBeCloseTo(0, 2);
    expect(joint.GetLengthA() + 2 * joint.GetLengthB()).toBeCloseTo(total, 2);
  });

  it('balances when massB = ratio * massA and reports the rope tension', () => {
    const { world, a, b, joint } = pulley(1, 2, 2);
    step(world, 120);
    expect(a.GetPosition().y).toBeCloseTo(5, 9);
    expect(b.GetPosition().y).toBeCloseTo(5, 9);
    // GetReactionForce is the tension along side B's axis, not scaled by the ratio (as 2.2.1).
    const force = joint.GetReactionForce(inv_h, new b2Vec2());
    expect(force.x).toBeCloseTo(0, 9);
    expect(force.y).toBeCloseTo(-10, 9);
    expect(joint.GetReactionTorque(inv_h)).toBe(0);
  });

  it('exposes its anchors, lengths and ratio', () => {
    const { joint } = pulley(1, 1, 1.5);
    const gA = joint.GetGroundAnchorA(new b2Vec2());
    const gB = joint.GetGroundAnchorB(new b2Vec2());
    expect([gA.x, gA.y, gB.x, gB.y]).toEqual([-2, 10, 2, 10]);
    expect([joint.GetLengthA(), joint.GetLengthB(), joint.GetRatio()]).toEqual([4.5, 4.5, 1.5]);
    const anchorA = joint.GetAnchorA(new b2Vec2());
    expect([anchorA.x, anchorA.y]).toEqual([-2, 5.5]);
  });

  it('dumps a b2PulleyJointDef with the C++ format', () => {
    const { a, b, joint } = pulley(1, 1, 1.5);
    a.m_islandIndex = 1;
    b.m_islandIndex = 2;
    joint.m_index = 0;
    expect(captureLog(() => joint.Dump())).toBe(
      '  b2PulleyJointDef jd;\n' +
        '  jd.bodyA = bodies[1];\n' +
        '  jd.bodyB = bodies[2];\n' +
        '  jd.collideConnected = bool(1);\n' +
        '  jd.groundAnchorA.Set(-2.000000000000000e+00f, 1.000000000000000e+01f);\n' +
        '  jd.groundAnchorB.Set(2.000000000000000e+00f, 1.000000000000000e+01f);\n' +
        '  jd.localAnchorA.Set(0.000000000000000e+00f, 5.000000000000000e-01f);\n' +
        '  jd.localAnchorB.Set(0.000000000000000e+00f, 5.000000000000000e-01f);\n' +
        '  jd.lengthA = 4.500000000000000e+00f;\n' +
        '  jd.lengthB = 4.500000000000000e+00f;\n' +
        '  jd.ratio = 1.500000000000000e+00f;\n' +
        '  joints[0] = m_world->CreateJoint(&jd);\n',
    );
  });
});
