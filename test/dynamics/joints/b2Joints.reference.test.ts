/*
 * Bit-exact comparison with Box2D 2.2.1 (C++, float64) on scenes built for the joint code paths
 * that the golden scenes leave out. b2Joints.reference.cpp builds the same scenes one for one and
 * printed b2Joints.reference.json: the state digest after every step (the golden trajectories'
 * FNV-1a over every body's position, angle and velocities, in creation order) and the world's
 * Dump() at the end.
 */

import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { b2CircleShape } from '../../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2Body, b2BodyDef, b2BodyType } from '../../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../../src/dynamics/b2Fixture';
import { b2World } from '../../../src/dynamics/b2World';
import { b2DistanceJointDef } from '../../../src/dynamics/joints/b2DistanceJoint';
import { b2FrictionJointDef } from '../../../src/dynamics/joints/b2FrictionJoint';
import { b2GearJointDef } from '../../../src/dynamics/joints/b2GearJoint';
import { b2MouseJoint, b2MouseJointDef } from '../../../src/dynamics/joints/b2MouseJoint';
import { b2PrismaticJoint, b2PrismaticJointDef } from '../../../src/dynamics/joints/b2PrismaticJoint';
import { b2PulleyJointDef } from '../../../src/dynamics/joints/b2PulleyJoint';
import { b2RevoluteJoint, b2RevoluteJointDef } from '../../../src/dynamics/joints/b2RevoluteJoint';
import { b2RopeJointDef } from '../../../src/dynamics/joints/b2RopeJoint';
import { b2WeldJointDef } from '../../../src/dynamics/joints/b2WeldJoint';
import { b2WheelJoint, b2WheelJointDef } from '../../../src/dynamics/joints/b2WheelJoint';
import { captureLog } from './jointTestWorld';

interface ReferenceScene {
  digests: string[];
  dump: string;
}

const reference = JSON.parse(readFileSync(path.join(path.dirname(fileURLToPath(import.meta.url)), 'b2Joints.reference.json'), 'utf8')) as {
  scenes: Record<string, ReferenceScene>;
};

/** A scene under construction: the world and its bodies in creation order. */
class Scene {
  readonly world = new b2World(new b2Vec2(0.0, -10.0));
  readonly bodies: b2Body[] = [];
  readonly digests: string[] = [];

  body(type: b2BodyType, x: number, y: number, angle: number, fixedRotation: boolean): b2Body {
    const bd = new b2BodyDef();
    bd.type = type;
    bd.position.Set(x, y);
    bd.angle = angle;
    bd.allowSleep = false;
    bd.fixedRotation = fixedRotation;
    const body = this.world.CreateBody(bd);
    this.bodies.push(body);
    return body;
  }

  ground(): b2Body {
    return this.body(b2BodyType.b2_staticBody, 0.0, 0.0, 0.0, false);
  }

  box(x: number, y: number, angle: number, hx: number, hy: number, density: number, fixedRotation = false): b2Body {
    const body = this.body(b2BodyType.b2_dynamicBody, x, y, angle, fixedRotation);
    const shape = new b2PolygonShape();
    shape.SetAsBox(hx, hy);
    this.fixture(body, shape, density);
    return body;
  }

  circle(x: number, y: number, radius: number, density: number): b2Body {
    const body = this.body(b2BodyType.b2_dynamicBody, x, y, 0.0, false);
    const shape = new b2CircleShape();
    shape.m_radius = radius;
    this.fixture(body, shape, density);
    return body;
  }

  private fixture(body: b2Body, shape: b2PolygonShape | b2CircleShape, density: number): void {
    const fd = new b2FixtureDef();
    fd.shape = shape;
    fd.density = density;
    fd.filter.categoryBits = 0;
    body.CreateFixture(fd);
  }

  step(dt: number): void {
    this.world.Step(dt, 8, 3);
    this.digests.push(digest(this.bodies));
  }
}

const s_bytes = new DataView(new ArrayBuffer(8));

function digest(bodies: readonly b2Body[]): string {
  let h = 2166136261;
  for (const b of bodies) {
    const p = b.GetPosition();
    const v = b.m_linearVelocity;
    for (const value of [p.x, p.y, b.GetAngle(), v.x, v.y, b.GetAngularVelocity()]) {
      s_bytes.setFloat64(0, value, true);
      for (let i = 0; i < 8; ++i) {
        h = Math.imul(h ^ s_bytes.getUint8(i), 16777619) >>> 0;
      }
    }
  }
  return h.toString(16).padStart(8, '0');
}

/** The top-level blocks of a world Dump() that are not bodies: one per joint. */
function jointBlocks(dump: string): string[] {
  const blocks = dump.split(/^\{\n/m).slice(1);
  return blocks.map((b) => b.slice(0, b.search(/^\}\n/m))).filter((b) => !b.startsWith('  b2BodyDef'));
}

function mouseScene(s: Scene): void {
  const g = s.ground();
  const b = s.box(1.0, 2.0, 0.3, 0.5, 0.25, 2.0);
  const md = new b2MouseJointDef();
  md.bodyA = g;
  md.bodyB = b;
  md.target.Set(1.3, 2.2);
  md.maxForce = 50.0;
  const mouse = s.world.CreateJoint(md) as b2MouseJoint;
  for (let k = 1; k <= 120; ++k) {
    if (k === 1) mouse.SetTarget(new b2Vec2(4.0, -1.0));
    if (k === 61) mouse.SetTarget(new b2Vec2(0.0, 5.0));
    if (k === 91) {
      mouse.SetMaxForce(5.0);
      mouse.SetFrequency(2.0);
      mouse.SetDampingRatio(0.3);
    }
    s.step(1.0 / 60.0);
  }
}

function limitsScene(s: Scene): void {
  const g = s.ground();
  const bar1 = s.box(1.0, 5.0, 0.0, 1.0, 0.1, 1.0);
  const r1 = new b2RevoluteJointDef();
  r1.Initialize(g, bar1, new b2Vec2(0.0, 5.0));
  r1.enableLimit = true;
  r1.lowerAngle = 0.3;
  r1.upperAngle = 0.3;
  r1.enableMotor = true;
  r1.motorSpeed = 1.0;
  r1.maxMotorTorque = 10.0;
  s.world.CreateJoint(r1);

  const bar2 = s.box(3.0, 5.0, 0.0, 1.0, 0.1, 1.0);
  const r2 = new b2RevoluteJointDef();
  r2.Initialize(bar1, bar2, new b2Vec2(2.0, 5.0));
  r2.enableLimit = true;
  r2.lowerAngle = -0.25;
  r2.upperAngle = 0.5;
  r2.enableMotor = true;
  r2.motorSpeed = -2.0;
  r2.maxMotorTorque = 3.0;
  const rev2 = s.world.CreateJoint(r2) as b2RevoluteJoint;

  const slider = s.box(6.0, 5.0, 0.2, 0.5, 0.5, 1.0, true);
  const p1 = new b2PrismaticJointDef();
  p1.Initialize(g, slider, new b2Vec2(6.0, 5.0), new b2Vec2(0.6, 0.8));
  p1.enableLimit = true;
  p1.lowerTranslation = 0.0;
  p1.upperTranslation = 0.0;
  s.world.CreateJoint(p1);

  const slider2 = s.box(9.0, 5.0, 0.0, 0.5, 0.25, 1.0);
  const p2 = new b2PrismaticJointDef();
  p2.Initialize(g, slider2, new b2Vec2(9.0, 5.0), new b2Vec2(1.0, 1.0));
  p2.enableLimit = true;
  p2.lowerTranslation = -0.5;
  p2.upperTranslation = 1.5;
  p2.enableMotor = true;
  p2.motorSpeed = 2.0;
  p2.maxMotorForce = 20.0;
  const pri2 = s.world.CreateJoint(p2) as b2PrismaticJoint;

  for (let k = 1; k <= 180; ++k) {
    if (k === 90) {
      rev2.EnableLimit(false);
      pri2.SetLimits(-2.0, 0.5);
    }
    if (k === 120) {
      rev2.EnableLimit(true);
      pri2.EnableMotor(false);
    }
    s.step(1.0 / 60.0);
  }
}

function wheelScene(s: Scene): void {
  const chassis = s.box(0.0, 3.0, 0.0, 1.5, 0.3, 1.0);
  const w1 = s.circle(-1.0, 2.0, 0.4, 1.0);
  const d1 = new b2WheelJointDef();
  d1.Initialize(chassis, w1, new b2Vec2(-1.0, 2.0), new b2Vec2(0.0, 1.0));
  d1.frequencyHz = 0.0;
  d1.enableMotor = true;
  d1.motorSpeed = -3.0;
  d1.maxMotorTorque = 5.0;
  const wheel1 = s.world.CreateJoint(d1) as b2WheelJoint;

  const w2 = s.circle(1.0, 2.0, 0.4, 1.0);
  const d2 = new b2WheelJointDef();
  d2.Initialize(chassis, w2, new b2Vec2(1.0, 2.0), new b2Vec2(0.2, 1.0));
  d2.frequencyHz = 4.0;
  d2.dampingRatio = 0.7;
  const wheel2 = s.world.CreateJoint(d2) as b2WheelJoint;

  for (let k = 1; k <= 120; ++k) {
    if (k === 60) {
      wheel1.SetSpringFrequencyHz(3.0);
      wheel2.EnableMotor(true);
      wheel2.SetMotorSpeed(4.0);
      wheel2.SetMaxMotorTorque(2.0);
    }
    s.step(1.0 / 60.0);
  }
}

function softScene(s: Scene): void {
  const g = s.ground();
  const a = s.box(0.0, 8.0, 0.0, 0.5, 0.5, 1.0);
  const b = s.box(2.0, 8.0, 0.0, 0.25, 0.25, 3.0);

  const rope1 = new b2RopeJointDef();
  rope1.bodyA = g;
  rope1.bodyB = a;
  rope1.localAnchorA.Set(0.0, 10.0);
  rope1.localAnchorB.Set(0.5, 0.0);
  rope1.maxLength = 3.0;
  s.world.CreateJoint(rope1);

  const rope2 = new b2RopeJointDef();
  rope2.bodyA = a;
  rope2.bodyB = b;
  rope2.localAnchorA.Set(0.5, 0.0);
  rope2.localAnchorB.Set(-0.25, 0.0);
  rope2.maxLength = 2.0;
  s.world.CreateJoint(rope2);

  const dist1 = new b2DistanceJointDef();
  dist1.Initialize(g, b, new b2Vec2(4.0, 10.0), new b2Vec2(2.25, 8.0));
  dist1.frequencyHz = 1.5;
  dist1.dampingRatio = 0.2;
  s.world.CreateJoint(dist1);

  const c = s.circle(6.0, 8.0, 0.2, 1.0);
  const dist2 = new b2DistanceJointDef();
  dist2.Initialize(g, c, new b2Vec2(6.0, 8.0), new b2Vec2(6.0, 8.0));
  s.world.CreateJoint(dist2);

  const d = s.box(-3.0, 5.0, 0.0, 0.3, 0.3, 1.0);
  const e = s.box(-6.0, 5.0, 0.0, 0.3, 0.3, 2.0);
  const pulley = new b2PulleyJointDef();
  pulley.Initialize(d, e, new b2Vec2(-3.0, 9.0), new b2Vec2(-6.0, 9.0), new b2Vec2(-3.0, 5.3), new b2Vec2(-6.0, 5.3), 1.5);
  s.world.CreateJoint(pulley);

  const f = s.box(10.0, 0.0, 0.0, 0.5, 0.5, 1.0);
  f.SetLinearVelocity(new b2Vec2(3.0, 1.0));
  f.SetAngularVelocity(2.0);
  const friction = new b2FrictionJointDef();
  friction.Initialize(g, f, new b2Vec2(10.0, 0.0));
  friction.maxForce = 5.0;
  friction.maxTorque = 2.0;
  s.world.CreateJoint(friction);

  const w = s.box(12.0, 5.0, 0.0, 1.0, 0.2, 1.0);
  const weld = new b2WeldJointDef();
  weld.Initialize(g, w, new b2Vec2(11.0, 5.0));
  weld.frequencyHz = 3.0;
  weld.dampingRatio = 0.5;
  s.world.CreateJoint(weld);

  for (let k = 1; k <= 150; ++k) {
    s.world.SetWarmStarting(k <= 100 || k > 120);
    s.step(k % 3 === 0 ? 1.0 / 30.0 : 1.0 / 60.0);
  }
}

function gearScene(s: Scene): void {
  const g = s.ground();
  const cBody = s.box(0.0, 0.0, 0.0, 1.0, 1.0, 1.0);
  const rc = new b2RevoluteJointDef();
  rc.Initialize(g, cBody, new b2Vec2(0.0, 0.0));
  rc.enableMotor = true;
  rc.motorSpeed = 1.0;
  rc.maxMotorTorque = 100.0;
  const revC = s.world.CreateJoint(rc);

  const aBody = s.box(0.0, 2.0, 0.0, 0.5, 0.2, 1.0);
  const pa = new b2PrismaticJointDef();
  pa.Initialize(cBody, aBody, new b2Vec2(0.0, 2.0), new b2Vec2(1.0, 0.5));
  const joint1 = s.world.CreateJoint(pa);

  const dBody = s.circle(4.0, 0.0, 0.5, 1.0);
  const rd = new b2RevoluteJointDef();
  rd.Initialize(g, dBody, new b2Vec2(4.0, 0.0));
  const revD = s.world.CreateJoint(rd);

  const bBody = s.box(4.0, 2.0, 0.0, 0.3, 0.3, 1.0);
  const pb = new b2PrismaticJointDef();
  pb.Initialize(dBody, bBody, new b2Vec2(4.0, 2.0), new b2Vec2(0.0, 1.0));
  const joint2 = s.world.CreateJoint(pb);

  const g1 = new b2GearJointDef();
  g1.bodyA = aBody;
  g1.bodyB = bBody;
  g1.joint1 = joint1;
  g1.joint2 = joint2;
  g1.ratio = 0.5;
  s.world.CreateJoint(g1);

  const g2 = new b2GearJointDef();
  g2.bodyA = cBody;
  g2.bodyB = dBody;
  g2.joint1 = revC;
  g2.joint2 = revD;
  g2.ratio = -2.0;
  s.world.CreateJoint(g2);

  for (let k = 1; k <= 120; ++k) {
    s.step(1.0 / 60.0);
  }
}

const scenes: Record<string, { covers: string; build: (s: Scene) => void }> = {
  mouse: { covers: 'the mouse joint with a moving target, force clamp and retuning', build: mouseScene },
  limits: {
    covers: 'equal and one-sided revolute/prismatic limits with motors, fixed rotation, limit toggling',
    build: limitsScene,
  },
  wheels: { covers: 'wheel joints on a falling chassis, spring disabled then enabled, motors', build: wheelScene },
  soft: {
    covers: 'rope, soft and zero-length distance, pulley, friction, soft weld; varying dt, warm starting off',
    build: softScene,
  },
  gears: { covers: 'prismatic-prismatic and revolute-revolute gears over moving bodies C and D', build: gearScene },
};

describe('joints against Box2D 2.2.1 C++ (bit for bit)', () => {
  for (const [name, { covers, build }] of Object.entries(scenes)) {
    const expected = reference.scenes[name];

    it(`${name}: ${covers}, every step`, () => {
      const s = new Scene();
      build(s);
      expect(s.digests.length).toBe(expected.digests.length);
      const first = s.digests.findIndex((d, i) => d !== expected.digests[i]);
      if (first >= 0) {
        expect.fail(`state digest differs from step ${first + 1}: ${s.digests[first]} != ${expected.digests[first]}`);
      }
    });

    it(`${name}: Dump() prints every joint as the C++ does`, () => {
      const s = new Scene();
      build(s);
      const dump = captureLog(() => s.world.Dump());
      const blocks = jointBlocks(expected.dump);
      expect(blocks.length).toBe(s.world.GetJointCount());
      expect(jointBlocks(dump)).toEqual(blocks);
      // The rest of the world's dump (bodies, fixtures, header) matches too.
      expect(dump).toBe(expected.dump);
    });
  }
});
