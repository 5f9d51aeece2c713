import { describe, expect, it } from 'vitest';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2Body, b2BodyDef, b2BodyType } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2MouseJointDef } from '../../src/dynamics/joints/b2MouseJoint';
import { b2PrismaticJointDef } from '../../src/dynamics/joints/b2PrismaticJoint';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { b2RopeJointDef } from '../../src/dynamics/joints/b2RopeJoint';
import { b2GearJointDef } from '../../src/dynamics/joints/b2GearJoint';
import { b2dJsonRead } from '../../src/io/b2dJsonRead';
import { b2dJsonScene } from '../../src/io/b2dJsonScene';
import { b2dJson_stateKey } from '../../src/io/b2dJsonState';
import { b2dJsonWrite, b2dJsonWriteString } from '../../src/io/b2dJsonWrite';
import { checkWorldInvariants, motionDigest, worldDigest } from '../support/invariants';
import { goldenSceneNames, loadGoldenScene } from '../support/scene';

/*
 * Determinism: a scene run twice gives the same full-state digests; a scene written mid-run with
 * the solver-state extension and read back steps on bit for bit like the original.
 */

function stepDigests(scene: b2dJsonScene, steps: number): string[] {
  const digests: string[] = [];
  for (let i = 0; i < steps; ++i) {
    scene.step();
    digests.push(worldDigest(scene.world));
  }
  return digests;
}

/** Step original and copy side by side; the first step whose digests differ, or -1. */
function firstDivergence(a: b2dJsonScene, b: b2dJsonScene, steps: number): number {
  for (let i = 0; i < steps; ++i) {
    a.step();
    b.step();
    if (worldDigest(a.world) !== worldDigest(b.world)) return i + 1;
  }
  return -1;
}

const kLead = 45;
const kFollow = 45;

describe('the same scene run twice gives identical digests', () => {
  for (const name of ['mixed-rain', 'bridge', 'gears', 'continuous-test', 'tumbler', 'character-collision']) {
    it(name, () => {
      const first = stepDigests(loadGoldenScene(name), 120);
      const second = stepDigests(loadGoldenScene(name), 120);
      expect(second).toEqual(first);
    });
  }
});

describe('a golden scene written mid-run with its solver state reloads and steps on bit for bit', () => {
  for (const name of goldenSceneNames()) {
    it(name, () => {
      const scene = loadGoldenScene(name);
      for (let i = 0; i < kLead; ++i) scene.step();
      const text = b2dJsonWriteString(scene, '', { solverState: true });
      const copy = b2dJsonRead(text);
      expect(worldDigest(copy.world)).toBe(worldDigest(scene.world));
      expect(checkWorldInvariants(copy.world)).toEqual([]);
      expect(firstDivergence(scene, copy, kFollow)).toBe(-1);
    });
  }
});

/** A scene exercising what plain b2dJson loses: sleep, TOI sub-steps, bullets, freed proxies, joints. */
function busyScene(): b2dJsonScene {
  const world = new b2World(new b2Vec2(0, -10));
  world.SetSubStepping(true);
  const scene = new b2dJsonScene(world);
  const ground = world.CreateBody(new b2BodyDef());
  const edge = new b2EdgeShape().Set(new b2Vec2(-20, 0), new b2Vec2(20, 0));
  ground.CreateFixture(edge, 0);
  const chain = new b2ChainShape();
  chain.CreateLoop([new b2Vec2(-20, 0), new b2Vec2(20, 0), new b2Vec2(20, 20), new b2Vec2(-20, 20)]);
  ground.CreateFixture(chain, 0);
  scene.bodies.push(ground);
  const bodies: b2Body[] = [];
  for (let i = 0; i < 24; ++i) {
    const bd = new b2BodyDef();
    bd.type = b2BodyType.b2_dynamicBody;
    bd.position.Set(-6 + (i % 6) * 2.1, 1 + Math.floor(i / 6) * 1.3);
    bd.angle = 0.1 * i;
    bd.bullet = i % 7 === 0;
    const b = world.CreateBody(bd);
    const fd = new b2FixtureDef();
    if (i % 3 === 0) {
      const c = new b2CircleShape();
      c.m_radius = 0.5;
      fd.shape = c;
    } else {
      fd.shape = new b2PolygonShape().SetAsBox(0.5, 0.4 + 0.05 * (i % 4), new b2Vec2(0.1, 0), 0.2);
    }
    fd.density = 1;
    fd.friction = 0.3 + 0.02 * i;
    fd.restitution = i % 5 === 0 ? 0.4 : 0;
    fd.isSensor = i === 11;
    b.CreateFixture(fd);
    bodies.push(b);
    scene.bodies.push(b);
  }
  // A fast bullet towards the pile, and holes in the tree's node pool.
  bodies[7].SetLinearVelocity(new b2Vec2(40, -5));
  world.DestroyBody(bodies[5]);
  world.DestroyBody(bodies[17]);
  bodies[9].SetActive(false);
  const rd = new b2RevoluteJointDef();
  rd.Initialize(bodies[1], bodies[2], bodies[1].GetWorldCenter());
  rd.enableLimit = true;
  rd.lowerAngle = -0.3;
  rd.upperAngle = 0.3;
  rd.enableMotor = true;
  rd.maxMotorTorque = 5;
  rd.motorSpeed = 1;
  const revolute = world.CreateJoint(rd);
  const pd = new b2PrismaticJointDef();
  pd.Initialize(ground, bodies[3], bodies[3].GetWorldCenter(), new b2Vec2(1, 0));
  pd.enableLimit = true;
  pd.lowerTranslation = -1;
  pd.upperTranslation = 1;
  const prismatic = world.CreateJoint(pd);
  const gd = new b2GearJointDef();
  gd.bodyA = bodies[2];
  gd.bodyB = bodies[3];
  gd.joint1 = revolute;
  gd.joint2 = prismatic;
  world.CreateJoint(gd);
  const ropeDef = new b2RopeJointDef();
  ropeDef.bodyA = bodies[12];
  ropeDef.bodyB = bodies[13];
  ropeDef.maxLength = 1.5;
  world.CreateJoint(ropeDef);
  const md = new b2MouseJointDef();
  md.bodyA = ground;
  md.bodyB = bodies[20];
  md.target.Set(0, 8);
  md.maxForce = 200;
  world.CreateJoint(md);
  scene.bodies.splice(0, scene.bodies.length, ...[...scene.bodies].filter((b) => !b.m_destroyed));
  return scene;
}

describe('the solver-state extension', () => {
  it('carries sleep, sub-stepped TOI, bullets, sensors, freed proxies and joint impulses bit for bit', () => {
    const scene = busyScene();
    let sawIncompleteStep = false;
    // Write at several points, including while a sub-stepped TOI phase is unfinished.
    for (let round = 0; round < 6; ++round) {
      for (let i = 0; i < 25; ++i) {
        scene.step();
        if (!scene.world.m_stepComplete) sawIncompleteStep = true;
      }
      const contactFriction = scene.world.GetContactList();
      if (contactFriction !== null) contactFriction.SetFriction(0.123);
      const copy = b2dJsonRead(b2dJsonWriteString(scene, '', { solverState: true }));
      expect(worldDigest(copy.world)).toBe(worldDigest(scene.world));
      const probe = b2dJsonRead(b2dJsonWriteString(scene, '', { solverState: true }));
      expect(firstDivergence(probe, copy, 40)).toBe(-1);
    }
    expect(sawIncompleteStep).toBe(true);
    let asleep = 0;
    for (let b = scene.world.GetBodyList(); b !== null; b = b.GetNext()) if (!b.IsAwake()) ++asleep;
    expect(asleep).toBeGreaterThan(0);
  });

  it('the original and its reloaded copy step identically for 200 steps', () => {
    const scene = busyScene();
    for (let i = 0; i < 60; ++i) scene.step();
    const copy = b2dJsonRead(b2dJsonWriteString(scene, '', { solverState: true }));
    expect(firstDivergence(scene, copy, 200)).toBe(-1);
  });

  it('without the extension, a reloaded world drifts (why it exists)', () => {
    const scene = loadGoldenScene('mixed-rain');
    for (let i = 0; i < 120; ++i) scene.step();
    const plain = b2dJsonRead(b2dJsonWriteString(scene));
    let diverged = false;
    for (let i = 0; i < 60 && !diverged; ++i) {
      scene.step();
      plain.step();
      diverged = motionDigest(scene.world) !== motionDigest(plain.world);
    }
    expect(diverged).toBe(true);
  });

  it('is one optional top-level key: the rest is the plain document, which still loads', () => {
    const scene = loadGoldenScene('bridge');
    for (let i = 0; i < 30; ++i) scene.step();
    const plain = b2dJsonWrite(scene);
    const extended = b2dJsonWrite(scene, { solverState: true });
    const { [b2dJson_stateKey]: state, ...rest } = extended;
    expect(state).toBeTypeOf('object');
    expect(rest).toEqual(plain);
    expect(Object.keys(plain)).not.toContain(b2dJson_stateKey);
    expect(b2dJsonRead(rest).world.GetBodyCount()).toBe(scene.world.GetBodyCount());
  });

  it('rejects a malformed extension with its path', () => {
    const scene = loadGoldenScene('bridge');
    scene.step();
    const doc = b2dJsonWrite(scene, { solverState: true }) as Record<string, any>;
    const bad = structuredClone(doc);
    bad[b2dJson_stateKey].version = 99;
    expect(() => b2dJsonRead(bad)).toThrow(`${b2dJson_stateKey}.version: expected 1, got 99`);
    const bad2 = structuredClone(doc);
    bad2[b2dJson_stateKey].bodies.pop();
    expect(() => b2dJsonRead(bad2)).toThrow(/webphysicsState\.bodies: expected \d+ entries/);
    const bad3 = structuredClone(doc);
    bad3[b2dJson_stateKey].joints[0].m_nonsense = 1;
    expect(() => b2dJsonRead(bad3)).toThrow('webphysicsState.joints[0].m_nonsense: this joint type has no such field');
    const bad4 = structuredClone(doc);
    const nodes = bad4[b2dJson_stateKey].broadPhase.tree.nodes as number[][];
    const inner = nodes.findIndex((n) => n[3] > 0);
    nodes[inner][7] += 1; // an inner node whose box no longer bounds its children exactly
    expect(() => b2dJsonRead(bad4)).toThrow(/^webphysicsState\.broadPhase\.tree: is not a valid dynamic tree/);
    const bad5 = structuredClone(doc);
    bad5[b2dJson_stateKey].contacts.push({ ...bad5[b2dJson_stateKey].contacts[0], fixtureA: [0, 99, 0] });
    expect(() => b2dJsonRead(bad5)).toThrow(/^webphysicsState\.contacts\[\d+\]\.fixtureA\[1\]: expected an integer in/);
  });

  it('rejects a contact on a fixture of an inactive body (it has no broad-phase proxies)', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const boxes: b2Body[] = [];
    for (const [x, active] of [
      [0.0, true],
      [1.5, true],
      [3.0, false],
    ] as const) {
      const bd = new b2BodyDef();
      bd.type = b2BodyType.b2_dynamicBody;
      bd.position.Set(x, 0.0);
      bd.active = active;
      const body = world.CreateBody(bd);
      body.CreateFixture(new b2PolygonShape().SetAsBox(1.0, 1.0), 1.0);
      boxes.push(body);
    }
    world.Step(1.0 / 60.0, 8, 3);
    expect(world.GetContactCount()).toBe(1);
    const doc = b2dJsonWrite(world, { solverState: true }) as Record<string, any>;
    const contacts = doc[b2dJson_stateKey].contacts;
    contacts.push({ ...contacts[0], fixtureA: [1, 0, 0], fixtureB: [2, 0, 0] });
    expect(() => b2dJsonRead(doc)).toThrow('webphysicsState.contacts[1]: joins a fixture that has no broad-phase proxies (its body is inactive)');
  });
});
