import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2MouseJoint, b2MouseJointDef } from '../../../src/dynamics/joints/b2MouseJoint';
import { h, inv_h, makeBox, makeGround, makeWorld, step } from './jointTestWorld';

/** A 1 kg box at (1, 2) grabbed at the world point `grab`. */
function grabbedBox(grab: b2Vec2, maxForce: number, gy = 0) {
  const world = makeWorld(0, gy);
  const ground = makeGround(world);
  const box = makeBox(world, 1, 2, 0.5, 0.5);
  const def = new b2MouseJointDef();
  def.bodyA = ground;
  def.bodyB = box;
  def.target.Assign(grab);
  def.maxForce = maxForce;
  const joint = world.CreateJoint(def) as b2MouseJoint;
  return { world, box, joint };
}

describe('b2MouseJoint', () => {
  it('anchors body B at the initial target and reports the target as anchor A', () => {
    const { joint } = grabbedBox(new b2Vec2(1.25, 2.5), 100);
    expect([joint.m_localAnchorB.x, joint.m_localAnchorB.y]).toEqual([0.25, 0.5]);
    const a = joint.GetAnchorA(new b2Vec2());
    const b = joint.GetAnchorB(new b2Vec2());
    expect([a.x, a.y]).toEqual([1.25, 2.5]);
    expect([b.x, b.y]).toEqual([1.25, 2.5]);
    expect(joint.GetTarget()).not.toBe(a);
  });

  it('pulls the grabbed point to a new target', () => {
    const { world, joint } = grabbedBox(new b2Vec2(1, 2), 1000);
    joint.SetTarget(new b2Vec2(4, -1));
    step(world, 180);
    const b = joint.GetAnchorB(new b2Vec2());
    expect(b.x).toBeCloseTo(4, 3);
    expect(b.y).toBeCloseTo(-1, 3);
  });

  it('holds a body against gravity with a force of m*g', () => {
    const { world, box, joint } = grabbedBox(new b2Vec2(1, 2), 1000, -10);
    step(world, 240);
    const force = joint.GetReactionForce(inv_h, new b2Vec2());
    expect(force.x).toBeCloseTo(0, 6);
    expect(force.y).toBeCloseTo(box.GetMass() * 10, 3);
    expect(joint.GetReactionTorque(inv_h)).toBe(0);
  });

  it('never pulls harder than maxForce', () => {
    const { world, box, joint } = grabbedBox(new b2Vec2(1, 2), 2);
    joint.SetTarget(new b2Vec2(100, 2));
    const force = new b2Vec2();
    step(world, 30, () => {
      joint.GetReactionForce(inv_h, force);
      expect(Math.hypot(force.x, force.y)).toBeLessThanOrEqual(2 * (1 + 1e-12));
    });
    // Saturated the whole time: v = n * h * F / m.
    expect(box.GetLinearVelocity().x).toBeCloseTo((30 * h * 2) / box.GetMass(), 9);
  });

  it('damps the angular velocity of body B by 0.98 per step', () => {
    const { world, box } = grabbedBox(new b2Vec2(1, 2), 1000);
    box.SetAngularVelocity(5);
    let w = 5;
    step(world, 10, (k) => {
      w *= 0.98;
      expect(box.GetAngularVelocity(), `w after step ${k}`).toBe(w);
    });
  });

  it('wakes body B when the target moves and exposes its tuning', () => {
    const { box, joint } = grabbedBox(new b2Vec2(1, 2), 10);
    box.SetAwake(false);
    joint.SetTarget(new b2Vec2(0, 0));
    expect(box.IsAwake()).toBe(true);
    expect([joint.GetTarget().x, joint.GetTarget().y]).toEqual([0, 0]);

    joint.SetMaxForce(20);
    joint.SetFrequency(3);
    joint.SetDampingRatio(0.5);
    expect([joint.GetMaxForce(), joint.GetFrequency(), joint.GetDampingRatio()]).toEqual([20, 3, 0.5]);
  });

  it('rejects invalid definitions', () => {
    expect(() => grabbedBox(new b2Vec2(NaN, 0), 10)).toThrow();
    expect(() => grabbedBox(new b2Vec2(0, 0), -1)).toThrow();
  });
});
