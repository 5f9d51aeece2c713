/*
 * Reading b2dJson scenes (the JSON written by R.U.B.E. and iforce2d's b2dJson) into a new world.
 *
 * Objects are created in file order, which fixes proxy ids and therefore contact and solver order:
 * the world, then each body (def, its fixtures in order, then SetMassData when `massData-mass` is
 * present), then each joint with its fields assigned directly to the def. Optional fields that are
 * missing take b2dJson's defaults, which are not always Box2D's: friction, restitution and density
 * 0, `awake` false, and the world flags false. Beyond b2dJson, a polygon may carry
 * `box: {hx, hy, center?, angle?}`, built with SetAsBox (which differs from Set in the last bits).
 *
 * Every value is checked, with the engine's rules (b2ArgumentError) applied to the JSON fields;
 * a bad one throws a b2dJsonError naming its JSON path and the rule it broke. The world is built
 * fresh, so on error nothing reaches a world the caller holds. A `webphysicsState` member (the
 * solver-state extension written by b2dJsonWrite(world, { solverState: true }), see b2dJsonState)
 * is applied last, so the world continues exactly where the written one was.
 *
 * With `{ skipUnknown: true }` the reader leaves out, instead of rejecting the document, what it
 * cannot build, as iforce2d's own loaders do: joints of a type Box2D 2.2.1 does not have (a
 * Box2D 2.3 motor joint...), fixtures with no shape it knows, and gear joints coupling a joint
 * left out. Each is listed in the scene's `skipped`, with its JSON path and the reason.
 */

import { b2ArgumentError } from '../common/b2ArgumentError';
import { b2Vec2 } from '../common/b2Math';
import { b2_epsilon, b2_maxPolygonVertices } from '../common/b2Settings';
import { b2ChainShape } from '../collision/shapes/b2ChainShape';
import { b2CircleShape } from '../collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../collision/shapes/b2PolygonShape';
import { b2MassData } from '../collision/shapes/b2Shape';
import type { b2Shape } from '../collision/shapes/b2Shape';
import { b2BodyDef } from '../dynamics/b2Body';
import type { b2Body } from '../dynamics/b2Body';
import { b2FixtureDef } from '../dynamics/b2Fixture';
import { b2World } from '../dynamics/b2World';
import { b2DistanceJointDef } from '../dynamics/joints/b2DistanceJoint';
import { b2FrictionJointDef } from '../dynamics/joints/b2FrictionJoint';
import { b2GearJointDef } from '../dynamics/joints/b2GearJoint';
import { b2JointType } from '../dynamics/joints/b2Joint';
import type { b2Joint, b2JointDef } from '../dynamics/joints/b2Joint';
import { b2MouseJointDef } from '../dynamics/joints/b2MouseJoint';
import type { b2MouseJoint } from '../dynamics/joints/b2MouseJoint';
import { b2PrismaticJointDef } from '../dynamics/joints/b2PrismaticJoint';
import { b2PulleyJointDef } from '../dynamics/joints/b2PulleyJoint';
import { b2RevoluteJointDef } from '../dynamics/joints/b2RevoluteJoint';
import { b2RopeJointDef } from '../dynamics/joints/b2RopeJoint';
import { b2WeldJointDef } from '../dynamics/joints/b2WeldJoint';
import { b2WheelJointDef } from '../dynamics/joints/b2WheelJoint';
import {
  b2dJsonBodyRecipe,
  b2dJsonBoxRecipe,
  b2dJsonJointRecipe,
  b2dJsonRecordBody,
  b2dJsonRecordBox,
  b2dJsonRecordJoint,
  b2dJsonSealBody,
} from './b2dJsonRecipes';
import { b2dJsonError, b2dJsonImage, b2dJsonScene, b2dJson_defaultStepSettings } from './b2dJsonScene';
import type { b2dJsonReadOptions } from './b2dJsonScene';
import { b2dJsonReadState, b2dJson_stateKey } from './b2dJsonState';
import type { b2dJsonColor, b2dJsonCustomProperty, b2dJsonItem, b2dJsonObject, b2dJsonValue } from './b2dJsonScene';

const kJointTypes = 'revolute, prismatic, distance, pulley, mouse, gear, wheel, weld, friction or rope';
const kShapeKeys = ['circle', 'edge', 'chain', 'loop', 'polygon'] as const;
const kCustomValueKeys = ['int', 'float', 'string', 'vec2', 'bool', 'color'] as const;

// Paths

function keyPath(path: string, key: string): string {
  return path === '' ? key : `${path}.${key}`;
}

function indexPath(path: string, index: number): string {
  return `${path}[${index}]`;
}

function fail(path: string, rule: string): never {
  throw new b2dJsonError(path === '' ? '(root)' : path, rule);
}

function describeValue(value: unknown): string {
  if (value === undefined) return 'nothing (the field is missing)';
  if (value === null) return 'null';
  if (Array.isArray(value)) return 'an array';
  if (typeof value === 'object') return 'an object';
  if (typeof value === 'string') {
    return `the string ${JSON.stringify(value.length > 40 ? `${value.slice(0, 40)}...` : value)}`;
  }
  return `${typeof value} ${Object.is(value, -0) ? '-0' : String(value)}`;
}

/**
 * Run an engine call, reporting its b2ArgumentError (or a Box2D assertion) as a b2dJsonError at
 * `path`: `rejected by b2PolygonShape.Set: vertices[2] makes the polygon non-convex (...)`.
 */
function guard<T>(path: string, create: () => T): T {
  try {
    return create();
  } catch (e) {
    if (e instanceof b2dJsonError) throw e;
    if (e instanceof b2ArgumentError) return fail(path, `rejected by ${e.message}`);
    return fail(path, `rejected by Box2D (${e instanceof Error ? e.message : String(e)})`);
  }
}

// Values

const s_hexFloat = new DataView(new ArrayBuffer(4));

function isObject(value: unknown): value is b2dJsonObject {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

function member(o: b2dJsonObject, key: string): b2dJsonValue | undefined {
  // null counts as missing, as in b2dJson (Json::Value::isNull).
  return Object.hasOwn(o, key) && o[key] !== null ? o[key] : undefined;
}

function asObject(value: unknown, path: string): b2dJsonObject {
  if (!isObject(value)) fail(path, `expected an object, got ${describeValue(value)}`);
  return value;
}

function asArray(value: unknown, path: string): b2dJsonValue[] {
  if (!Array.isArray(value)) fail(path, `expected an array, got ${describeValue(value)}`);
  return value as b2dJsonValue[];
}

/** A finite number, or b2dJson's binary float: the 8 hex digits of an IEEE float32. */
function asNumber(value: unknown, path: string): number {
  if (typeof value === 'number' && Number.isFinite(value)) return value;
  if (typeof value === 'string' && /^[0-9A-Fa-f]{8}$/.test(value)) {
    s_hexFloat.setUint32(0, parseInt(value, 16));
    const f = s_hexFloat.getFloat32(0);
    if (Number.isFinite(f)) return f;
  }
  return fail(path, `expected a finite number, got ${describeValue(value)}`);
}

function asInteger(value: unknown, path: string, min: number, max: number): number {
  if (typeof value !== 'number' || !Number.isInteger(value) || value < min || value > max) {
    fail(path, `expected an integer in [${min}, ${max}], got ${describeValue(value)}`);
  }
  return value;
}

function optNumber(o: b2dJsonObject, key: string, path: string, defaultValue: number): number {
  const value = member(o, key);
  return value === undefined ? defaultValue : asNumber(value, keyPath(path, key));
}

function optNonNegative(o: b2dJsonObject, key: string, path: string, defaultValue: number): number {
  const value = optNumber(o, key, path, defaultValue);
  if (!(value >= 0)) fail(keyPath(path, key), `expected a finite number >= 0, got ${value}`);
  return value;
}

function optPositive(o: b2dJsonObject, key: string, path: string, defaultValue: number): number {
  const value = optNumber(o, key, path, defaultValue);
  if (!(value > 0)) {
    const missing = member(o, key) === undefined ? ' (the field is missing and defaults to it)' : '';
    fail(keyPath(path, key), `expected a finite number > 0, got ${value}${missing}`);
  }
  return value;
}

function reqNumber(o: b2dJsonObject, key: string, path: string): number {
  const value = member(o, key);
  if (value === undefined) fail(keyPath(path, key), 'required field is missing');
  return asNumber(value, keyPath(path, key));
}

function reqPositive(o: b2dJsonObject, key: string, path: string): number {
  const value = reqNumber(o, key, path);
  if (!(value > 0)) fail(keyPath(path, key), `expected a finite number > 0, got ${value}`);
  return value;
}

/** A joint axis: the joint normalizes it, so it must not be zero. */
function checkAxis(path: string, key: string, axis: b2Vec2): void {
  if (!(axis.x * axis.x + axis.y * axis.y > 0)) fail(keyPath(path, key), 'expected a non-zero axis, got (0, 0)');
}

function optInteger(o: b2dJsonObject, key: string, path: string, defaultValue: number, min: number, max: number): number {
  const value = member(o, key);
  return value === undefined ? defaultValue : asInteger(value, keyPath(path, key), min, max);
}

function optBool(o: b2dJsonObject, key: string, path: string, defaultValue: boolean): boolean {
  const value = member(o, key);
  if (value === undefined) return defaultValue;
  if (typeof value !== 'boolean') fail(keyPath(path, key), `expected true or false, got ${describeValue(value)}`);
  return value;
}

function optString(o: b2dJsonObject, key: string, path: string): string {
  const value = member(o, key);
  if (value === undefined) return '';
  if (typeof value !== 'string') fail(keyPath(path, key), `expected a string, got ${describeValue(value)}`);
  return value;
}

function optArray(o: b2dJsonObject, key: string, path: string): b2dJsonValue[] {
  const value = member(o, key);
  return value === undefined ? [] : asArray(value, keyPath(path, key));
}

/** A vector: {x, y} (a missing coordinate is 0) or the number 0, b2dJson's zero vector. */
function asVec(value: unknown, path: string, out: b2Vec2): b2Vec2 {
  if (value === 0) return out.Set(0, 0);
  if (!isObject(value)) fail(path, `expected a vector {x, y} or 0, got ${describeValue(value)}`);
  return out.Set(optNumber(value, 'x', path, 0), optNumber(value, 'y', path, 0));
}

/** An optional vector; missing is the zero vector (b2dJson's default). */
function optVec(o: b2dJsonObject, key: string, path: string, out: b2Vec2): b2Vec2 {
  const value = member(o, key);
  return value === undefined ? out.Set(0, 0) : asVec(value, keyPath(path, key), out);
}

/** b2dJson's vertex list: {x: [...], y: [...]}, two arrays of equal length. */
function reqVertices(o: b2dJsonObject, key: string, path: string): b2Vec2[] {
  const p = keyPath(path, key);
  const value = member(o, key);
  if (value === undefined) fail(p, 'required field is missing');
  const list = asObject(value, p);
  const xs = asArray(member(list, 'x'), keyPath(p, 'x'));
  const ys = asArray(member(list, 'y'), keyPath(p, 'y'));
  if (xs.length !== ys.length) fail(p, `x has ${xs.length} entries but y has ${ys.length}`);
  const vertices: b2Vec2[] = [];
  for (let i = 0; i < xs.length; ++i) {
    vertices.push(new b2Vec2(asNumber(xs[i], indexPath(keyPath(p, 'x'), i)), asNumber(ys[i], indexPath(keyPath(p, 'y'), i))));
  }
  return vertices;
}

// Metadata

function readCustomProperty(value: unknown, path: string): b2dJsonCustomProperty {
  const o = asObject(value, path);
  const name = optString(o, 'name', path);
  const present = kCustomValueKeys.filter((k) => member(o, k) !== undefined);
  if (present.length !== 1) {
    const found = present.length === 0 ? 'none' : present.join(', ');
    fail(path, `expected exactly one value (${kCustomValueKeys.join(', ')}), found ${found}`);
  }
  const key = present[0];
  const p = keyPath(path, key);
  const v = member(o, key);
  switch (key) {
    case 'int':
      return { name, type: 'int', value: asInteger(v, p, -2147483648, 2147483647) };
    case 'float':
      return { name, type: 'float', value: asNumber(v, p) };
    case 'string':
      if (typeof v !== 'string') fail(p, `expected a string, got ${describeValue(v)}`);
      return { name, type: 'string', value: v };
    case 'vec2':
      return { name, type: 'vec2', value: asVec(v, p, new b2Vec2()) };
    case 'bool':
      if (typeof v !== 'boolean') fail(p, `expected true or false, got ${describeValue(v)}`);
      return { name, type: 'bool', value: v };
    case 'color': {
      const rgba = asArray(v, p);
      if (rgba.length !== 4) fail(p, `expected 4 components [r, g, b, a], got ${rgba.length}`);
      const color = rgba.map((c, i) => asInteger(c, indexPath(p, i), 0, 255)) as b2dJsonColor;
      return { name, type: 'color', value: color };
    }
  }
}

function readMetadata(scene: b2dJsonScene, item: b2dJsonItem, o: b2dJsonObject, path: string): void {
  scene.setName(item, optString(o, 'name', path));
  const properties = optArray(o, 'customProperties', path).map((v, i) => readCustomProperty(v, indexPath(keyPath(path, 'customProperties'), i)));
  scene.setCustomProperties(item, properties);
}

// Shapes

function readPolygon(o: b2dJsonObject, path: string): { shape: b2Shape; box: b2dJsonBoxRecipe | null } {
  const boxValue = member(o, 'box');
  // With a box the vertices are only there for other readers, but they must still be well formed.
  const hasVertices = boxValue === undefined || member(o, 'vertices') !== undefined;
  const vertices = hasVertices ? reqVertices(o, 'vertices', path) : [];
  if (boxValue !== undefined) {
    const boxPath = keyPath(path, 'box');
    const box = asObject(boxValue, boxPath);
    const hx = reqPositive(box, 'hx', boxPath);
    const hy = reqPositive(box, 'hy', boxPath);
    const polygon = new b2PolygonShape();
    if (member(box, 'center') === undefined) {
      guard(boxPath, () => polygon.SetAsBox(hx, hy));
      return { shape: polygon, box: new b2dJsonBoxRecipe(hx, hy, null, 0) };
    }
    const center = optVec(box, 'center', boxPath, new b2Vec2());
    const angle = optNumber(box, 'angle', boxPath, 0);
    guard(boxPath, () => polygon.SetAsBox(hx, hy, center, angle));
    return { shape: polygon, box: new b2dJsonBoxRecipe(hx, hy, center, angle) };
  }
  const count = vertices.length;
  if (count === 2) {
    // b2dJson turns a two-vertex polygon into an edge.
    const edge = new b2EdgeShape();
    guard(keyPath(path, 'vertices'), () => edge.Set(vertices[0], vertices[1]));
    return { shape: edge, box: null };
  }
  if (count < 3 || count > b2_maxPolygonVertices) {
    const rule = `a polygon needs 3 to ${b2_maxPolygonVertices} vertices (2 make an edge), got ${count}`;
    fail(keyPath(path, 'vertices'), rule);
  }
  const polygon = new b2PolygonShape();
  guard(keyPath(path, 'vertices'), () => polygon.Set(vertices, count));
  return { shape: polygon, box: null };
}

const kNoShape = `no shape: expected one of ${kShapeKeys.join(', ')}`;

function readShape(fixture: b2dJsonObject, path: string): { shape: b2Shape; box: b2dJsonBoxRecipe | null } {
  const present = kShapeKeys.filter((k) => member(fixture, k) !== undefined);
  if (present.length !== 1) {
    fail(path, present.length === 0 ? kNoShape : `more than one shape: ${present.join(', ')}`);
  }
  const key = present[0];
  const p = keyPath(path, key);
  const o = asObject(member(fixture, key), p);
  switch (key) {
    case 'circle': {
      const circle = new b2CircleShape();
      circle.m_radius = optNonNegative(o, 'radius', p, 0);
      optVec(o, 'center', p, circle.m_p);
      return { shape: circle, box: null };
    }
    case 'edge': {
      const edge = new b2EdgeShape();
      optVec(o, 'vertex1', p, edge.m_vertex1);
      optVec(o, 'vertex2', p, edge.m_vertex2);
      edge.m_hasVertex0 = optBool(o, 'hasVertex0', p, false);
      edge.m_hasVertex3 = optBool(o, 'hasVertex3', p, false);
      if (edge.m_hasVertex0) optVec(o, 'vertex0', p, edge.m_vertex0);
      if (edge.m_hasVertex3) optVec(o, 'vertex3', p, edge.m_vertex3);
      const v1 = edge.m_vertex1;
      const v2 = edge.m_vertex2;
      if (!((v2.x - v1.x) * (v2.x - v1.x) + (v2.y - v1.y) * (v2.y - v1.y) > b2_epsilon * b2_epsilon)) {
        fail(keyPath(p, 'vertex2'), 'coincides with vertex1 (an edge must be longer than b2_epsilon)');
      }
      return { shape: edge, box: null };
    }
    case 'chain': {
      const vertices = reqVertices(o, 'vertices', p);
      if (vertices.length < 2) {
        fail(keyPath(p, 'vertices'), `a chain needs at least 2 vertices, got ${vertices.length}`);
      }
      const chain = new b2ChainShape();
      guard(keyPath(p, 'vertices'), () => chain.CreateChain(vertices, vertices.length));
      if (optBool(o, 'hasPrevVertex', p, false)) chain.SetPrevVertex(optVec(o, 'prevVertex', p, new b2Vec2()));
      if (optBool(o, 'hasNextVertex', p, false)) chain.SetNextVertex(optVec(o, 'nextVertex', p, new b2Vec2()));
      return { shape: chain, box: null };
    }
    case 'loop': {
      // The format before chains had prev/next vertices (b2dJson r197).
      const vertices = reqVertices(o, 'vertices', p);
      if (vertices.length < 3) fail(keyPath(p, 'vertices'), `a loop needs at least 3 vertices, got ${vertices.length}`);
      const chain = new b2ChainShape();
      guard(keyPath(p, 'vertices'), () => chain.CreateLoop(vertices, vertices.length));
      return { shape: chain, box: null };
    }
    case 'polygon':
      return readPolygon(o, p);
  }
}

// Bodies and fixtures

/** The reader's state beyond the scene: its options, and the joints by file index (null: skipped). */
interface Reading {
  readonly scene: b2dJsonScene;
  readonly skipUnknown: boolean;
  readonly jointsInFile: (b2Joint | null)[];
}

/** Leave out an item the reader cannot build, when the options allow it; reject the document otherwise. */
function skip(reading: Reading, path: string, reason: string): null {
  if (!reading.skipUnknown) fail(path, reason);
  reading.scene.skipped.push({ path, reason });
  return null;
}

function readFixture(reading: Reading, body: b2Body, value: unknown, path: string): void {
  const scene = reading.scene;
  const o = asObject(value, path);
  if (kShapeKeys.every((k) => member(o, k) === undefined)) {
    skip(reading, path, kNoShape);
    return;
  }
  const def = new b2FixtureDef();
  def.friction = optNonNegative(o, 'friction', path, 0);
  def.restitution = optNonNegative(o, 'restitution', path, 0);
  def.density = optNonNegative(o, 'density', path, 0);
  def.isSensor = optBool(o, 'sensor', path, false);
  def.filter.categoryBits = optInteger(o, 'filter-categoryBits', path, 0x0001, 0, 0xffff);
  def.filter.maskBits = optInteger(o, 'filter-maskBits', path, 0xffff, 0, 0xffff);
  def.filter.groupIndex = optInteger(o, 'filter-groupIndex', path, 0, -32768, 32767);
  const { shape, box } = readShape(o, path);
  def.shape = shape;
  const fixture = guard(path, () => body.CreateFixture(def));
  // The fixture owns a clone of the shape; that clone is what the writer will see.
  if (box !== null) b2dJsonRecordBox(fixture.m_shape as b2PolygonShape, box);
  readMetadata(scene, fixture, o, path);
}

function readBody(reading: Reading, value: unknown, path: string): b2Body {
  const scene = reading.scene;
  const o = asObject(value, path);
  const def = new b2BodyDef();
  def.type = optInteger(o, 'type', path, 0, 0, 2);
  optVec(o, 'position', path, def.position);
  def.angle = optNumber(o, 'angle', path, 0);
  optVec(o, 'linearVelocity', path, def.linearVelocity);
  def.angularVelocity = optNumber(o, 'angularVelocity', path, 0);
  def.linearDamping = optNonNegative(o, 'linearDamping', path, 0);
  def.angularDamping = optNonNegative(o, 'angularDamping', path, 0);
  def.gravityScale = optNumber(o, 'gravityScale', path, 1);
  def.bullet = optBool(o, 'bullet', path, false);
  def.allowSleep = optBool(o, 'allowSleep', path, true);
  def.awake = optBool(o, 'awake', path, false);
  def.active = optBool(o, 'active', path, true);
  def.fixedRotation = optBool(o, 'fixedRotation', path, false);

  let massData: b2MassData | null = null;
  if (member(o, 'massData-mass') !== undefined) {
    massData = new b2MassData();
    massData.mass = optNumber(o, 'massData-mass', path, 0);
    optVec(o, 'massData-center', path, massData.center);
    massData.I = optNumber(o, 'massData-I', path, 0);
  }
  const fixtures = optArray(o, 'fixture', path);

  const body = guard(path, () => scene.world.CreateBody(def));
  const fixturesPath = keyPath(path, 'fixture');
  for (let i = 0; i < fixtures.length; ++i) {
    readFixture(reading, body, fixtures[i], indexPath(fixturesPath, i));
  }
  if (massData !== null) {
    const data = massData;
    guard(keyPath(path, 'massData-mass'), () => body.SetMassData(data));
  }
  b2dJsonRecordBody(body, new b2dJsonBodyRecipe(def.position.Clone(), def.angle, def.linearVelocity.Clone(), def.angularVelocity, massData));
  readMetadata(scene, body, o, path);
  return body;
}

// Joints

function bodyIndex(o: b2dJsonObject, key: string, path: string, bodies: readonly b2Body[]): b2Body {
  const p = keyPath(path, key);
  const value = member(o, key);
  if (value === undefined) fail(p, 'required field is missing');
  if (bodies.length === 0) fail(p, 'the scene has no bodies');
  return bodies[asInteger(value, p, 0, bodies.length - 1)];
}

/** The joint a gear couples, by its index in the file; null when that joint was skipped. */
function gearJointIndex(reading: Reading, o: b2dJsonObject, key: string, path: string): b2Joint | null {
  const joints = reading.jointsInFile;
  const p = keyPath(path, key);
  const value = member(o, key);
  if (value === undefined) fail(p, 'required field is missing');
  if (joints.length === 0) fail(p, 'a gear joint must come after the joints it couples, and none precede it');
  const index = asInteger(value, p, 0, joints.length - 1);
  const joint = joints[index];
  if (joint === null) return skip(reading, path, `${p} is joint[${index}], which was skipped`);
  const type = joint.m_type;
  if (type !== b2JointType.e_revoluteJoint && type !== b2JointType.e_prismaticJoint) {
    fail(p, `a gear joint couples revolute or prismatic joints, joint[${value as number}] is a ${b2JointType[type]}`);
  }
  return joint;
}

function readJoint(reading: Reading, value: unknown, path: string): b2Joint | null {
  const scene = reading.scene;
  const o = asObject(value, path);
  const typePath = keyPath(path, 'type');
  const type = member(o, 'type');
  if (type === undefined) fail(typePath, 'required field is missing');
  if (typeof type !== 'string') fail(typePath, `expected a joint type name, got ${describeValue(type)}`);

  let def: b2JointDef;
  let localAxisA: b2Vec2 | null = null;
  let mouseTarget: b2Vec2 | null = null;
  switch (type) {
    case 'revolute': {
      const d = new b2RevoluteJointDef();
      optVec(o, 'anchorA', path, d.localAnchorA);
      optVec(o, 'anchorB', path, d.localAnchorB);
      d.referenceAngle = optNumber(o, 'refAngle', path, 0);
      d.enableLimit = optBool(o, 'enableLimit', path, false);
      d.lowerAngle = optNumber(o, 'lowerLimit', path, 0);
      d.upperAngle = optNumber(o, 'upperLimit', path, 0);
      d.enableMotor = optBool(o, 'enableMotor', path, false);
      d.motorSpeed = optNumber(o, 'motorSpeed', path, 0);
      d.maxMotorTorque = optNonNegative(o, 'maxMotorTorque', path, 0);
      def = d;
      break;
    }
    case 'prismatic': {
      const d = new b2PrismaticJointDef();
      optVec(o, 'anchorA', path, d.localAnchorA);
      optVec(o, 'anchorB', path, d.localAnchorB);
      // Old b2dJson files name the axis localAxis1.
      const axisKey = member(o, 'localAxisA') === undefined ? 'localAxis1' : 'localAxisA';
      optVec(o, axisKey, path, d.localAxisA);
      checkAxis(path, axisKey, d.localAxisA);
      localAxisA = d.localAxisA.Clone();
      d.referenceAngle = optNumber(o, 'refAngle', path, 0);
      d.enableLimit = optBool(o, 'enableLimit', path, false);
      d.lowerTranslation = optNumber(o, 'lowerLimit', path, 0);
      d.upperTranslation = optNumber(o, 'upperLimit', path, 0);
      d.enableMotor = optBool(o, 'enableMotor', path, false);
      d.motorSpeed = optNumber(o, 'motorSpeed', path, 0);
      d.maxMotorForce = optNonNegative(o, 'maxMotorForce', path, 0);
      def = d;
      break;
    }
    case 'distance': {
      const d = new b2DistanceJointDef();
      optVec(o, 'anchorA', path, d.localAnchorA);
      optVec(o, 'anchorB', path, d.localAnchorB);
      d.length = optNonNegative(o, 'length', path, 0);
      d.frequencyHz = optNonNegative(o, 'frequency', path, 0);
      d.dampingRatio = optNonNegative(o, 'dampingRatio', path, 0);
      def = d;
      break;
    }
    case 'pulley': {
      const d = new b2PulleyJointDef();
      optVec(o, 'groundAnchorA', path, d.groundAnchorA);
      optVec(o, 'groundAnchorB', path, d.groundAnchorB);
      optVec(o, 'anchorA', path, d.localAnchorA);
      optVec(o, 'anchorB', path, d.localAnchorB);
      d.lengthA = optNonNegative(o, 'lengthA', path, 0);
      d.lengthB = optNonNegative(o, 'lengthB', path, 0);
      d.ratio = optNumber(o, 'ratio', path, 0);
      if (d.ratio === 0) fail(keyPath(path, 'ratio'), 'must not be 0 (the pulley joint divides by it)');
      def = d;
      break;
    }
    case 'mouse': {
      const d = new b2MouseJointDef();
      mouseTarget = optVec(o, 'target', path, new b2Vec2());
      // b2dJson builds the joint at anchorB (which fixes the body-B anchor), then moves the target.
      optVec(o, 'anchorB', path, d.target);
      d.maxForce = optNonNegative(o, 'maxForce', path, 0);
      d.frequencyHz = optPositive(o, 'frequency', path, 0);
      d.dampingRatio = optNonNegative(o, 'dampingRatio', path, 0);
      def = d;
      break;
    }
    case 'gear': {
      const d = new b2GearJointDef();
      const joint1 = gearJointIndex(reading, o, 'joint1', path);
      if (joint1 === null) return null;
      const joint2 = gearJointIndex(reading, o, 'joint2', path);
      if (joint2 === null) return null;
      d.joint1 = joint1;
      d.joint2 = joint2;
      d.ratio = optNumber(o, 'ratio', path, 0);
      def = d;
      break;
    }
    case 'wheel': {
      const d = new b2WheelJointDef();
      optVec(o, 'anchorA', path, d.localAnchorA);
      optVec(o, 'anchorB', path, d.localAnchorB);
      optVec(o, 'localAxisA', path, d.localAxisA);
      checkAxis(path, 'localAxisA', d.localAxisA);
      d.enableMotor = optBool(o, 'enableMotor', path, false);
      d.motorSpeed = optNumber(o, 'motorSpeed', path, 0);
      d.maxMotorTorque = optNonNegative(o, 'maxMotorTorque', path, 0);
      d.frequencyHz = optNonNegative(o, 'springFrequency', path, 0);
      d.dampingRatio = optNonNegative(o, 'springDampingRatio', path, 0);
      def = d;
      break;
    }
    case 'weld': {
      const d = new b2WeldJointDef();
      optVec(o, 'anchorA', path, d.localAnchorA);
      optVec(o, 'anchorB', path, d.localAnchorB);
      d.referenceAngle = optNumber(o, 'refAngle', path, 0);
      d.frequencyHz = optNonNegative(o, 'frequency', path, 0);
      d.dampingRatio = optNonNegative(o, 'dampingRatio', path, 0);
      def = d;
      break;
    }
    case 'friction': {
      const d = new b2FrictionJointDef();
      optVec(o, 'anchorA', path, d.localAnchorA);
      optVec(o, 'anchorB', path, d.localAnchorB);
      d.maxForce = optNonNegative(o, 'maxForce', path, 0);
      d.maxTorque = optNonNegative(o, 'maxTorque', path, 0);
      def = d;
      break;
    }
    case 'rope': {
      const d = new b2RopeJointDef();
      optVec(o, 'anchorA', path, d.localAnchorA);
      optVec(o, 'anchorB', path, d.localAnchorB);
      d.maxLength = optNonNegative(o, 'maxLength', path, 0);
      def = d;
      break;
    }
    case 'motor':
      return skip(reading, typePath, 'motor joints are not part of Box2D 2.2.1 (they arrived in 2.3)');
    default:
      return skip(reading, typePath, `unknown joint type ${JSON.stringify(type)} (expected ${kJointTypes})`);
  }
  const bodyA = bodyIndex(o, 'bodyA', path, scene.bodies);
  const bodyB = bodyIndex(o, 'bodyB', path, scene.bodies);
  if (bodyA === bodyB) fail(keyPath(path, 'bodyB'), 'bodyA and bodyB are the same body; a joint needs two');
  def.bodyA = bodyA;
  def.bodyB = bodyB;
  def.collideConnected = optBool(o, 'collideConnected', path, false);

  const joint = guard(path, () => scene.world.CreateJoint(def));
  if (mouseTarget !== null) {
    const mouse = joint as b2MouseJoint;
    // SetTarget wakes body B; skip it when it would not move the target.
    if (!Object.is(mouseTarget.x, mouse.m_targetA.x) || !Object.is(mouseTarget.y, mouse.m_targetA.y)) {
      mouse.SetTarget(mouseTarget);
    }
  }
  const mouseAnchorB = mouseTarget === null ? null : (def as b2MouseJointDef).target.Clone();
  b2dJsonRecordJoint(joint, new b2dJsonJointRecipe(bodyA, bodyB, localAxisA, mouseAnchorB));
  readMetadata(scene, joint, o, path);
  return joint;
}

function readImage(scene: b2dJsonScene, value: unknown, path: string): b2dJsonImage {
  const o = asObject(value, path);
  const index = optInteger(o, 'body', path, -1, -1, scene.bodies.length - 1);
  const fields: b2dJsonObject = {};
  for (const key of Object.keys(o)) {
    if (key !== 'body' && key !== 'name' && key !== 'customProperties') fields[key] = structuredClone(o[key]);
  }
  const image = new b2dJsonImage(index < 0 ? null : scene.bodies[index], fields);
  readMetadata(scene, image, o, path);
  return image;
}

/**
 * Build a new world from a b2dJson document, given as JSON text or as the parsed value.
 * Throws b2dJsonError (path and rule) on malformed input; `options.skipUnknown` leaves out what
 * this reader does not know instead (see the file header), listing it in the scene's `skipped`.
 */
export function b2dJsonRead(input: unknown, options: Readonly<b2dJsonReadOptions> = {}): b2dJsonScene {
  let document = input;
  if (typeof input === 'string') {
    try {
      document = JSON.parse(input);
    } catch (e) {
      fail('', `not valid JSON (${e instanceof Error ? e.message : String(e)})`);
    }
  }
  const root = asObject(document, '');

  const gravity = optVec(root, 'gravity', '', new b2Vec2());
  const stepsPerSecond = optNumber(root, 'stepsPerSecond', '', b2dJson_defaultStepSettings.stepsPerSecond);
  if (!(stepsPerSecond > 0)) fail('stepsPerSecond', `expected a number > 0, got ${stepsPerSecond}`);
  const defaults = b2dJson_defaultStepSettings;
  const stepSettings = {
    stepsPerSecond,
    velocityIterations: optInteger(root, 'velocityIterations', '', defaults.velocityIterations, 0, 0x7fffffff),
    positionIterations: optInteger(root, 'positionIterations', '', defaults.positionIterations, 0, 0x7fffffff),
  };
  const bodies = optArray(root, 'body', '');
  const joints = optArray(root, 'joint', '');
  const images = optArray(root, 'image', '');

  const world = new b2World(gravity);
  world.SetAllowSleeping(optBool(root, 'allowSleep', '', false));
  world.SetWarmStarting(optBool(root, 'warmStarting', '', false));
  world.SetContinuousPhysics(optBool(root, 'continuousPhysics', '', false));
  world.SetSubStepping(optBool(root, 'subStepping', '', false));
  world.SetAutoClearForces(optBool(root, 'autoClearForces', '', false));

  const scene = new b2dJsonScene(world, stepSettings);
  const reading: Reading = { scene, skipUnknown: options.skipUnknown === true, jointsInFile: [] };
  readMetadata(scene, world, root, '');
  for (let i = 0; i < bodies.length; ++i) {
    scene.bodies.push(readBody(reading, bodies[i], indexPath('body', i)));
  }
  for (let i = 0; i < joints.length; ++i) {
    const joint = readJoint(reading, joints[i], indexPath('joint', i));
    reading.jointsInFile.push(joint);
    if (joint !== null) scene.joints.push(joint);
  }
  for (let i = 0; i < images.length; ++i) {
    scene.images.push(readImage(scene, images[i], indexPath('image', i)));
  }
  const state = member(root, b2dJson_stateKey);
  if (state !== undefined) {
    // The state lists every body, fixture and joint of the file, in order.
    if (scene.skipped.length > 0) {
      fail(b2dJson_stateKey, `cannot be applied to a scene with skipped items (${scene.skipped[0].path}...)`);
    }
    b2dJsonReadState(world, scene.bodies, scene.joints, state);
  }
  for (const body of scene.bodies) b2dJsonSealBody(body);
  return scene;
}
