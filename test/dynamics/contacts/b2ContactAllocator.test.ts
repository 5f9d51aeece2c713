import { describe, expect, it } from 'vitest';
import { b2CircleShape } from '../../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../../src/collision/shapes/b2PolygonShape';
import { b2Shape } from '../../../src/collision/shapes/b2Shape';
import { b2Vec2 } from '../../../src/common/b2Math';
import type { b2Body } from '../../../src/dynamics/b2Body';
import { b2BodyDef, b2BodyType } from '../../../src/dynamics/b2Body';
import type { b2Fixture } from '../../../src/dynamics/b2Fixture';
import { b2World } from '../../../src/dynamics/b2World';
import { b2Contact } from '../../../src/dynamics/contacts/b2Contact';
import { b2ContactAllocator } from '../../../src/dynamics/contacts/b2ContactAllocator';

/*
 * The world's store of destroyed contacts (b2ContactAllocator): b2Contact.Destroy hands contacts
 * back, b2Contact.Create reuses them, and a reused contact is a new one in every field.
 */

function body(world: b2World, x: number, y: number, shape: b2Shape, type = b2BodyType.b2_dynamicBody): b2Fixture {
  const def = new b2BodyDef();
  def.type = type;
  def.position.Set(x, y);
  return world.CreateBody(def).CreateFixture(shape, 1.0);
}

const box = () => new b2PolygonShape().SetAsBox(0.5, 0.5);
function circle(): b2CircleShape {
  const c = new b2CircleShape();
  c.m_radius = 0.5;
  return c;
}

/** Every field a contact's behaviour depends on, as plain data. */
function stateOf(c: b2Contact): unknown {
  const m = c.m_manifold;
  return {
    flags: c.m_flags,
    prev: c.m_prev,
    next: c.m_next,
    fixtures: [c.m_fixtureA, c.m_fixtureB, c.m_indexA, c.m_indexB],
    edges: [c.m_nodeA.contact === c, c.m_nodeA.other, c.m_nodeA.prev, c.m_nodeA.next, c.m_nodeB.contact === c, c.m_nodeB.other, c.m_nodeB.prev, c.m_nodeB.next],
    toi: [c.m_toiCount, c.m_toi],
    mix: [c.m_friction, c.m_restitution],
    manifold: [m.type, m.pointCount, m.localNormal.x, m.localNormal.y, m.localPoint.x, m.localPoint.y],
    points: m.points.map((p) => [p.localPoint.x, p.localPoint.y, p.normalImpulse, p.tangentImpulse, p.id.key]),
  };
}

describe('b2ContactAllocator', () => {
  it('returns stored contacts last in, first out, per pair of shape types', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = body(world, 0, 0, box());
    const b = body(world, 0, 0.9, box());
    const allocator = new b2ContactAllocator();
    const c1 = b2Contact.Create(a, 0, b, 0)!;
    const c2 = b2Contact.Create(a, 0, b, 0)!;
    b2Contact.Destroy(c1, allocator);
    b2Contact.Destroy(c2, allocator);
    expect(allocator.GetCount()).toBe(2);
    expect(allocator.Allocate(b2Shape.e_circle, b2Shape.e_polygon)).toBeNull();
    expect(allocator.Allocate(b2Shape.e_polygon, b2Shape.e_polygon)).toBe(c2);
    expect(allocator.Allocate(b2Shape.e_polygon, b2Shape.e_polygon)).toBe(c1);
    expect(allocator.Allocate(b2Shape.e_polygon, b2Shape.e_polygon)).toBeNull();
    expect(allocator.GetCount()).toBe(0);
  });

  it('a stored contact holds no fixture or body (they may be destroyed)', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const allocator = new b2ContactAllocator();
    const c = b2Contact.Create(body(world, 0, 0, box()), 0, body(world, 0, 0.9, box()), 0)!;
    b2Contact.Destroy(c, allocator);
    expect(c.m_fixtureA).toBeNull();
    expect(c.m_fixtureB).toBeNull();
    expect(c.m_nodeA.other).toBeNull();
    expect(c.m_nodeB.other).toBeNull();
  });

  it('b2Contact.Create reinitialises a stored contact into the state of a new one, with A and B swapped as the registry says', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const ground = body(world, 0, 0, box(), b2BodyType.b2_staticBody);
    const ball = body(world, 0, 0.95, circle());
    ground.SetFriction(0.3);
    ball.SetRestitution(0.4);
    // A touching contact with a full manifold, impulses and flags, then destroyed into the store.
    for (let i = 0; i < 5; ++i) world.Step(1 / 60, 8, 3);
    const used = world.GetContactList()!;
    expect(used.IsTouching()).toBe(true);
    used.SetFriction(9.0);
    const allocator = new b2ContactAllocator();
    world.m_contactManager.m_contactList = null; // detach it so the world does not step it again
    b2Contact.Destroy(used, allocator);

    // Circle first: the polygon-circle registration is the reverse one, so fixture A is the box.
    const reused = b2Contact.Create(ball, 0, ground, 0, allocator)!;
    const fresh = b2Contact.Create(ball, 0, ground, 0)!;
    expect(reused).toBe(used);
    expect(reused.constructor).toBe(fresh.constructor);
    expect(reused.m_fixtureA).toBe(ground);
    expect(stateOf(reused)).toEqual(stateOf(fresh));
  });

  it('a world whose contacts end and begin again constructs no new ones once its store is stocked', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    body(world, 0, -0.5, new b2PolygonShape().SetAsBox(20.0, 0.5), b2BodyType.b2_staticBody);
    const bodies: b2Body[] = [];
    for (let i = 0; i < 40; ++i) bodies.push(body(world, -10 + 0.5 * i, 0.45 + (i % 3), box()).GetBody());
    const seen = new Set<b2Contact>();
    let ended = 0;
    // Lift every box off the ground and drop it again: all contacts end, then begin again.
    const cycle = () => {
      for (const b of bodies) b.SetTransform(new b2Vec2(b.GetPosition().x, 3.0 + b.GetPosition().x / 40), 0.0);
      const before = world.GetContactCount();
      world.Step(1 / 60, 8, 3);
      ended += before - world.GetContactCount();
      for (let s = 0; s < 40; ++s) {
        world.Step(1 / 60, 8, 3);
        for (let c = world.GetContactList(); c; c = c.GetNext()) seen.add(c);
      }
    };
    cycle();
    cycle();
    const constructed = seen.size;
    ended = 0;
    for (let i = 0; i < 3; ++i) cycle();
    expect(ended).toBeGreaterThan(0);
    expect(world.GetContactCount()).toBeGreaterThan(0);
    expect(seen.size).toBe(constructed);
  });
});
