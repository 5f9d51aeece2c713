/*
 * R.U.B.E. files as found in the wild: what their writers leave out or vary (zero vectors in two
 * spellings, bodies without fixtures, no `awake`, mass data overriding the fixtures', keys in any
 * order), and items from a newer Box2D that iforce2d's loaders skip (b2dJsonRead's skipUnknown).
 */

import { describe, expect, it } from 'vitest';
import { b2BodyType } from '../../src/dynamics/b2Body';
import { b2JointType } from '../../src/dynamics/joints/b2Joint';
import type { b2GearJoint } from '../../src/dynamics/joints/b2GearJoint';
import { b2dJsonBodiesInCreationOrder, b2dJsonError, b2dJsonRead, b2dJsonWrite } from '../../src/io/b2dJson';
import type { b2dJsonObject, b2dJsonScene, b2dJsonValue } from '../../src/io/b2dJson';

const circle = { density: 1, friction: 0.5, circle: { radius: 0.5, center: 0 } };

/** A car on a ground line, with what R.U.B.E. 1.7 writes for a Box2D 2.3 scene: a motor joint. */
function carWithMotorJoint(): b2dJsonObject {
  return {
    gravity: { x: 0, y: -10 },
    body: [
      { type: 0, position: 0, fixture: [{ friction: 0.8, edge: { vertex1: { x: -20, y: 0 }, vertex2: { x: 20, y: 0 } } }] },
      {
        type: 2,
        awake: true,
        position: { x: 0, y: 1.5 },
        fixture: [{ density: 1, polygon: { vertices: { x: [-1, 1, 1, -1], y: [-0.25, -0.25, 0.25, 0.25] } } }],
      },
      { type: 2, awake: true, position: { x: -0.8, y: 0.6 }, fixture: [circle] },
      { type: 2, awake: true, position: { x: 0.8, y: 0.6 }, fixture: [circle] },
    ],
    joint: [
      { type: 'revolute', bodyA: 1, bodyB: 2, anchorA: { x: -0.8, y: -0.9 }, anchorB: 0, enableMotor: true, motorSpeed: -5, maxMotorTorque: 50 },
      { type: 'motor', bodyA: 0, bodyB: 1, maxForce: 10, maxTorque: 10, correctionFactor: 0.3 },
      { type: 'revolute', bodyA: 1, bodyB: 3, anchorA: { x: 0.8, y: -0.9 }, anchorB: 0 },
      { type: 'gear', bodyA: 2, bodyB: 3, joint1: 0, joint2: 2, ratio: 1 },
      { type: 'gear', bodyA: 2, bodyB: 3, joint1: 0, joint2: 1, ratio: 1 },
    ],
  };
}

describe('b2dJsonRead with skipUnknown', () => {
  it('rejects a file with a motor joint whole by default, naming the joint', () => {
    const error = readError(carWithMotorJoint());
    expect(error).toBeInstanceOf(b2dJsonError);
    expect(error.message).toBe('joint[1].type: motor joints are not part of Box2D 2.2.1 (they arrived in 2.3)');
    expect(readError(withEllipse()).message).toBe('body[3].fixture[1]: no shape: expected one of circle, edge, chain, loop, polygon');
  });

  it('leaves out the motor joint, an unknown shape and a gear on the motor joint, lists them, and builds the rest', () => {
    const scene = b2dJsonRead(withEllipse(), { skipUnknown: true });
    expect(scene.skipped).toEqual([
      { path: 'body[3].fixture[1]', reason: 'no shape: expected one of circle, edge, chain, loop, polygon' },
      { path: 'joint[1].type', reason: 'motor joints are not part of Box2D 2.2.1 (they arrived in 2.3)' },
      { path: 'joint[4]', reason: 'joint[4].joint2 is joint[1], which was skipped' },
    ]);
    expect(scene.bodies).toHaveLength(4);
    expect(scene.bodies[3].GetFixtureList()!.GetNext()).toBeNull();
    // The gear after the skipped joint couples the file's joint[0] and joint[2].
    expect(scene.joints.map((j) => j.GetType())).toEqual([b2JointType.e_revoluteJoint, b2JointType.e_revoluteJoint, b2JointType.e_gearJoint]);
    const gear = scene.joints[2] as b2GearJoint;
    expect([gear.m_joint1, gear.m_joint2]).toEqual([scene.joints[0], scene.joints[1]]);
    expect(scene.world.GetJointCount()).toBe(3);
    // The motor turns the rear wheel and the gear the front one: the car drives off.
    for (let i = 0; i < 120; ++i) scene.step();
    expect(scene.bodies[1].GetPosition().x).toBeGreaterThan(2);
  });

  it('skips nothing in a file it fully knows', () => {
    const document = carWithMotorJoint();
    const joints = document.joint as b2dJsonObject[];
    joints.splice(1, 1);
    joints.pop();
    joints[2].joint2 = 1;
    const scene = b2dJsonRead(document, { skipUnknown: true });
    expect(scene.skipped).toEqual([]);
    expect(scene.joints).toHaveLength(3);
  });

  it('refuses a solver state for a scene with skipped items', () => {
    const read = b2dJsonRead(carWithMotorJoint(), { skipUnknown: true });
    const state = (b2dJsonWrite(read, { solverState: true }) as b2dJsonObject).webphysicsState;
    expect(() => b2dJsonRead({ ...carWithMotorJoint(), webphysicsState: state }, { skipUnknown: true })).toThrow(
      'webphysicsState: cannot be applied to a scene with skipped items (joint[1].type...)',
    );
  });
});

/** The car with a fixture of a shape b2dJson does not have. */
function withEllipse(): b2dJsonObject {
  const document = carWithMotorJoint();
  ((document.body as b2dJsonObject[])[3].fixture as b2dJsonValue[]).push({ density: 1, ellipse: { rx: 1, ry: 2 } });
  return document;
}

function readError(document: b2dJsonObject): b2dJsonError {
  try {
    b2dJsonRead(document);
  } catch (e) {
    return e as b2dJsonError;
  }
  throw new Error('expected a throw');
}

/** The document with every object's keys in reverse order, recursively. */
function reverseKeys(value: b2dJsonValue): b2dJsonValue {
  if (Array.isArray(value)) return value.map(reverseKeys);
  if (value === null || typeof value !== 'object') return value;
  const out: b2dJsonObject = {};
  for (const key of Object.keys(value).reverse()) out[key] = reverseKeys(value[key]);
  return out;
}

/** Each body's position and angle after `steps` steps. */
function trajectory(scene: b2dJsonScene, steps: number): number[][] {
  for (let i = 0; i < steps; ++i) scene.step();
  return b2dJsonBodiesInCreationOrder(scene.world).map((b) => [b.GetPosition().x, b.GetPosition().y, b.GetAngle()]);
}

describe('R.U.B.E. files as found in the wild', () => {
  const wild: b2dJsonObject = {
    gravity: { x: 0, y: -10 },
    allowSleep: true,
    body: [
      // Zero vectors as 0 and as {x: 0, y: 0} in one file.
      {
        type: 0,
        position: 0,
        linearVelocity: { x: 0, y: 0 },
        fixture: [{ friction: 0.6, polygon: { vertices: { x: [-10, 10, 10, -10], y: [-1, -1, 0, 0] } } }],
      },
      // No awake: b2dJson's default is asleep, so it hangs in the air until something wakes it.
      { type: 2, position: { x: 0, y: 5 }, fixture: [circle] },
      // Awake, with mass data that overrides its fixtures'.
      { type: 2, awake: true, position: { x: 2, y: 3 }, angularVelocity: 0, fixture: [circle], 'massData-mass': 5, 'massData-center': 0, 'massData-I': 2 },
      // No fixtures: a bare anchor body.
      { type: 2, awake: true, position: { x: -3, y: 4 }, linearVelocity: 0 },
    ],
  };

  it('zero vectors as 0 and {x:0, y:0}, bodies without fixtures, no awake and mass data load as b2dJson means', () => {
    const scene = b2dJsonRead(wild);
    const [ground, sleeper, heavy, bare] = scene.bodies;
    expect([ground.GetPosition().x, ground.GetPosition().y, ground.GetType()]).toEqual([0, 0, b2BodyType.b2_staticBody]);
    expect(sleeper.IsAwake()).toBe(false);
    expect(heavy.IsAwake()).toBe(true);
    expect([heavy.GetMass(), heavy.GetInertia()]).toEqual([5, 2]);
    expect([bare.GetFixtureList(), bare.GetMass()]).toEqual([null, 1]);
    const [, sleeperAfter, heavyAfter, bareAfter] = trajectory(scene, 60);
    // The sleeper stays put; the others fall.
    expect(sleeperAfter[1]).toBe(5);
    expect(sleeper.IsAwake()).toBe(false);
    expect(heavyAfter[1]).toBeLessThan(3);
    expect(bareAfter[1]).toBeLessThan(0);
  });

  it('keys in any order build the same world, step for step', () => {
    const sorted = trajectory(b2dJsonRead(wild), 240);
    const reversed = trajectory(b2dJsonRead(reverseKeys(wild)), 240);
    expect(reversed).toEqual(sorted);
  });
});
