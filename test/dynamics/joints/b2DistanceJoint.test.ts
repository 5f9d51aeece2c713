import { describe, expect, it } from 'vitest';
import { b2MassData } from '../../../src/collision/shapes/b2Shape';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2_linearSlop } from '../../../src/common/b2Settings';
import { b2DistanceJoint, b2DistanceJointDef } from '../../../src/dynamics/joints/b2DistanceJoint';
import { captureLog, inv_h, makeBox, makeCircle, makeGround, makeWorld, step } from './jointTestWorld';

function anchorDistance(joint: b2DistanceJoint): number {
  const a = joint.GetAnchorA(new b2Vec2());
  const b = joint.GetAnchorB(new b2Vec2());
  return Math.hypot(b.x - a.x, b.y - a.y);
}

/** A 1 kg circle hanging `length` below a ground anchor at (0, 10), or level with it when swinging. */
function pendulum(frequencyHz: number, dampingRatio: number, swinging: boolean) {
  const world = makeWorld();
  const ground = makeGround(world);
  const length = 3;
  const bob = swinging ? makeCircle(world, length, 10, 0.25) : makeCircle(world, 0, 10 - length, 0.25);
  const md = new b2MassData();
  md.mass = 1;
  md.I = 0.1;
  bob.SetMassData(md);
  const def = new b2DistanceJointDef();
  def.Initialize(ground, bob, new b2Vec2(0, 10), bob.GetPosition());
  def.frequencyHz = frequencyHz;
  def.dampingRatio = dampingRatio;
  const joint = world.CreateJoint(def) as b2DistanceJoint;
  return { world, bob, joint, length };
}

describe('b2DistanceJointDef.Initialize', () => {
  it('stores local anchors and the anchor distance as the length', () => {
    const world = makeWorld();
    const a = makeBox(world, 1, 1, 0.5, 0.5);
    const b = makeBox(world, 2, 2, 0.5, 0.5);
    const def = new b2DistanceJointDef();
    def.Initialize(a, b, new b2Vec2(1, 2), new b2Vec2(4, 6));
    expect([def.localAnchorA.x, def.localAnchorA.y]).toEqual([0, 1]);
    expect([def.localAnchorB.x, def.localAnchorB.y]).toEqual([2, 4]);
    expect(def.length).toBe(5);
  });
});

describe('b2DistanceJoint', () => {
  it('keeps a swinging pendulum at its length when rigid', () => {
    const { world, bob, joint, length } = pendulum(0, 0, true);
    let worst = 0;
    let lowest = Infinity;
    step(world, 120, () => {
      worst = Math.max(worst, Math.abs(anchorDistance(joint) - length));
      lowest = Math.min(lowest, bob.GetPosition().y);
    });
    // The bob swung down to the bottom, so the constraint did real work.
    expect(lowest).toBeLessThan(10 - 2.9);
    expect(worst).toBeLessThan(b2_linearSlop);
  });

  it('reacts with m*g along the rod when the rigid pendulum hangs at rest', () => {
    const { world, joint } = pendulum(0, 0, false);
    step(world, 60);
    const force = joint.GetReactionForce(inv_h, new b2Vec2());
    expect(force.x).toBeCloseTo(0, 9);
    expect(force.y).toBeCloseTo(10, 9);
    expect(joint.GetReactionTorque(inv_h)).toBe(0);
  });

  it('oscillates about the static stretch g / omega^2 when soft', () => {
    const hz = 2;
    const { world, joint, length } = pendulum(hz, 0, false);
    const omega = 2 * Math.PI * hz;
    const lengths: number[] = [];
    step(world, 150, () => lengths.push(anchorDistance(joint)));

    const mean = lengths.reduce((s, l) => s + l, 0) / lengths.length;
    expect(mean - length).toBeCloseTo(10 / (omega * omega), 2);
    const amplitude = Math.max(...lengths) - Math.min(...lengths);
    expect(amplitude).toBeGreaterThan(0.05);

    // 150 steps are 2.5 s = 5 periods at 2 Hz: about 10 crossings of the mean.
    let crossings = 0;
    for (let i = 1; i < lengths.length; ++i) {
      if (lengths[i - 1] - mean < 0 !== lengths[i] - mean < 0) ++crossings;
    }
    expect(crossings).toBeGreaterThanOrEqual(8);
    expect(crossings).toBeLessThanOrEqual(11);
  });

  it('settles at the static stretch when soft and damped', () => {
    const hz = 3;
    const { world, joint, length } = pendulum(hz, 1, false);
    step(world, 240);
    const omega = 2 * Math.PI * hz;
    expect(anchorDistance(joint) - length).toBeCloseTo(10 / (omega * omega), 3);
  });

  it('exposes its parameters through the getters and setters', () => {
    const { joint } = pendulum(0, 0, false);
    expect(joint.GetLength()).toBe(3);
    joint.SetLength(2.5);
    joint.SetFrequency(4);
    joint.SetDampingRatio(0.25);
    expect([joint.GetLength(), joint.GetFrequency(), joint.GetDampingRatio()]).toEqual([2.5, 4, 0.25]);
    expect([joint.GetLocalAnchorA().x, joint.GetLocalAnchorA().y]).toEqual([0, 10]);
    expect([joint.GetLocalAnchorB().x, joint.GetLocalAnchorB().y]).toEqual([0, 0]);
  });

  it('dumps a b2DistanceJointDef with the C++ format', () => {
    const { joint } = pendulum(2, 0.5, false);
    joint.GetBodyA().m_islandIndex = 0;
    joint.GetBodyB().m_islandIndex = 1;
    joint.m_index = 0;
    expect(captureLog(() => joint.Dump())).toBe(
      '  b2DistanceJointDef jd;\n' +
        '  jd.bodyA = bodies[0];\n' +
        '  jd.bodyB = bodies[1];\n' +
        '  jd.collideConnected = bool(0);\n' +
        '  jd.localAnchorA.Set(0.000000000000000e+00f, 1.000000000000000e+01f);\n' +
        '  jd.localAnchorB.Set(0.000000000000000e+00f, 0.000000000000000e+00f);\n' +
        '  jd.length = 3.000000000000000e+00f;\n' +
        '  jd.frequencyHz = 2.000000000000000e+00f;\n' +
        '  jd.dampingRatio = 5.000000000000000e-01f;\n' +
        '  joints[0] = m_world->CreateJoint(&jd);\n',
    );
  });
});
