import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2MassData } from '../../src/collision/shapes/b2Shape';
import { b2Body, b2BodyDef, b2BodyType } from '../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2MouseJointDef } from '../../src/dynamics/joints/b2MouseJoint';
import type { b2MouseJoint } from '../../src/dynamics/joints/b2MouseJoint';
import { b2PrismaticJointDef } from '../../src/dynamics/joints/b2PrismaticJoint';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import type { b2RevoluteJoint } from '../../src/dynamics/joints/b2RevoluteJoint';
import type { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import {
  b2dJsonBodiesInCreationOrder,
  b2dJsonError,
  b2dJsonFixturesInCreationOrder,
  b2dJsonJointsInCreationOrder,
  b2dJsonRead,
  b2dJsonStringify,
  b2dJsonWrite,
  b2dJsonWriteString,
} from '../../src/io/b2dJson';
import type { b2dJsonObject, b2dJsonScene, b2dJsonValue } from '../../src/io/b2dJson';
import { goldenSceneNames, readGoldenScene, stateDigest } from '../support/scene';

// A comparable picture of a world: every field of every body, fixture (with shape and proxies)
// and joint, numbers as text so -0 differs from 0, references to other objects by name.
type Snapshot = string | boolean | null | Snapshot[] | { [key: string]: Snapshot };
const kSkippedFields = new Set(['m_prev', 'm_next', 'm_world', 'm_userData', 'm_edgeA', 'm_edgeB', 'm_contactList', 'm_jointList']);

function snap(value: unknown, refs: Map<object, string>, depth = 0): Snapshot {
  if (typeof value === 'number') return Object.is(value, -0) ? '-0' : String(value);
  if (typeof value === 'string' || typeof value === 'boolean') return value;
  if (value === null || value === undefined) return null;
  if (typeof value !== 'object') return `<${typeof value}>`;
  const ref = refs.get(value);
  if (ref !== undefined) return `@${ref}`;
  if (depth > 12) throw new Error('snapshot too deep: unexpected object graph');
  if (ArrayBuffer.isView(value)) {
    return Array.from(value as unknown as ArrayLike<number>, (x) => snap(x, refs, depth + 1));
  }
  if (Array.isArray(value)) return value.map((x) => snap(x, refs, depth + 1));
  const out: { [key: string]: Snapshot } = {};
  for (const key of Object.keys(value)) {
    if (!kSkippedFields.has(key)) out[key] = snap((value as Record<string, unknown>)[key], refs, depth + 1);
  }
  return out;
}

function worldSnapshot(world: b2World): Snapshot {
  const refs = new Map<object, string>();
  const bodies = b2dJsonBodiesInCreationOrder(world);
  const joints = b2dJsonJointsInCreationOrder(world);
  refs.set(world, 'world');
  bodies.forEach((b, i) => {
    refs.set(b, `body${i}`);
    b2dJsonFixturesInCreationOrder(b).forEach((f, k) => refs.set(f, `body${i}.fixture${k}`));
  });
  joints.forEach((j, i) => refs.set(j, `joint${i}`));
  return {
    world: snap(
      {
        gravity: world.m_gravity,
        flags: world.m_flags,
        allowSleep: world.m_allowSleep,
        warmStarting: world.m_warmStarting,
        continuousPhysics: world.m_continuousPhysics,
        subStepping: world.m_subStepping,
        proxyCount: world.GetProxyCount(),
        contactCount: world.GetContactCount(),
      },
      refs,
    ),
    bodies: bodies.map((b) => ({
      body: snap(b, refs),
      fixtures: b2dJsonFixturesInCreationOrder(b).map((f) => snap(f, refs)),
    })),
    joints: joints.map((j) => snap(j, refs)),
  };
}

/** The path of the first difference between two snapshots, with both values, or null. */
function firstDifference(a: Snapshot, b: Snapshot, path = ''): string | null {
  if (typeof a !== 'object' || typeof b !== 'object' || a === null || b === null) {
    return a === b ? null : `${path}: ${JSON.stringify(a)} vs ${JSON.stringify(b)}`;
  }
  if (Array.isArray(a) !== Array.isArray(b)) return `${path}: array vs object`;
  const keys = new Set([...Object.keys(a), ...Object.keys(b)]);
  for (const key of keys) {
    const av = (a as Record<string, Snapshot>)[key];
    const bv = (b as Record<string, Snapshot>)[key];
    if (av === undefined || bv === undefined) return `${path}.${key}: present on one side only`;
    const d = firstDifference(av, bv, Array.isArray(a) ? `${path}[${key}]` : `${path}.${key}`);
    if (d !== null) return d;
  }
  return null;
}

function expectSameWorld(a: b2World, b: b2World): void {
  expect(firstDifference(worldSnapshot(a), worldSnapshot(b))).toBeNull();
}

function expectSameSteps(a: b2dJsonScene, b: b2dJsonScene, steps: number): void {
  for (let step = 0; step <= steps; ++step) {
    if (step > 0) {
      a.step();
      b.step();
    }
    const da = stateDigest(a.bodies);
    const db = stateDigest(b.bodies);
    if (da !== db) expect.fail(`digests differ at step ${step}: ${da} vs ${db}`);
  }
}

/**
 * What a reload of a stepped world keeps: poses, angular velocities, masses and flags exactly;
 * linear velocities to rounding, since loading adds b2Cross(w, r) center-of-mass corrections to
 * the def velocity. Without the writer's correction the error would be the whole w * |r|.
 */
function expectSameMotion(original: readonly b2Body[], copy: readonly b2Body[], label: string): void {
  expect(copy.length).toBe(original.length);
  original.forEach((b, i) => {
    const c = copy[i];
    const where = `${label} body[${i}]`;
    const exact = (body: b2Body) => [
      body.m_xf.p.x,
      body.m_xf.p.y,
      body.m_sweep.a,
      body.m_angularVelocity,
      body.m_mass,
      body.m_I,
      body.m_sweep.localCenter.x,
      body.m_sweep.localCenter.y,
      body.m_flags & kWrittenFlags,
    ];
    expect(exact(c), where).toEqual(exact(b));
    const lc = b.m_sweep.localCenter;
    const scale = Math.abs(b.m_angularVelocity) * (Math.hypot(lc.x, lc.y) + 1);
    for (const axis of ['x', 'y'] as const) {
      const v = b.m_linearVelocity[axis];
      const error = Math.abs(c.m_linearVelocity[axis] - v);
      expect(error, `${where} v${axis}`).toBeLessThanOrEqual(1e-14 * (Math.abs(v) + scale));
    }
  });
}

function readError(input: unknown): b2dJsonError {
  try {
    b2dJsonRead(input);
  } catch (e) {
    if (e instanceof b2dJsonError) return e;
    throw e;
  }
  throw new Error('expected b2dJsonRead to throw');
}

const kWrittenFlags = b2Body.e_bulletFlag | b2Body.e_autoSleepFlag | b2Body.e_awakeFlag | b2Body.e_activeFlag | b2Body.e_fixedRotationFlag;

const circleFixture = { density: 1, circle: { radius: 0.5, center: { x: 0, y: 0 } } };

describe('b2dJson round trip of the golden scenes', () => {
  for (const name of goldenSceneNames()) {
    it(`${name}: read, write, read gives the same bodies, fixtures and joints and the same 60 steps`, () => {
      const original = b2dJsonRead(readGoldenScene(name));
      const text = b2dJsonWriteString(original);
      const copy = b2dJsonRead(text);
      expectSameWorld(original.world, copy.world);
      expect(copy.stepSettings).toEqual(original.stepSettings);
      // Writing is stable: the copy writes the same text.
      expect(b2dJsonWriteString(copy)).toBe(text);
      expectSameSteps(original, copy, 60);
    });
  }

  it('writing the bare world (no scene) reloads to the same world', () => {
    const original = b2dJsonRead(readGoldenScene('joint-zoo'));
    const copy = b2dJsonRead(b2dJsonWrite(original.world));
    expectSameWorld(original.world, copy.world);
    expectSameSteps(original, copy, 60);
  });

  it('a stepped world reloads with the same poses and masses, and velocities equal to rounding', () => {
    for (const name of ['car', 'compound-shapes', 'joint-zoo', 'revolute', 'varying-restitution']) {
      const original = b2dJsonRead(readGoldenScene(name));
      for (let i = 0; i < 45; ++i) original.step();
      expectSameMotion(original.bodies, b2dJsonRead(b2dJsonWriteString(original)).bodies, name);
    }
  });
});

describe('b2dJson writing worlds built in code', () => {
  function buildWorld(): b2World {
    const world = new b2World(new b2Vec2(0, -9.5));
    const ground = world.CreateBody(new b2BodyDef());
    const groundBox = new b2PolygonShape();
    groundBox.SetAsBox(20, 0.5, new b2Vec2(0.25, -1), 0.05);
    ground.CreateFixture(groundBox, 0);

    const def = new b2BodyDef();
    def.type = b2BodyType.b2_dynamicBody;
    def.position.Set(1.1, 3.3);
    def.angle = 0.7;
    def.linearVelocity.Set(0.3, -0.2);
    def.angularVelocity = 1.7;
    const body = world.CreateBody(def);
    const box = new b2PolygonShape();
    box.SetAsBox(0.4, 0.3, new b2Vec2(0.35, 0.1), 0.3);
    const fd = new b2FixtureDef();
    fd.shape = box;
    fd.density = 2.5;
    fd.friction = 0.45;
    body.CreateFixture(fd);
    const triangle = new b2PolygonShape();
    triangle.Set([new b2Vec2(-0.5, 0), new b2Vec2(0.3, -0.1), new b2Vec2(0.1, 0.6)], 3);
    body.CreateFixture(triangle, 1.3);
    const massData = new b2MassData();
    massData.mass = 3.1;
    massData.center.Set(0.12, -0.07);
    massData.I = 0.9;
    body.SetMassData(massData);

    const wheel = world.CreateBody(def);
    const circle = new b2CircleShape();
    circle.m_radius = 0.35;
    circle.m_p.Set(0.2, 0.1);
    wheel.CreateFixture(circle, 1);

    const pd = new b2PrismaticJointDef();
    pd.bodyA = ground;
    pd.bodyB = body;
    pd.localAnchorA.Set(1, 2);
    pd.localAxisA.Set(3, 4.1);
    pd.enableLimit = true;
    pd.lowerTranslation = -1;
    pd.upperTranslation = 2;
    world.CreateJoint(pd);

    const rd = new b2RevoluteJointDef();
    rd.Initialize(body, wheel, new b2Vec2(1.3, 3.1));
    world.CreateJoint(rd);

    const md = new b2MouseJointDef();
    md.bodyA = ground;
    md.bodyB = wheel;
    md.target.Set(1.37, 3.41);
    md.maxForce = 100;
    const mouse = world.CreateJoint(md) as b2MouseJoint;
    mouse.SetTarget(new b2Vec2(2.5, 4));
    return world;
  }

  it('a world with SetAsBox, Set, SetMassData, a non-unit prismatic axis and a mouse joint reloads exactly', () => {
    const world = buildWorld();
    const copy = b2dJsonRead(b2dJsonWriteString(world));
    expectSameWorld(world, copy.world);
  });

  it('after stepping it reloads with the same poses and masses, and velocities equal to rounding', () => {
    const world = buildWorld();
    for (let i = 0; i < 20; ++i) world.Step(1 / 60, 8, 3);
    expectSameMotion(b2dJsonBodiesInCreationOrder(world), b2dJsonRead(b2dJsonWriteString(world)).bodies, 'built world');
  });

  it('the writer emits box for SetAsBox polygons and only vertices for Set polygons', () => {
    const world = buildWorld();
    const doc = b2dJsonWrite(world) as { body: { fixture: { polygon?: b2dJsonObject }[] }[] };
    expect(doc.body[0].fixture[0].polygon?.box).toBeDefined();
    expect(doc.body[1].fixture[0].polygon?.box).toBeDefined();
    expect(doc.body[1].fixture[1].polygon?.box).toBeUndefined();
  });
});

describe('b2dJson numbers and vectors', () => {
  it('-0 survives writing and reading', () => {
    const scene = b2dJsonRead({
      gravity: { x: -0, y: -10 },
      body: [
        {
          type: 2,
          position: { x: -0, y: 1 },
          angle: -0,
          angularVelocity: -0,
          fixture: [{ ...circleFixture, friction: -0, circle: { radius: 0.5, center: { x: -0, y: 0 } } }],
        },
      ],
    });
    const text = b2dJsonWriteString(scene);
    expect(text).toContain('"position":{"x":-0,"y":1}');
    const copy = b2dJsonRead(text);
    const body = copy.bodies[0];
    const fixture = b2dJsonFixturesInCreationOrder(body)[0];
    expect(Object.is(copy.world.m_gravity.x, -0)).toBe(true);
    expect(Object.is(body.m_xf.p.x, -0)).toBe(true);
    expect(Object.is(body.m_sweep.a, -0)).toBe(true);
    expect(Object.is(body.m_angularVelocity, -0)).toBe(true);
    expect(Object.is(fixture.m_friction, -0)).toBe(true);
    expect(Object.is((fixture.m_shape as b2CircleShape).m_p.x, -0)).toBe(true);
  });

  it('b2dJsonStringify writes -0, the shortest exact doubles, and refuses non-finite numbers', () => {
    const values = [-0, 0.1, 1 / 3, 2 ** -1074, 1.7976931348623157e308, -123.456e-300];
    const text = b2dJsonStringify(values);
    const back = JSON.parse(text) as number[];
    values.forEach((v, i) => expect(Object.is(back[i], v)).toBe(true));
    expect(b2dJsonStringify({ a: [1, { b: -0 }] }, 2)).toBe('{\n  "a": [\n    1,\n    {\n      "b": -0\n    }\n  ]\n}');
    const nan = { body: [{ angle: NaN }] } as unknown as b2dJsonValue;
    expect(() => b2dJsonStringify(nan)).toThrow('body[0].angle: cannot write the non-finite number NaN');
  });

  it('17-significant-digit numbers parse to the exact double', () => {
    const scene = b2dJsonRead('{"body":[{"type":2,"position":{"x":0.10000000000000001,"y":-3.3306690738754696e-16}}]}');
    expect(scene.bodies[0].m_xf.p.x).toBe(0.1);
    expect(scene.bodies[0].m_xf.p.y).toBe(-3.3306690738754696e-16);
  });

  it('vectors written as the number 0 load as zero vectors', () => {
    const scene = b2dJsonRead({
      gravity: 0,
      body: [{ type: 2, position: 0, linearVelocity: 0, fixture: [{ density: 1, circle: { radius: 0.5, center: 0 } }] }],
    });
    expect([scene.world.m_gravity.x, scene.world.m_gravity.y]).toEqual([0, 0]);
    const body = scene.bodies[0];
    expect([body.m_xf.p.x, body.m_xf.p.y, body.m_linearVelocity.x, body.m_linearVelocity.y]).toEqual([0, 0, 0, 0]);
  });

  it("b2dJson's binary floats (8 hex digits of a float32) load as that float", () => {
    const scene = b2dJsonRead({ body: [{ type: 2, position: { x: '3F800000', y: 'BEA00000' }, angle: '40490FDB' }] });
    const body = scene.bodies[0];
    expect([body.m_xf.p.x, body.m_xf.p.y]).toEqual([1, -0.3125]);
    expect(body.m_sweep.a).toBe(Math.fround(Math.PI));
  });
});

describe('b2dJson defaults and extensions', () => {
  it("missing optional fields take b2dJson's defaults", () => {
    const scene = b2dJsonRead({
      body: [{ fixture: [{ circle: { radius: 0.5 } }] }, { type: 2 }],
      joint: [{ type: 'revolute', bodyA: 0, bodyB: 1 }],
    });
    const world = scene.world;
    expect([world.m_gravity.x, world.m_gravity.y]).toEqual([0, 0]);
    const worldFlags = [world.m_allowSleep, world.m_warmStarting, world.m_continuousPhysics, world.m_subStepping];
    expect(worldFlags).toEqual([false, false, false, false]);
    expect(world.m_flags & b2World.e_clearForces).toBe(0);
    expect(scene.stepSettings).toEqual({ stepsPerSecond: 60, velocityIterations: 8, positionIterations: 3 });

    const [ground, body] = scene.bodies;
    expect(ground.m_type).toBe(b2BodyType.b2_staticBody);
    expect(body.m_type).toBe(b2BodyType.b2_dynamicBody);
    // awake defaults to false in b2dJson; allowSleep and active to true.
    expect(body.IsAwake()).toBe(false);
    expect(body.IsSleepingAllowed()).toBe(true);
    expect(body.IsActive()).toBe(true);
    expect(body.IsBullet() || body.IsFixedRotation()).toBe(false);
    expect([body.m_gravityScale, body.m_linearDamping, body.m_angularDamping, body.m_sweep.a]).toEqual([1, 0, 0, 0]);

    const fixture = b2dJsonFixturesInCreationOrder(ground)[0];
    expect([fixture.m_friction, fixture.m_restitution, fixture.m_density, fixture.m_isSensor]).toEqual([0, 0, 0, false]);
    const filter = fixture.m_filter;
    expect([filter.categoryBits, filter.maskBits, filter.groupIndex]).toEqual([1, 0xffff, 0]);
    const circle = fixture.m_shape as b2CircleShape;
    expect([circle.m_radius, circle.m_p.x, circle.m_p.y]).toEqual([0.5, 0, 0]);

    const joint = scene.joints[0] as b2RevoluteJoint;
    expect([joint.m_enableLimit, joint.m_referenceAngle, joint.m_collideConnected]).toEqual([false, 0, false]);
  });

  it('a polygon with box is built with SetAsBox, not Set, and writes its box back', () => {
    const center = { x: 0.3, y: -0.2 };
    const vertices = { x: [-0.1, 0.7, 0.7, -0.1], y: [-0.6, -0.6, 0.2, 0.2] };
    const box = { hx: 0.4, hy: 0.4, center, angle: 0.25 };
    const scene = b2dJsonRead({ body: [{ fixture: [{ polygon: { vertices, box } }] }] });
    const shape = b2dJsonFixturesInCreationOrder(scene.bodies[0])[0].m_shape as b2PolygonShape;
    const expected = new b2PolygonShape();
    expected.SetAsBox(0.4, 0.4, new b2Vec2(center.x, center.y), 0.25);
    for (let i = 0; i < 4; ++i) {
      expect([shape.m_vertices[i].x, shape.m_vertices[i].y, shape.m_normals[i].x, shape.m_normals[i].y]).toEqual([
        expected.m_vertices[i].x,
        expected.m_vertices[i].y,
        expected.m_normals[i].x,
        expected.m_normals[i].y,
      ]);
    }
    expect([shape.m_centroid.x, shape.m_centroid.y]).toEqual([0.3, -0.2]);
    const written = b2dJsonWrite(scene) as { body: { fixture: { polygon: b2dJsonObject }[] }[] };
    expect(written.body[0].fixture[0].polygon.box).toEqual({ hx: 0.4, hy: 0.4, center, angle: 0.25 });
  });

  it('a chain keeps its prev/next vertices, and an old-style loop closes itself', () => {
    const scene = b2dJsonRead({
      body: [
        {
          fixture: [
            {
              chain: {
                vertices: { x: [0, 1, 2], y: [0, 0.5, 0] },
                hasPrevVertex: true,
                prevVertex: { x: -1, y: 0.25 },
                hasNextVertex: false,
              },
            },
            { loop: { vertices: { x: [0, 1, 1], y: [0, 0, 1] } } },
          ],
        },
      ],
    });
    const [chain, loop] = b2dJsonFixturesInCreationOrder(scene.bodies[0]).map((f) => f.m_shape as b2ChainShape);
    const prev = chain.m_prevVertex;
    expect([chain.m_count, chain.m_hasPrevVertex, chain.m_hasNextVertex, prev.x, prev.y]).toEqual([3, true, false, -1, 0.25]);
    expect([loop.m_count, loop.m_hasPrevVertex, loop.m_hasNextVertex]).toEqual([4, true, true]);
  });

  it('massData-mass triggers SetMassData after the fixtures', () => {
    const scene = b2dJsonRead({
      body: [
        { type: 2, fixture: [circleFixture], 'massData-mass': 4, 'massData-center': { x: 0.5, y: 0 }, 'massData-I': 3 },
        { type: 2, fixture: [circleFixture] },
      ],
    });
    const [custom, plain] = scene.bodies;
    expect([custom.m_mass, custom.m_sweep.localCenter.x, custom.m_I]).toEqual([4, 0.5, 3 - 4 * 0.25]);
    // b2CircleShape.ComputeMass: density * b2_pi * r * r.
    expect(plain.m_mass).toBe(1 * 3.14159265359 * 0.5 * 0.5);
  });

  it('names and custom properties are kept on the world, bodies, fixtures, joints and images, and written back', () => {
    const doc = {
      name: 'level 1',
      customProperties: [{ name: 'music', string: 'calm.ogg' }],
      body: [
        {
          name: 'ground',
          fixture: [{ name: 'floor', circle: { radius: 1 }, customProperties: [{ name: 'ice', bool: true }] }],
          customProperties: [
            { name: 'hp', int: 7 },
            { name: 'drag', float: 0.25 },
            { name: 'spawn', vec2: { x: 1, y: -2 } },
            { name: 'tint', color: [255, 128, 0, 255] },
          ],
        },
        { name: 'crate', type: 2, fixture: [circleFixture] },
      ],
      joint: [{ name: 'hinge', type: 'revolute', bodyA: 0, bodyB: 1, customProperties: [{ name: 'breakable', bool: false }] }],
      image: [{ name: 'sky', body: 1, file: 'sky.png', scale: 2, customProperties: [{ name: 'layer', int: -1 }] }],
    };
    const check = (scene: b2dJsonScene) => {
      const [ground, crate] = scene.bodies;
      const floor = b2dJsonFixturesInCreationOrder(ground)[0];
      expect(scene.getName(scene.world)).toBe('level 1');
      const music = scene.getCustomProperty(scene.world, 'music');
      expect(music).toEqual({ name: 'music', type: 'string', value: 'calm.ogg' });
      expect(scene.getBodyByName('crate')).toBe(crate);
      expect(scene.getFixtureByName('floor')).toBe(floor);
      expect(scene.getJointByName('hinge')).toBe(scene.joints[0]);
      expect(scene.getName(crate)).toBe('crate');
      expect(scene.getCustomProperties(ground).map((p) => [p.name, p.type, p.value])).toEqual([
        ['hp', 'int', 7],
        ['drag', 'float', 0.25],
        ['spawn', 'vec2', new b2Vec2(1, -2)],
        ['tint', 'color', [255, 128, 0, 255]],
      ]);
      expect(scene.getCustomProperty(floor, 'ice')?.value).toBe(true);
      expect(scene.getCustomProperty(scene.joints[0], 'breakable')?.value).toBe(false);
      const sky = scene.getImageByName('sky');
      expect(sky?.body).toBe(crate);
      expect(sky?.fields).toEqual({ file: 'sky.png', scale: 2 });
      expect(sky && scene.getCustomProperty(sky, 'layer')?.value).toBe(-1);
      expect(scene.getName(ground)).toBe('ground');
      expect(scene.getBodyByName('nobody')).toBeNull();
    };
    const scene = b2dJsonRead(doc);
    check(scene);
    check(b2dJsonRead(b2dJsonWriteString(scene)));
  });
});

describe('b2dJson malformed input', () => {
  const body = (fixture: unknown) => ({ body: [{ type: 2, fixture: [fixture] }] });
  const twoBodies = (joint: unknown) => ({ body: [{}, { type: 2, fixture: [circleFixture] }], joint: [joint] });
  const cases: [string, unknown, string][] = [
    ['text that is not JSON', '{"body": [', '(root): not valid JSON'],
    ['a document that is not an object', '[1, 2]', '(root): expected an object, got an array'],
    ['body not an array', { body: { type: 2 } }, 'body: expected an array, got an object'],
    [
      'a bad vertex coordinate',
      body({ polygon: { vertices: { x: [0, 1, 'abc'], y: [0, 0, 1] } } }),
      'body[0].fixture[0].polygon.vertices.x[2]: expected a finite number, got the string "abc"',
    ],
    [
      'vertex arrays of different lengths',
      body({ polygon: { vertices: { x: [0, 1, 1], y: [0, 0] } } }),
      'body[0].fixture[0].polygon.vertices: x has 3 entries but y has 2',
    ],
    [
      'too many polygon vertices',
      body({ polygon: { vertices: { x: [0, 1, 2, 3, 4, 5, 6, 7, 8], y: [0, 1, 2, 3, 4, 5, 6, 7, 8] } } }),
      'body[0].fixture[0].polygon.vertices: a polygon needs 3 to 8 vertices',
    ],
    [
      'a degenerate polygon Box2D rejects',
      body({ polygon: { vertices: { x: [0, 0, 1], y: [0, 0, 1] } } }),
      'body[0].fixture[0].polygon.vertices: rejected by b2PolygonShape.Set: vertices[1] coincides with vertices[0]',
    ],
    ['an unknown shape type', body({ ellipse: { rx: 1 } }), 'body[0].fixture[0]: no shape: expected one of circle, edge, chain, loop, polygon'],
    ['two shapes in one fixture', body({ circle: { radius: 1 }, edge: {} }), 'body[0].fixture[0]: more than one shape: circle, edge'],
    ['a missing box half-width', body({ polygon: { box: { hy: 1 } } }), 'body[0].fixture[0].polygon.box.hx: required field is missing'],
    ['a bad body type', { body: [{ type: 3 }] }, 'body[0].type: expected an integer in [0, 2], got number 3'],
    ['a negative damping', { body: [{ type: 2, linearDamping: -1 }] }, 'body[0].linearDamping: expected a finite number >= 0'],
    ['a flag that is not a boolean', { body: [{ type: 2, bullet: 1 }] }, 'body[0].bullet: expected true or false, got number 1'],
    [
      'a filter outside uint16',
      body({ circle: { radius: 1 }, 'filter-maskBits': 70000 }),
      'body[0].fixture[0].filter-maskBits: expected an integer in [0, 65535]',
    ],
    ['a vector that is a non-zero number', { gravity: 5 }, 'gravity: expected a vector {x, y} or 0, got number 5'],
    ['a body index out of range', twoBodies({ type: 'revolute', bodyA: 0, bodyB: 5 }), 'joint[0].bodyB: expected an integer in [0, 1], got number 5'],
    ['a missing body index', twoBodies({ type: 'weld', bodyA: 0 }), 'joint[0].bodyB: required field is missing'],
    ['a joint on one body', twoBodies({ type: 'rope', bodyA: 1, bodyB: 1, maxLength: 2 }), 'joint[0].bodyB: bodyA and bodyB are the same body'],
    ['an unknown joint type', twoBodies({ type: 'spring', bodyA: 0, bodyB: 1 }), 'joint[0].type: unknown joint type "spring"'],
    ['a motor joint', twoBodies({ type: 'motor', bodyA: 0, bodyB: 1 }), 'joint[0].type: motor joints are not part of Box2D 2.2.1'],
    ['a zero pulley ratio', twoBodies({ type: 'pulley', bodyA: 0, bodyB: 1 }), 'joint[0].ratio: must not be 0 (the pulley joint divides by it)'],
    [
      'a gear before any joint',
      twoBodies({ type: 'gear', bodyA: 0, bodyB: 1, joint1: 0, joint2: 0 }),
      'joint[0].joint1: a gear joint must come after the joints it couples',
    ],
    [
      'mass data Box2D rejects',
      { body: [{ type: 2, 'massData-mass': 1, 'massData-I': 0.5, 'massData-center': { x: 1, y: 0 } }] },
      'body[0].massData-mass: rejected by b2Body.SetMassData: massData.I must exceed mass * |center|^2',
    ],
    [
      'a custom property with two values',
      { customProperties: [{ name: 'x', int: 1, bool: true }] },
      'customProperties[0]: expected exactly one value (int, float, string, vec2, bool, color), found int, bool',
    ],
    ['an image on a missing body', { image: [{ body: 2 }] }, 'image[0].body: expected an integer in [-1, -1], got number 2'],
  ];
  for (const [what, input, message] of cases) {
    it(`${what} is reported with its path and rule`, () => {
      const error = readError(input);
      expect(error.message.slice(0, message.length)).toBe(message);
      expect(error.message).toBe(`${error.path}: ${error.rule}`);
    });
  }

  it('a gear coupling a weld joint is rejected, naming the joint', () => {
    const error = readError({
      body: [{}, { type: 2, fixture: [circleFixture] }, { type: 2, fixture: [circleFixture] }],
      joint: [
        { type: 'weld', bodyA: 0, bodyB: 1 },
        { type: 'revolute', bodyA: 0, bodyB: 2 },
        { type: 'gear', bodyA: 1, bodyB: 2, joint1: 0, joint2: 1 },
      ],
    });
    expect(error.path).toBe('joint[2].joint1');
    expect(error.rule).toBe('a gear joint couples revolute or prismatic joints, joint[0] is a e_weldJoint');
  });

  it('a failed read leaves nothing behind: the next read builds the same world as a fresh one', () => {
    const good = readGoldenScene('revolute');
    const fresh = b2dJsonRead(good);
    const bad = { ...(good as object), joint: [{ type: 'revolute', bodyA: 0, bodyB: 99 }] };
    expect(() => b2dJsonRead(bad)).toThrow(b2dJsonError);
    const after = b2dJsonRead(good);
    expectSameWorld(fresh.world, after.world);
    expectSameSteps(fresh, after, 30);
  });
});
