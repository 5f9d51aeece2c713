/*
 * Replays the reference scenes of test/reference-scenes: a b2dJson scene loaded with the port's
 * reader, a script of API calls applied between steps, and five FNV-1a digests per step. The
 * expected digests were printed by Box2D 2.2.1 (C++, float64, built as the golden README says) running
 * a driver with exactly these semantics; test/reference-scenes/README.md describes them.
 */

import { readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { b2AABB, b2RayCastInput, b2RayCastOutput, b2WorldManifold } from '../../src/collision/b2Collision';
import type { b2Manifold } from '../../src/collision/b2Collision';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2MassData } from '../../src/collision/shapes/b2Shape';
import type { b2Shape } from '../../src/collision/shapes/b2Shape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef } from '../../src/dynamics/b2Body';
import type { b2Body, b2BodyType } from '../../src/dynamics/b2Body';
import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { b2Filter, b2FixtureDef } from '../../src/dynamics/b2Fixture';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import type { b2World } from '../../src/dynamics/b2World';
import { b2ContactListener, b2QueryCallback, b2RayCastCallback } from '../../src/dynamics/b2WorldCallbacks';
import type { b2ContactImpulse } from '../../src/dynamics/b2WorldCallbacks';
import { b2DistanceJointDef } from '../../src/dynamics/joints/b2DistanceJoint';
import type { b2DistanceJoint } from '../../src/dynamics/joints/b2DistanceJoint';
import { b2FrictionJointDef } from '../../src/dynamics/joints/b2FrictionJoint';
import type { b2FrictionJoint } from '../../src/dynamics/joints/b2FrictionJoint';
import { b2GearJointDef } from '../../src/dynamics/joints/b2GearJoint';
import type { b2GearJoint } from '../../src/dynamics/joints/b2GearJoint';
import { b2JointType } from '../../src/dynamics/joints/b2Joint';
import type { b2Joint } from '../../src/dynamics/joints/b2Joint';
import { b2MouseJointDef } from '../../src/dynamics/joints/b2MouseJoint';
import type { b2MouseJoint } from '../../src/dynamics/joints/b2MouseJoint';
import { b2PrismaticJointDef } from '../../src/dynamics/joints/b2PrismaticJoint';
import type { b2PrismaticJoint } from '../../src/dynamics/joints/b2PrismaticJoint';
import { b2PulleyJointDef } from '../../src/dynamics/joints/b2PulleyJoint';
import type { b2PulleyJoint } from '../../src/dynamics/joints/b2PulleyJoint';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import type { b2RevoluteJoint } from '../../src/dynamics/joints/b2RevoluteJoint';
import { b2RopeJointDef } from '../../src/dynamics/joints/b2RopeJoint';
import type { b2RopeJoint } from '../../src/dynamics/joints/b2RopeJoint';
import { b2WeldJointDef } from '../../src/dynamics/joints/b2WeldJoint';
import type { b2WeldJoint } from '../../src/dynamics/joints/b2WeldJoint';
import { b2WheelJointDef } from '../../src/dynamics/joints/b2WheelJoint';
import type { b2WheelJoint } from '../../src/dynamics/joints/b2WheelJoint';
import { b2dJsonRead } from '../../src/io/b2dJsonRead';

type J = any;

export const referenceScenesDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../reference-scenes');

/** The five digests of a step, in the order of the expected files' rows. */
export const kReferenceColumns = ['bodies', 'aux', 'joints', 'events', 'queries'] as const;

export interface ReferenceExpectation {
  steps: number;
  columns: string[];
  /** rows[k]: the five digests after step k (k = 0: the loaded scene after the step-0 actions). */
  rows: string[];
}

export function referenceCaseNames(): string[] {
  const expectations = JSON.parse(readFileSync(path.join(referenceScenesDir, 'manifest.json'), 'utf8')) as string[];
  return expectations;
}

const FNV0 = 2166136261;
const s_bytes = new DataView(new ArrayBuffer(8));

function fnv(h: number, v: number): number {
  if (v !== v) {
    // NaN sign and payload differ between engines: hash the one quiet NaN.
    s_bytes.setBigUint64(0, 0x7ff8000000000000n, true);
  } else {
    s_bytes.setFloat64(0, v, true);
  }
  for (let i = 0; i < 8; ++i) h = Math.imul(h ^ s_bytes.getUint8(i), 16777619) >>> 0;
  return h;
}

const hex = (h: number): string => h.toString(16).padStart(8, '0');

function num(o: J, k: string, d = 0): number {
  const v = o[k];
  return v === undefined || v === null ? d : v;
}
function bool(o: J, k: string, d = false): boolean {
  const v = o[k];
  return v === undefined || v === null ? d : v;
}
function has(o: J, k: string): boolean {
  return o[k] !== undefined && o[k] !== null;
}
function vecOf(o: J, k: string): b2Vec2 {
  const v = o[k];
  if (v === undefined || v === null || typeof v === 'number') return new b2Vec2(0, 0);
  return new b2Vec2(num(v, 'x'), num(v, 'y'));
}
function verts(o: J, k: string): b2Vec2[] {
  const v = o[k];
  return v.x.map((x: number, i: number) => new b2Vec2(x, v.y[i]));
}

/** One replay: the world, the id tables of the script, and the running digests. */
class Replay {
  readonly world: b2World;
  readonly hz: number;
  readonly velocityIterations: number;
  readonly positionIterations: number;
  readonly bodies: (b2Body | null)[] = [];
  readonly fixtures: (b2Fixture | null)[] = [];
  readonly joints: (b2Joint | null)[] = [];
  events = FNV0;
  queries = FNV0;
  readonly disabledFixtures: number[] = [];

  constructor(sceneText: string, script: J) {
    const scene = b2dJsonRead(sceneText);
    this.world = scene.world;
    this.hz = scene.stepSettings.stepsPerSecond;
    this.velocityIterations = scene.stepSettings.velocityIterations;
    this.positionIterations = scene.stepSettings.positionIterations;
    // Ids: scene bodies, fixtures (per body in creation order) and joints in file order, then what
    // the script creates, in the order it creates them.
    for (const b of scene.bodies) {
      b.SetUserData(this.bodies.length + 1);
      this.bodies.push(b);
      const list: b2Fixture[] = [];
      for (let f = b.GetFixtureList(); f !== null; f = f.GetNext()) list.unshift(f);
      for (const f of list) {
        f.m_userData = this.fixtures.length + 1;
        this.fixtures.push(f);
      }
    }
    for (const j of scene.joints) {
      j.SetUserData(this.joints.length + 1);
      this.joints.push(j);
    }
    if (Array.isArray(script.disableFixtures)) this.disabledFixtures.push(...script.disableFixtures);
    if (script.listener === true || this.disabledFixtures.length > 0) {
      this.world.SetContactListener(new ReplayListener(this));
    }
  }

  fixtureId(f: b2Fixture): number {
    return (f.m_userData as number) - 1;
  }

  ref<T>(list: (T | null)[], o: J, k: string): T {
    const i = num(o, k, -1);
    const x = list[i];
    if (x === undefined || x === null) throw new Error(`script refers to a missing ${k} ${i}`);
    return x;
  }

  readShape(f: J): b2Shape {
    if (has(f, 'circle')) {
      const s = new b2CircleShape();
      s.m_radius = num(f.circle, 'radius');
      s.m_p.Assign(vecOf(f.circle, 'center'));
      return s;
    }
    if (has(f, 'edge')) {
      const e = f.edge;
      const s = new b2EdgeShape();
      s.m_vertex1.Assign(vecOf(e, 'vertex1'));
      s.m_vertex2.Assign(vecOf(e, 'vertex2'));
      s.m_hasVertex0 = bool(e, 'hasVertex0');
      s.m_hasVertex3 = bool(e, 'hasVertex3');
      if (s.m_hasVertex0) s.m_vertex0.Assign(vecOf(e, 'vertex0'));
      if (s.m_hasVertex3) s.m_vertex3.Assign(vecOf(e, 'vertex3'));
      return s;
    }
    if (has(f, 'chain')) {
      const vs = verts(f.chain, 'vertices');
      const s = new b2ChainShape();
      s.CreateChain(vs, vs.length);
      if (bool(f.chain, 'hasPrevVertex')) s.SetPrevVertex(vecOf(f.chain, 'prevVertex'));
      if (bool(f.chain, 'hasNextVertex')) s.SetNextVertex(vecOf(f.chain, 'nextVertex'));
      return s;
    }
    if (has(f, 'loop')) {
      const vs = verts(f.loop, 'vertices');
      const s = new b2ChainShape();
      s.CreateLoop(vs, vs.length);
      return s;
    }
    const p = f.polygon;
    const s = new b2PolygonShape();
    if (has(p, 'box')) {
      const box = p.box;
      if (has(box, 'center')) s.SetAsBox(num(box, 'hx'), num(box, 'hy'), vecOf(box, 'center'), num(box, 'angle'));
      else s.SetAsBox(num(box, 'hx'), num(box, 'hy'));
      return s;
    }
    const vs = verts(p, 'vertices');
    if (vs.length === 2) {
      const e = new b2EdgeShape();
      e.Set(vs[0], vs[1]);
      return e;
    }
    s.Set(vs, vs.length);
    return s;
  }

  createFixture(body: b2Body, f: J): void {
    const def = new b2FixtureDef();
    def.friction = num(f, 'friction');
    def.restitution = num(f, 'restitution');
    def.density = num(f, 'density');
    def.isSensor = bool(f, 'sensor');
    def.filter.categoryBits = num(f, 'filter-categoryBits', 1);
    def.filter.maskBits = num(f, 'filter-maskBits', 0xffff);
    def.filter.groupIndex = num(f, 'filter-groupIndex', 0);
    def.shape = this.readShape(f);
    def.userData = this.fixtures.length + 1;
    this.fixtures.push(body.CreateFixture(def));
  }

  createBody(o: J): void {
    const def = new b2BodyDef();
    def.type = num(o, 'type') as b2BodyType;
    def.position.Assign(vecOf(o, 'position'));
    def.angle = num(o, 'angle');
    def.linearVelocity.Assign(vecOf(o, 'linearVelocity'));
    def.angularVelocity = num(o, 'angularVelocity');
    def.linearDamping = num(o, 'linearDamping');
    def.angularDamping = num(o, 'angularDamping');
    def.gravityScale = num(o, 'gravityScale', 1);
    def.bullet = bool(o, 'bullet');
    def.allowSleep = bool(o, 'allowSleep', true);
    def.awake = bool(o, 'awake');
    def.active = bool(o, 'active', true);
    def.fixedRotation = bool(o, 'fixedRotation');
    const body = this.world.CreateBody(def);
    body.SetUserData(this.bodies.length + 1);
    this.bodies.push(body);
    for (const f of o.fixture ?? []) this.createFixture(body, f);
    if (has(o, 'massData-mass')) {
      const md = new b2MassData();
      md.mass = num(o, 'massData-mass');
      md.center.Assign(vecOf(o, 'massData-center'));
      md.I = num(o, 'massData-I');
      body.SetMassData(md);
    }
  }

  /**
   * A joint def of the scene format. With `init` the def is first filled by its Initialize (the
   * world anchors and axis named in the script), and only the fields present are assigned after.
   */
  createJoint(o: J, init: boolean): void {
    const bA = this.ref(this.bodies, o, 'bodyA');
    const bB = this.ref(this.bodies, o, 'bodyB');
    const N = (d: J, field: string, key: string): void => {
      if (!init || has(o, key)) d[field] = num(o, key);
    };
    const B = (d: J, field: string, key: string): void => {
      if (!init || has(o, key)) d[field] = bool(o, key);
    };
    const V = (d: J, field: string, key: string): void => {
      if (!init || has(o, key)) d[field].Assign(vecOf(o, key));
    };
    let d: J;
    switch (o.type as string) {
      case 'revolute':
        d = new b2RevoluteJointDef();
        if (init) d.Initialize(bA, bB, vecOf(o, 'anchor'));
        V(d, 'localAnchorA', 'anchorA');
        V(d, 'localAnchorB', 'anchorB');
        N(d, 'referenceAngle', 'refAngle');
        B(d, 'enableLimit', 'enableLimit');
        N(d, 'lowerAngle', 'lowerLimit');
        N(d, 'upperAngle', 'upperLimit');
        B(d, 'enableMotor', 'enableMotor');
        N(d, 'motorSpeed', 'motorSpeed');
        N(d, 'maxMotorTorque', 'maxMotorTorque');
        break;
      case 'prismatic':
        d = new b2PrismaticJointDef();
        if (init) d.Initialize(bA, bB, vecOf(o, 'anchor'), vecOf(o, 'axis'));
        V(d, 'localAnchorA', 'anchorA');
        V(d, 'localAnchorB', 'anchorB');
        V(d, 'localAxisA', 'localAxisA');
        N(d, 'referenceAngle', 'refAngle');
        B(d, 'enableLimit', 'enableLimit');
        N(d, 'lowerTranslation', 'lowerLimit');
        N(d, 'upperTranslation', 'upperLimit');
        B(d, 'enableMotor', 'enableMotor');
        N(d, 'motorSpeed', 'motorSpeed');
        N(d, 'maxMotorForce', 'maxMotorForce');
        break;
      case 'distance':
        d = new b2DistanceJointDef();
        if (init) d.Initialize(bA, bB, vecOf(o, 'worldAnchorA'), vecOf(o, 'worldAnchorB'));
        V(d, 'localAnchorA', 'anchorA');
        V(d, 'localAnchorB', 'anchorB');
        N(d, 'length', 'length');
        N(d, 'frequencyHz', 'frequency');
        N(d, 'dampingRatio', 'dampingRatio');
        break;
      case 'pulley':
        d = new b2PulleyJointDef();
        if (init) {
          d.Initialize(
            bA,
            bB,
            vecOf(o, 'worldGroundAnchorA'),
            vecOf(o, 'worldGroundAnchorB'),
            vecOf(o, 'worldAnchorA'),
            vecOf(o, 'worldAnchorB'),
            num(o, 'initRatio'),
          );
        }
        V(d, 'groundAnchorA', 'groundAnchorA');
        V(d, 'groundAnchorB', 'groundAnchorB');
        V(d, 'localAnchorA', 'anchorA');
        V(d, 'localAnchorB', 'anchorB');
        N(d, 'lengthA', 'lengthA');
        N(d, 'lengthB', 'lengthB');
        N(d, 'ratio', 'ratio');
        break;
      case 'mouse':
        d = new b2MouseJointDef();
        d.target.Assign(vecOf(o, 'target'));
        d.maxForce = num(o, 'maxForce');
        d.frequencyHz = num(o, 'frequency', 5);
        d.dampingRatio = num(o, 'dampingRatio', 0.7);
        break;
      case 'gear':
        d = new b2GearJointDef();
        d.joint1 = this.ref(this.joints, o, 'joint1');
        d.joint2 = this.ref(this.joints, o, 'joint2');
        d.ratio = num(o, 'ratio');
        break;
      case 'wheel':
        d = new b2WheelJointDef();
        if (init) d.Initialize(bA, bB, vecOf(o, 'anchor'), vecOf(o, 'axis'));
        V(d, 'localAnchorA', 'anchorA');
        V(d, 'localAnchorB', 'anchorB');
        V(d, 'localAxisA', 'localAxisA');
        B(d, 'enableMotor', 'enableMotor');
        N(d, 'motorSpeed', 'motorSpeed');
        N(d, 'maxMotorTorque', 'maxMotorTorque');
        N(d, 'frequencyHz', 'springFrequency');
        N(d, 'dampingRatio', 'springDampingRatio');
        break;
      case 'weld':
        d = new b2WeldJointDef();
        if (init) d.Initialize(bA, bB, vecOf(o, 'anchor'));
        V(d, 'localAnchorA', 'anchorA');
        V(d, 'localAnchorB', 'anchorB');
        N(d, 'referenceAngle', 'refAngle');
        N(d, 'frequencyHz', 'frequency');
        N(d, 'dampingRatio', 'dampingRatio');
        break;
      case 'friction':
        d = new b2FrictionJointDef();
        if (init) d.Initialize(bA, bB, vecOf(o, 'anchor'));
        V(d, 'localAnchorA', 'anchorA');
        V(d, 'localAnchorB', 'anchorB');
        N(d, 'maxForce', 'maxForce');
        N(d, 'maxTorque', 'maxTorque');
        break;
      case 'rope':
        d = new b2RopeJointDef();
        V(d, 'localAnchorA', 'anchorA');
        V(d, 'localAnchorB', 'anchorB');
        N(d, 'maxLength', 'maxLength');
        break;
      default:
        throw new Error(`script: unknown joint type ${String(o.type)}`);
    }
    d.bodyA = bA;
    d.bodyB = bB;
    d.collideConnected = bool(o, 'collideConnected');
    const joint = this.world.CreateJoint(d);
    joint.SetUserData(this.joints.length + 1);
    this.joints.push(joint);
  }

  forgetJoint(j: b2Joint): void {
    for (let i = 0; i < this.joints.length; ++i) if (this.joints[i] === j) this.joints[i] = null;
  }

  destroyBody(b: b2Body): void {
    for (let je = b.GetJointList(); je !== null; je = je.next) this.forgetJoint(je.joint);
    for (let f = b.GetFixtureList(); f !== null; f = f.GetNext()) this.fixtures[this.fixtureId(f)] = null;
    for (let i = 0; i < this.bodies.length; ++i) if (this.bodies[i] === b) this.bodies[i] = null;
    this.world.DestroyBody(b);
  }

  jointCall(j: b2Joint, o: J): void {
    const m: string = o.method;
    const args: J[] = o.args ?? [];
    const a0 = typeof args[0] === 'number' ? args[0] : 0;
    const a1 = typeof args[1] === 'number' ? args[1] : 0;
    const b0 = typeof args[0] === 'boolean' ? args[0] : false;
    const t = j.GetType();
    const fail = (): never => {
      throw new Error(`script: no joint method ${m} on joint type ${t}`);
    };
    switch (t) {
      case b2JointType.e_revoluteJoint: {
        const r = j as b2RevoluteJoint;
        if (m === 'EnableLimit') r.EnableLimit(b0);
        else if (m === 'SetLimits') r.SetLimits(a0, a1);
        else if (m === 'EnableMotor') r.EnableMotor(b0);
        else if (m === 'SetMotorSpeed') r.SetMotorSpeed(a0);
        else if (m === 'SetMaxMotorTorque') r.SetMaxMotorTorque(a0);
        else fail();
        break;
      }
      case b2JointType.e_prismaticJoint: {
        const r = j as b2PrismaticJoint;
        if (m === 'EnableLimit') r.EnableLimit(b0);
        else if (m === 'SetLimits') r.SetLimits(a0, a1);
        else if (m === 'EnableMotor') r.EnableMotor(b0);
        else if (m === 'SetMotorSpeed') r.SetMotorSpeed(a0);
        else if (m === 'SetMaxMotorForce') r.SetMaxMotorForce(a0);
        else fail();
        break;
      }
      case b2JointType.e_wheelJoint: {
        const r = j as b2WheelJoint;
        if (m === 'EnableMotor') r.EnableMotor(b0);
        else if (m === 'SetMotorSpeed') r.SetMotorSpeed(a0);
        else if (m === 'SetMaxMotorTorque') r.SetMaxMotorTorque(a0);
        else if (m === 'SetSpringFrequencyHz') r.SetSpringFrequencyHz(a0);
        else if (m === 'SetSpringDampingRatio') r.SetSpringDampingRatio(a0);
        else fail();
        break;
      }
      case b2JointType.e_distanceJoint: {
        const r = j as b2DistanceJoint;
        if (m === 'SetLength') r.SetLength(a0);
        else if (m === 'SetFrequency') r.SetFrequency(a0);
        else if (m === 'SetDampingRatio') r.SetDampingRatio(a0);
        else fail();
        break;
      }
      case b2JointType.e_mouseJoint: {
        const r = j as b2MouseJoint;
        if (m === 'SetTarget') r.SetTarget(new b2Vec2(a0, a1));
        else if (m === 'SetMaxForce') r.SetMaxForce(a0);
        else if (m === 'SetFrequency') r.SetFrequency(a0);
        else if (m === 'SetDampingRatio') r.SetDampingRatio(a0);
        else fail();
        break;
      }
      case b2JointType.e_gearJoint:
        if (m === 'SetRatio') (j as b2GearJoint).SetRatio(a0);
        else fail();
        break;
      case b2JointType.e_weldJoint: {
        const r = j as b2WeldJoint;
        if (m === 'SetFrequency') r.SetFrequency(a0);
        else if (m === 'SetDampingRatio') r.SetDampingRatio(a0);
        else fail();
        break;
      }
      case b2JointType.e_frictionJoint: {
        const r = j as b2FrictionJoint;
        if (m === 'SetMaxForce') r.SetMaxForce(a0);
        else if (m === 'SetMaxTorque') r.SetMaxTorque(a0);
        else fail();
        break;
      }
      case b2JointType.e_ropeJoint:
        if (m === 'SetMaxLength') (j as b2RopeJoint).SetMaxLength(a0);
        else fail();
        break;
      default:
        fail();
    }
  }

  q(x: number | boolean): void {
    this.queries = fnv(this.queries, typeof x === 'boolean' ? (x ? 1 : 0) : x);
  }

  qv(v: { x: number; y: number }): void {
    this.q(v.x);
    this.q(v.y);
  }

  /** The API probe: world lists, body and fixture queries, shape functions, tree metrics. */
  probe(): void {
    const w = this.world;
    const bodyId = (b: b2Body): number => (b.GetUserData() as number) - 1;
    const jointId = (j: b2Joint): number => (j.GetUserData() as number) - 1;
    this.q(w.GetProxyCount());
    this.q(w.GetBodyCount());
    this.q(w.GetJointCount());
    this.q(w.GetContactCount());
    this.q(w.GetTreeHeight());
    this.q(w.GetTreeBalance());
    this.q(w.GetTreeQuality());
    const t = new b2Vec2();
    for (let b = w.GetBodyList(); b !== null; b = b.GetNext()) {
      this.q(bodyId(b));
      for (let f = b.GetFixtureList(); f !== null; f = f.GetNext()) this.q(this.fixtureId(f));
      for (let je = b.GetJointList(); je !== null; je = je.next) {
        this.q(jointId(je.joint));
        this.q(bodyId(je.other));
      }
      for (let ce = b.GetContactList(); ce !== null; ce = ce.next) {
        this.q(bodyId(ce.other));
        this.q(this.fixtureId(ce.contact.GetFixtureA()));
      }
      this.qv(b.GetWorldPoint(new b2Vec2(1, 2), t));
      this.qv(b.GetLocalPoint(new b2Vec2(3, -1), t));
      this.qv(b.GetWorldVector(new b2Vec2(0.5, -2), t));
      this.qv(b.GetLocalVector(new b2Vec2(-1, 0.25), t));
      this.qv(b.GetLinearVelocityFromWorldPoint(new b2Vec2(2, 3), t));
      this.qv(b.GetLinearVelocityFromLocalPoint(new b2Vec2(-1, 1), t));
      this.q(b.GetTransform().q.GetAngle());
      const md = new b2MassData();
      b.GetMassData(md);
      this.q(md.mass);
      this.qv(md.center);
      this.q(md.I);
      this.qv(b.GetLocalCenter());
      this.q(b.GetType());
      this.q(b.IsBullet());
      this.q(b.IsActive());
      this.q(b.IsFixedRotation());
      this.q(b.IsSleepingAllowed());
      this.q(b.GetLinearDamping());
      this.q(b.GetAngularDamping());
      this.q(b.GetGravityScale());
    }
    for (let j = w.GetJointList(); j !== null; j = j.GetNext()) {
      this.q(jointId(j));
      this.q(j.IsActive());
    }
    const wm = new b2WorldManifold();
    for (let c = w.GetContactList(); c !== null; c = c.GetNext()) {
      this.q(this.fixtureId(c.GetFixtureA()));
      this.q(this.fixtureId(c.GetFixtureB()));
      this.q(c.GetChildIndexA());
      this.q(c.GetChildIndexB());
      this.q(c.IsTouching());
      this.q(c.IsEnabled());
      const count = c.GetManifold().pointCount;
      this.q(count);
      if (count > 0) {
        c.GetWorldManifold(wm);
        this.qv(wm.normal);
        for (let i = 0; i < count; ++i) this.qv(wm.points[i]);
      }
    }
    for (const f of this.fixtures) {
      if (f === null) continue;
      const b = f.GetBody();
      const c = b.GetWorldCenter();
      this.q(f.TestPoint(c));
      this.q(f.TestPoint(new b2Vec2(c.x + 0.3, c.y + 0.1)));
      this.q(f.TestPoint(new b2Vec2(c.x + -1, c.y + 0.7)));
      const md = new b2MassData();
      f.GetMassData(md);
      this.q(md.mass);
      this.qv(md.center);
      this.q(md.I);
      const n = f.GetShape().GetChildCount();
      for (let i = 0; i < n; ++i) {
        const aabb = new b2AABB();
        f.GetShape().ComputeAABB(aabb, b.GetTransform(), i);
        this.qv(aabb.lowerBound);
        this.qv(aabb.upperBound);
        if (b.IsActive()) {
          const fa = f.GetAABB(i);
          this.qv(fa.lowerBound);
          this.qv(fa.upperBound);
        }
        const mid = aabb.GetCenter(new b2Vec2());
        const input = new b2RayCastInput();
        input.p1.Set(mid.x + -3, mid.y + 2.5);
        input.p2.Set(mid.x + 2, mid.y + -1.5);
        input.maxFraction = 1;
        const out = new b2RayCastOutput();
        let hit = f.RayCast(out, input, i);
        this.q(hit);
        if (hit) {
          this.q(out.fraction);
          this.qv(out.normal);
        }
        input.p1.Set(mid.x, mid.y);
        input.p2.Set(mid.x + 0, mid.y + 4);
        input.maxFraction = 0.8;
        hit = f.RayCast(out, input, i);
        this.q(hit);
        if (hit) {
          this.q(out.fraction);
          this.qv(out.normal);
        }
        const in2 = new b2RayCastInput();
        in2.p1.Set(mid.x + -5, mid.y + -1);
        in2.p2.Set(mid.x + 5, mid.y + 1);
        in2.maxFraction = 1;
        hit = aabb.RayCast(out, in2);
        this.q(hit);
        if (hit) {
          this.q(out.fraction);
          this.qv(out.normal);
        }
      }
    }
  }

  apply(a: J): void {
    const body = (): b2Body => this.ref(this.bodies, a, 'body');
    const fixture = (): b2Fixture => this.ref(this.fixtures, a, 'fixture');
    const w = this.world;
    switch (a.op as string) {
      case 'setTransform':
        body().SetTransform(vecOf(a, 'position'), num(a, 'angle'));
        break;
      case 'setLinearVelocity':
        body().SetLinearVelocity(vecOf(a, 'v'));
        break;
      case 'setAngularVelocity':
        body().SetAngularVelocity(num(a, 'w'));
        break;
      case 'applyForce':
        body().ApplyForce(vecOf(a, 'force'), vecOf(a, 'point'));
        break;
      case 'applyForceToCenter':
        body().ApplyForceToCenter(vecOf(a, 'force'));
        break;
      case 'applyTorque':
        body().ApplyTorque(num(a, 'torque'));
        break;
      case 'applyLinearImpulse':
        body().ApplyLinearImpulse(vecOf(a, 'impulse'), vecOf(a, 'point'));
        break;
      case 'applyAngularImpulse':
        body().ApplyAngularImpulse(num(a, 'impulse'));
        break;
      case 'setType':
        body().SetType(num(a, 'type') as b2BodyType);
        break;
      case 'setActive':
        body().SetActive(bool(a, 'flag'));
        break;
      case 'setAwake':
        body().SetAwake(bool(a, 'flag'));
        break;
      case 'setBullet':
        body().SetBullet(bool(a, 'flag'));
        break;
      case 'setFixedRotation':
        body().SetFixedRotation(bool(a, 'flag'));
        break;
      case 'setSleepingAllowed':
        body().SetSleepingAllowed(bool(a, 'flag'));
        break;
      case 'setGravityScale':
        body().SetGravityScale(num(a, 'scale'));
        break;
      case 'setLinearDamping':
        body().SetLinearDamping(num(a, 'damping'));
        break;
      case 'setAngularDamping':
        body().SetAngularDamping(num(a, 'damping'));
        break;
      case 'setMassData': {
        const md = new b2MassData();
        md.mass = num(a, 'mass');
        md.center.Assign(vecOf(a, 'center'));
        md.I = num(a, 'I');
        body().SetMassData(md);
        break;
      }
      case 'resetMassData':
        body().ResetMassData();
        break;
      case 'destroyBody':
        this.destroyBody(body());
        break;
      case 'createBody':
        this.createBody(a.def);
        break;
      case 'createFixture':
        this.createFixture(body(), a.def);
        break;
      case 'destroyFixture': {
        const f = fixture();
        this.fixtures[this.fixtureId(f)] = null;
        f.GetBody().DestroyFixture(f);
        break;
      }
      case 'setFilterData': {
        const filter = new b2Filter();
        filter.categoryBits = num(a, 'categoryBits', 1);
        filter.maskBits = num(a, 'maskBits', 0xffff);
        filter.groupIndex = num(a, 'groupIndex', 0);
        fixture().SetFilterData(filter);
        break;
      }
      case 'refilter':
        fixture().Refilter();
        break;
      case 'setSensor':
        fixture().SetSensor(bool(a, 'flag'));
        break;
      case 'setDensity':
        fixture().SetDensity(num(a, 'density'));
        break;
      case 'setFriction':
        fixture().SetFriction(num(a, 'friction'));
        break;
      case 'setRestitution':
        fixture().SetRestitution(num(a, 'restitution'));
        break;
      case 'createJoint':
        this.createJoint(a.def, false);
        break;
      case 'createJointInit':
        this.createJoint(a.def, true);
        break;
      case 'destroyJoint': {
        const j = this.ref(this.joints, a, 'joint');
        this.forgetJoint(j);
        w.DestroyJoint(j);
        break;
      }
      case 'jointCall':
        this.jointCall(this.ref(this.joints, a, 'joint'), a);
        break;
      case 'setGravity':
        w.SetGravity(vecOf(a, 'gravity'));
        break;
      case 'setWarmStarting':
        w.SetWarmStarting(bool(a, 'flag'));
        break;
      case 'setContinuousPhysics':
        w.SetContinuousPhysics(bool(a, 'flag'));
        break;
      case 'setSubStepping':
        w.SetSubStepping(bool(a, 'flag'));
        break;
      case 'setAllowSleeping':
        w.SetAllowSleeping(bool(a, 'flag'));
        break;
      case 'setAutoClearForces':
        w.SetAutoClearForces(bool(a, 'flag'));
        break;
      case 'clearForces':
        w.ClearForces();
        break;
      case 'rayCast': {
        const mode = a.mode ?? 'closest';
        w.RayCast(new ReplayRayCast(this, mode === 'closest' ? 0 : mode === 'all' ? 1 : 2), vecOf(a, 'p1'), vecOf(a, 'p2'));
        this.q(-1);
        break;
      }
      case 'queryAABB': {
        const aabb = new b2AABB();
        aabb.lowerBound.Assign(vecOf(a, 'lower'));
        aabb.upperBound.Assign(vecOf(a, 'upper'));
        w.QueryAABB(new ReplayQuery(this), aabb);
        this.q(-2);
        break;
      }
      case 'probe':
        this.probe();
        break;
      case 'step':
        w.Step(num(a, 'dt'), num(a, 'vel'), num(a, 'pos'));
        break;
      default:
        throw new Error(`script: unknown op ${String(a.op)}`);
    }
  }

  bodiesDigest(): number {
    let h = FNV0;
    const v = new b2Vec2();
    for (const b of this.bodies) {
      if (b === null) continue;
      h = fnv(h, b.GetPosition().x);
      h = fnv(h, b.GetPosition().y);
      h = fnv(h, b.GetAngle());
      b.GetLinearVelocity(v);
      h = fnv(h, v.x);
      h = fnv(h, v.y);
      h = fnv(h, b.GetAngularVelocity());
    }
    return h;
  }

  auxDigest(): number {
    let h = FNV0;
    let touching = 0;
    for (let c = this.world.GetContactList(); c !== null; c = c.GetNext()) if (c.IsTouching()) ++touching;
    h = fnv(h, this.world.GetContactCount());
    h = fnv(h, touching);
    h = fnv(h, this.world.GetProxyCount());
    for (const b of this.bodies) {
      if (b === null) continue;
      h = fnv(h, b.IsAwake() ? 1 : 0);
      h = fnv(h, b.GetMass());
      h = fnv(h, b.GetInertia());
      h = fnv(h, b.GetWorldCenter().x);
      h = fnv(h, b.GetWorldCenter().y);
    }
    return h;
  }

  jointsDigest(): number {
    let h = FNV0;
    // -0 and +0 hash alike here: before a joint's first solve the C++ reads fields it has not
    // initialized yet (the pulley's m_uB), whose zero products may carry either sign.
    const jh = (x: number): void => {
      h = fnv(h, x === 0 ? 0 : x);
    };
    const inv_dt = this.hz;
    const v = new b2Vec2();
    for (const j of this.joints) {
      if (j === null) continue;
      j.GetReactionForce(inv_dt, v);
      jh(v.x);
      jh(v.y);
      jh(j.GetReactionTorque(inv_dt));
      j.GetAnchorA(v);
      jh(v.x);
      jh(v.y);
      j.GetAnchorB(v);
      jh(v.x);
      jh(v.y);
      switch (j.GetType()) {
        case b2JointType.e_revoluteJoint: {
          const r = j as b2RevoluteJoint;
          jh(r.GetJointAngle());
          jh(r.GetJointSpeed());
          jh(r.GetMotorTorque(inv_dt));
          break;
        }
        case b2JointType.e_prismaticJoint: {
          const r = j as b2PrismaticJoint;
          jh(r.GetJointTranslation());
          jh(r.GetJointSpeed());
          jh(r.GetMotorForce(inv_dt));
          break;
        }
        case b2JointType.e_wheelJoint: {
          const r = j as b2WheelJoint;
          jh(r.GetJointTranslation());
          jh(r.GetJointSpeed());
          jh(r.GetMotorTorque(inv_dt));
          break;
        }
        case b2JointType.e_pulleyJoint: {
          const r = j as b2PulleyJoint;
          jh(r.GetLengthA());
          jh(r.GetLengthB());
          break;
        }
        default:
          break;
      }
    }
    return h;
  }

  row(): string {
    return [this.bodiesDigest(), this.auxDigest(), this.jointsDigest(), this.events, this.queries].map(hex).join(' ');
  }
}

class ReplayListener extends b2ContactListener {
  private readonly wm = new b2WorldManifold();
  constructor(private readonly r: Replay) {
    super();
  }
  private e(x: number): void {
    this.r.events = fnv(this.r.events, x);
  }
  override BeginContact(c: b2Contact): void {
    this.e(1);
    this.e(this.r.fixtureId(c.GetFixtureA()));
    this.e(this.r.fixtureId(c.GetFixtureB()));
    this.e(c.GetChildIndexA());
    this.e(c.GetChildIndexB());
  }
  override EndContact(c: b2Contact): void {
    this.e(2);
    this.e(this.r.fixtureId(c.GetFixtureA()));
    this.e(this.r.fixtureId(c.GetFixtureB()));
  }
  override PreSolve(c: b2Contact, old: b2Manifold): void {
    this.e(3);
    this.e(this.r.fixtureId(c.GetFixtureA()));
    this.e(this.r.fixtureId(c.GetFixtureB()));
    this.e(old.pointCount);
    const m = c.GetManifold();
    this.e(m.pointCount);
    this.e(m.type);
    this.e(m.localNormal.x);
    this.e(m.localNormal.y);
    for (let i = 0; i < m.pointCount; ++i) {
      this.e(m.points[i].localPoint.x);
      this.e(m.points[i].localPoint.y);
      this.e(m.points[i].id.key);
    }
    if (m.pointCount > 0) {
      c.GetWorldManifold(this.wm);
      this.e(this.wm.normal.x);
      this.e(this.wm.normal.y);
      for (let i = 0; i < m.pointCount; ++i) {
        this.e(this.wm.points[i].x);
        this.e(this.wm.points[i].y);
      }
    }
    for (const id of this.r.disabledFixtures) {
      if (this.r.fixtureId(c.GetFixtureA()) === id || this.r.fixtureId(c.GetFixtureB()) === id) c.SetEnabled(false);
    }
  }
  override PostSolve(c: b2Contact, impulse: b2ContactImpulse): void {
    this.e(4);
    this.e(this.r.fixtureId(c.GetFixtureA()));
    this.e(this.r.fixtureId(c.GetFixtureB()));
    // Only the first point: when the two constraints of a manifold are redundant the solver keeps
    // one, and the C++ leaves the second impulse uninitialized.
    if (c.GetManifold().pointCount > 0) {
      this.e(impulse.normalImpulses[0]);
      this.e(impulse.tangentImpulses[0]);
    }
  }
}

class ReplayRayCast extends b2RayCastCallback {
  constructor(
    private readonly r: Replay,
    private readonly mode: number,
  ) {
    super();
  }
  override ReportFixture(f: b2Fixture, p: b2Vec2, n: b2Vec2, fraction: number): number {
    this.r.q(this.r.fixtureId(f));
    this.r.qv(p);
    this.r.qv(n);
    this.r.q(fraction);
    return this.mode === 0 ? fraction : this.mode === 1 ? 1 : 0;
  }
}

class ReplayQuery extends b2QueryCallback {
  constructor(private readonly r: Replay) {
    super();
  }
  override ReportFixture(f: b2Fixture): boolean {
    this.r.q(this.r.fixtureId(f));
    return true;
  }
}

export function readReferenceExpectation(name: string): ReferenceExpectation {
  return JSON.parse(readFileSync(path.join(referenceScenesDir, `${name}.expected.json`), 'utf8')) as ReferenceExpectation;
}

/**
 * Load `name`, run its script for the expected number of steps and compare every row. Returns
 * null when all agree, else the first differing step and digest.
 */
export function runReferenceCase(name: string): string | null {
  const sceneText = readFileSync(path.join(referenceScenesDir, `${name}.scene.json`), 'utf8');
  const script = JSON.parse(readFileSync(path.join(referenceScenesDir, `${name}.script.json`), 'utf8')) as J;
  const expected = readReferenceExpectation(name);
  const replay = new Replay(sceneText, script);
  const actions: J[] = script.actions ?? [];
  const byStep = new Map<number, J[]>();
  for (const a of actions) {
    const list = byStep.get(a.step) ?? [];
    list.push(a);
    byStep.set(a.step, list);
  }
  const dt = 1 / replay.hz;
  let k = 0;
  try {
    for (; k <= expected.steps; ++k) {
      if (k > 0) replay.world.Step(dt, replay.velocityIterations, replay.positionIterations);
      for (const a of byStep.get(k) ?? []) replay.apply(a);
      const got = replay.row();
      const want = expected.rows[k];
      if (got === want) continue;
      const g = got.split(' ');
      const e = want.split(' ');
      const differing = kReferenceColumns.filter((_, i) => g[i] !== e[i]);
      return `${name}: step ${k} differs in ${differing.join(', ')} (got ${got}, expected ${want})`;
    }
  } catch (err) {
    return `${name}: threw at step ${k}: ${err instanceof Error ? (err.stack ?? err.message) : String(err)}`;
  }
  return null;
}
