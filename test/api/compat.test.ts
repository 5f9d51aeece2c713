/*
 * The Box2DWeb 2.1a mappings through the ES entry (src/index.ts loads the compat layer): each
 * 2.1a member against the 2.2.1 call it maps to, the constructor forms, the namespace object,
 * and a golden trajectory run with the layer installed.
 */

import { describe, expect, it } from 'vitest';
import * as wp from '../../src/index';
import { b2Vec2, b2World, b2BodyDef, b2FixtureDef, b2PolygonShape, b2CircleShape, Box2D } from '../../src/index';
import { b2World as b2WorldEngine } from '../../src/dynamics/b2World';
import { b2CircleShape as b2CircleShapeEngine } from '../../src/collision/shapes/b2CircleShape';
import { loadGoldenScene, readTrajectory, stateDigest } from '../support/scene';

function dynamicBody(world: wp.b2World, x: number, y: number, shape: wp.b2Shape, density = 1): wp.b2Body {
  const def = new b2BodyDef();
  def.type = wp.b2_dynamicBody;
  def.position.Set(x, y);
  const body = world.CreateBody(def);
  body.CreateFixture(shape, density);
  return body;
}

function staticBox(world: wp.b2World, x: number, y: number, hx: number, hy: number): wp.b2Body {
  const def = new b2BodyDef();
  def.position.Set(x, y);
  const body = world.CreateBody(def);
  body.CreateFixture(new b2PolygonShape().SetAsBox(hx, hy), 0);
  return body;
}

describe('the ES entry and the Box2D namespace', () => {
  it('export the same objects under the same names', () => {
    expect(Box2D.Dynamics.b2World).toBe(wp.b2World);
    expect(Box2D.Common.Math.b2Vec2).toBe(wp.b2Vec2);
    expect(Box2D.Common.Math.b2Math).toBe(wp.b2Math);
    expect(Box2D.Collision.Shapes.b2CircleShape).toBe(wp.b2CircleShape);
    expect(Box2D.Dynamics.b2DebugDraw).toBe(wp.b2DebugDraw);
    expect(Box2D.Dynamics.b2FilterData).toBe(wp.b2Filter);
    expect(Box2D.Dynamics.Joints.b2WheelJointDef).toBe(wp.b2WheelJointDef);
    expect(Box2D.Common.b2Settings.b2_linearSlop).toBe(wp.b2_linearSlop);
    expect(Box2D.Common.b2Settings.b2_contactBaumgarte).toBe(wp.b2_baumgarte);
  });

  it('keep the engine classes behind the 2.1a constructor forms: instanceof, statics and subclasses work', () => {
    const world = new b2World(new b2Vec2(0, -10));
    expect(world).toBeInstanceOf(b2WorldEngine);
    expect(new b2WorldEngine(new b2Vec2(0, 0))).toBeInstanceOf(b2World);
    expect(wp.b2dJsonRead('{}').world).toBeInstanceOf(b2World);
    expect(b2World.e_locked).toBe(b2WorldEngine.e_locked);
    class MyWorld extends b2World {
      tag = 'mine';
    }
    const mine = new MyWorld(new b2Vec2(0, -10), false);
    expect(mine.tag).toBe('mine');
    expect(mine).toBeInstanceOf(b2WorldEngine);
    expect(mine.GetAllowSleeping()).toBe(false);

    const circle = new b2CircleShape(0.75);
    expect(circle.m_radius).toBe(0.75);
    expect(circle).toBeInstanceOf(b2CircleShapeEngine);
    const body = dynamicBody(world, 0, 0, circle);
    const shape = body.GetFixtureList()!.GetShape();
    expect(shape).toBeInstanceOf(b2CircleShape);
    expect(shape).not.toBe(circle);
    expect(new b2CircleShape().m_radius).toBe(0);
  });
});

describe('2.1a constructors', () => {
  it('new b2World(gravity, doSleep) sets whether bodies may sleep', () => {
    expect(new b2World(new b2Vec2(0, 10), true).GetAllowSleeping()).toBe(true);
    expect(new b2World(new b2Vec2(0, 10), false).GetAllowSleeping()).toBe(false);
    expect(new b2World(new b2Vec2(0, 10)).GetAllowSleeping()).toBe(true);
    const g = new b2World(new b2Vec2(1, 10), false).GetGravity();
    expect([g.x, g.y]).toEqual([1, 10]);
  });

  it('new b2EdgeShape(v1, v2), new b2RayCastInput(p1, p2, maxFraction), new b2Transform(position, R)', () => {
    const edge = new wp.b2EdgeShape(new b2Vec2(1, 2), new b2Vec2(4, 6));
    expect([edge.GetVertex1().x, edge.GetVertex2().y, edge.GetLength()]).toEqual([1, 6, 5]);
    const input = new wp.b2RayCastInput(new b2Vec2(1, 2), new b2Vec2(3, 4), 0.5);
    expect([input.p1.x, input.p1.y, input.p2.x, input.p2.y, input.maxFraction]).toEqual([1, 2, 3, 4, 0.5]);
    expect(new wp.b2RayCastInput().maxFraction).toBe(1);
    const R = wp.b2Mat22.FromAngle(0.3);
    const xf = new wp.b2Transform(new b2Vec2(5, 6), R);
    expect([xf.p.x, xf.p.y, xf.q.s, xf.q.c]).toEqual([5, 6, R.col1.y, R.col1.x]);
    const xf2 = new wp.b2Transform(new b2Vec2(1, 1), new wp.b2Rot(0.3));
    expect([xf2.q.s, xf2.q.c]).toEqual([R.col1.y, R.col1.x]);
  });
});

describe('Box2D.Common.Math', () => {
  it('b2Vec2 helpers work in place as 2.1a, except Copy, GetNegative and Make which allocate', () => {
    const v = b2Vec2.Make(3, -4);
    const copy = v.Copy();
    expect(copy).not.toBe(v);
    expect(copy).toEqual(v);
    expect([v.GetNegative().x, v.GetNegative().y]).toEqual([-3, 4]);
    const w = new b2Vec2(-0, -2);
    w.Abs();
    expect(Object.is(w.x, -0)).toBe(true); // 2.1a's Abs negates only negative components
    expect(w.y).toBe(2);
    const m = new wp.b2Mat22(new b2Vec2(1, 2), new b2Vec2(3, 4));
    const a = v.Copy();
    a.MulM(m);
    expect([a.x, a.y]).toEqual([1 * 3 + 3 * -4, 2 * 3 + 4 * -4]);
    const t = v.Copy();
    t.MulTM(m);
    expect([t.x, t.y]).toEqual([3 * 1 + -4 * 2, 3 * 3 + -4 * 4]);
    const s = new b2Vec2(1, 1);
    s.SetV(v);
    s.NegativeSelf();
    expect([s.x, s.y]).toEqual([-3, 4]);
    const v3 = new wp.b2Vec3(1, 2, 3).Copy();
    v3.NegativeSelf();
    expect([v3.x, v3.y, v3.z]).toEqual([-1, -2, -3]);
  });

  it('b2Mat22 has col1/col2, Set(angle) with the engine sin and cos, and the 2.2.1 Set(c1, c2)', () => {
    const m = new wp.b2Mat22();
    expect(m.col1).toBe(m.ex);
    expect(m.col2).toBe(m.ey);
    (m.Set as unknown as (angle: number) => void)(0.7);
    expect([m.col1.x, m.col1.y, m.col2.x, m.col2.y]).toEqual([wp.b2Cos(0.7), wp.b2Sin(0.7), -wp.b2Sin(0.7), wp.b2Cos(0.7)]);
    expect(m.GetAngle()).toBe(wp.b2Atan2(wp.b2Sin(0.7), wp.b2Cos(0.7)));
    m.Set(new b2Vec2(1, -2), new b2Vec2(-3, 4));
    expect([m.ex.x, m.ex.y, m.ey.x, m.ey.y]).toEqual([1, -2, -3, 4]);
    m.AddM(wp.b2Mat22.FromVV(new b2Vec2(1, 1), new b2Vec2(1, 1)));
    m.Abs();
    expect([m.ex.x, m.ex.y, m.ey.x, m.ey.y]).toEqual([2, 1, 2, 5]);
    m.col1 = new b2Vec2(9, 8);
    expect([m.ex.x, m.ex.y]).toEqual([9, 8]);
    const m3 = new wp.b2Mat33();
    m3.SetVVV(new wp.b2Vec3(1, 0, 0), new wp.b2Vec3(0, 2, 0), new wp.b2Vec3(0, 0, 3));
    expect([m3.col1.x, m3.col2.y, m3.col3.z]).toEqual([1, 2, 3]);
    m3.SetIdentity();
    expect([m3.col2.y, m3.col3.z, m3.col1.y]).toEqual([1, 1, 0]);
  });

  it("b2Transform's position and R map onto p and q", () => {
    const xf = new wp.b2Transform();
    xf.Set(new b2Vec2(1, 2), 0.5);
    expect(xf.position).toBe(xf.p);
    const R = xf.R;
    expect([R.col1.x, R.col1.y, R.col2.x, R.col2.y]).toEqual([xf.q.c, xf.q.s, -xf.q.s, xf.q.c]);
    expect(xf.GetAngle()).toBe(xf.q.GetAngle());
    const other = new wp.b2Transform();
    (other.Set as unknown as (xf: wp.b2Transform) => void)(xf);
    expect(other).toEqual(xf);
    other.R = wp.b2Mat22.FromAngle(0);
    expect([other.q.s, other.q.c]).toEqual([0, 1]);
    other.Initialize(new b2Vec2(7, 8), R);
    expect([other.p.x, other.p.y, other.q.s, other.q.c]).toEqual([7, 8, xf.q.s, xf.q.c]);
    const sweep = new wp.b2Sweep();
    sweep.t0 = 0.25;
    expect(sweep.alpha0).toBe(0.25);
    expect(sweep.Copy().t0).toBe(0.25);
  });

  it('b2Math helpers return new objects computed by the 2.2.1 functions', () => {
    const a = new b2Vec2(0.1, 0.7);
    const b = new b2Vec2(-0.3, 0.2);
    const xf = new wp.b2Transform(new b2Vec2(1, 2), new wp.b2Rot(0.4));
    const M = new wp.b2Mat22(new b2Vec2(0.3, 0.1), new b2Vec2(-0.2, 0.9));
    const math = wp.b2Math;
    expect(math.MulX(xf, a)).toEqual(wp.b2MulXV(xf, a, new b2Vec2()));
    expect(math.MulXT(xf, a)).toEqual(wp.b2MulTXV(xf, a, new b2Vec2()));
    expect(math.MulMV(M, a)).toEqual(wp.b2MulMV(M, a, new b2Vec2()));
    expect(math.MulTMV(M, a)).toEqual(wp.b2MulTMV(M, a, new b2Vec2()));
    expect(math.CrossVF(a, 2)).toEqual(wp.b2CrossVS(a, 2, new b2Vec2()));
    expect(math.CrossFV(2, a)).toEqual(wp.b2CrossSV(2, a, new b2Vec2()));
    expect(math.MulMM(M, M)).toEqual(wp.b2MulMM(M, M, new wp.b2Mat22()));
    expect(math.MulTMM(M, M)).toEqual(wp.b2MulTMM(M, M, new wp.b2Mat22()));
    expect(math.AddMM(M, M)).toEqual(wp.b2AddMM(M, M, new wp.b2Mat22()));
    expect(math.ClampV(a, b, b)).toEqual(b);
    expect(math.Dot(a, b)).toBe(wp.b2Dot(a, b));
    expect(math.CrossVV(a, b)).toBe(wp.b2Cross(a, b));
    expect(math.Distance(a, b)).toBe(wp.b2Vec2Distance(a, b));
    expect([math.Min(1, 2), math.Max(1, 2), math.Clamp(3, 0, 2), math.NextPowerOfTwo(5)]).toEqual([1, 2, 2, 8]);
    const x = [1];
    const y = [2];
    math.Swap(x, y);
    expect([x[0], y[0]]).toEqual([2, 1]);
    expect(math.b2Vec2_zero).toEqual(new b2Vec2());
  });

  it('b2Color.color packs the channels as 0xRRGGBB', () => {
    expect(new wp.b2Color(0.5, 0.9, 0.5).color).toBe((128 << 16) | (230 << 8) | 128);
    expect(new wp.b2Color(1, 0, 2).color).toBe(0xff00ff);
  });
});

describe('Box2D.Collision', () => {
  it('b2AABB: GetCenter() allocates, Combine(a, b) is the union, Combine(a) still grows, TestOverlap', () => {
    const a = new wp.b2AABB();
    a.lowerBound.Set(0, 0);
    a.upperBound.Set(2, 2);
    const b = new wp.b2AABB();
    b.lowerBound.Set(1, -1);
    b.upperBound.Set(4, 1);
    expect(a.GetCenter()).toEqual(new b2Vec2(1, 1));
    expect(a.GetExtents()).toEqual(new b2Vec2(1, 1));
    const u = new wp.b2AABB();
    u.Combine(a, b);
    expect([u.lowerBound.x, u.lowerBound.y, u.upperBound.x, u.upperBound.y]).toEqual([0, -1, 4, 2]);
    expect(wp.b2AABB.Combine(a, b)).toEqual(u);
    const grown = a.Clone();
    grown.Combine(b);
    expect(grown).toEqual(u);
    expect(a.TestOverlap(b)).toBe(true);
    b.lowerBound.Set(3, 3);
    b.upperBound.Set(4, 4);
    expect(a.TestOverlap(b)).toBe(false);
  });

  it('manifolds answer to their 2.1a m_ names', () => {
    const world = new b2World(new b2Vec2(0, -10), true);
    staticBox(world, 0, 0, 5, 0.5);
    dynamicBody(world, 0, 1.0, new b2PolygonShape().SetAsBox(0.5, 0.5));
    for (let i = 0; i < 30; ++i) world.Step(1 / 60, 8, 3);
    const contact = world.GetContactList()!;
    const m = contact.GetManifold();
    expect(m.m_pointCount).toBe(2);
    expect(m.m_points).toBe(m.points);
    expect(m.m_localPlaneNormal).toBe(m.localNormal);
    expect(m.m_type).toBe(m.type);
    expect(m.m_points[0].m_normalImpulse).toBe(m.points[0].normalImpulse);
    expect(m.m_points[0].m_id).toBe(m.points[0].id);
    const wm = new wp.b2WorldManifold();
    contact.GetWorldManifold(wm);
    expect(wm.m_normal).toBe(wm.normal);
    expect(wm.m_normal.y).toBeCloseTo(1, 12);
    const copy = m.Copy();
    expect(copy.pointCount).toBe(2);
    copy.Reset();
    expect([copy.m_pointCount, copy.points[0].normalImpulse]).toEqual([0, 0]);
  });

  it("shapes: 2.1a type names, TestOverlap, the circle's accessors", () => {
    expect([wp.b2Shape.e_circleShape, wp.b2Shape.e_polygonShape, wp.b2Shape.e_edgeShape]).toEqual([
      wp.b2Shape.e_circle,
      wp.b2Shape.e_polygon,
      wp.b2Shape.e_edge,
    ]);
    const circle = new b2CircleShape(1);
    circle.SetLocalPosition(new b2Vec2(0.5, 0));
    expect(circle.GetLocalPosition()).toBe(circle.m_p);
    circle.SetRadius(2);
    expect(circle.GetRadius()).toBe(2);
    const box = b2PolygonShape.AsBox(1, 1);
    const near = new wp.b2Transform(new b2Vec2(3, 0), new wp.b2Rot(0));
    const far = new wp.b2Transform(new b2Vec2(4, 0), new wp.b2Rot(0));
    const origin = new wp.b2Transform();
    expect(wp.b2Shape.TestOverlap(circle, origin, box, near)).toBe(true);
    expect(wp.b2Shape.TestOverlap(circle, origin, box, far)).toBe(false);
    expect(circle.Copy()).toEqual(circle);
  });

  it('b2PolygonShape builders match the 2.2.1 calls bit for bit', () => {
    const vertices = [new b2Vec2(0, 0), new b2Vec2(2, 0.1), new b2Vec2(1.5, 1.7), new b2Vec2(-0.2, 1)];
    expect(b2PolygonShape.AsArray(vertices, 0)).toEqual(new b2PolygonShape().Set(vertices));
    expect(b2PolygonShape.AsVector(vertices, 3)).toEqual(new b2PolygonShape().Set(vertices, 3));
    expect(b2PolygonShape.AsBox(1, 2)).toEqual(new b2PolygonShape().SetAsBox(1, 2));
    expect(b2PolygonShape.AsOrientedBox(1, 2, new b2Vec2(3, 4), 0.5)).toEqual(new b2PolygonShape().SetAsBox(1, 2, new b2Vec2(3, 4), 0.5));
    const shape = new b2PolygonShape();
    shape.SetAsArray(vertices);
    expect(shape.GetVertices()).toEqual(vertices);
    expect(shape.GetVertices()[0]).toBe(shape.m_vertices[0]);
    expect(shape.GetNormals()).toHaveLength(4);
    expect(b2PolygonShape.ComputeCentroid(vertices, 4)).toEqual(shape.m_centroid);
  });

  it('SetAsEdge makes a two-vertex polygon that becomes an edge fixture a box can rest on', () => {
    const ground = b2PolygonShape.AsEdge(new b2Vec2(-10, 0), new b2Vec2(10, 0));
    expect(ground.GetVertexCount()).toBe(2);
    expect([ground.m_normals[0].x, ground.m_normals[0].y, ground.m_normals[1].y]).toEqual([0, -1, 1]);
    expect([ground.m_centroid.x, ground.m_centroid.y]).toEqual([0, 0]);
    const world = new b2World(new b2Vec2(0, -10), true);
    const groundBody = world.CreateBody(new b2BodyDef());
    const def = new b2FixtureDef();
    def.shape = ground;
    const fixture = groundBody.CreateFixture(def);
    expect(def.shape).toBe(ground);
    expect(fixture.GetShape()).toBeInstanceOf(wp.b2EdgeShape);
    const edge = fixture.GetShape() as wp.b2EdgeShape;
    expect([edge.m_vertex1.x, edge.m_vertex2.x, edge.m_radius]).toEqual([-10, 10, wp.b2_polygonRadius]);
    const box = dynamicBody(world, 0, 2, b2PolygonShape.AsBox(0.5, 0.5));
    for (let i = 0; i < 120; ++i) world.Step(1 / 60, 8, 3);
    expect(box.GetPosition().y).toBeCloseTo(0.5, 1);
    expect(groundBody.CreateFixture2(b2PolygonShape.AsEdge(new b2Vec2(0, 0), new b2Vec2(1, 1))).GetType()).toBe(wp.b2Shape.e_edge);
  });
});

describe('Box2D.Dynamics', () => {
  function scene() {
    const world = new b2World(new b2Vec2(0, -10), true);
    const ground = staticBox(world, 0, -1, 20, 1);
    const a = dynamicBody(world, -2, 0.5, b2PolygonShape.AsBox(0.5, 0.5));
    const b = dynamicBody(world, 2, 0.5, new b2CircleShape(0.5));
    return { world, ground, a, b };
  }

  it('QueryAABB and RayCast take 2.1a functions, and a falsy return stops the query as in 2.1a', () => {
    const { world, a, b } = scene();
    const aabb = new wp.b2AABB();
    aabb.lowerBound.Set(-5, 0);
    aabb.upperBound.Set(5, 1);
    const found: wp.b2Fixture[] = [];
    world.QueryAABB((fixture) => {
      found.push(fixture);
      return true;
    }, aabb);
    expect(new Set(found.map((f) => f.GetBody()))).toEqual(new Set([a, b, world.GetBodyList()!.GetNext()!.GetNext()]));
    let calls = 0;
    world.QueryAABB(() => {
      calls++;
    }, aabb);
    expect(calls).toBe(1);
    const objectCalls: wp.b2Fixture[] = [];
    world.QueryAABB({ ReportFixture: (f: wp.b2Fixture) => objectCalls.push(f) > 0 }, aabb);
    expect(objectCalls).toHaveLength(3);

    const points: wp.b2Vec2[] = [];
    world.RayCast(
      (fixture, point, normal, fraction) => {
        points.push(point);
        return 1;
      },
      new b2Vec2(-10, 0.5),
      new b2Vec2(10, 0.5),
    );
    // Each report has its own point (2.1a made a new one each time).
    expect(points).toHaveLength(2);
    expect(points[0]).not.toBe(points[1]);
    expect(points.map((p) => p.x).sort((x, y) => x - y)).toEqual([-2.5, 1.5]);
    expect(world.RayCastOne(new b2Vec2(-10, 0.5), new b2Vec2(10, 0.5))!.GetBody()).toBe(a);
    expect(world.RayCastOne(new b2Vec2(10, 0.5), new b2Vec2(-10, 0.5))!.GetBody()).toBe(b);
    expect(world.RayCastOne(new b2Vec2(-10, 5), new b2Vec2(10, 5))).toBe(null);
    expect(world.RayCastAll(new b2Vec2(-10, 0.5), new b2Vec2(10, 0.5)).map((f) => f.GetBody())).toHaveLength(2);
  });

  it('QueryPoint reports the fixtures containing the point; QueryShape those overlapping the shape', () => {
    const { world, a, b } = scene();
    const at = (x: number, y: number) => {
      const bodies: wp.b2Body[] = [];
      world.QueryPoint((f) => bodies.push(f.GetBody()) > 0, new b2Vec2(x, y));
      return bodies;
    };
    expect(at(-2, 0.5)).toEqual([a]);
    expect(at(2.3, 0.6)).toEqual([b]);
    expect(at(0, 0.5)).toEqual([]);
    const probe = new b2CircleShape(0.3);
    const overlapping = (x: number, y: number) => {
      const bodies: wp.b2Body[] = [];
      world.QueryShape((f) => bodies.push(f.GetBody()) > 0, probe, new wp.b2Transform(new b2Vec2(x, y), new wp.b2Rot(0)));
      return bodies;
    };
    expect(overlapping(-1.4, 0.5)).toEqual([a]);
    expect(overlapping(-1.1, 2)).toEqual([]);
    expect(overlapping(0, -0.1)).toHaveLength(1);
  });

  it('GetGroundBody creates one static body at the origin, once', () => {
    const world = new b2World(new b2Vec2(0, 10), true);
    expect(world.GetBodyCount()).toBe(0);
    const ground = world.GetGroundBody();
    expect(world.GetGroundBody()).toBe(ground);
    expect(world.GetBodyCount()).toBe(1);
    expect(ground.GetType()).toBe(wp.b2_staticBody);
    expect([ground.GetPosition().x, ground.GetPosition().y, ground.GetFixtureList()]).toEqual([0, 0, null]);
    world.Validate();
  });

  it("b2Body's 2.1a setters, GetDefinition and ApplyImpulse map onto SetTransform and ApplyLinearImpulse", () => {
    const { world, a } = scene();
    a.SetPositionAndAngle(new b2Vec2(1, 2), 0.5);
    expect([a.GetPosition().x, a.GetPosition().y, a.GetAngle()]).toEqual([1, 2, 0.5]);
    a.SetPosition(new b2Vec2(3, 4));
    expect([a.GetPosition().x, a.GetAngle()]).toEqual([3, 0.5]);
    a.SetAngle(0.25);
    expect([a.GetPosition().x, a.GetPosition().y, a.GetAngle()]).toEqual([3, 4, 0.25]);
    const xf = new wp.b2Transform();
    xf.Set(new b2Vec2(-1, 1), 0.125);
    (a.SetTransform as unknown as (xf: wp.b2Transform) => void)(xf);
    expect([a.GetPosition().x, a.GetPosition().y, a.GetAngle()]).toEqual([-1, 1, xf.q.GetAngle()]);

    a.SetLinearVelocity(new b2Vec2(1, 2));
    a.SetUserData({ name: 'a' });
    const def = a.GetDefinition();
    expect([def.type, def.position.x, def.angle, def.linearVelocity.y, def.userData.name]).toEqual([wp.b2_dynamicBody, -1, a.GetAngle(), 2, 'a']);
    const twin = world.CreateBody(def);
    expect([twin.GetPosition().x, twin.GetAngle(), twin.GetLinearVelocity().x]).toEqual([-1, a.GetAngle(), 1]);

    const one = scene();
    const two = scene();
    one.a.ApplyImpulse(new b2Vec2(0.3, 2), new b2Vec2(-2.2, 0.7));
    two.a.ApplyLinearImpulse(new b2Vec2(0.3, 2), new b2Vec2(-2.2, 0.7));
    for (let i = 0; i < 10; ++i) {
      one.world.Step(1 / 60, 8, 3);
      two.world.Step(1 / 60, 8, 3);
    }
    expect(one.a.GetTransform()).toEqual(two.a.GetTransform());
    expect(one.a.GetAngularVelocity()).toBe(two.a.GetAngularVelocity());
  });

  it('fixtures: GetAABB() without an index, GetMassData() allocating, RayCast on the first child', () => {
    const { world, a } = scene();
    const fixture = a.GetFixtureList()!;
    expect(fixture.GetAABB()).toBe(fixture.GetAABB(0));
    const mass = fixture.GetMassData() as unknown as wp.b2MassData;
    expect(mass.mass).toBe(1);
    const chain = new wp.b2ChainShape();
    chain.CreateChain([new b2Vec2(0, 5), new b2Vec2(1, 5), new b2Vec2(2, 6)]);
    const chainFixture = world.CreateBody(new b2BodyDef()).CreateFixture(chain, 0);
    const box = chainFixture.GetAABB();
    expect(box.Contains(chainFixture.GetAABB(0))).toBe(true);
    expect(box.Contains(chainFixture.GetAABB(1))).toBe(true);
    const output = new wp.b2RayCastOutput();
    expect(fixture.RayCast(output, new wp.b2RayCastInput(new b2Vec2(-5, 0.5), new b2Vec2(0, 0.5)))).toBe(true);
    expect(output.fraction).toBeCloseTo(0.5, 12);
  });

  it('b2FilterData is b2Filter, with Copy; contacts say whether they involve a sensor', () => {
    expect(wp.b2FilterData).toBe(wp.b2Filter);
    const filter = new wp.b2FilterData();
    filter.groupIndex = -3;
    const copy = filter.Copy();
    expect(copy).not.toBe(filter);
    expect(copy.groupIndex).toBe(-3);
    const { world, a } = scene();
    world.Step(1 / 60, 8, 3);
    const contact = world.GetContactList()!;
    expect(contact.IsSensor()).toBe(false);
    a.GetFixtureList()!.SetSensor(true);
    const sensorContact = a.GetContactList()!.contact;
    expect(sensorContact.IsSensor()).toBe(true);
  });

  it('listeners need only the methods they use: 2.1a gave the others empty defaults', () => {
    const { world, a } = scene();
    const listener = new wp.b2DestructionListener();
    const gone: string[] = [];
    listener.SayGoodbyeFixture = () => gone.push('fixture');
    world.SetDestructionListener(listener);
    const def = new wp.b2DistanceJointDef();
    def.Initialize(a, world.GetGroundBody(), new b2Vec2(0, 0), new b2Vec2(0, 1));
    world.CreateJoint(def);
    world.DestroyBody(a);
    expect(gone).toEqual(['fixture']);
  });

  it('joints: anchors and reaction forces without an out vector, 2.1a pulley names, type constants', () => {
    const { world, a, b } = scene();
    const def = new wp.b2PulleyJointDef();
    def.Initialize(a, b, new b2Vec2(-2, 5), new b2Vec2(2, 5), new b2Vec2(-2, 1), new b2Vec2(2, 1), 1);
    const pulley = world.CreateJoint(def) as wp.b2PulleyJoint;
    for (let i = 0; i < 5; ++i) world.Step(1 / 60, 8, 3);
    expect(pulley.GetAnchorA()).toEqual(pulley.GetAnchorA(new b2Vec2()));
    expect(pulley.GetAnchorB()).toEqual(pulley.GetAnchorB(new b2Vec2()));
    expect(pulley.GetReactionForce(60)).toEqual(pulley.GetReactionForce(60, new b2Vec2()));
    expect(pulley.GetGroundAnchorA()).toEqual(new b2Vec2(-2, 5));
    expect(pulley.GetLength1()).toBe(pulley.GetLengthA());
    expect(pulley.GetLength2()).toBe(pulley.GetLengthB());
    expect(wp.b2Joint.e_pulleyJoint).toBe(wp.b2JointType.e_pulleyJoint);
    expect(wp.b2Joint.e_atUpperLimit).toBe(wp.b2LimitState.e_atUpperLimit);
    expect(pulley.GetType()).toBe(wp.b2Joint.e_pulleyJoint);
    const pjd = new wp.b2PrismaticJointDef();
    pjd.Initialize(a, b, new b2Vec2(0, 0), new b2Vec2(1, 0));
    const prismatic = world.CreateJoint(pjd) as wp.b2PrismaticJoint;
    expect(() => (prismatic.GetMotorForce as unknown as () => number)()).toThrow(/GetMotorForce\(1 \/ timeStep\)/);
    expect(prismatic.GetMotorForce(60)).toBe(0);
  });

  it('removed 2.1a calls throw through the ES entry too', () => {
    const world = new b2World(new b2Vec2(0, 10), true);
    expect(() => (world as any).SetBroadPhase(null)).toThrow(
      'b2World.SetBroadPhase is not available: Box2D 2.2 removed it. The world always uses its dynamic-tree broad phase (b2BroadPhase); remove the call.',
    );
    expect(() => new wp.b2EdgeChainDef()).toThrow(/new b2EdgeChainDef\(\) is not available/);
    expect(() => new Box2D.Dynamics.Controllers.b2ConstantForceController()).toThrow(/no controllers/);
  });
});

describe('with the compatibility layer installed', () => {
  it('a golden scene still follows the C++ reference trajectory bit for bit', () => {
    const trajectory = readTrajectory('bridge');
    const scene = loadGoldenScene('bridge');
    scene.world.SetContactListener(null);
    for (let k = 1; k <= 120; ++k) {
      scene.world.Step(1 / 60, scene.stepSettings.velocityIterations, scene.stepSettings.positionIterations);
      expect(stateDigest(scene.bodies), `step ${k}`).toBe(trajectory.digests[k]);
    }
  });
});
