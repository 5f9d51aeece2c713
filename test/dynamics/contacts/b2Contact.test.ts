import { describe, expect, it } from 'vitest';
import { b2Manifold } from '../../../src/collision/b2Collision';
import { b2ManifoldField } from '../../../src/collision/b2ManifoldRecord';
import { b2ChainShape } from '../../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../../src/collision/shapes/b2PolygonShape';
import type { b2Shape } from '../../../src/collision/shapes/b2Shape';
import { b2Vec2 } from '../../../src/common/b2Math';
import { b2BodyDef, b2BodyType } from '../../../src/dynamics/b2Body';
import { b2FixtureDef } from '../../../src/dynamics/b2Fixture';
import type { b2Fixture } from '../../../src/dynamics/b2Fixture';
import { b2World } from '../../../src/dynamics/b2World';
import { b2ContactListener } from '../../../src/dynamics/b2WorldCallbacks';
import { b2ChainAndCircleContact } from '../../../src/dynamics/contacts/b2ChainAndCircleContact';
import { b2ChainAndPolygonContact } from '../../../src/dynamics/contacts/b2ChainAndPolygonContact';
import { b2CircleContact } from '../../../src/dynamics/contacts/b2CircleContact';
import { b2Contact, b2MixFriction, b2MixRestitution } from '../../../src/dynamics/contacts/b2Contact';
import { b2InitializeContactRegisters } from '../../../src/dynamics/contacts/b2ContactRegistry';
import { b2EdgeAndCircleContact } from '../../../src/dynamics/contacts/b2EdgeAndCircleContact';
import { b2EdgeAndPolygonContact } from '../../../src/dynamics/contacts/b2EdgeAndPolygonContact';
import { b2PolygonAndCircleContact } from '../../../src/dynamics/contacts/b2PolygonAndCircleContact';
import { b2PolygonContact } from '../../../src/dynamics/contacts/b2PolygonContact';

type ShapeName = 'circle' | 'edge' | 'polygon' | 'chain';

function makeShape(name: ShapeName): b2Shape {
  switch (name) {
    case 'circle': {
      const circle = new b2CircleShape();
      circle.m_radius = 0.5;
      return circle;
    }
    case 'edge':
      return new b2EdgeShape().Set(new b2Vec2(-1.0, 0.0), new b2Vec2(1.0, 0.0));
    case 'polygon':
      return new b2PolygonShape().SetAsBox(0.5, 0.5);
    case 'chain': {
      const chain = new b2ChainShape();
      chain.CreateChain([new b2Vec2(-3.0, 0.0), new b2Vec2(-1.0, 0.0), new b2Vec2(1.0, 0.0), new b2Vec2(3.0, 0.0)]);
      return chain;
    }
  }
}

interface FixtureOptions {
  type?: b2BodyType;
  x?: number;
  y?: number;
  friction?: number;
  restitution?: number;
  isSensor?: boolean;
  awake?: boolean;
}

function addFixture(world: b2World, shape: b2Shape, options: FixtureOptions = {}): b2Fixture {
  const bd = new b2BodyDef();
  bd.type = options.type ?? b2BodyType.b2_dynamicBody;
  bd.position.Set(options.x ?? 0.0, options.y ?? 0.0);
  bd.awake = options.awake ?? true;
  const body = world.CreateBody(bd);
  const fd = new b2FixtureDef();
  fd.shape = shape;
  fd.density = 1.0;
  fd.friction = options.friction ?? 0.2;
  fd.restitution = options.restitution ?? 0.0;
  fd.isSensor = options.isSensor ?? false;
  return body.CreateFixture(fd);
}

function newWorld(): b2World {
  // The contact manager's constructor fills the contact registry.
  return new b2World(new b2Vec2(0.0, -10.0));
}

/** Records the listener calls Update makes, with the old manifold's point count for PreSolve. */
class RecordingListener extends b2ContactListener {
  readonly events: string[] = [];

  override BeginContact(contact: b2Contact): void {
    this.events.push('BeginContact');
  }

  override EndContact(contact: b2Contact): void {
    this.events.push('EndContact');
  }

  override PreSolve(contact: b2Contact, oldManifold: b2Manifold): void {
    this.events.push(`PreSolve(old points ${oldManifold.pointCount}, new points ${contact.GetManifold().pointCount})`);
  }
}

describe('b2Contact registry', () => {
  const cases: [ShapeName, ShapeName, (new (...args: never[]) => b2Contact) | null, boolean][] = [
    ['circle', 'circle', b2CircleContact, false],
    ['polygon', 'circle', b2PolygonAndCircleContact, false],
    ['circle', 'polygon', b2PolygonAndCircleContact, true],
    ['polygon', 'polygon', b2PolygonContact, false],
    ['edge', 'circle', b2EdgeAndCircleContact, false],
    ['circle', 'edge', b2EdgeAndCircleContact, true],
    ['edge', 'polygon', b2EdgeAndPolygonContact, false],
    ['polygon', 'edge', b2EdgeAndPolygonContact, true],
    ['chain', 'circle', b2ChainAndCircleContact, false],
    ['circle', 'chain', b2ChainAndCircleContact, true],
    ['chain', 'polygon', b2ChainAndPolygonContact, false],
    ['polygon', 'chain', b2ChainAndPolygonContact, true],
    ['edge', 'edge', null, false],
    ['edge', 'chain', null, false],
    ['chain', 'edge', null, false],
    ['chain', 'chain', null, false],
  ];

  for (const [nameA, nameB, expectedClass, swapped] of cases) {
    const description =
      expectedClass === null
        ? `creates no contact for ${nameA} vs ${nameB}`
        : `creates a ${expectedClass.name} for ${nameA} vs ${nameB}${swapped ? ', swapping the fixtures' : ''}`;
    it(description, () => {
      const world = newWorld();
      const fixtureA = addFixture(world, makeShape(nameA), { x: -10.0 });
      const fixtureB = addFixture(world, makeShape(nameB), { x: 10.0 });
      // Chains pass the child index through; the other contact types always use child 0.
      const indexA = nameA === 'chain' ? 2 : 0;
      const indexB = nameB === 'chain' ? 1 : 0;

      const contact = b2Contact.Create(fixtureA, indexA, fixtureB, indexB);

      if (expectedClass === null) {
        expect(contact).toBeNull();
        return;
      }
      expect(contact).toBeInstanceOf(expectedClass);
      expect(contact!.GetFixtureA()).toBe(swapped ? fixtureB : fixtureA);
      expect(contact!.GetFixtureB()).toBe(swapped ? fixtureA : fixtureB);
      expect(contact!.GetChildIndexA()).toBe(swapped ? indexB : indexA);
      expect(contact!.GetChildIndexB()).toBe(swapped ? indexA : indexB);
    });
  }

  it("makes every contact a b2Contact holding its type's Evaluate, one class for all (one hidden class in V8), and instanceof answers for its type only", () => {
    const types = [
      b2CircleContact,
      b2PolygonAndCircleContact,
      b2PolygonContact,
      b2EdgeAndCircleContact,
      b2EdgeAndPolygonContact,
      b2ChainAndCircleContact,
      b2ChainAndPolygonContact,
    ];
    for (const [nameA, nameB, expectedClass] of cases) {
      if (expectedClass === null) continue;
      const world = newWorld();
      const contact = b2Contact.Create(addFixture(world, makeShape(nameA)), 0, addFixture(world, makeShape(nameB), { x: 10.0 }), 0)!;
      expect(Object.getPrototypeOf(contact)).toBe(b2Contact.prototype);
      const type = expectedClass as unknown as { Evaluate: unknown };
      expect(contact.m_evaluate).toBe(type.Evaluate);
      expect(types.filter((t) => contact instanceof t)).toEqual([expectedClass]);
    }
    expect({} instanceof b2PolygonContact).toBe(false);
  });

  it('gives a contact built with the C++ constructor of each type the manifold of the one Create makes', () => {
    for (const [nameA, nameB, expectedClass, swapped] of cases) {
      if (expectedClass === null || swapped) continue;
      const world = newWorld();
      const fixtureA = addFixture(world, makeShape(nameA));
      const fixtureB = addFixture(world, makeShape(nameB), { x: 0.5, y: 0.3 });
      // A chain's child 1 is the edge from (-1, 0) to (1, 0), under fixture B.
      const indexA = nameA === 'chain' ? 1 : 0;
      const made = b2Contact.Create(fixtureA, indexA, fixtureB, 0)!;
      const Type = expectedClass as unknown as new (...args: unknown[]) => b2Contact;
      const built = nameA === 'chain' ? new Type(fixtureA, indexA, fixtureB, 0) : new Type(fixtureA, fixtureB);
      expect(built).toBeInstanceOf(expectedClass);
      const xfA = fixtureA.GetBody().GetTransform();
      const xfB = fixtureB.GetBody().GetTransform();
      const a = new b2Manifold();
      const b = new b2Manifold();
      made.Evaluate(a, xfA, xfB);
      built.Evaluate(b, xfA, xfB);
      expect(a.pointCount, `${nameA} vs ${nameB}`).toBeGreaterThan(0);
      expect(JSON.stringify(b), `${nameA} vs ${nameB}`).toBe(JSON.stringify(a));
    }
  });

  it('registers each pair once as primary and its reverse as non-primary, and re-initialising is harmless', () => {
    b2InitializeContactRegisters();
    b2InitializeContactRegisters();
    const registers = b2Contact.s_registers;
    // e_circle 0, e_edge 1, e_polygon 2, e_chain 3
    expect(registers[2][0].primary).toBe(true);
    expect(registers[0][2].primary).toBe(false);
    expect(registers[0][2].createFcn).toBe(registers[2][0].createFcn);
    expect(registers[0][0].primary).toBe(true);
    expect(registers[1][1].createFcn).toBeNull();
    expect(registers[3][1].createFcn).toBeNull();
    let registered = 0;
    for (const row of registers) {
      for (const register of row) {
        if (register.createFcn !== null && register.primary) ++registered;
      }
    }
    expect(registered).toBe(7);
  });
});

describe('b2Contact construction', () => {
  it('mixes friction as the square root of the product and restitution as the maximum', () => {
    expect(b2MixFriction(0.5, 0.125)).toBe(0.25);
    expect(b2MixFriction(0.0, 0.8)).toBe(0.0);
    expect(b2MixRestitution(0.3, 0.7)).toBe(0.7);
    expect(b2MixRestitution(0.7, 0.3)).toBe(0.7);

    const world = newWorld();
    const fixtureA = addFixture(world, makeShape('circle'), { friction: 0.5, restitution: 0.3 });
    const fixtureB = addFixture(world, makeShape('circle'), { x: 3.0, friction: 0.125, restitution: 0.7 });
    const contact = b2Contact.Create(fixtureA, 0, fixtureB, 0)!;
    expect(contact.GetFriction()).toBe(0.25);
    expect(contact.GetRestitution()).toBe(0.7);

    contact.SetFriction(0.9);
    contact.SetRestitution(0.05);
    expect(contact.GetFriction()).toBe(0.9);
    expect(contact.GetRestitution()).toBe(0.05);
    contact.ResetFriction();
    contact.ResetRestitution();
    expect(contact.GetFriction()).toBe(0.25);
    expect(contact.GetRestitution()).toBe(0.7);
  });

  it('keeps m_toi in its b2ContactScalars and m_friction, m_restitution in its manifold record (the fields are accessors)', () => {
    const world = newWorld();
    const contact = b2Contact.Create(addFixture(world, makeShape('polygon')), 0, addFixture(world, makeShape('circle'), { x: 3.0 }), 0)!;
    // No scalars until m_toi is set or the contact becomes a TOI candidate: m_toi reads 1 until then.
    expect(contact.m_scalars).toBeNull();
    expect(contact.m_toi).toBe(1.0);
    contact.m_toi = 0.25;
    contact.m_friction = 0.5;
    contact.m_restitution = 0.75;
    expect({ ...contact.m_scalars }).toEqual({ toi: 0.25 });
    const m = contact.GetManifold();
    expect([m.m_record[m.m_offset + b2ManifoldField.friction], m.m_record[m.m_offset + b2ManifoldField.restitution]]).toEqual([0.5, 0.75]);
    contact.m_scalars!.toi = 0.125;
    expect(contact.m_toi).toBe(0.125);
    expect(contact.GetFriction()).toBe(0.5);
    // The manifold's own copies leave them: they belong to the contact.
    m.Assign(new b2Manifold());
    expect([contact.GetFriction(), contact.GetRestitution()]).toEqual([0.5, 0.75]);
  });

  it('starts enabled, not touching, with an empty manifold, no TOI count and unlinked edges', () => {
    const world = newWorld();
    const fixtureA = addFixture(world, makeShape('polygon'));
    const fixtureB = addFixture(world, makeShape('circle'), { x: 3.0 });
    const contact = b2Contact.Create(fixtureA, 0, fixtureB, 0)!;
    expect(contact.m_flags).toBe(b2Contact.e_enabledFlag);
    expect(contact.IsEnabled()).toBe(true);
    expect(contact.IsTouching()).toBe(false);
    expect(contact.GetManifold().pointCount).toBe(0);
    expect(contact.m_toiCount).toBe(0);
    expect(contact.GetNext()).toBeNull();
    expect(contact.m_prev).toBeNull();
    expect(contact.m_nodeA.prev).toBeNull();
    expect(contact.m_nodeA.next).toBeNull();
    expect(contact.m_nodeB.prev).toBeNull();
    expect(contact.m_nodeB.next).toBeNull();
    expect(contact.m_nodeA.other).toBe(fixtureB.GetBody());
    expect(contact.m_nodeB.other).toBe(fixtureA.GetBody());

    contact.SetEnabled(false);
    expect(contact.IsEnabled()).toBe(false);
    contact.FlagForFiltering();
    expect(contact.m_flags).toBe(b2Contact.e_filterFlag);
  });
});

describe('b2Contact.Update', () => {
  /** A unit box resting 0.01 into a static slab: a two-point face contact. */
  function boxOnSlab(): b2Contact {
    const world = newWorld();
    const slab = addFixture(world, new b2PolygonShape().SetAsBox(5.0, 0.5), { type: b2BodyType.b2_staticBody });
    const box = addFixture(world, makeShape('polygon'), { y: 0.99 });
    return b2Contact.Create(slab, 0, box, 0)!;
  }

  it('carries the stored impulses over to the new points with the same id key', () => {
    const contact = boxOnSlab();
    contact.Update(null);
    const manifold = contact.GetManifold();
    expect(manifold.pointCount).toBe(2);
    const key0 = manifold.points[0].id.key;
    const key1 = manifold.points[1].id.key;
    expect(key0).not.toBe(key1);

    manifold.points[0].normalImpulse = 1.5;
    manifold.points[0].tangentImpulse = 0.25;
    manifold.points[1].normalImpulse = 2.5;
    manifold.points[1].tangentImpulse = -0.5;
    contact.Update(null);
    expect([manifold.points[0].normalImpulse, manifold.points[0].tangentImpulse]).toEqual([1.5, 0.25]);
    expect([manifold.points[1].normalImpulse, manifold.points[1].tangentImpulse]).toEqual([2.5, -0.5]);

    // Swap the stored ids: the impulses must follow the keys, not the point order.
    manifold.points[0].id.key = key1;
    manifold.points[1].id.key = key0;
    contact.Update(null);
    expect(manifold.points[0].id.key).toBe(key0);
    expect([manifold.points[0].normalImpulse, manifold.points[0].tangentImpulse]).toEqual([2.5, -0.5]);
    expect([manifold.points[1].normalImpulse, manifold.points[1].tangentImpulse]).toEqual([1.5, 0.25]);

    // A stored point whose key no longer exists passes nothing on.
    manifold.points[1].id.key = 0x7f7f7f7f;
    contact.Update(null);
    expect([manifold.points[0].normalImpulse, manifold.points[0].tangentImpulse]).toEqual([2.5, -0.5]);
    expect([manifold.points[1].normalImpulse, manifold.points[1].tangentImpulse]).toEqual([0.0, 0.0]);
  });

  it('calls BeginContact then PreSolve with the old manifold, PreSolve while touching, and EndContact on separation', () => {
    const world = newWorld();
    const fixtureA = addFixture(world, makeShape('circle'));
    const fixtureB = addFixture(world, makeShape('circle'), { x: 0.9 });
    const contact = b2Contact.Create(fixtureA, 0, fixtureB, 0)!;
    const listener = new RecordingListener();

    contact.Update(listener);
    expect(contact.IsTouching()).toBe(true);
    contact.Update(listener);
    fixtureB.GetBody().SetTransform(new b2Vec2(1.1, 0.0), 0.0);
    contact.Update(listener);
    expect(contact.IsTouching()).toBe(false);
    contact.Update(listener);

    expect(listener.events).toEqual(['BeginContact', 'PreSolve(old points 0, new points 1)', 'PreSolve(old points 1, new points 1)', 'EndContact']);
  });

  it('re-enables a contact that was disabled', () => {
    const contact = boxOnSlab();
    contact.SetEnabled(false);
    contact.Update(null);
    expect(contact.IsEnabled()).toBe(true);
  });

  it('wakes both bodies when the touching state changes', () => {
    const world = newWorld();
    const fixtureA = addFixture(world, makeShape('circle'), { awake: false });
    const fixtureB = addFixture(world, makeShape('circle'), { x: 0.9, awake: false });
    const contact = b2Contact.Create(fixtureA, 0, fixtureB, 0)!;
    expect(fixtureA.GetBody().IsAwake()).toBe(false);

    contact.Update(null);
    expect(fixtureA.GetBody().IsAwake()).toBe(true);
    expect(fixtureB.GetBody().IsAwake()).toBe(true);

    // Still touching: no state change, so sleeping bodies stay asleep.
    fixtureA.GetBody().SetAwake(false);
    fixtureB.GetBody().SetAwake(false);
    contact.Update(null);
    expect(fixtureA.GetBody().IsAwake()).toBe(false);
    expect(fixtureB.GetBody().IsAwake()).toBe(false);
  });

  it('tests sensor overlap without a manifold, PreSolve or waking', () => {
    const world = newWorld();
    const sensor = addFixture(world, makeShape('circle'), { isSensor: true, awake: false });
    const other = addFixture(world, makeShape('polygon'), { x: 0.9, awake: false });
    const contact = b2Contact.Create(sensor, 0, other, 0)!;
    const listener = new RecordingListener();

    contact.Update(listener);
    expect(contact.IsTouching()).toBe(true);
    expect(contact.GetManifold().pointCount).toBe(0);
    expect(sensor.GetBody().IsAwake()).toBe(false);
    expect(other.GetBody().IsAwake()).toBe(false);
    expect(listener.events).toEqual(['BeginContact']);
  });
});

describe('b2Contact.Destroy', () => {
  it('wakes both bodies when the manifold has points', () => {
    const world = newWorld();
    const fixtureA = addFixture(world, makeShape('circle'));
    const fixtureB = addFixture(world, makeShape('circle'), { x: 0.9 });
    const contact = b2Contact.Create(fixtureA, 0, fixtureB, 0)!;
    contact.Update(null);
    fixtureA.GetBody().SetAwake(false);
    fixtureB.GetBody().SetAwake(false);

    b2Contact.Destroy(contact);
    expect(fixtureA.GetBody().IsAwake()).toBe(true);
    expect(fixtureB.GetBody().IsAwake()).toBe(true);
  });

  it('leaves the bodies asleep when the manifold is empty', () => {
    const world = newWorld();
    const fixtureA = addFixture(world, makeShape('circle'), { awake: false });
    const fixtureB = addFixture(world, makeShape('circle'), { x: 3.0, awake: false });
    const contact = b2Contact.Create(fixtureA, 0, fixtureB, 0)!;

    b2Contact.Destroy(contact);
    expect(fixtureA.GetBody().IsAwake()).toBe(false);
    expect(fixtureB.GetBody().IsAwake()).toBe(false);
  });
});
