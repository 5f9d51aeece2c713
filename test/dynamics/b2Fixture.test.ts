import { afterEach, describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2LogSink, b2SetLogSink, b2_linearSlop, b2_polygonRadius } from '../../src/common/b2Settings';
import { b2RayCastInput, b2RayCastOutput } from '../../src/collision/b2Collision';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Shape } from '../../src/collision/shapes/b2Shape';
import { b2BroadPhase } from '../../src/collision/b2BroadPhase';
import { b2BodyDef, b2_dynamicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import type { b2Body, b2BodyType } from '../../src/dynamics/b2Body';
import { b2Filter, b2FixtureDef } from '../../src/dynamics/b2Fixture';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2ContactListener } from '../../src/dynamics/b2WorldCallbacks';
import type { b2Contact } from '../../src/dynamics/contacts/b2Contact';

const dt = 1.0 / 60.0;
const defaultSink = b2LogSink;

afterEach(() => {
  b2SetLogSink(defaultSink);
});

function createBody(world: b2World, type: b2BodyType, x = 0.0, y = 0.0): b2Body {
  const bd = new b2BodyDef();
  bd.type = type;
  bd.position.Set(x, y);
  return world.CreateBody(bd);
}

function boxFixture(body: b2Body, filter?: Partial<b2Filter>, density = 1.0): b2Fixture {
  const fd = new b2FixtureDef();
  fd.shape = new b2PolygonShape().SetAsBox(1.0, 1.0);
  fd.density = density;
  if (filter) {
    Object.assign(fd.filter, filter);
  }
  return body.CreateFixture(fd);
}

/** Two overlapping dynamic boxes in zero gravity with the given filters; contact count after one step. */
function contactsBetween(filterA: Partial<b2Filter>, filterB: Partial<b2Filter>): number {
  const world = new b2World(new b2Vec2(0.0, 0.0));
  boxFixture(createBody(world, b2_dynamicBody, 0.0, 0.0), filterA);
  boxFixture(createBody(world, b2_dynamicBody, 1.0, 0.0), filterB);
  world.Step(dt, 8, 3);
  return world.GetContactCount();
}

describe('b2Filter and b2FixtureDef', () => {
  it('have the C++ defaults', () => {
    const filter = new b2Filter();
    expect([filter.categoryBits, filter.maskBits, filter.groupIndex]).toEqual([0x0001, 0xffff, 0]);
    const fd = new b2FixtureDef();
    expect(fd.shape).toBeNull();
    expect(fd.userData).toBeNull();
    expect([fd.friction, fd.restitution, fd.density, fd.isSensor]).toEqual([0.2, 0.0, 0.0, false]);
    expect([fd.filter.categoryBits, fd.filter.maskBits, fd.filter.groupIndex]).toEqual([0x0001, 0xffff, 0]);
  });

  it('copies wrap to the C++ field widths (uint16 bits, int16 group)', () => {
    const source = new b2Filter();
    source.categoryBits = 0x10002;
    source.maskBits = -1;
    source.groupIndex = 0x8000;
    const copy = new b2Filter().Assign(source);
    expect([copy.categoryBits, copy.maskBits, copy.groupIndex]).toEqual([0x0002, 0xffff, -32768]);
    source.groupIndex = -3;
    expect(source.Clone().groupIndex).toBe(-3);
  });
});

describe('b2Fixture creation', () => {
  it('copies the definition, clones the shape and owns a copy of the filter', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2_dynamicBody);
    const fd = new b2FixtureDef();
    const circle = new b2CircleShape();
    circle.m_radius = 2.0;
    fd.shape = circle;
    fd.userData = { tag: 1 };
    fd.friction = 0.6;
    fd.restitution = 0.3;
    fd.density = 2.5;
    fd.isSensor = true;
    fd.filter.groupIndex = -2;
    const f = body.CreateFixture(fd);
    fd.filter.groupIndex = 7;
    circle.m_radius = 9.0;

    expect(f.GetBody()).toBe(body);
    expect(f.GetType()).toBe(b2Shape.e_circle);
    expect(f.GetShape()).not.toBe(circle);
    expect(f.GetShape().m_radius).toBe(2.0);
    expect(f.GetUserData()).toBe(fd.userData);
    expect([f.GetFriction(), f.GetRestitution(), f.GetDensity(), f.IsSensor()]).toEqual([0.6, 0.3, 2.5, true]);
    expect(f.GetFilterData().groupIndex).toBe(-2);
    expect(f.m_proxyCount).toBe(1);
    expect(f.m_proxies[0].fixture).toBe(f);
    expect(f.m_proxies[0].childIndex).toBe(0);
    expect(world.m_contactManager.m_broadPhase.GetUserData(f.m_proxies[0].proxyId)).toBe(f.m_proxies[0]);
  });

  it('rejects a definition without a shape', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2_dynamicBody);
    expect(() => body.CreateFixture(new b2FixtureDef())).toThrow();
    expect(body.GetFixtureList()).toBeNull();
  });

  it('gives a chain one proxy per edge, each with the AABB of its edge', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2_staticBody, 1.0, 0.0);
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(0.0, 0.0), new b2Vec2(2.0, 0.0), new b2Vec2(2.0, 3.0)]);
    const f = body.CreateFixture(chain, 0.0);

    expect(f.m_proxyCount).toBe(2);
    expect(world.GetProxyCount()).toBe(2);
    expect(f.m_proxies.map((p) => p.childIndex)).toEqual([0, 1]);
    // The 2.2.1 chain AABB is the bare segment's (b2ChainShape::ComputeAABB adds no radius).
    const a0 = f.GetAABB(0);
    expect([a0.lowerBound.x, a0.lowerBound.y, a0.upperBound.x, a0.upperBound.y]).toEqual([1.0, 0.0, 3.0, 0.0]);
    const a1 = f.GetAABB(1);
    expect([a1.lowerBound.x, a1.lowerBound.y, a1.upperBound.x, a1.upperBound.y]).toEqual([3.0, 0.0, 3.0, 3.0]);
    expect(() => f.GetAABB(2)).toThrow();
  });

  it('DestroyProxies clears the proxy ids and Destroy requires it first', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2_dynamicBody);
    const f = boxFixture(body);
    expect(() => f.Destroy()).toThrow();
    f.DestroyProxies(world.m_contactManager.m_broadPhase);
    expect(f.m_proxyCount).toBe(0);
    expect(f.m_proxies[0].proxyId).toBe(b2BroadPhase.e_nullProxy);
    expect(world.GetProxyCount()).toBe(0);
    f.Destroy();
  });

  it('Synchronize covers the swept shape and moves the proxy by the displacement', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2_dynamicBody);
    const f = boxFixture(body);
    const xf1 = body.GetTransform().Clone();
    const xf2 = xf1.Clone();
    xf2.p.Set(5.0, -2.0);
    f.Synchronize(world.m_contactManager.m_broadPhase, xf1, xf2);
    const aabb = f.GetAABB(0);
    const r = f.GetShape().m_radius;
    expect(aabb.lowerBound.x).toBeCloseTo(-1.0 - r, 14);
    expect(aabb.lowerBound.y).toBeCloseTo(-3.0 - r, 14);
    expect(aabb.upperBound.x).toBeCloseTo(6.0 + r, 14);
    expect(aabb.upperBound.y).toBeCloseTo(1.0 + r, 14);
    const fat = world.m_contactManager.m_broadPhase.GetFatAABB(f.m_proxies[0].proxyId);
    expect(fat.lowerBound.x).toBeLessThanOrEqual(aabb.lowerBound.x);
    expect(fat.upperBound.x).toBeGreaterThanOrEqual(aabb.upperBound.x);
  });
});

describe('b2Fixture filtering', () => {
  it('collides by default', () => {
    expect(contactsBetween({}, {})).toBe(1);
  });

  it('needs each mask to accept the other category', () => {
    expect(contactsBetween({ categoryBits: 0x0002 }, { maskBits: 0xffff & ~0x0002 })).toBe(0);
    expect(contactsBetween({ maskBits: 0x0004 }, { categoryBits: 0x0002 })).toBe(0);
    expect(contactsBetween({ categoryBits: 0x0002, maskBits: 0x0004 }, { categoryBits: 0x0004, maskBits: 0x0002 })).toBe(1);
  });

  it('always collides within the same positive group, whatever the masks', () => {
    expect(contactsBetween({ groupIndex: 3, maskBits: 0 }, { groupIndex: 3, maskBits: 0 })).toBe(1);
  });

  it('never collides within the same negative group, whatever the masks', () => {
    expect(contactsBetween({ groupIndex: -3 }, { groupIndex: -3 })).toBe(0);
  });

  it('falls back to the masks for different groups', () => {
    expect(contactsBetween({ groupIndex: -3 }, { groupIndex: -4 })).toBe(1);
    expect(contactsBetween({ groupIndex: 3, maskBits: 0 }, { groupIndex: 4 })).toBe(0);
  });

  it('decides what physically collides: a box falls through the ground or lands on it by category, mask and group', () => {
    /** Drops a 2 x 2 box from y = 2 onto a static ground (top at y = 0.5); its height after 1.5 s. */
    function drop(groundFilter: Partial<b2Filter>, boxFilter: Partial<b2Filter>): number {
      const world = new b2World(new b2Vec2(0.0, -10.0));
      const ground = createBody(world, b2_staticBody);
      const fd = new b2FixtureDef();
      fd.shape = new b2PolygonShape().SetAsBox(10.0, 0.5);
      Object.assign(fd.filter, groundFilter);
      ground.CreateFixture(fd);
      const body = createBody(world, b2_dynamicBody, 0.0, 2.0);
      boxFixture(body, boxFilter);
      for (let k = 0; k < 90; ++k) world.Step(dt, 8, 3);
      return body.GetPosition().y;
    }
    const landed = 0.5 + 1.0 + 2.0 * b2_polygonRadius - b2_linearSlop;
    const fellThrough = (y: number) => y < -5.0;

    expect(drop({}, {})).toBeCloseTo(landed, 3);
    // The box's mask rejects the ground's category, or the ground's mask rejects the box's.
    expect(fellThrough(drop({ categoryBits: 0x0002 }, { maskBits: 0xffff & ~0x0002 }))).toBe(true);
    expect(fellThrough(drop({ maskBits: 0xffff & ~0x0004 }, { categoryBits: 0x0004 }))).toBe(true);
    // A shared positive group overrides the masks; a shared negative group overrides matching masks.
    expect(drop({ categoryBits: 0x0002, groupIndex: 5 }, { maskBits: 0xffff & ~0x0002, groupIndex: 5 })).toBeCloseTo(landed, 3);
    expect(fellThrough(drop({ groupIndex: -5 }, { groupIndex: -5 }))).toBe(true);
    // Different groups fall back to the masks.
    expect(drop({ groupIndex: -5 }, { groupIndex: -6 })).toBeCloseTo(landed, 3);
  });

  it('Refilter after SetFilterData drops the contact on the next step and a later one restores it', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = boxFixture(createBody(world, b2_dynamicBody, 0.0, 0.0));
    boxFixture(createBody(world, b2_dynamicBody, 1.0, 0.0));
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(1);

    const filter = a.GetFilterData().Clone();
    filter.maskBits = 0;
    a.SetFilterData(filter);
    expect(a.GetFilterData()).not.toBe(filter);
    expect(a.GetFilterData().maskBits).toBe(0);
    // Only flagged: the contact lives until the next collide phase.
    expect(world.GetContactCount()).toBe(1);
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(0);

    filter.maskBits = 0xffff;
    a.SetFilterData(filter);
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(1);
  });
});

describe('b2Fixture sensors', () => {
  it('creates a contact that touches without points and never pushes the body', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const ground = createBody(world, b2_staticBody);
    const sensor = new b2FixtureDef();
    const circle = new b2CircleShape();
    circle.m_radius = 5.0;
    sensor.shape = circle;
    sensor.isSensor = true;
    ground.CreateFixture(sensor);

    const ball = createBody(world, b2_dynamicBody, 0.0, 1.0);
    const ballShape = new b2CircleShape();
    ballShape.m_radius = 1.0;
    ball.CreateFixture(ballShape, 1.0);

    const events: string[] = [];
    class Recorder extends b2ContactListener {
      override BeginContact(): void {
        events.push('begin');
      }
      override PreSolve(): void {
        events.push('presolve');
      }
      override PostSolve(): void {
        events.push('postsolve');
      }
    }
    world.SetContactListener(new Recorder());
    world.Step(dt, 8, 3);

    expect(world.GetContactCount()).toBe(1);
    const contact = world.GetContactList()!;
    expect(contact.IsTouching()).toBe(true);
    expect(contact.GetManifold().pointCount).toBe(0);
    expect(events).toEqual(['begin']);
    // Free fall: v = h * gravity, untouched by the sensor.
    expect(Object.is(ball.GetLinearVelocity().y, dt * (1.0 * -10.0 + ball.m_invMass * 0.0))).toBe(true);
    expect(ball.GetLinearVelocity().x).toBe(0.0);
  });

  it('SetSensor wakes the body only when the flag changes', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2_dynamicBody);
    const f = boxFixture(body);
    body.SetAwake(false);
    f.SetSensor(false);
    expect(body.IsAwake()).toBe(false);
    f.SetSensor(true);
    expect(f.IsSensor()).toBe(true);
    expect(body.IsAwake()).toBe(true);
  });
});

describe('b2Fixture queries and material', () => {
  it('TestPoint and RayCast use the body transform', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const f = boxFixture(createBody(world, b2_dynamicBody, 5.0, 0.0));
    expect(f.TestPoint(new b2Vec2(5.5, 0.5))).toBe(true);
    expect(f.TestPoint(new b2Vec2(6.5, 0.0))).toBe(false);

    const input = new b2RayCastInput();
    input.p1.Set(0.0, 0.0);
    input.p2.Set(10.0, 0.0);
    input.maxFraction = 1.0;
    const output = new b2RayCastOutput();
    expect(f.RayCast(output, input, 0)).toBe(true);
    expect(output.fraction).toBeCloseTo(0.4, 14);
    expect(output.normal.x).toBeCloseTo(-1.0, 14);
    expect(output.normal.y).toBeCloseTo(0.0, 14);
    input.p2.Set(0.0, 10.0);
    expect(f.RayCast(output, input, 0)).toBe(false);
  });

  it('SetDensity changes the mass only after ResetMassData, and rejects negative densities', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2_dynamicBody);
    const f = boxFixture(body);
    expect(body.GetMass()).toBe(4.0);
    f.SetDensity(3.0);
    expect(body.GetMass()).toBe(4.0);
    body.ResetMassData();
    expect(body.GetMass()).toBe(12.0);
    expect(() => f.SetDensity(-1.0)).toThrow();
    expect(f.GetDensity()).toBe(3.0);
  });

  it('SetFriction and SetRestitution leave existing contacts with their mixed values', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = boxFixture(createBody(world, b2_dynamicBody, 0.0, 0.0));
    const b = boxFixture(createBody(world, b2_dynamicBody, 1.0, 0.0));
    a.SetFriction(0.8);
    b.SetFriction(0.2);
    a.SetRestitution(0.1);
    b.SetRestitution(0.6);
    world.Step(dt, 8, 3);
    const contact: b2Contact = world.GetContactList()!;
    expect(contact.GetFriction()).toBe(Math.sqrt(0.8 * 0.2));
    expect(contact.GetRestitution()).toBe(0.6);

    a.SetFriction(0.5);
    a.SetRestitution(0.9);
    expect(contact.GetFriction()).toBe(Math.sqrt(0.8 * 0.2));
    expect(contact.GetRestitution()).toBe(0.6);
    expect([a.GetFriction(), a.GetRestitution()]).toEqual([0.5, 0.9]);
  });

  it('keeps user data', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const f = boxFixture(createBody(world, b2_dynamicBody));
    expect(f.GetUserData()).toBeNull();
    f.SetUserData('x');
    expect(f.GetUserData()).toBe('x');
  });
});

describe('b2Fixture.Dump', () => {
  function dump(f: b2Fixture, bodyIndex: number): string {
    let text = '';
    b2SetLogSink((s) => {
      text += s;
    });
    f.Dump(bodyIndex);
    return text;
  }

  it('prints a circle fixture as C++ source with the %.15lef format', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const fd = new b2FixtureDef();
    const circle = new b2CircleShape();
    circle.m_radius = 0.5;
    circle.m_p.Set(1.0, -2.0);
    fd.shape = circle;
    fd.density = 1.0;
    fd.filter.groupIndex = -1;
    const f = createBody(world, b2_dynamicBody).CreateFixture(fd);

    expect(dump(f, 3)).toBe(
      '    b2FixtureDef fd;\n' +
        '    fd.friction = 2.000000000000000e-01f;\n' +
        '    fd.restitution = 0.000000000000000e+00f;\n' +
        '    fd.density = 1.000000000000000e+00f;\n' +
        '    fd.isSensor = bool(0);\n' +
        '    fd.filter.categoryBits = uint16(1);\n' +
        '    fd.filter.maskBits = uint16(65535);\n' +
        '    fd.filter.groupIndex = int16(-1);\n' +
        '    b2CircleShape shape;\n' +
        '    shape.m_radius = 5.000000000000000e-01f;\n' +
        '    shape.m_p.Set(1.000000000000000e+00f, -2.000000000000000e+00f);\n' +
        '\n' +
        '    fd.shape = &shape;\n' +
        '\n' +
        '    bodies[3]->CreateFixture(&fd);\n',
    );
  });

  it('prints polygon vertices, edge vertices and chain vertices', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2_staticBody);
    const polygon = body.CreateFixture(new b2PolygonShape().SetAsBox(1.0, 2.0), 0.0);
    const edge = new b2EdgeShape();
    edge.Set(new b2Vec2(0.0, 0.0), new b2Vec2(1.0, 0.0));
    const edgeFixture = body.CreateFixture(edge, 0.0);
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(0.0, 0.0), new b2Vec2(1.0, 1.0)]);
    const chainFixture = body.CreateFixture(chain, 0.0);

    const p = dump(polygon, 0);
    expect(p).toContain('    b2PolygonShape shape;\n    b2Vec2 vs[8];\n');
    expect(p).toContain('    vs[0].Set(-1.000000000000000e+00f, -2.000000000000000e+00f);\n');
    expect(p).toContain('    vs[2].Set(1.000000000000000e+00f, 2.000000000000000e+00f);\n');
    expect(p).toContain('    shape.Set(vs, 4);\n');

    const e = dump(edgeFixture, 0);
    expect(e).toContain('    shape.m_vertex2.Set(1.000000000000000e+00f, 0.000000000000000e+00f);\n');
    expect(e).toContain('    shape.m_hasVertex0 = bool(0);\n');

    const c = dump(chainFixture, 1);
    expect(c).toContain('    b2Vec2 vs[2];\n');
    expect(c).toContain('    vs[1].Set(1.000000000000000e+00f, 1.000000000000000e+00f);\n');
    expect(c).toContain('    shape.CreateChain(vs, 2);\n');
    expect(c).toContain('    shape.m_hasNextVertex = bool(0);\n');
    expect(c.endsWith('    bodies[1]->CreateFixture(&fd);\n')).toBe(true);
  });
});
