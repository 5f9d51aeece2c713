/*
 * What public Box2DWeb programs do that Box2D 2.2.1 alone does not take, run beside Box2DWeb 2.1a
 * itself (node_modules/box2dweb, loaded as the benchmarks load it): each app below is one function
 * run on both libraries' Box2D namespaces, and the results must agree where 2.1a's behaviour is
 * what the app relies on.
 */

import { describe, expect, it } from 'vitest';
import { loadBox2DWeb } from '../../bench/engines/box2dweb.mjs';
import * as wp from '../../src/index';

/** A library's Box2D namespace, as an app written for Box2DWeb sees it (untyped JavaScript). */
type Lib = any;

const box2dweb: Lib = loadBox2DWeb();
const webphysics: Lib = wp.Box2D;

/** Run `app` on Box2DWeb 2.1a and on WebPhysics. */
function both<T>(app: (Box2D: Lib) => T): { box2dweb: T; webphysics: T } {
  return { box2dweb: app(box2dweb), webphysics: app(webphysics) };
}

function thrown(fn: () => unknown): Error {
  try {
    fn();
  } catch (e) {
    return e as Error;
  }
  throw new Error('expected a throw');
}

describe('destroying while walking the lists', () => {
  /** A chain of six balls joined by revolute joints, then walks that destroy as they go. */
  function destroyWhileWalking(Box2D: Lib) {
    const { b2Vec2 } = Box2D.Common.Math;
    const { b2World, b2BodyDef, b2Body } = Box2D.Dynamics;
    const { b2CircleShape } = Box2D.Collision.Shapes;
    const { b2RevoluteJointDef } = Box2D.Dynamics.Joints;
    const world = new b2World(new b2Vec2(0, 10), true);
    const bd = new b2BodyDef();
    bd.type = b2Body.b2_dynamicBody;
    const bodies = [];
    for (let i = 0; i < 6; i++) {
      bd.position.Set(3 * i, 0);
      const body = world.CreateBody(bd);
      body.CreateFixture2(new b2CircleShape(1), 1);
      body.SetUserData(`body${i}`);
      bodies.push(body);
    }
    for (let i = 0; i < 5; i++) {
      const jd = new b2RevoluteJointDef();
      jd.Initialize(bodies[i], bodies[i + 1], new b2Vec2(3 * i + 1.5, 0));
      jd.userData = `joint${i}`;
      world.CreateJoint(jd);
    }
    world.Step(1 / 60, 8, 3);

    // The walks read the next link of the object just destroyed, as the apps do.
    const jointsSeen: string[] = [];
    let doomedJoint = null;
    for (let j = world.GetJointList(); j; j = j.GetNext()) {
      jointsSeen.push(j.GetUserData());
      if (jointsSeen.length % 2 === 1) {
        world.DestroyJoint(j);
        doomedJoint = j;
      }
    }
    const bodiesSeen: string[] = [];
    let doomedBody = null;
    for (let b = world.GetBodyList(); b; b = b.m_next) {
      if (b.GetUserData() === null) continue; // 2.1a's own ground body
      bodiesSeen.push(b.GetUserData());
      if (bodiesSeen.length % 3 !== 0) {
        world.DestroyBody(b);
        doomedBody = b;
      }
    }
    const left: string[] = [];
    for (let b = world.GetBodyList(); b; b = b.GetNext()) if (b.GetUserData() !== null) left.push(b.GetUserData());
    world.Step(1 / 60, 8, 3);
    return { jointsSeen, bodiesSeen, left, jointCount: world.GetJointCount(), world, doomedBody, doomedJoint };
  }

  it('reaches every body and joint after the one destroyed, through GetNext() and m_next, as in 2.1a', () => {
    const r = both(destroyWhileWalking);
    expect(r.webphysics.jointsSeen).toEqual(['joint4', 'joint3', 'joint2', 'joint1', 'joint0']);
    expect(r.webphysics.jointsSeen).toEqual(r.box2dweb.jointsSeen);
    expect(r.webphysics.bodiesSeen).toEqual(['body5', 'body4', 'body3', 'body2', 'body1', 'body0']);
    expect(r.webphysics.bodiesSeen).toEqual(r.box2dweb.bodiesSeen);
    expect(r.webphysics.left).toEqual(['body3', 'body0']);
    expect(r.webphysics.left).toEqual(r.box2dweb.left);
    expect(r.webphysics.jointCount).toBe(0);
    expect(r.box2dweb.jointCount).toBe(0);
  });

  it('leaves the destroyed body and joint unusable, and the world consistent', () => {
    const { world, doomedBody, doomedJoint } = destroyWhileWalking(webphysics);
    expect(thrown(() => doomedBody.ApplyForce(new wp.b2Vec2(1, 0), new wp.b2Vec2(0, 0))).message).toBe('b2Body.ApplyForce: this body has been destroyed');
    expect(thrown(() => world.DestroyBody(doomedBody)).message).toBe('b2World.DestroyBody: body has been destroyed');
    expect(thrown(() => world.DestroyJoint(doomedJoint)).message).toBe('b2World.DestroyJoint: joint has been destroyed');
    let count = 0;
    for (let b = world.GetBodyList(); b; b = b.GetNext()) ++count;
    expect(count).toBe(world.GetBodyCount());
    expect(count).toBe(2);
    world.Validate();
  });
});

describe('the ground body', () => {
  /** Clear the level by destroying every body in the list (the ground too), then drag a new box. */
  function clearThenDrag(Box2D: Lib) {
    const { b2Vec2 } = Box2D.Common.Math;
    const { b2World, b2BodyDef, b2Body, b2FixtureDef } = Box2D.Dynamics;
    const { b2PolygonShape } = Box2D.Collision.Shapes;
    const { b2MouseJointDef } = Box2D.Dynamics.Joints;
    const world = new b2World(new b2Vec2(0, 0), true);
    const firstGround = world.GetGroundBody();
    const bd = new b2BodyDef();
    bd.type = b2Body.b2_dynamicBody;
    const fd = new b2FixtureDef();
    fd.density = 1;
    fd.shape = new b2PolygonShape();
    fd.shape.SetAsBox(0.5, 0.5);
    world.CreateBody(bd).CreateFixture(fd);
    for (let b = world.GetBodyList(); b; b = b.GetNext()) world.DestroyBody(b);
    const emptied = world.GetBodyCount();

    bd.position.Set(5, 5);
    const box = world.CreateBody(bd);
    box.CreateFixture(fd);
    const md = new b2MouseJointDef();
    md.bodyA = world.GetGroundBody();
    md.bodyB = box;
    md.target.Set(5, 5);
    md.maxForce = 1000 * box.GetMass();
    const mouse = world.CreateJoint(md);
    mouse.SetTarget(new b2Vec2(8, 4));
    for (let i = 0; i < 120; i++) {
      world.Step(1 / 60, 8, 3);
      world.ClearForces();
    }
    return { world, firstGround, emptied, x: box.GetPosition().x, y: box.GetPosition().y };
  }

  it('GetGroundBody after the ground was destroyed gives a body a mouse joint can hold, as 2.1a let apps do', () => {
    const r = both(clearThenDrag);
    expect(r.webphysics.emptied).toBe(0);
    expect(r.box2dweb.emptied).toBe(0);
    for (const result of [r.box2dweb, r.webphysics]) {
      expect(result.x).toBeCloseTo(8, 1);
      expect(result.y).toBeCloseTo(4, 1);
    }
  });

  it('the new ground body is live, static, at the origin, and handed back again until destroyed', () => {
    const { world, firstGround } = clearThenDrag(webphysics);
    const ground = world.GetGroundBody();
    expect(ground).not.toBe(firstGround);
    expect(world.GetGroundBody()).toBe(ground);
    expect(ground.GetType()).toBe(wp.b2_staticBody);
    expect([ground.GetPosition().x, ground.GetPosition().y, ground.GetFixtureList()]).toEqual([0, 0, null]);
    expect(world.GetBodyCount()).toBe(2);
  });
});

describe('world.DrawShape', () => {
  /** A circle and a box drawn by the app itself with 2.1a's public DrawShape(shape, xf, color). */
  function drawShapes(Box2D: Lib) {
    const { b2Vec2, b2Transform, b2Mat22 } = Box2D.Common.Math;
    const { b2World, b2DebugDraw } = Box2D.Dynamics;
    const { b2PolygonShape, b2CircleShape } = Box2D.Collision.Shapes;
    const world = new b2World(new b2Vec2(0, 10), true);
    const context = new RecordingContext();
    const debugDraw = new b2DebugDraw();
    debugDraw.SetSprite(context);
    debugDraw.SetDrawScale(30);
    debugDraw.SetFlags(b2DebugDraw.e_shapeBit);
    world.SetDebugDraw(debugDraw);
    const xf = new b2Transform(new b2Vec2(2, 3), b2Mat22.FromAngle(0.5));
    const circle = new b2CircleShape(0.75);
    circle.SetLocalPosition(new b2Vec2(0.5, 0));
    const box = new b2PolygonShape();
    box.SetAsBox(1, 0.5);
    const color = new Box2D.Common.b2Color(0.9, 0.7, 0.7);
    world.DrawShape(circle, xf, color);
    world.DrawShape(box, xf, color);
    return { world, context, xf, circle, box, color };
  }

  it('draws a shape at a transform where 2.1a draws it', () => {
    const r = both(drawShapes);
    expect(geometry(r.webphysics.context)).toEqual(geometry(r.box2dweb.context));
    expect(geometry(r.webphysics.context).arcs).toHaveLength(1);
    expect(geometry(r.webphysics.context).points.length).toBeGreaterThan(4);
  });

  it('takes a fixture for its shape, and rejects anything else naming the argument', () => {
    const { world, context, xf, circle, color } = drawShapes(webphysics);
    const body = world.CreateBody(new wp.b2BodyDef());
    const fixture = body.CreateFixture(circle, 0);
    const before = context.calls.length;
    world.DrawShape(fixture, xf, color);
    const viaFixture = context.calls.slice(before);
    world.DrawShape(circle, xf, color);
    expect(context.calls.slice(before + viaFixture.length)).toEqual(viaFixture);

    const shapeError = thrown(() => world.DrawShape({}, xf, color));
    expect(shapeError).toBeInstanceOf(wp.b2ArgumentError);
    expect(shapeError.message).toBe('b2World.DrawShape: shape must be a b2Shape or a b2Fixture, got an object');
    expect(thrown(() => world.DrawShape(circle, null, color)).message).toBe('b2World.DrawShape: xf must be a b2Transform, got null');
    expect(thrown(() => world.DrawShape(circle, xf, undefined)).message).toBe('b2World.DrawShape: color must be a b2Color, got undefined');
    body.DestroyFixture(fixture);
    expect(thrown(() => world.DrawShape(fixture, xf, color)).message).toBe('b2World.DrawShape: fixture has been destroyed');
    world.SetDebugDraw(null);
    expect(thrown(() => world.DrawShape(circle, xf, color)).message).toBe('b2World.DrawShape: the world has no debug draw (call SetDebugDraw first)');
    // The world is untouched.
    world.Step(1 / 60, 8, 3);
    expect(world.GetBodyCount()).toBe(1);
  });
});

describe('SetAsEdge under a circle', () => {
  /** A circle centred exactly on a SetAsEdge segment's line, then a second on the reversed segment. */
  function circleOnEdgeLine(Box2D: Lib, reversed: boolean, shape: 'circle' | 'box') {
    const { b2Vec2 } = Box2D.Common.Math;
    const { b2World, b2BodyDef, b2Body, b2FixtureDef } = Box2D.Dynamics;
    const { b2PolygonShape, b2CircleShape } = Box2D.Collision.Shapes;
    const world = new b2World(new b2Vec2(0, 10), true);
    const floor = new b2PolygonShape();
    const left = new b2Vec2(-5, 5);
    const right = new b2Vec2(5, 5);
    if (reversed) floor.SetAsEdge(right, left);
    else floor.SetAsEdge(left, right);
    const fd = new b2FixtureDef();
    fd.shape = floor;
    world.CreateBody(new b2BodyDef()).CreateFixture(fd);
    const bd = new b2BodyDef();
    bd.type = b2Body.b2_dynamicBody;
    bd.position.Set(0.3, 5);
    const player = world.CreateBody(bd);
    fd.density = 1;
    if (shape === 'circle') {
      fd.shape = new b2CircleShape(0.5);
    } else {
      fd.shape = new b2PolygonShape();
      fd.shape.SetAsBox(0.5, 0.5);
    }
    player.CreateFixture(fd);
    for (let i = 0; i < 60; i++) {
      world.Step(1 / 60, 10, 10);
      world.ClearForces();
    }
    return player.GetPosition().y;
  }

  it('pushes the circle to the side 2.1a does, for either vertex order', () => {
    for (const reversed of [false, true]) {
      const r = both((Box2D) => circleOnEdgeLine(Box2D, reversed, 'circle'));
      // Standing on the floor (centre 0.5 above it) or fallen through it.
      const side = (y: number) => (y < 5 ? 'on top' : 'fell through');
      expect(side(r.webphysics)).toBe(reversed ? 'fell through' : 'on top');
      expect(side(r.webphysics)).toBe(side(r.box2dweb));
      if (!reversed) expect(r.webphysics).toBeCloseTo(r.box2dweb, 1);
    }
  });

  it('leaves a box on a SetAsEdge floor where 2.1a does', () => {
    const r = both((Box2D) => circleOnEdgeLine(Box2D, false, 'box'));
    expect(r.webphysics).toBeLessThan(5);
    expect(r.box2dweb).toBeLessThan(5);
  });

  it("keeps 2.2.1's edge collision for a b2EdgeShape: the circle goes to the edge's other side", () => {
    const world = new wp.b2World(new wp.b2Vec2(0, 10), true);
    world.CreateBody(new wp.b2BodyDef()).CreateFixture(new wp.b2EdgeShape(new wp.b2Vec2(-5, 5), new wp.b2Vec2(5, 5)), 0);
    const bd = new wp.b2BodyDef();
    bd.type = wp.b2_dynamicBody;
    bd.position.Set(0.3, 5);
    const ball = world.CreateBody(bd);
    ball.CreateFixture(new wp.b2CircleShape(0.5), 1);
    for (let i = 0; i < 60; i++) world.Step(1 / 60, 10, 10);
    expect(ball.GetPosition().y).toBeGreaterThan(5);
  });

  it("the SetAsEdge fixture's shape stays an edge, and so does its clone", () => {
    const floor = new wp.b2PolygonShape();
    floor.SetAsEdge(new wp.b2Vec2(-5, 5), new wp.b2Vec2(5, 5));
    const world = new wp.b2World(new wp.b2Vec2(0, 10), true);
    const shape = world.CreateBody(new wp.b2BodyDef()).CreateFixture(floor, 0).GetShape();
    for (const edge of [shape, shape.Clone()]) {
      expect(edge).toBeInstanceOf(wp.b2EdgeShape);
      expect(edge.GetType()).toBe(wp.b2Shape.e_edge);
      const e = edge as wp.b2EdgeShape;
      expect([e.m_vertex1.x, e.m_vertex1.y, e.m_vertex2.x, e.m_vertex2.y, e.m_radius]).toEqual([-5, 5, 5, 5, floor.m_radius]);
    }
  });
});

describe('b2LineJointDef', () => {
  /**
   * A two-wheeled car as iforce2d's Box2DWeb R.U.B.E. loader builds a wheel joint: a zero-length
   * distance joint for the spring, then a b2LineJointDef (limits and motor off) for the axis.
   * The wheels are driven by setting their spin, as that loader's demo does.
   */
  function rubeCar(Box2D: Lib) {
    const { b2Vec2 } = Box2D.Common.Math;
    const { b2World, b2BodyDef, b2Body, b2FixtureDef } = Box2D.Dynamics;
    const { b2PolygonShape, b2CircleShape } = Box2D.Collision.Shapes;
    const { b2DistanceJointDef, b2LineJointDef } = Box2D.Dynamics.Joints;
    const world = new b2World(new b2Vec2(0, -10), true);
    const fd = new b2FixtureDef();
    fd.friction = 0.9;
    fd.density = 1;
    fd.shape = new b2PolygonShape();
    fd.shape.SetAsBox(50, 0.5);
    const gd = new b2BodyDef();
    gd.position.Set(0, -0.5);
    world.CreateBody(gd).CreateFixture(fd);
    const bd = new b2BodyDef();
    bd.type = b2Body.b2_dynamicBody;
    bd.position.Set(0, 1.5);
    const chassis = world.CreateBody(bd);
    fd.shape = new b2PolygonShape();
    fd.shape.SetAsBox(1.5, 0.25);
    chassis.CreateFixture(fd);
    const wheels = [];
    const lines = [];
    for (const x of [-1, 1]) {
      bd.position.Set(x, 0.6);
      const wheel = world.CreateBody(bd);
      fd.shape = new b2CircleShape(0.4);
      wheel.CreateFixture(fd);
      wheels.push(wheel);
      const spring = new b2DistanceJointDef();
      spring.bodyA = chassis;
      spring.bodyB = wheel;
      spring.localAnchorA.SetV({ x, y: -0.9 });
      spring.length = 0;
      spring.frequencyHz = 4;
      spring.dampingRatio = 0.7;
      world.CreateJoint(spring);
      const line = new b2LineJointDef();
      line.bodyA = chassis;
      line.bodyB = wheel;
      line.localAnchorA.SetV({ x, y: -0.9 });
      line.localAxisA.SetV({ x: 0, y: 1 });
      lines.push(world.CreateJoint(line));
    }
    for (let i = 0; i < 180; i++) {
      for (const wheel of wheels) wheel.SetAngularVelocity(-10);
      world.Step(1 / 60, 8, 3);
      world.ClearForces();
    }
    return {
      world,
      lines,
      x: chassis.GetPosition().x,
      y: chassis.GetPosition().y,
      angle: chassis.GetAngle(),
      wheelY: wheels[0].GetPosition().y,
      translation: lines[0].GetJointTranslation(),
      jointCount: world.GetJointCount(),
    };
  }

  it("builds a R.U.B.E. loader's wheel joint, and the car drives as in 2.1a", () => {
    const r = both(rubeCar);
    expect(r.webphysics.jointCount).toBe(4);
    // Three seconds at 10 rad/s on wheels of radius 0.4: about 10.7 m in both.
    expect(r.webphysics.x).toBeGreaterThan(10);
    expect(Math.abs(r.webphysics.x - r.box2dweb.x)).toBeLessThan(0.1);
    for (const key of ['y', 'angle', 'wheelY', 'translation'] as const) {
      expect(Math.abs(r.webphysics[key] - r.box2dweb[key])).toBeLessThan(0.01);
    }
  });

  it('makes a wheel joint without a spring, with the line joint calls of 2.1a', () => {
    const { world, lines } = rubeCar(webphysics);
    const line = lines[0];
    const { b2Joint, b2WheelJoint, b2LineJoint } = webphysics.Dynamics.Joints;
    expect(line).toBeInstanceOf(b2WheelJoint);
    expect(line).toBeInstanceOf(b2LineJoint);
    expect(line.GetType()).toBe(b2Joint.e_lineJoint);
    expect(line.GetType()).toBe(b2Joint.e_wheelJoint);
    expect(line.GetSpringFrequencyHz()).toBe(0);
    expect([line.IsLimitEnabled(), line.IsMotorEnabled()]).toEqual([false, false]);
    line.SetLimits(-0.5, 0.25);
    line.SetMaxMotorForce(40);
    expect([line.GetLowerLimit(), line.GetUpperLimit(), line.GetMaxMotorForce()]).toEqual([-0.5, 0.25, 40]);
    line.EnableLimit(false);
    line.EnableMotor(false);

    // GetJointSpeed is the speed along the axis, as 2.1a's: the wheel rises at 1 m/s.
    const chassis = line.GetBodyA();
    const wheel = line.GetBodyB();
    chassis.SetLinearVelocity(new wp.b2Vec2(0, 0));
    chassis.SetAngularVelocity(0);
    wheel.SetLinearVelocity(new wp.b2Vec2(0, 1));
    wheel.SetAngularVelocity(3);
    expect(line.GetJointSpeed()).toBeCloseTo(Math.cos(chassis.GetAngle()), 9);
    world.Step(1 / 60, 8, 3);
  });

  it('refuses what a wheel joint cannot do, naming the field, and leaves the world as it was', () => {
    const { world, lines } = rubeCar(webphysics);
    const line = lines[0];
    const { b2LineJointDef } = webphysics.Dynamics.Joints;
    const def = new b2LineJointDef();
    def.Initialize(line.GetBodyA(), line.GetBodyB(), new wp.b2Vec2(0, 0), new wp.b2Vec2(1, 0));
    def.enableLimit = true;
    const limitError = thrown(() => world.CreateJoint(def));
    expect(limitError).toBeInstanceOf(wp.b2ArgumentError);
    expect(limitError.message).toMatch(
      /^b2World\.CreateJoint: def\.enableLimit must be false for a b2LineJointDef: .*no translation limits .*b2PrismaticJointDef/,
    );
    def.enableLimit = false;
    def.enableMotor = true;
    expect(thrown(() => world.CreateJoint(def)).message).toMatch(
      /^b2World\.CreateJoint: def\.enableMotor must be false for a b2LineJointDef: .*turns bodyB .*maxMotorTorque.*b2PrismaticJointDef/,
    );
    expect(world.GetJointCount()).toBe(4);
    expect(thrown(() => line.EnableLimit(true)).message).toMatch(/^b2LineJoint\.EnableLimit: flag must be false: .*no translation limits/);
    expect(thrown(() => line.EnableMotor(true)).message).toMatch(/^b2LineJoint\.EnableMotor: flag must be false: .*turns bodyB/);
    expect(thrown(() => line.SetLimits(1, 0)).message).toBe('b2LineJoint.SetLimits: lower must not exceed upper (1 > 0)');
    expect([line.IsLimitEnabled(), line.IsMotorEnabled()]).toEqual([false, false]);
    def.enableMotor = false;
    expect(world.CreateJoint(def).GetType()).toBe(wp.b2JointType.e_wheelJoint);
    world.Step(1 / 60, 8, 3);
  });
});

describe('Box2D.Collision.b2Segment', () => {
  /** Random segments against each other and clipped to boxes, with 2.1a's calls. */
  function segmentWork(Box2D: Lib) {
    const { b2Vec2 } = Box2D.Common.Math;
    const { b2Segment, b2AABB } = Box2D.Collision;
    let seed = 12345;
    const random = () => {
      seed = (seed * 1103515245 + 12345) % 2147483648;
      return (seed / 2147483648) * 20 - 10;
    };
    const results: unknown[] = [];
    for (let i = 0; i < 500; i++) {
      const a = new b2Segment();
      a.p1.Set(random(), random());
      a.p2.Set(random(), random());
      const b = new b2Segment();
      b.p1.Set(random(), random());
      b.p2.Set(random(), random());
      const lambda = [-1];
      const normal = new b2Vec2(0, 0);
      const hit = a.TestSegment(lambda, normal, b, 1 + (i % 3) * 0.5);
      results.push([hit, lambda[0], normal.x, normal.y]);
      const box = new b2AABB();
      box.lowerBound.Set(-12, -11);
      box.upperBound.Set(13, 12);
      const extended = i % 3 === 0 ? 'Extend' : i % 3 === 1 ? 'ExtendForward' : 'ExtendBackward';
      a[extended](box);
      results.push([a.p1.x, a.p1.y, a.p2.x, a.p2.y]);
    }
    return results;
  }

  it("TestSegment, Extend, ExtendForward and ExtendBackward give 2.1a's results to the bit", () => {
    const r = both(segmentWork);
    expect(r.webphysics).toEqual(r.box2dweb);
    expect(r.webphysics.filter((x) => Array.isArray(x) && x[0] === true).length).toBeGreaterThan(20);
  });

  it('rejects a lambda that is not an array, naming it', () => {
    const segment = new wp.b2Segment();
    segment.p2.Set(1, 0);
    const error = thrown(() => segment.TestSegment(null as unknown as number[], new wp.b2Vec2(), segment, 1));
    expect(error).toBeInstanceOf(wp.b2ArgumentError);
    expect(error.message).toBe('b2Segment.TestSegment: lambda must be an array (the fraction goes to lambda[0]), got null');
  });
});

describe('polygons of more than b2_maxPolygonVertices', () => {
  /** A regular polygon of n vertices, counter-clockwise, as plain {x, y} objects. */
  const outline = (n: number) => Array.from({ length: n }, (_, i) => ({ x: Math.cos((2 * Math.PI * i) / n), y: Math.sin((2 * Math.PI * i) / n) }));

  it('are refused, saying how to split them (2.1a took any number), and the shape is left as it was', () => {
    const accepted = box2dweb.Collision.Shapes.b2PolygonShape.AsArray(outline(12), 12);
    expect(accepted.GetVertexCount()).toBe(12);

    const polygon = new wp.b2PolygonShape().SetAsBox(1, 2);
    const error = thrown(() => polygon.SetAsArray(outline(12) as wp.b2Vec2[], 12));
    expect(error).toBeInstanceOf(wp.b2ArgumentError);
    expect(error.message).toBe(
      'b2PolygonShape.SetAsArray: vertices has 12 vertices, and Box2D 2.2 polygons have at most b2_maxPolygonVertices = 8 ' +
        '(Box2DWeb 2.1a took any number): split the outline into convex pieces of at most 8 vertices and create a fixture for each',
    );
    expect(polygon.m_vertexCount).toBe(4);
    expect(polygon.m_vertices[2].y).toBe(2);
    expect(thrown(() => wp.b2PolygonShape.AsVector(outline(9) as wp.b2Vec2[])).message).toMatch(/^b2PolygonShape\.AsVector: vertices has 9 vertices/);
    expect(thrown(() => polygon.SetAsVector(null as unknown as wp.b2Vec2[])).message).toBe(
      'b2PolygonShape.SetAsVector: vertices must be an array of vectors, got null',
    );
    polygon.SetAsArray(outline(8) as wp.b2Vec2[]);
    expect(polygon.m_vertexCount).toBe(8);
  });
});

describe('PreSolve', () => {
  /** A ball dropped onto a ground box, a listener recording each call in order. */
  function listenerOrder(Box2D: Lib) {
    const { b2Vec2 } = Box2D.Common.Math;
    const { b2World, b2BodyDef, b2Body, b2FixtureDef, b2ContactListener } = Box2D.Dynamics;
    const { b2PolygonShape, b2CircleShape } = Box2D.Collision.Shapes;
    const world = new b2World(new b2Vec2(0, 10), true);
    const calls: string[] = [];
    const listener = new b2ContactListener();
    listener.BeginContact = () => calls.push('begin');
    listener.PreSolve = (contact: Lib) => calls.push(`pre ${contact.GetManifold().m_pointCount}`);
    world.SetContactListener(listener);
    const bd = new b2BodyDef();
    bd.position.Set(0, 5);
    const fd = new b2FixtureDef();
    fd.shape = new b2PolygonShape();
    fd.shape.SetAsBox(10, 0.5);
    world.CreateBody(bd).CreateFixture(fd);
    bd.type = b2Body.b2_dynamicBody;
    bd.position.Set(0, 0);
    fd.density = 1;
    fd.shape = new b2CircleShape(0.5);
    world.CreateBody(bd).CreateFixture(fd);
    for (let i = 0; i < 120; ++i) world.Step(1 / 60, 8, 3);
    return calls;
  }

  it("reaches touching contacts only, after BeginContact (2.2.1's rule), where 2.1a also calls it before the shapes touch", () => {
    const { box2dweb, webphysics } = both(listenerOrder);
    expect(box2dweb.slice(0, box2dweb.indexOf('begin'))).toContain('pre 0');
    expect(webphysics[0]).toBe('begin');
    expect(webphysics).not.toContain('pre 0');
    // From the first touch on, PreSolve comes every step (until the ball falls asleep), with the manifold's points.
    const first = webphysics.indexOf('pre 1');
    expect(first).toBe(1);
    expect(webphysics.slice(first).filter((c) => c !== 'pre 1')).toEqual([]);
    expect(webphysics.length).toBeGreaterThan(20);
  });
});

describe('2.1a habits that keep working', () => {
  /** Boxes from plain {x, y} vertices, all from one reused body and fixture definition. */
  function reusedDefinitions(Box2D: Lib) {
    const { b2Vec2 } = Box2D.Common.Math;
    const { b2World, b2BodyDef, b2Body, b2FixtureDef } = Box2D.Dynamics;
    const { b2PolygonShape } = Box2D.Collision.Shapes;
    const { b2DistanceJointDef } = Box2D.Dynamics.Joints;
    const world = new b2World(new b2Vec2(0, 10), true);
    const fd = new b2FixtureDef();
    fd.density = 1;
    fd.friction = 0.5;
    fd.shape = new b2PolygonShape();
    fd.shape.SetAsArray(
      [
        { x: -10, y: 0 },
        { x: 10, y: 0 },
        { x: 10, y: 1 },
        { x: -10, y: 1 },
      ],
      4,
    );
    const bd = new b2BodyDef();
    bd.position.Set(0, 10);
    world.CreateBody(bd).CreateFixture(fd);
    bd.type = b2Body.b2_dynamicBody;
    fd.shape = new b2PolygonShape();
    fd.shape.SetAsArray([
      { x: -0.5, y: -0.5 },
      { x: 0.5, y: -0.5 },
      { x: 0.5, y: 0.5 },
      { x: -0.5, y: 0.5 },
    ]);
    const boxes = [];
    const jd = new b2DistanceJointDef();
    for (let i = 0; i < 4; i++) {
      bd.position.Set(-6 + 4 * i, 5);
      const box = world.CreateBody(bd);
      box.CreateFixture(fd);
      if (boxes.length > 0) {
        jd.Initialize(boxes[boxes.length - 1], box, boxes[boxes.length - 1].GetPosition(), box.GetPosition());
        world.CreateJoint(jd);
      }
      boxes.push(box);
    }
    // A copy from GetDefinition, changed, makes a new body and leaves the original alone.
    const copy = boxes[0].GetDefinition();
    copy.position.x += 3;
    copy.position.y -= 4;
    const twin = world.CreateBody(copy);
    twin.CreateFixture(fd);
    // Velocities and radii written directly, as many apps do.
    boxes[3].m_linearVelocity.x = 2;
    for (let i = 0; i < 120; i++) {
      world.Step(1 / 60, 8, 3);
      world.ClearForces();
    }
    return {
      boxes: boxes.map((b: Lib) => [b.GetPosition().x, b.GetPosition().y]),
      twin: [twin.GetPosition().x, twin.GetPosition().y],
      jointCount: world.GetJointCount(),
    };
  }

  it('plain {x, y} vertices, one definition reused for many bodies and joints, GetDefinition copies, m_linearVelocity.x writes', () => {
    const r = both(reusedDefinitions);
    expect(r.webphysics.jointCount).toBe(3);
    expect(r.box2dweb.jointCount).toBe(3);
    // The boxes rest on the ground's top (y = 10) and the twin beside the first one.
    for (const [x, y] of [...r.webphysics.boxes, r.webphysics.twin]) {
      expect(y).toBeGreaterThan(9.4);
      expect(y).toBeLessThan(9.51);
      expect(x).toBeGreaterThan(-7);
    }
    r.webphysics.boxes.forEach(([x, y]: number[], i: number) => {
      expect(Math.abs(x - r.box2dweb.boxes[i][0])).toBeLessThan(0.05);
      expect(Math.abs(y - r.box2dweb.boxes[i][1])).toBeLessThan(0.02);
    });
    // The pushed box dragged the chain to the right.
    expect(r.webphysics.boxes[3][0]).toBeGreaterThan(6.1);
    expect(Math.abs(r.webphysics.twin[0] - r.box2dweb.twin[0])).toBeLessThan(0.05);
  });

  it("a radius written to the fixture's circle, m_radius, is the one that collides", () => {
    const r = both((Box2D: Lib) => {
      const { b2Vec2 } = Box2D.Common.Math;
      const { b2World, b2BodyDef, b2Body } = Box2D.Dynamics;
      const { b2PolygonShape, b2CircleShape } = Box2D.Collision.Shapes;
      const world = new b2World(new b2Vec2(0, 10), true);
      const ground = world.CreateBody(new b2BodyDef());
      ground.CreateFixture2(b2PolygonShape.AsOrientedBox(10, 1, new b2Vec2(0, 11), 0), 0);
      const bd = new b2BodyDef();
      bd.type = b2Body.b2_dynamicBody;
      bd.position.Set(0, 5);
      const ball = world.CreateBody(bd);
      ball.CreateFixture2(new b2CircleShape(0.5), 1).GetShape().m_radius = 2;
      for (let i = 0; i < 120; i++) world.Step(1 / 60, 8, 3);
      return ball.GetPosition().y;
    });
    expect(r.webphysics).toBeCloseTo(8, 1);
    expect(r.box2dweb).toBeCloseTo(8, 1);
  });

  it('runs on a page that replaced Object.prototype.hasOwnProperty', () => {
    const hasOwnProperty = Object.prototype.hasOwnProperty;
    Object.defineProperty(Object.prototype, 'hasOwnProperty', {
      value: () => {
        throw new Error('this page replaced hasOwnProperty');
      },
      configurable: true,
      writable: true,
    });
    try {
      const result = reusedDefinitions(webphysics);
      expect(result.jointCount).toBe(3);
      const scene = wp.b2dJsonRead(
        {
          gravity: { x: 0, y: -10 },
          body: [{ type: 2, awake: true, fixture: [{ density: 1, circle: { radius: 1 } }] }],
          joint: [{ type: 'motor', bodyA: 0, bodyB: 0 }],
        },
        { skipUnknown: true },
      );
      scene.step();
      expect(scene.bodies[0].GetPosition().y).toBeLessThan(0);
      expect(wp.b2dJsonWriteString(scene)).toContain('"body"');
    } finally {
      Object.defineProperty(Object.prototype, 'hasOwnProperty', { value: hasOwnProperty, configurable: true, writable: true });
    }
  });
});

/** A canvas 2D context that records its calls, as [name, ...arguments]. */
class RecordingContext {
  readonly canvas = { width: 600, height: 400 };
  readonly calls: unknown[][] = [];
  strokeStyle = '';
  fillStyle = '';
  lineWidth = 1;
  globalAlpha = 1;
}
for (const name of ['beginPath', 'closePath', 'moveTo', 'lineTo', 'arc', 'stroke', 'fill', 'clearRect', 'save', 'restore']) {
  Object.defineProperty(RecordingContext.prototype, name, {
    value(this: RecordingContext, ...args: unknown[]) {
      this.calls.push([name, ...args]);
    },
  });
}

/** What a drawing puts on the canvas: circles (centre, radius) and the distinct path points. */
function geometry(context: RecordingContext): { arcs: number[][]; points: string[] } {
  const arcs = context.calls.filter((c) => c[0] === 'arc').map((c) => c.slice(1, 4) as number[]);
  const points = context.calls.filter((c) => (c[0] === 'moveTo' || c[0] === 'lineTo') && !(c[1] === 0 && c[2] === 0)).map((c) => `${c[1]},${c[2]}`);
  return { arcs, points: [...new Set(points)].sort() };
}
