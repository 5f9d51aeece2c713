import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2_linearSlop } from '../../../src/common/b2Settings';
import { b2LimitState } from '../../../src/dynamics/joints/b2Joint';
import { b2RopeJoint, b2RopeJointDef } from '../../../src/dynamics/joints/b2RopeJoint';
import { captureLog, h, inv_h, makeBox, makeGround, makeWorld, step } from './jointTestWorld';

function anchorDistance(joint: b2RopeJoint): number {
  const a = joint.GetAnchorA(new b2Vec2());
  const b = joint.GetAnchorB(new b2Vec2());
  return Math.hypot(b.x - a.x, b.y - a.y);
}

/** A 1 kg box tied to a ground anchor at (0, 10) by a rope of maxLength 5, starting 2 m below it. */
function tetheredBox(gx = 0, gy = -10) {
  const world = makeWorld(gx, gy);
  const ground = makeGround(world);
  const box = makeBox(world, 0, 8, 0.5, 0.5);
  const def = new b2RopeJointDef();
  def.bodyA = ground;
  def.bodyB = box;
  def.localAnchorA.Set(0, 10);
  def.localAnchorB.Set(0, 0);
  def.maxLength = 5;
  const joint = world.CreateJoint(def) as b2RopeJoint;
  return { world, box, joint };
}

describe('b2RopeJoint', () => {
  it('leaves a slack rope without effect: the body falls exactly as in free fall', () => {
    const { world, box, joint } = tetheredBox();
    let vy = 0.0;
    let y = 8.0;
    step(world, 15, (k) => {
      vy = vy + h * -10.0;
      y = y + h * vy;
      expect(box.GetPosition().y, `y after step ${k}`).toBe(y);
      expect(box.GetLinearVelocity().y, `vy after step ${k}`).toBe(vy);
    });
    expect(joint.GetLimitState()).toBe(b2LimitState.e_inactiveLimit);
    expect(Math.abs(joint.GetReactionForce(inv_h, new b2Vec2()).y)).toBe(0);
  });

  it('stops the fall at maxLength and then carries m*g', () => {
    const { world, box, joint } = tetheredBox();
    let longest = 0;
    step(world, 240, () => {
      longest = Math.max(longest, anchorDistance(joint));
    });
    expect(longest).toBeLessThan(5 + b2_linearSlop);
    expect(anchorDistance(joint)).toBeGreaterThan(5 - b2_linearSlop);
    expect(box.GetLinearVelocity().y).toBeCloseTo(0, 6);

    const force = joint.GetReactionForce(inv_h, new b2Vec2());
    expect(box.GetMass()).toBe(1);
    expect(force.x).toBeCloseTo(0, 9);
    expect(force.y).toBeCloseTo(10, 6);
    expect(joint.GetReactionTorque(inv_h)).toBe(0);
  });

  it('reports e_atUpperLimit when stretched past maxLength and pulls the body back', () => {
    const { world, box, joint } = tetheredBox(0, 0);
    box.SetTransform(new b2Vec2(0, 10 - 5.1), 0);
    step(world, 1);
    expect(joint.GetLimitState()).toBe(b2LimitState.e_atUpperLimit);
    // One step corrects at most b2_maxLinearCorrection of position error.
    expect(anchorDistance(joint)).toBeLessThan(5.1);
    step(world, 5);
    expect(anchorDistance(joint)).toBeLessThan(5 + b2_linearSlop);
  });

  it('never pushes: a body moving towards the anchor passes well inside maxLength', () => {
    const { world, box, joint } = tetheredBox(0, 0);
    box.SetLinearVelocity(new b2Vec2(0, 3));
    let shortest = Infinity;
    step(world, 60, () => {
      shortest = Math.min(shortest, anchorDistance(joint));
    });
    expect(shortest).toBeLessThan(0.5);
    expect(box.GetLinearVelocity().y).toBe(3);
  });

  it('exposes its anchors and max length', () => {
    const { joint } = tetheredBox();
    expect([joint.GetLocalAnchorA().x, joint.GetLocalAnchorA().y]).toEqual([0, 10]);
    expect([joint.GetLocalAnchorB().x, joint.GetLocalAnchorB().y]).toEqual([0, 0]);
    expect(joint.GetMaxLength()).toBe(5);
    joint.SetMaxLength(4);
    expect(joint.GetMaxLength()).toBe(4);
  });

  it('dumps a b2RopeJointDef with the C++ format', () => {
    const { joint } = tetheredBox();
    joint.GetBodyA().m_islandIndex = 3;
    joint.GetBodyB().m_islandIndex = 4;
    joint.m_index = 1;
    expect(captureLog(() => joint.Dump())).toBe(
      '  b2RopeJointDef jd;\n' +
        '  jd.bodyA = bodies[3];\n' +
        '  jd.bodyB = bodies[4];\n' +
        '  jd.collideConnected = bool(0);\n' +
        '  jd.localAnchorA.Set(0.000000000000000e+00f, 1.000000000000000e+01f);\n' +
        '  jd.localAnchorB.Set(0.000000000000000e+00f, 0.000000000000000e+00f);\n' +
        '  jd.maxLength = 5.000000000000000e+00f;\n' +
        '  joints[1] = m_world->CreateJoint(&jd);\n',
    );
  });
});

describe('b2RopeJoint compared with a rigid limit', () => {
  it('lets the body rise to the same height as without a rope', () => {
    const free = makeWorld(0, -10);
    const freeBox = makeBox(free, 0, 8, 0.5, 0.5);
    freeBox.SetLinearVelocity(new b2Vec2(0, 4));
    const { world, box } = tetheredBox();
    box.SetLinearVelocity(new b2Vec2(0, 4));
    step(free, 20);
    step(world, 20);
    expect(box.GetPosition().y).toBe(freeBox.GetPosition().y);
    expect(box.GetPosition().y).toBeGreaterThan(8.5);
  });
});
