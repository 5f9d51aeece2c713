import { describe, expect, it } from 'vitest';
import { b2AABB } from '../../src/collision/b2Collision';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2MassData, type b2Shape } from '../../src/collision/shapes/b2Shape';
import { b2ArgumentError } from '../../src/common/b2ArgumentError';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2Body, b2BodyDef, b2BodyType } from '../../src/dynamics/b2Body';
import { b2Filter, b2FixtureDef, type b2Fixture } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2ContactListener, b2QueryCallback, b2RayCastCallback } from '../../src/dynamics/b2WorldCallbacks';
import { b2DistanceJoint, b2DistanceJointDef } from '../../src/dynamics/joints/b2DistanceJoint';
import { b2FrictionJoint, b2FrictionJointDef } from '../../src/dynamics/joints/b2FrictionJoint';
import { b2GearJoint, b2GearJointDef } from '../../src/dynamics/joints/b2GearJoint';
import { b2JointDef, type b2Joint } from '../../src/dynamics/joints/b2Joint';
import { b2MouseJoint, b2MouseJointDef } from '../../src/dynamics/joints/b2MouseJoint';
import { b2PrismaticJoint, b2PrismaticJointDef } from '../../src/dynamics/joints/b2PrismaticJoint';
import { b2PulleyJointDef } from '../../src/dynamics/joints/b2PulleyJoint';
import { b2RevoluteJoint, b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { b2RopeJoint, b2RopeJointDef } from '../../src/dynamics/joints/b2RopeJoint';
import { b2WeldJoint, b2WeldJointDef } from '../../src/dynamics/joints/b2WeldJoint';
import { b2WheelJoint, b2WheelJointDef } from '../../src/dynamics/joints/b2WheelJoint';
import { b2dJsonError } from '../../src/io/b2dJsonScene';
import { b2dJsonRead } from '../../src/io/b2dJsonRead';
import { checkWorldInvariants, worldDigest } from '../support/invariants';

/*
 * One test per validation rule: the call throws a b2ArgumentError naming the method, the argument
 * and the rule; the world's full-state digest is unchanged; and the world still steps cleanly.
 */

const h = 1 / 60;

interface Scene {
  world: b2World;
  ground: b2Body;
  box: b2Body;
  ball: b2Body;
  boxFixture: b2Fixture;
  revolute: b2RevoluteJoint;
  prismatic: b2PrismaticJoint;
  distance: b2DistanceJoint;
  mouse: b2MouseJoint;
  rope: b2RopeJoint;
  weld: b2WeldJoint;
  wheel: b2WheelJoint;
  friction: b2FrictionJoint;
  gear: b2GearJoint;
}

function dynamicBody(world: b2World, x: number, y: number): b2Body {
  const bd = new b2BodyDef();
  bd.type = b2BodyType.b2_dynamicBody;
  bd.position.Set(x, y);
  return world.CreateBody(bd);
}

function box(hx: number, hy: number): b2PolygonShape {
  return new b2PolygonShape().SetAsBox(hx, hy);
}

function circle(radius: number): b2CircleShape {
  const c = new b2CircleShape();
  c.m_radius = radius;
  return c;
}

/** A ground, a box, a ball and bodies for one joint of each kind, stepped 30 times. */
function makeScene(): Scene {
  const world = new b2World(new b2Vec2(0, -10));
  const ground = world.CreateBody(new b2BodyDef());
  ground.CreateFixture(box(20, 0.5), 0);
  const boxBody = dynamicBody(world, 0, 1.5);
  const boxFixture = boxBody.CreateFixture(box(0.5, 0.5), 1);
  const ball = dynamicBody(world, 2, 1.5);
  ball.CreateFixture(circle(0.5), 1);
  const make = (x: number) => {
    const b = dynamicBody(world, x, 4);
    b.CreateFixture(box(0.25, 0.25), 1);
    return b;
  };
  const [b1, b2, b3, b4, b5, b6, b7, b8, b9] = [-8, -6, -4, -2, 4, 6, 8, 10, 12].map(make);

  const rd = new b2RevoluteJointDef();
  rd.Initialize(ground, b1, new b2Vec2(-8, 5));
  rd.enableLimit = true;
  rd.lowerAngle = -0.5;
  rd.upperAngle = 0.5;
  const revolute = world.CreateJoint(rd) as b2RevoluteJoint;
  const pd = new b2PrismaticJointDef();
  pd.Initialize(ground, b2, new b2Vec2(-6, 4), new b2Vec2(0, 1));
  const prismatic = world.CreateJoint(pd) as b2PrismaticJoint;
  const dd = new b2DistanceJointDef();
  dd.Initialize(ground, b3, new b2Vec2(-4, 6), b3.GetPosition());
  const distance = world.CreateJoint(dd) as b2DistanceJoint;
  const md = new b2MouseJointDef();
  md.bodyA = ground;
  md.bodyB = b4;
  md.target.Set(-2, 4);
  md.maxForce = 100;
  const mouse = world.CreateJoint(md) as b2MouseJoint;
  const ropeDef = new b2RopeJointDef();
  ropeDef.bodyA = ground;
  ropeDef.bodyB = b5;
  ropeDef.localAnchorA.Set(4, 6);
  ropeDef.localAnchorB.Set(0, 0);
  ropeDef.maxLength = 2.5;
  const rope = world.CreateJoint(ropeDef) as b2RopeJoint;
  const wd = new b2WeldJointDef();
  wd.Initialize(b5, b6, new b2Vec2(5, 4));
  const weld = world.CreateJoint(wd) as b2WeldJoint;
  const whd = new b2WheelJointDef();
  whd.Initialize(ground, b7, b7.GetPosition(), new b2Vec2(0, 1));
  const wheel = world.CreateJoint(whd) as b2WheelJoint;
  const fd = new b2FrictionJointDef();
  fd.Initialize(ground, b8, b8.GetPosition());
  const friction = world.CreateJoint(fd) as b2FrictionJoint;
  const rd2 = new b2RevoluteJointDef();
  rd2.Initialize(ground, b9, b9.GetPosition());
  const revolute2 = world.CreateJoint(rd2);
  const gd = new b2GearJointDef();
  gd.bodyA = b1;
  gd.bodyB = b9;
  gd.joint1 = revolute;
  gd.joint2 = revolute2;
  gd.ratio = 2;
  const gear = world.CreateJoint(gd) as b2GearJoint;
  for (let i = 0; i < 30; ++i) world.Step(h, 8, 3);
  return {
    world,
    ground,
    box: boxBody,
    ball,
    boxFixture,
    revolute,
    prismatic,
    distance,
    mouse,
    rope,
    weld,
    wheel,
    friction,
    gear,
  };
}

interface Expected {
  method: string;
  argument: string;
  rule: RegExp;
}

function caught(act: () => unknown): unknown {
  try {
    act();
  } catch (e) {
    return e;
  }
  return undefined;
}

function expectArgumentError(error: unknown, expected: Expected): void {
  expect(error, 'the call must throw').toBeInstanceOf(b2ArgumentError);
  const e = error as b2ArgumentError;
  expect(e.method).toBe(expected.method);
  expect(e.argument).toBe(expected.argument);
  expect(e.rule).toMatch(expected.rule);
  expect(e.message).toBe(`${e.method}: ${e.argument} ${e.rule}`);
}

/** The call is rejected and the world is exactly as before; it then steps without faults. */
function expectRejected(world: b2World, act: () => unknown, expected: Expected): void {
  const before = worldDigest(world);
  const counts = [world.GetBodyCount(), world.GetJointCount(), world.GetContactCount(), world.GetProxyCount()];
  expectArgumentError(caught(act), expected);
  expect(worldDigest(world), 'the world changed').toBe(before);
  expect([world.GetBodyCount(), world.GetJointCount(), world.GetContactCount(), world.GetProxyCount()]).toEqual(counts);
  expect(world.IsLocked()).toBe(false);
  for (let i = 0; i < 10; ++i) world.Step(h, 8, 3);
  expect(checkWorldInvariants(world)).toEqual([]);
}

function polygonState(p: b2PolygonShape): number[] {
  const out = [p.m_vertexCount, p.m_vertices.length, p.m_normals.length, p.m_centroid.x, p.m_centroid.y];
  for (let i = 0; i < p.m_vertices.length; ++i) out.push(p.m_vertices[i].x, p.m_vertices[i].y, p.m_normals[i].x, p.m_normals[i].y);
  return out;
}

function v(x: number, y: number): b2Vec2 {
  return new b2Vec2(x, y);
}

const square = [v(0, 0), v(1, 0), v(1, 1), v(0, 1)];

describe('b2PolygonShape.Set and SetAsBox reject bad vertex lists, leaving the polygon unchanged', () => {
  const cases: [string, readonly b2Vec2[], number | undefined, string, RegExp][] = [
    ['fewer than 3 vertices', [v(0, 0), v(1, 0)], undefined, 'count', /^must be an integer in \[3, 8\], got 2$/],
    ['more than b2_maxPolygonVertices', Array.from({ length: 9 }, (_, i) => v(Math.cos(i), Math.sin(i))), undefined, 'count', /in \[3, 8\], got 9/],
    ['a count beyond the array', square, 5, 'count', /^is 5 but vertices has only 4 entries$/],
    ['a non-integer count', square, 3.5, 'count', /got 3.5/],
    ['a non-finite vertex', [v(0, 0), v(NaN, 0), v(1, 1)], undefined, 'vertices[1]', /must be a vector of finite numbers, got \(NaN, 0\)/],
    ['an infinite vertex', [v(0, 0), v(1, 0), v(1, Infinity)], undefined, 'vertices[2]', /finite numbers, got \(1, Infinity\)/],
    [
      'a zero-length edge',
      [v(0, 0), v(0, 0), v(1, 0), v(1, 1)],
      undefined,
      'vertices[1]',
      /^coincides with vertices\[0\] \(polygon edges must be longer than b2_epsilon\)$/,
    ],
    [
      'clockwise vertices',
      [v(0, 0), v(0, 1), v(1, 1), v(1, 0)],
      undefined,
      'vertices',
      /^are clockwise \(signed area -1; vertices must be counter-clockwise and convex\)$/,
    ],
    ['collinear vertices (zero area)', [v(0, 0), v(1, 0), v(2, 0)], undefined, 'vertices', /^enclose an area of 0, which must exceed b2_epsilon$/],
    ['an area below b2_epsilon', [v(0, 0), v(1e-4, 0), v(1e-4, 1e-4)], undefined, 'vertices', /which must exceed b2_epsilon/],
    [
      'a reflex vertex',
      [v(0, 0), v(2, 0), v(1, 0.5), v(2, 2), v(0, 2)],
      undefined,
      'vertices[2]',
      /^makes the polygon non-convex \(vertices must be counter-clockwise and convex\)$/,
    ],
    [
      'a pentagram (every turn left, but self-intersecting)',
      [0, 2, 4, 1, 3].map((k) => v(Math.cos((2 * Math.PI * k) / 5), Math.sin((2 * Math.PI * k) / 5))),
      undefined,
      'vertices[3]',
      /^makes the polygon non-convex/,
    ],
  ];
  for (const [what, vertices, count, argument, rule] of cases) {
    it(`rejects ${what}`, () => {
      const p = new b2PolygonShape().SetAsBox(1, 2);
      const before = polygonState(p);
      expectArgumentError(
        caught(() => p.Set(vertices, count)),
        { method: 'b2PolygonShape.Set', argument, rule },
      );
      expect(polygonState(p)).toEqual(before);
    });
  }

  it('accepts convex counter-clockwise polygons, collinear midpoints included, as 2.2.1 did', () => {
    const p = new b2PolygonShape();
    p.Set([v(0, 0), v(1, 0), v(2, 0), v(2, 1), v(0, 1)]);
    expect(p.m_vertexCount).toBe(5);
    p.Set([0, 1, 2, 3, 4, 5, 6, 7].map((k) => v(Math.cos(k * 0.785), Math.sin(k * 0.785))));
    expect(p.m_vertexCount).toBe(8);
  });

  const boxCases: [string, () => unknown, string, RegExp][] = [
    ['a zero half-width', () => new b2PolygonShape().SetAsBox(0, 1), 'hx', /^must be a finite number > 0, got 0$/],
    ['a negative half-height', () => new b2PolygonShape().SetAsBox(1, -1), 'hy', /got -1$/],
    ['a NaN half-width', () => new b2PolygonShape().SetAsBox(NaN, 1), 'hx', /got NaN$/],
    ['an infinite half-height', () => new b2PolygonShape().SetAsBox(1, Infinity), 'hy', /got Infinity$/],
    ['a non-finite center', () => new b2PolygonShape().SetAsBox(1, 1, v(NaN, 0), 0), 'center', /finite numbers/],
    ['a non-finite angle', () => new b2PolygonShape().SetAsBox(1, 1, v(0, 0), Infinity), 'angle', /^must be a finite number, got Infinity$/],
  ];
  for (const [what, act, argument, rule] of boxCases) {
    it(`SetAsBox rejects ${what}`, () => {
      expectArgumentError(caught(act), { method: 'b2PolygonShape.SetAsBox', argument, rule });
    });
  }
});

describe('b2EdgeShape and b2ChainShape reject degenerate vertices', () => {
  it('rejects a zero-length edge and a non-finite end point', () => {
    const e = new b2EdgeShape().Set(v(0, 0), v(1, 0));
    expectArgumentError(
      caught(() => e.Set(v(1, 1), v(1, 1))),
      {
        method: 'b2EdgeShape.Set',
        argument: 'v2',
        rule: /^coincides with v1 \(an edge must be longer than b2_epsilon\)$/,
      },
    );
    expectArgumentError(
      caught(() => e.Set(v(0, NaN), v(1, 1))),
      { method: 'b2EdgeShape.Set', argument: 'v1', rule: /finite/ },
    );
    expect([e.m_vertex1.x, e.m_vertex1.y, e.m_vertex2.x, e.m_vertex2.y]).toEqual([0, 0, 1, 0]);
  });

  const chainCases: [string, (c: b2ChainShape) => unknown, string, string, RegExp][] = [
    [
      'a chain of one vertex',
      (c) => c.CreateChain([v(0, 0)]),
      'b2ChainShape.CreateChain',
      'count',
      /^must be an integer >= 2 \(a chain needs at least 2 vertices\), got 1$/,
    ],
    ['a loop of two vertices', (c) => c.CreateLoop([v(0, 0), v(1, 0)]), 'b2ChainShape.CreateLoop', 'count', /a loop needs at least 3 vertices\), got 2/],
    [
      'a repeated consecutive vertex',
      (c) => c.CreateChain([v(0, 0), v(1, 0), v(1, 0), v(2, 0)]),
      'b2ChainShape.CreateChain',
      'vertices[2]',
      /^repeats vertices\[1\] \(consecutive chain vertices must be more than b2_epsilon apart\)$/,
    ],
    [
      'a loop whose last vertex is its first',
      (c) => c.CreateLoop([v(0, 0), v(1, 0), v(1, 1), v(0, 0)]),
      'b2ChainShape.CreateLoop',
      'vertices[0]',
      /^closes the loop onto vertices\[3\]/,
    ],
    ['a non-finite vertex', (c) => c.CreateChain([v(0, 0), v(Infinity, 0)]), 'b2ChainShape.CreateChain', 'vertices[1]', /finite/],
    ['a count beyond the array', (c) => c.CreateChain([v(0, 0), v(1, 0)], 3), 'b2ChainShape.CreateChain', 'count', /^is 3 but vertices has only 2 entries$/],
    ['a non-finite prev vertex', (c) => c.SetPrevVertex(v(NaN, NaN)), 'b2ChainShape.SetPrevVertex', 'prevVertex', /finite/],
    ['a non-finite next vertex', (c) => c.SetNextVertex(v(0, NaN)), 'b2ChainShape.SetNextVertex', 'nextVertex', /finite/],
  ];
  for (const [what, act, method, argument, rule] of chainCases) {
    it(`rejects ${what}`, () => {
      const c = new b2ChainShape();
      expectArgumentError(
        caught(() => act(c)),
        { method, argument, rule },
      );
      expect(c.m_count).toBe(0);
      expect(c.m_vertices).toEqual([]);
    });
  }

  it('rejects creating a chain twice', () => {
    const c = new b2ChainShape();
    c.CreateChain([v(0, 0), v(1, 0)]);
    expectArgumentError(
      caught(() => c.CreateLoop([v(0, 0), v(1, 0), v(1, 1)])),
      {
        method: 'b2ChainShape.CreateLoop',
        argument: 'this chain',
        rule: /^already has vertices/,
      },
    );
    expect(c.m_count).toBe(2);
  });
});

describe('b2Body.CreateFixture checks the shape it clones and the def', () => {
  const tiny = () => {
    const p = new b2PolygonShape();
    p.SetAsBox(1e-4, 1e-4);
    return p;
  };
  const cases: [string, () => b2Shape, number, string, RegExp][] = [
    ['a circle of negative radius', () => circle(-1), 1, 'shape.m_radius', /got -1$/],
    ['a circle of NaN radius', () => circle(NaN), 1, 'shape.m_radius', /got NaN$/],
    ['a circle of infinite radius', () => circle(Infinity), 1, 'shape.m_radius', /got Infinity$/],
    [
      'a circle at a non-finite position',
      () => {
        const c = circle(1);
        c.m_p.Set(NaN, 0);
        return c;
      },
      1,
      'shape.m_p',
      /finite/,
    ],
    ['a polygon never set (no vertices)', () => new b2PolygonShape(), 1, 'shape.m_vertexCount', /in \[3, 8\], got 0$/],
    [
      'a polygon whose vertices were made non-convex',
      () => {
        const p = box(1, 1);
        p.m_vertices[2].Set(0, -0.5);
        return p;
      },
      1,
      'shape.m_vertices[2]',
      /non-convex/,
    ],
    [
      'a polygon with a NaN normal',
      () => {
        const p = box(1, 1);
        p.m_normals[1].x = NaN;
        return p;
      },
      1,
      'shape.m_normals[1]',
      /finite/,
    ],
    ['a polygon too small to have mass, with density', tiny, 1, 'shape.m_vertices', /which must exceed b2_epsilon/],
    [
      'a polygon with a negative radius',
      () => {
        const p = box(1, 1);
        p.m_radius = -0.1;
        return p;
      },
      1,
      'shape.m_radius',
      /must be a finite number >= 0, got -0.1/,
    ],
    [
      'an edge of zero length',
      () => {
        const e = new b2EdgeShape().Set(v(0, 0), v(1, 0));
        e.m_vertex2.Set(0, 0);
        return e;
      },
      0,
      'shape.m_vertex2',
      /^coincides with shape.m_vertex1/,
    ],
    [
      'an edge with a non-finite ghost vertex',
      () => {
        const e = new b2EdgeShape().Set(v(0, 0), v(1, 0));
        e.m_hasVertex0 = true;
        e.m_vertex0.Set(NaN, 0);
        return e;
      },
      0,
      'shape.m_vertex0',
      /finite/,
    ],
    ['a chain never created', () => new b2ChainShape(), 0, 'shape.m_count', /a chain needs at least 2 vertices\), got 0/],
    [
      'a chain with a repeated vertex',
      () => {
        const c = new b2ChainShape();
        c.CreateChain([v(0, 0), v(1, 0), v(2, 0)]);
        c.m_vertices[2].Set(1, 0);
        return c;
      },
      0,
      'shape.m_vertices[2]',
      /repeats shape.m_vertices\[1\]/,
    ],
    [
      'a shape of unknown type',
      () => {
        const c = circle(1);
        c.m_type = 7;
        return c;
      },
      0,
      'shape.m_type',
      /got 7$/,
    ],
  ];
  for (const [what, shape, density, argument, rule] of cases) {
    it(`rejects ${what}`, () => {
      const { world, box: body } = makeScene();
      expectRejected(world, () => body.CreateFixture(shape(), density), { method: 'b2Body.CreateFixture', argument, rule });
    });
  }

  it('accepts a tiny polygon without density, as 2.2.1 does', () => {
    const { world, ground } = makeScene();
    const f = ground.CreateFixture(tiny(), 0);
    expect(f.m_proxyCount).toBe(1);
    world.Step(h, 8, 3);
  });

  const defCases: [string, (d: b2FixtureDef) => void, string, RegExp][] = [
    ['no shape', (d) => (d.shape = null), 'def.shape', /^must be set$/],
    ['a negative density', (d) => (d.density = -1), 'def.density', /^must be a finite number >= 0, got -1$/],
    ['a NaN density', (d) => (d.density = NaN), 'def.density', /got NaN$/],
    ['a negative friction', (d) => (d.friction = -0.5), 'def.friction', /got -0.5$/],
    ['an infinite friction', (d) => (d.friction = Infinity), 'def.friction', /got Infinity$/],
    ['a negative restitution', (d) => (d.restitution = -1), 'def.restitution', /got -1$/],
    ['a NaN restitution', (d) => (d.restitution = NaN), 'def.restitution', /got NaN$/],
    ['a bad def.shape', (d) => (d.shape = {} as b2Shape), 'def.shape', /^must be a b2Shape, got an object$/],
  ];
  for (const [what, edit, argument, rule] of defCases) {
    it(`rejects a fixture def with ${what}`, () => {
      const { world, box: body } = makeScene();
      const def = new b2FixtureDef();
      def.shape = box(0.2, 0.2);
      def.density = 1;
      edit(def);
      expectRejected(world, () => body.CreateFixture(def), { method: 'b2Body.CreateFixture', argument, rule });
    });
  }

  it('rejects a negative density passed with a shape', () => {
    const { world, box: body } = makeScene();
    expectRejected(world, () => body.CreateFixture(box(0.2, 0.2), -2), {
      method: 'b2Body.CreateFixture',
      argument: 'density',
      rule: /got -2$/,
    });
  });
});

describe('b2World.CreateBody checks the body def', () => {
  const cases: [string, (d: b2BodyDef) => void, string, RegExp][] = [
    [
      'a type out of range',
      (d) => (d.type = 3 as b2BodyType),
      'def.type',
      /^must be b2_staticBody \(0\), b2_kinematicBody \(1\) or b2_dynamicBody \(2\), got 3$/,
    ],
    ['a fractional type', (d) => (d.type = 1.5 as b2BodyType), 'def.type', /got 1.5$/],
    ['a NaN position', (d) => d.position.Set(NaN, 0), 'def.position', /^must be a vector of finite numbers, got \(NaN, 0\)$/],
    ['an infinite angle', (d) => (d.angle = Infinity), 'def.angle', /^must be a finite number, got Infinity$/],
    ['a NaN linear velocity', (d) => d.linearVelocity.Set(0, NaN), 'def.linearVelocity', /\(0, NaN\)/],
    ['a NaN angular velocity', (d) => (d.angularVelocity = NaN), 'def.angularVelocity', /got NaN$/],
    ['a negative linear damping', (d) => (d.linearDamping = -0.1), 'def.linearDamping', /^must be a finite number >= 0, got -0.1$/],
    ['a NaN angular damping', (d) => (d.angularDamping = NaN), 'def.angularDamping', /got NaN$/],
    ['an infinite gravity scale', (d) => (d.gravityScale = -Infinity), 'def.gravityScale', /got -Infinity$/],
  ];
  for (const [what, edit, argument, rule] of cases) {
    it(`rejects ${what}`, () => {
      const { world } = makeScene();
      const def = new b2BodyDef();
      def.type = b2BodyType.b2_dynamicBody;
      edit(def);
      expectRejected(world, () => world.CreateBody(def), { method: 'b2World.CreateBody', argument, rule });
    });
  }

  it('rejects a missing def', () => {
    const { world } = makeScene();
    expectRejected(world, () => world.CreateBody(null as unknown as b2BodyDef), {
      method: 'b2World.CreateBody',
      argument: 'def',
      rule: /^must be set, got null$/,
    });
  });
});

describe('b2Body setters reject non-finite or out-of-range values', () => {
  const cases: [string, (s: Scene) => unknown, string, string, RegExp][] = [
    ['SetTransform with a NaN position', (s) => s.box.SetTransform(v(NaN, 1), 0), 'b2Body.SetTransform', 'position', /\(NaN, 1\)/],
    ['SetTransform with an infinite angle', (s) => s.box.SetTransform(v(0, 1), Infinity), 'b2Body.SetTransform', 'angle', /Infinity/],
    ['SetLinearVelocity with NaN', (s) => s.box.SetLinearVelocity(v(NaN, 0)), 'b2Body.SetLinearVelocity', 'v', /NaN/],
    ['SetAngularVelocity with Infinity', (s) => s.box.SetAngularVelocity(Infinity), 'b2Body.SetAngularVelocity', 'w', /Infinity/],
    ['ApplyForce with a NaN force', (s) => s.box.ApplyForce(v(NaN, 0), v(0, 0)), 'b2Body.ApplyForce', 'force', /NaN/],
    ['ApplyForce with an infinite point', (s) => s.box.ApplyForce(v(1, 0), v(Infinity, 0)), 'b2Body.ApplyForce', 'point', /Infinity/],
    ['ApplyForceToCenter with NaN', (s) => s.box.ApplyForceToCenter(v(0, NaN)), 'b2Body.ApplyForceToCenter', 'force', /NaN/],
    ['ApplyTorque with NaN', (s) => s.box.ApplyTorque(NaN), 'b2Body.ApplyTorque', 'torque', /NaN/],
    ['ApplyLinearImpulse with Infinity', (s) => s.box.ApplyLinearImpulse(v(Infinity, 0), v(0, 0)), 'b2Body.ApplyLinearImpulse', 'impulse', /Infinity/],
    ['ApplyLinearImpulse with a NaN point', (s) => s.box.ApplyLinearImpulse(v(1, 0), v(0, NaN)), 'b2Body.ApplyLinearImpulse', 'point', /NaN/],
    ['ApplyAngularImpulse with NaN', (s) => s.box.ApplyAngularImpulse(NaN), 'b2Body.ApplyAngularImpulse', 'impulse', /NaN/],
    ['SetLinearDamping below 0', (s) => s.box.SetLinearDamping(-1), 'b2Body.SetLinearDamping', 'linearDamping', />= 0, got -1/],
    ['SetAngularDamping with NaN', (s) => s.box.SetAngularDamping(NaN), 'b2Body.SetAngularDamping', 'angularDamping', /NaN/],
    ['SetGravityScale with NaN', (s) => s.box.SetGravityScale(NaN), 'b2Body.SetGravityScale', 'scale', /NaN/],
    ['SetType with an unknown type', (s) => s.box.SetType(5 as b2BodyType), 'b2Body.SetType', 'type', /got 5$/],
    [
      'SetType making a body a mouse joint drags static',
      (s) => s.mouse.GetBodyB().SetType(b2BodyType.b2_staticBody),
      'b2Body.SetType',
      'type',
      /^must stay b2_dynamicBody while a mouse joint drags this body \(destroy the mouse joint first\)$/,
    ],
    [
      'SetMassData with a NaN mass',
      (s) => {
        const m = new b2MassData();
        m.mass = NaN;
        s.box.SetMassData(m);
      },
      'b2Body.SetMassData',
      'massData.mass',
      /NaN/,
    ],
    [
      'SetMassData with an inertia below m |c|^2',
      (s) => {
        const m = new b2MassData();
        m.mass = 2;
        m.I = 1;
        m.center.Set(1, 0);
        s.box.SetMassData(m);
      },
      'b2Body.SetMassData',
      'massData.I',
      /^must exceed mass \* \|center\|\^2 \(the rotational inertia about the center of mass must be positive\), got 1$/,
    ],
    ['SetMassData with no mass data', (s) => s.box.SetMassData(null as unknown as b2MassData), 'b2Body.SetMassData', 'massData', /must be set/],
  ];
  for (const [what, act, method, argument, rule] of cases) {
    it(`rejects ${what}`, () => {
      const scene = makeScene();
      expectRejected(scene.world, () => act(scene), { method, argument, rule });
    });
  }

  it('still ignores valid impulses on static bodies as Box2D does (checked before the early return)', () => {
    const scene = makeScene();
    scene.ground.ApplyLinearImpulse(v(1, 1), v(0, 0));
    expectRejected(scene.world, () => scene.ground.ApplyLinearImpulse(v(NaN, 1), v(0, 0)), {
      method: 'b2Body.ApplyLinearImpulse',
      argument: 'impulse',
      rule: /NaN/,
    });
  });
});

describe('b2Fixture setters reject bad values', () => {
  const cases: [string, (f: b2Fixture) => unknown, string, string, RegExp][] = [
    ['a negative density', (f) => f.SetDensity(-1), 'b2Fixture.SetDensity', 'density', />= 0, got -1/],
    ['a NaN friction', (f) => f.SetFriction(NaN), 'b2Fixture.SetFriction', 'friction', /NaN/],
    ['a negative restitution', (f) => f.SetRestitution(-0.1), 'b2Fixture.SetRestitution', 'restitution', /-0.1/],
    ['a missing filter', (f) => f.SetFilterData(null as unknown as b2Filter), 'b2Fixture.SetFilterData', 'filter', /must be set/],
    ['a child index out of range', (f) => f.GetAABB(1), 'b2Fixture.GetAABB', 'childIndex', /^must be an integer in \[0, 1\)/],
  ];
  for (const [what, act, method, argument, rule] of cases) {
    it(`rejects ${what}`, () => {
      const scene = makeScene();
      expectRejected(scene.world, () => act(scene.boxFixture), { method, argument, rule });
    });
  }
});

describe('b2World rejects bad step arguments, gravity, queries and ray casts', () => {
  const cases: [string, (w: b2World) => unknown, string, string, RegExp][] = [
    ['a NaN time step', (w) => w.Step(NaN, 8, 3), 'b2World.Step', 'dt', /^must be a finite number >= 0, got NaN$/],
    ['a negative time step', (w) => w.Step(-h, 8, 3), 'b2World.Step', 'dt', /got -0.01666/],
    ['an infinite time step', (w) => w.Step(Infinity, 8, 3), 'b2World.Step', 'dt', /got Infinity/],
    ['negative velocity iterations', (w) => w.Step(h, -1, 3), 'b2World.Step', 'velocityIterations', /^must be an integer in \[0, 2147483647\], got -1$/],
    ['fractional velocity iterations', (w) => w.Step(h, 7.5, 3), 'b2World.Step', 'velocityIterations', /got 7.5$/],
    ['NaN position iterations', (w) => w.Step(h, 8, NaN), 'b2World.Step', 'positionIterations', /got NaN$/],
    ['a NaN gravity', (w) => w.SetGravity(v(0, NaN)), 'b2World.SetGravity', 'gravity', /\(0, NaN\)/],
    [
      'a query without a callback',
      (w) => w.QueryAABB(null as unknown as b2QueryCallback, new b2AABB()),
      'b2World.QueryAABB',
      'callback',
      /ReportFixture method, got null/,
    ],
    [
      'a query box with NaN',
      (w) => {
        const aabb = new b2AABB();
        aabb.upperBound.Set(NaN, 1);
        w.QueryAABB({ ReportFixture: () => true }, aabb);
      },
      'b2World.QueryAABB',
      'aabb.upperBound',
      /NaN/,
    ],
    ['a ray from a NaN point', (w) => w.RayCast({ ReportFixture: () => 1 }, v(NaN, 0), v(1, 1)), 'b2World.RayCast', 'point1', /NaN/],
    [
      'a ray of zero length',
      (w) => w.RayCast({ ReportFixture: () => 1 }, v(1, 1), v(1, 1)),
      'b2World.RayCast',
      'point2',
      /^must differ from point1 \(\|point2 - point1\|\^2 must be > 0\)$/,
    ],
    [
      'a ray whose length squared underflows',
      (w) => w.RayCast({ ReportFixture: () => 1 }, v(0, 0), v(0, -5e-324)),
      'b2World.RayCast',
      'point2',
      /^must differ from point1/,
    ],
    ['a ray without a callback', (w) => w.RayCast({} as b2RayCastCallback, v(0, 0), v(1, 1)), 'b2World.RayCast', 'callback', /an object$/],
  ];
  for (const [what, act, method, argument, rule] of cases) {
    it(`rejects ${what}`, () => {
      const { world } = makeScene();
      expectRejected(world, () => act(world), { method, argument, rule });
    });
  }

  it('rejects a world with non-finite gravity', () => {
    expectArgumentError(
      caught(() => new b2World(v(Infinity, 0))),
      { method: 'new b2World', argument: 'gravity', rule: /Infinity/ },
    );
  });

  it('accepts a zero time step and zero iterations', () => {
    const { world } = makeScene();
    world.Step(0, 0, 0);
    world.Step(h, 0, 0);
    expect(checkWorldInvariants(world)).toEqual([]);
  });
});

describe('b2World.CreateJoint checks the joint def', () => {
  type Make = (s: Scene) => b2JointDef;
  const revolute: Make = (s) => {
    const d = new b2RevoluteJointDef();
    d.Initialize(s.ground, s.box, v(0, 1));
    return d;
  };
  const prismatic: Make = (s) => {
    const d = new b2PrismaticJointDef();
    d.Initialize(s.ground, s.box, v(0, 1), v(1, 0));
    return d;
  };
  const distance: Make = (s) => {
    const d = new b2DistanceJointDef();
    d.Initialize(s.ground, s.box, v(0, 3), s.box.GetPosition());
    return d;
  };
  const pulley: Make = (s) => {
    const d = new b2PulleyJointDef();
    d.Initialize(s.box, s.ball, v(0, 5), v(2, 5), s.box.GetPosition(), s.ball.GetPosition(), 1);
    return d;
  };
  const mouse: Make = (s) => {
    const d = new b2MouseJointDef();
    d.bodyA = s.ground;
    d.bodyB = s.box;
    d.target.Set(0, 1.5);
    d.maxForce = 10;
    return d;
  };
  const gear: Make = (s) => {
    const d = new b2GearJointDef();
    d.bodyA = s.revolute.GetBodyB();
    d.bodyB = s.prismatic.GetBodyB();
    d.joint1 = s.revolute;
    d.joint2 = s.prismatic;
    return d;
  };
  const wheel: Make = (s) => {
    const d = new b2WheelJointDef();
    d.Initialize(s.ground, s.ball, s.ball.GetPosition(), v(0, 1));
    return d;
  };
  const weld: Make = (s) => {
    const d = new b2WeldJointDef();
    d.Initialize(s.box, s.ball, v(1, 1.5));
    return d;
  };
  const friction: Make = (s) => {
    const d = new b2FrictionJointDef();
    d.Initialize(s.ground, s.box, s.box.GetPosition());
    return d;
  };
  const rope: Make = (s) => {
    const d = new b2RopeJointDef();
    d.bodyA = s.box;
    d.bodyB = s.ball;
    d.maxLength = 3;
    return d;
  };
  const other = new b2World(v(0, 0));
  const stranger = other.CreateBody(new b2BodyDef());

  const cases: [string, Make, (d: any, s: Scene) => void, string, RegExp][] = [
    ['a missing def', revolute, () => undefined, 'def', /must be set/],
    ['a missing bodyA', revolute, (d) => (d.bodyA = null), 'def.bodyA', /^must be a b2Body, got null$/],
    ['a body joined to itself', revolute, (d) => (d.bodyB = d.bodyA), 'def.bodyB', /^is def.bodyA \(a joint connects two different bodies\)$/],
    ['a body from another world', revolute, (d) => (d.bodyB = stranger), 'def.bodyB', /^belongs to another world$/],
    [
      'a destroyed body',
      revolute,
      (d, s) => {
        const b = dynamicBody(s.world, 30, 30);
        s.world.DestroyBody(b);
        d.bodyB = b;
      },
      'def.bodyB',
      /^has been destroyed$/,
    ],
    [
      'an unknown joint type',
      () => {
        const d = new b2JointDef();
        return d;
      },
      (d, s) => {
        d.bodyA = s.ground;
        d.bodyB = s.box;
      },
      'def.type',
      /^must be a joint type \(use a b2XxxJointDef\), got e_unknownJoint$/,
    ],
    ['a revolute NaN lower limit', revolute, (d) => (d.lowerAngle = NaN), 'def.lowerAngle', /NaN/],
    ['a revolute NaN reference angle', revolute, (d) => (d.referenceAngle = NaN), 'def.referenceAngle', /NaN/],
    ['a revolute negative motor torque', revolute, (d) => (d.maxMotorTorque = -5), 'def.maxMotorTorque', />= 0, got -5/],
    ['a revolute infinite motor speed', revolute, (d) => (d.motorSpeed = Infinity), 'def.motorSpeed', /Infinity/],
    ['a revolute NaN anchor', revolute, (d) => d.localAnchorA.Set(NaN, 0), 'def.localAnchorA', /NaN/],
    ['a prismatic zero axis', prismatic, (d) => d.localAxisA.Set(0, 0), 'def.localAxisA', /^must not be the zero vector/],
    ['a prismatic infinite upper limit', prismatic, (d) => (d.upperTranslation = Infinity), 'def.upperTranslation', /Infinity/],
    ['a prismatic negative motor force', prismatic, (d) => (d.maxMotorForce = -1), 'def.maxMotorForce', /-1/],
    ['a negative distance length', distance, (d) => (d.length = -1), 'def.length', />= 0, got -1/],
    ['a distance NaN frequency', distance, (d) => (d.frequencyHz = NaN), 'def.frequencyHz', /NaN/],
    ['a distance negative damping ratio', distance, (d) => (d.dampingRatio = -1), 'def.dampingRatio', /-1/],
    ['a zero pulley ratio', pulley, (d) => (d.ratio = 0), 'def.ratio', /^must not be 0$/],
    ['a NaN pulley ratio', pulley, (d) => (d.ratio = NaN), 'def.ratio', /got NaN/],
    ['a negative pulley length', pulley, (d) => (d.lengthA = -1), 'def.lengthA', />= 0, got -1/],
    ['a NaN pulley ground anchor', pulley, (d) => d.groundAnchorB.Set(NaN, 0), 'def.groundAnchorB', /NaN/],
    ['a mouse joint with negative max force', mouse, (d) => (d.maxForce = -1), 'def.maxForce', /-1/],
    ['a mouse joint with zero frequency', mouse, (d) => (d.frequencyHz = 0), 'def.frequencyHz', /> 0, got 0/],
    ['a mouse joint with a NaN target', mouse, (d) => d.target.Set(NaN, 0), 'def.target', /NaN/],
    ['a mouse joint with negative damping', mouse, (d) => (d.dampingRatio = -0.5), 'def.dampingRatio', /-0.5/],
    [
      'a mouse joint on a static body',
      mouse,
      (d, s) => ((d.bodyA = s.ball), (d.bodyB = s.ground)),
      'def.bodyB',
      /^must be a dynamic body \(the mouse joint drags body B by its mass\)$/,
    ],
    ['a gear without joint1', gear, (d) => (d.joint1 = null), 'def.joint1', /^must be a b2Joint, got null$/],
    [
      'a gear coupling a distance joint',
      gear,
      (d, s) => (d.joint2 = s.distance),
      'def.joint2',
      /^must be a revolute or prismatic joint, got a e_distanceJoint$/,
    ],
    ['a gear coupling a joint with itself', gear, (d) => (d.joint2 = d.joint1), 'def.joint2', /^is def.joint1/],
    [
      'a gear coupling a destroyed joint',
      gear,
      (d, s) => {
        const j = s.world.CreateJoint(revolute(s));
        s.world.DestroyJoint(j);
        d.joint1 = j;
      },
      'def.joint1',
      /^has been destroyed$/,
    ],
    ['a gear with a NaN ratio', gear, (d) => (d.ratio = NaN), 'def.ratio', /NaN/],
    ['a wheel zero axis', wheel, (d) => d.localAxisA.Set(0, 0), 'def.localAxisA', /zero vector/],
    ['a wheel negative spring frequency', wheel, (d) => (d.frequencyHz = -2), 'def.frequencyHz', /-2/],
    ['a weld negative damping', weld, (d) => (d.dampingRatio = -1), 'def.dampingRatio', /-1/],
    ['a weld NaN reference angle', weld, (d) => (d.referenceAngle = NaN), 'def.referenceAngle', /NaN/],
    ['a friction negative max force', friction, (d) => (d.maxForce = -1), 'def.maxForce', /-1/],
    ['a friction infinite max torque', friction, (d) => (d.maxTorque = Infinity), 'def.maxTorque', /Infinity/],
    ['a rope of negative length', rope, (d) => (d.maxLength = -1), 'def.maxLength', />= 0, got -1/],
    ['a rope of NaN length', rope, (d) => (d.maxLength = NaN), 'def.maxLength', /NaN/],
  ];
  for (const [what, make, edit, argument, rule] of cases) {
    it(`rejects ${what}`, () => {
      const s = makeScene();
      let def: b2JointDef | undefined = make(s);
      if (what === 'a missing def') def = undefined;
      else edit(def, s);
      expectRejected(s.world, () => s.world.CreateJoint(def as b2JointDef), { method: 'b2World.CreateJoint', argument, rule });
    });
  }

  it('accepts each valid def (the makers above are valid)', () => {
    const s = makeScene();
    for (const make of [revolute, prismatic, distance, pulley, mouse, gear, wheel, weld, friction, rope]) {
      s.world.CreateJoint(make(s));
    }
    for (let i = 0; i < 30; ++i) s.world.Step(h, 8, 3);
    expect(checkWorldInvariants(s.world)).toEqual([]);
  });
});

describe('joint setters reject bad values', () => {
  const cases: [string, (s: Scene) => unknown, string, string, RegExp][] = [
    ['revolute SetLimits with lower above upper', (s) => s.revolute.SetLimits(1, 0), 'b2RevoluteJoint.SetLimits', 'lower', /^must not exceed upper \(1 > 0\)$/],
    ['revolute SetLimits with NaN', (s) => s.revolute.SetLimits(NaN, 0), 'b2RevoluteJoint.SetLimits', 'lower', /NaN/],
    ['revolute SetMotorSpeed with NaN', (s) => s.revolute.SetMotorSpeed(NaN), 'b2RevoluteJoint.SetMotorSpeed', 'speed', /NaN/],
    ['revolute SetMaxMotorTorque below 0', (s) => s.revolute.SetMaxMotorTorque(-1), 'b2RevoluteJoint.SetMaxMotorTorque', 'torque', /-1/],
    ['prismatic SetLimits with lower above upper', (s) => s.prismatic.SetLimits(2, 1), 'b2PrismaticJoint.SetLimits', 'lower', /2 > 1/],
    ['prismatic SetMaxMotorForce below 0', (s) => s.prismatic.SetMaxMotorForce(-1), 'b2PrismaticJoint.SetMaxMotorForce', 'force', /-1/],
    ['prismatic SetMotorSpeed with Infinity', (s) => s.prismatic.SetMotorSpeed(Infinity), 'b2PrismaticJoint.SetMotorSpeed', 'speed', /Infinity/],
    ['distance SetLength below 0', (s) => s.distance.SetLength(-1), 'b2DistanceJoint.SetLength', 'length', /-1/],
    ['distance SetFrequency with NaN', (s) => s.distance.SetFrequency(NaN), 'b2DistanceJoint.SetFrequency', 'hz', /NaN/],
    ['distance SetDampingRatio below 0', (s) => s.distance.SetDampingRatio(-1), 'b2DistanceJoint.SetDampingRatio', 'ratio', /-1/],
    ['mouse SetTarget with NaN', (s) => s.mouse.SetTarget(v(NaN, 0)), 'b2MouseJoint.SetTarget', 'target', /NaN/],
    ['mouse SetMaxForce below 0', (s) => s.mouse.SetMaxForce(-1), 'b2MouseJoint.SetMaxForce', 'force', /-1/],
    ['mouse SetFrequency of 0', (s) => s.mouse.SetFrequency(0), 'b2MouseJoint.SetFrequency', 'hz', /> 0, got 0/],
    ['mouse SetDampingRatio with NaN', (s) => s.mouse.SetDampingRatio(NaN), 'b2MouseJoint.SetDampingRatio', 'ratio', /NaN/],
    ['rope SetMaxLength of 0', (s) => s.rope.SetMaxLength(0), 'b2RopeJoint.SetMaxLength', 'length', /> 0, got 0/],
    ['weld SetFrequency below 0', (s) => s.weld.SetFrequency(-1), 'b2WeldJoint.SetFrequency', 'hz', /-1/],
    ['weld SetDampingRatio with NaN', (s) => s.weld.SetDampingRatio(NaN), 'b2WeldJoint.SetDampingRatio', 'ratio', /NaN/],
    ['wheel SetSpringFrequencyHz below 0', (s) => s.wheel.SetSpringFrequencyHz(-1), 'b2WheelJoint.SetSpringFrequencyHz', 'hz', /-1/],
    ['wheel SetSpringDampingRatio with NaN', (s) => s.wheel.SetSpringDampingRatio(NaN), 'b2WheelJoint.SetSpringDampingRatio', 'ratio', /NaN/],
    ['wheel SetMaxMotorTorque below 0', (s) => s.wheel.SetMaxMotorTorque(-3), 'b2WheelJoint.SetMaxMotorTorque', 'torque', /-3/],
    ['wheel SetMotorSpeed with NaN', (s) => s.wheel.SetMotorSpeed(NaN), 'b2WheelJoint.SetMotorSpeed', 'speed', /NaN/],
    ['friction SetMaxForce below 0', (s) => s.friction.SetMaxForce(-1), 'b2FrictionJoint.SetMaxForce', 'force', /-1/],
    ['friction SetMaxTorque with Infinity', (s) => s.friction.SetMaxTorque(Infinity), 'b2FrictionJoint.SetMaxTorque', 'torque', /Infinity/],
    ['gear SetRatio with NaN', (s) => s.gear.SetRatio(NaN), 'b2GearJoint.SetRatio', 'ratio', /NaN/],
  ];
  for (const [what, act, method, argument, rule] of cases) {
    it(`rejects ${what}`, () => {
      const scene = makeScene();
      expectRejected(scene.world, () => act(scene), { method, argument, rule });
    });
  }
});

describe('destroyed bodies, fixtures and joints are rejected', () => {
  const destroyedRule = /^has been destroyed$/;

  it('DestroyBody twice throws, naming the body', () => {
    const { world, ball } = makeScene();
    world.DestroyBody(ball);
    expectRejected(world, () => world.DestroyBody(ball), { method: 'b2World.DestroyBody', argument: 'body', rule: destroyedRule });
  });

  it('DestroyBody of a body of another world throws', () => {
    const { world } = makeScene();
    const other = new b2World(v(0, -10));
    const b = other.CreateBody(new b2BodyDef());
    expectRejected(world, () => world.DestroyBody(b), { method: 'b2World.DestroyBody', argument: 'body', rule: /^belongs to another world$/ });
    expect(other.GetBodyCount()).toBe(1);
  });

  it('DestroyJoint twice throws, and so does destroying a joint its body took with it', () => {
    const s = makeScene();
    s.world.DestroyJoint(s.weld);
    expectRejected(s.world, () => s.world.DestroyJoint(s.weld), { method: 'b2World.DestroyJoint', argument: 'joint', rule: destroyedRule });
    s.world.DestroyBody(s.distance.GetBodyB());
    expectRejected(s.world, () => s.world.DestroyJoint(s.distance), { method: 'b2World.DestroyJoint', argument: 'joint', rule: destroyedRule });
  });

  it('DestroyJoint of a joint of another world throws', () => {
    const s = makeScene();
    const t = makeScene();
    expectRejected(s.world, () => s.world.DestroyJoint(t.weld), { method: 'b2World.DestroyJoint', argument: 'joint', rule: /another world/ });
  });

  it('DestroyJoint of a joint a gear couples throws until the gear is destroyed', () => {
    const s = makeScene();
    expectRejected(s.world, () => s.world.DestroyJoint(s.revolute), {
      method: 'b2World.DestroyJoint',
      argument: 'joint',
      rule: /^is coupled by a gear joint \(destroy the gear joint first\)$/,
    });
    s.world.DestroyJoint(s.gear);
    s.world.DestroyJoint(s.revolute);
    expect(checkWorldInvariants(s.world)).toEqual([]);
  });

  it("DestroyBody of a body whose joint a gear on other bodies couples throws; the gear's own body takes it along", () => {
    const s = makeScene();
    // The gear couples revolute (ground - b1) and another revolute (ground - b9): destroying the ground would leave it.
    expectRejected(s.world, () => s.world.DestroyBody(s.ground), {
      method: 'b2World.DestroyBody',
      argument: 'body',
      rule: /^has a joint that a gear joint on other bodies couples \(destroy the gear joint first\)$/,
    });
    // b1 carries the gear itself: its joints and the gear go together.
    const joints = s.world.GetJointCount();
    s.world.DestroyBody(s.revolute.GetBodyB());
    expect(s.world.GetJointCount()).toBe(joints - 2);
    expect(s.gear.m_destroyed && s.revolute.m_destroyed).toBe(true);
    for (let i = 0; i < 10; ++i) s.world.Step(h, 8, 3);
    expect(checkWorldInvariants(s.world)).toEqual([]);
  });

  it('DestroyFixture twice, or with another body, throws', () => {
    const s = makeScene();
    const f = s.box.CreateFixture(box(0.1, 0.1), 1);
    s.box.DestroyFixture(f);
    expectRejected(s.world, () => s.box.DestroyFixture(f), { method: 'b2Body.DestroyFixture', argument: 'fixture', rule: destroyedRule });
    expectRejected(s.world, () => s.ball.DestroyFixture(s.boxFixture), {
      method: 'b2Body.DestroyFixture',
      argument: 'fixture',
      rule: /^belongs to another body$/,
    });
  });

  const bodyCalls: [string, (b: b2Body) => unknown][] = [
    ['CreateFixture', (b) => b.CreateFixture(box(1, 1), 1)],
    ['DestroyFixture', (b) => b.DestroyFixture({ m_destroyed: false, m_body: b } as unknown as b2Fixture)],
    ['SetTransform', (b) => b.SetTransform(v(0, 0), 0)],
    ['SetLinearVelocity', (b) => b.SetLinearVelocity(v(1, 0))],
    ['SetAngularVelocity', (b) => b.SetAngularVelocity(1)],
    ['ApplyForce', (b) => b.ApplyForce(v(1, 0), v(0, 0))],
    ['ApplyForceToCenter', (b) => b.ApplyForceToCenter(v(1, 0))],
    ['ApplyTorque', (b) => b.ApplyTorque(1)],
    ['ApplyLinearImpulse', (b) => b.ApplyLinearImpulse(v(1, 0), v(0, 0))],
    ['ApplyAngularImpulse', (b) => b.ApplyAngularImpulse(1)],
    ['SetMassData', (b) => b.SetMassData(new b2MassData())],
    ['ResetMassData', (b) => b.ResetMassData()],
    ['SetLinearDamping', (b) => b.SetLinearDamping(1)],
    ['SetAngularDamping', (b) => b.SetAngularDamping(1)],
    ['SetGravityScale', (b) => b.SetGravityScale(1)],
    ['SetType', (b) => b.SetType(b2BodyType.b2_staticBody)],
    ['SetBullet', (b) => b.SetBullet(true)],
    ['SetSleepingAllowed', (b) => b.SetSleepingAllowed(false)],
    ['SetActive', (b) => b.SetActive(false)],
    ['SetFixedRotation', (b) => b.SetFixedRotation(true)],
  ];
  for (const [name, call] of bodyCalls) {
    it(`b2Body.${name} on a destroyed body throws`, () => {
      const s = makeScene();
      s.world.DestroyBody(s.ball);
      expectRejected(s.world, () => call(s.ball), { method: `b2Body.${name}`, argument: 'this body', rule: destroyedRule });
    });
  }

  const fixtureCalls: [string, (f: b2Fixture) => unknown][] = [
    ['SetSensor', (f) => f.SetSensor(true)],
    ['SetFilterData', (f) => f.SetFilterData(new b2Filter())],
    ['Refilter', (f) => f.Refilter()],
    ['TestPoint', (f) => f.TestPoint(v(0, 0))],
    ['GetMassData', (f) => f.GetMassData(new b2MassData())],
    ['SetDensity', (f) => f.SetDensity(1)],
    ['SetFriction', (f) => f.SetFriction(1)],
    ['SetRestitution', (f) => f.SetRestitution(1)],
    ['GetAABB', (f) => f.GetAABB(0)],
  ];
  for (const [name, call] of fixtureCalls) {
    it(`b2Fixture.${name} on a destroyed fixture throws (DestroyBody destroys its fixtures)`, () => {
      const s = makeScene();
      s.world.DestroyBody(s.box);
      expectRejected(s.world, () => call(s.boxFixture), { method: `b2Fixture.${name}`, argument: 'this fixture', rule: destroyedRule });
    });
  }

  const jointCalls: [string, (s: Scene) => [b2Joint, () => unknown]][] = [
    ['b2RevoluteJoint.EnableLimit', (s) => [s.revolute, () => s.revolute.EnableLimit(false)]],
    ['b2RevoluteJoint.SetLimits', (s) => [s.revolute, () => s.revolute.SetLimits(0, 1)]],
    ['b2RevoluteJoint.EnableMotor', (s) => [s.revolute, () => s.revolute.EnableMotor(true)]],
    ['b2PrismaticJoint.SetMotorSpeed', (s) => [s.prismatic, () => s.prismatic.SetMotorSpeed(1)]],
    ['b2DistanceJoint.SetLength', (s) => [s.distance, () => s.distance.SetLength(1)]],
    ['b2MouseJoint.SetTarget', (s) => [s.mouse, () => s.mouse.SetTarget(v(0, 0))]],
    ['b2RopeJoint.SetMaxLength', (s) => [s.rope, () => s.rope.SetMaxLength(1)]],
    ['b2WeldJoint.SetFrequency', (s) => [s.weld, () => s.weld.SetFrequency(1)]],
    ['b2WheelJoint.EnableMotor', (s) => [s.wheel, () => s.wheel.EnableMotor(true)]],
    ['b2FrictionJoint.SetMaxForce', (s) => [s.friction, () => s.friction.SetMaxForce(1)]],
    ['b2GearJoint.SetRatio', (s) => [s.gear, () => s.gear.SetRatio(1)]],
  ];
  for (const [method, make] of jointCalls) {
    it(`${method} on a destroyed joint throws`, () => {
      const s = makeScene();
      const [joint, call] = make(s);
      if (joint === s.revolute) s.world.DestroyJoint(s.gear);
      s.world.DestroyJoint(joint);
      expectRejected(s.world, call, { method, argument: 'this joint', rule: destroyedRule });
    });
  }
});

describe('calls the lock forbids throw with one wording', () => {
  const lockedRule = /^is locked \(called during a time step or a callback\)$/;
  const calls: [string, (s: Scene) => unknown][] = [
    ['b2World.CreateBody', (s) => s.world.CreateBody(new b2BodyDef())],
    ['b2World.DestroyBody', (s) => s.world.DestroyBody(s.ball)],
    [
      'b2World.CreateJoint',
      (s) => {
        const d = new b2WeldJointDef();
        d.Initialize(s.box, s.ball, v(1, 1));
        return s.world.CreateJoint(d);
      },
    ],
    ['b2World.DestroyJoint', (s) => s.world.DestroyJoint(s.weld)],
    ['b2World.Step', (s) => s.world.Step(h, 8, 3)],
    ['b2Body.CreateFixture', (s) => s.box.CreateFixture(box(0.1, 0.1), 1)],
    ['b2Body.DestroyFixture', (s) => s.box.DestroyFixture(s.boxFixture)],
    ['b2Body.SetTransform', (s) => s.box.SetTransform(v(0, 3), 0)],
    ['b2Body.SetType', (s) => s.box.SetType(b2BodyType.b2_staticBody)],
    ['b2Body.SetActive', (s) => s.box.SetActive(false)],
    ['b2Body.SetMassData', (s) => s.box.SetMassData(new b2MassData())],
  ];
  for (const [method, call] of calls) {
    it(`${method} inside a contact callback`, () => {
      const s = makeScene();
      const errors: unknown[] = [];
      let before = '';
      class Listener extends b2ContactListener {
        override PreSolve(): void {
          if (errors.length > 0) return;
          before = worldDigest(s.world);
          errors.push(caught(() => call(s)));
          expect(worldDigest(s.world)).toBe(before);
        }
      }
      s.box.ApplyLinearImpulse(v(0, -1), s.box.GetWorldCenter());
      s.world.SetContactListener(new Listener());
      s.world.Step(h, 8, 3);
      expect(errors.length).toBe(1);
      expectArgumentError(errors[0], { method, argument: 'the world', rule: lockedRule });
      s.world.SetContactListener(null);
      for (let i = 0; i < 10; ++i) s.world.Step(h, 8, 3);
      expect(checkWorldInvariants(s.world)).toEqual([]);
    });
  }
});

describe('b2dJsonRead reports the new rules with JSON paths', () => {
  const body = (fixture: unknown) => ({ body: [{ type: 2, fixture: [fixture] }] });
  const twoBodies = (joint: unknown) => ({ body: [{}, { type: 2, fixture: [{ density: 1, circle: { radius: 0.5 } }] }], joint: [joint] });
  const cases: [string, unknown, string, string][] = [
    ['a negative friction', body({ friction: -1, circle: { radius: 1 } }), 'body[0].fixture[0].friction', 'expected a finite number >= 0, got -1'],
    ['a negative restitution', body({ restitution: -0.5, circle: { radius: 1 } }), 'body[0].fixture[0].restitution', 'expected a finite number >= 0, got -0.5'],
    ['a circle of negative radius', body({ circle: { radius: -1 } }), 'body[0].fixture[0].circle.radius', 'expected a finite number >= 0, got -1'],
    ['a zero box half-width', body({ polygon: { box: { hx: 0, hy: 1 } } }), 'body[0].fixture[0].polygon.box.hx', 'expected a finite number > 0, got 0'],
    [
      'a non-convex polygon',
      body({ polygon: { vertices: { x: [0, 2, 1, 2, 0], y: [0, 0, 0.5, 2, 2] } } }),
      'body[0].fixture[0].polygon.vertices',
      'rejected by b2PolygonShape.Set: vertices[2] makes the polygon non-convex (vertices must be counter-clockwise and convex)',
    ],
    [
      'a clockwise polygon',
      body({ polygon: { vertices: { x: [0, 0, 1, 1], y: [0, 1, 1, 0] } } }),
      'body[0].fixture[0].polygon.vertices',
      'rejected by b2PolygonShape.Set: vertices are clockwise (signed area -1; vertices must be counter-clockwise and convex)',
    ],
    [
      'a zero-length edge',
      body({ edge: { vertex1: { x: 1, y: 1 }, vertex2: { x: 1, y: 1 } } }),
      'body[0].fixture[0].edge.vertex2',
      'coincides with vertex1 (an edge must be longer than b2_epsilon)',
    ],
    [
      'a two-vertex polygon of zero length',
      body({ polygon: { vertices: { x: [1, 1], y: [2, 2] } } }),
      'body[0].fixture[0].polygon.vertices',
      'rejected by b2EdgeShape.Set: v2 coincides with v1 (an edge must be longer than b2_epsilon)',
    ],
    [
      'a chain with a repeated vertex',
      body({ chain: { vertices: { x: [0, 1, 1], y: [0, 0, 0] } } }),
      'body[0].fixture[0].chain.vertices',
      'rejected by b2ChainShape.CreateChain: vertices[2] repeats vertices[1] (consecutive chain vertices must be more than b2_epsilon apart)',
    ],
    [
      'a zero prismatic axis',
      twoBodies({ type: 'prismatic', bodyA: 0, bodyB: 1, localAxisA: 0 }),
      'joint[0].localAxisA',
      'expected a non-zero axis, got (0, 0)',
    ],
    [
      'a rope of negative maxLength',
      twoBodies({ type: 'rope', bodyA: 0, bodyB: 1, maxLength: -1 }),
      'joint[0].maxLength',
      'expected a finite number >= 0, got -1',
    ],
    [
      'a mouse joint without frequency',
      twoBodies({ type: 'mouse', bodyA: 0, bodyB: 1 }),
      'joint[0].frequency',
      'expected a finite number > 0, got 0 (the field is missing and defaults to it)',
    ],
    ['a negative distance length', twoBodies({ type: 'distance', bodyA: 0, bodyB: 1, length: -2 }), 'joint[0].length', 'expected a finite number >= 0, got -2'],
    [
      'a negative motor torque',
      twoBodies({ type: 'wheel', bodyA: 0, bodyB: 1, localAxisA: { x: 0, y: 1 }, maxMotorTorque: -1 }),
      'joint[0].maxMotorTorque',
      'expected a finite number >= 0, got -1',
    ],
  ];
  for (const [what, doc, path, rule] of cases) {
    it(`rejects ${what}`, () => {
      const error = caught(() => b2dJsonRead(doc));
      expect(error).toBeInstanceOf(b2dJsonError);
      expect(error).toBeInstanceOf(b2ArgumentError);
      const e = error as b2dJsonError;
      expect([e.method, e.argument, e.path, e.rule]).toEqual(['b2dJsonRead', path, path, rule]);
      expect(e.message).toBe(`${path}: ${rule}`);
    });
  }
});
