import { describe, expect, it } from 'vitest';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2ChainShape } from '../../src/collision/shapes/b2ChainShape';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2EdgeShape } from '../../src/collision/shapes/b2EdgeShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2BodyDef, b2_dynamicBody, b2_staticBody } from '../../src/dynamics/b2Body';
import type { b2Body, b2BodyType } from '../../src/dynamics/b2Body';
import { b2ContactManager, b2_defaultFilter, b2_defaultListener } from '../../src/dynamics/b2ContactManager';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2ContactFilter, b2ContactListener } from '../../src/dynamics/b2WorldCallbacks';
import { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';

const dt = 1.0 / 60.0;

function createBody(world: b2World, type: b2BodyType, x = 0.0, y = 0.0, awake = true): b2Body {
  const bd = new b2BodyDef();
  bd.type = type;
  bd.position.Set(x, y);
  bd.awake = awake;
  return world.CreateBody(bd);
}

function box(body: b2Body, hx = 1.0, hy = 1.0, center?: b2Vec2): b2Fixture {
  return body.CreateFixture(new b2PolygonShape().SetAsBox(hx, hy, center, 0.0), 1.0);
}

function circle(body: b2Body, radius: number): b2Fixture {
  const shape = new b2CircleShape();
  shape.m_radius = radius;
  return body.CreateFixture(shape, 1.0);
}

/** The contacts of the world list, head first. */
function contactList(world: b2World): b2Contact[] {
  const contacts: b2Contact[] = [];
  for (let c = world.GetContactList(); c; c = c.GetNext()) {
    contacts.push(c);
  }
  return contacts;
}

/** The contacts of a body's edge list, head first. */
function bodyContacts(body: b2Body): b2Contact[] {
  const contacts: b2Contact[] = [];
  for (let e = body.GetContactList(); e; e = e.next) {
    contacts.push(e.contact);
  }
  return contacts;
}

class Recorder extends b2ContactListener {
  readonly events: string[] = [];
  override BeginContact(): void {
    this.events.push('begin');
  }
  override EndContact(): void {
    this.events.push('end');
  }
}

describe('b2ContactManager construction', () => {
  it('starts empty with the default filter and listener and fills the contact registry', () => {
    const cm = new b2ContactManager();
    expect(cm.m_contactList).toBeNull();
    expect(cm.m_contactCount).toBe(0);
    expect(cm.m_contactFilter).toBe(b2_defaultFilter);
    expect(cm.m_contactListener).toBe(b2_defaultListener);
    expect(b2_defaultFilter).toBeInstanceOf(b2ContactFilter);
    expect(b2_defaultListener).toBeInstanceOf(b2ContactListener);
    expect(b2Contact.s_initialized).toBe(true);
    expect(cm.m_broadPhase.GetProxyCount()).toBe(0);
  });
});

describe('b2ContactManager.AddPair', () => {
  it('skips fixtures on the same body', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const body = createBody(world, b2_dynamicBody);
    const f1 = box(body);
    const f2 = box(body, 0.5, 0.5, new b2Vec2(0.5, 0.0));
    world.m_contactManager.AddPair(f1.m_proxies[0], f2.m_proxies[0]);
    expect(world.GetContactCount()).toBe(0);
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(0);
    expect(body.GetContactList()).toBeNull();
  });

  it('does not duplicate an existing contact, in either proxy order', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const fa = box(createBody(world, b2_dynamicBody, 0.0, 0.0));
    const fb = box(createBody(world, b2_dynamicBody, 1.0, 0.0));
    const cm = world.m_contactManager;
    cm.AddPair(fa.m_proxies[0], fb.m_proxies[0]);
    expect(cm.m_contactCount).toBe(1);
    const contact = cm.m_contactList;

    cm.AddPair(fa.m_proxies[0], fb.m_proxies[0]);
    cm.AddPair(fb.m_proxies[0], fa.m_proxies[0]);
    cm.FindNewContacts();
    world.Step(dt, 8, 3);
    expect(cm.m_contactCount).toBe(1);
    expect(contactList(world)).toEqual([contact]);
  });

  it('creates one contact per overlapping child of a chain', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const ground = createBody(world, b2_staticBody);
    const chain = new b2ChainShape();
    chain.CreateChain([new b2Vec2(-5.0, 0.0), new b2Vec2(0.0, 0.0), new b2Vec2(5.0, 0.0)]);
    const fChain = ground.CreateFixture(chain, 0.0);
    box(createBody(world, b2_dynamicBody, 0.0, 0.5));
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(2);
    const children = contactList(world).map((c) => (c.GetFixtureA() === fChain ? c.GetChildIndexA() : c.GetChildIndexB()));
    expect(children.sort()).toEqual([0, 1]);
  });

  it('prepends the contact to the world and both bodies, links its edges and wakes both bodies', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2_dynamicBody, 0.0, 0.0, false);
    const b = createBody(world, b2_dynamicBody, 1.0, 0.0, false);
    const c = createBody(world, b2_dynamicBody, -1.0, 0.0, false);
    const fa = box(a);
    const fb = box(b);
    const fc = box(c);
    expect([a.IsAwake(), b.IsAwake(), c.IsAwake()]).toEqual([false, false, false]);

    const cm = world.m_contactManager;
    cm.AddPair(fa.m_proxies[0], fb.m_proxies[0]);
    const ab = cm.m_contactList!;
    cm.AddPair(fa.m_proxies[0], fc.m_proxies[0]);
    const ac = cm.m_contactList!;

    expect(cm.m_contactCount).toBe(2);
    expect(contactList(world)).toEqual([ac, ab]);
    expect(ac.m_prev).toBeNull();
    expect(ab.m_prev).toBe(ac);
    expect(bodyContacts(a)).toEqual([ac, ab]);
    expect(bodyContacts(b)).toEqual([ab]);
    expect(bodyContacts(c)).toEqual([ac]);
    expect(ab.m_nodeA.other).toBe(b);
    expect(ab.m_nodeB.other).toBe(a);
    expect(ac.m_nodeA.next).toBe(ab.m_nodeA);
    expect(ab.m_nodeA.prev).toBe(ac.m_nodeA);
    expect([a.IsAwake(), b.IsAwake(), c.IsAwake()]).toEqual([true, true, true]);
    expect(ab.IsTouching()).toBe(false);
  });

  it('follows the registry when it swaps the fixtures (polygon before circle)', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2_dynamicBody, 0.0, 0.0);
    const b = createBody(world, b2_dynamicBody, 1.0, 0.0);
    const fCircle = circle(a, 1.0);
    const fPolygon = box(b);
    world.m_contactManager.AddPair(fCircle.m_proxies[0], fPolygon.m_proxies[0]);

    const contact = world.GetContactList()!;
    expect(contact.GetFixtureA()).toBe(fPolygon);
    expect(contact.GetFixtureB()).toBe(fCircle);
    expect(b.GetContactList()).toBe(contact.m_nodeA);
    expect(a.GetContactList()).toBe(contact.m_nodeB);
    expect(contact.m_nodeA.other).toBe(a);
  });

  it('creates nothing for shape pairs without a contact type (edge against edge)', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const e1 = new b2EdgeShape();
    e1.Set(new b2Vec2(-1.0, 0.0), new b2Vec2(1.0, 0.0));
    const fa = createBody(world, b2_dynamicBody).CreateFixture(e1, 0.0);
    const fb = createBody(world, b2_dynamicBody, 0.0, 0.0).CreateFixture(e1, 0.0);
    world.m_contactManager.AddPair(fa.m_proxies[0], fb.m_proxies[0]);
    expect(world.GetContactCount()).toBe(0);
    expect(world.GetContactList()).toBeNull();
  });

  it('creates no contact between two non-dynamic bodies', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    box(createBody(world, b2_staticBody));
    box(createBody(world, b2_staticBody, 1.0, 0.0));
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(0);
  });

  it('asks the user filter, and skips filtering when there is none', () => {
    class Never extends b2ContactFilter {
      calls = 0;
      override ShouldCollide(): boolean {
        ++this.calls;
        return false;
      }
    }
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const never = new Never();
    world.SetContactFilter(never);
    const fa = box(createBody(world, b2_dynamicBody));
    const fb = box(createBody(world, b2_dynamicBody, 1.0, 0.0));
    world.Step(dt, 8, 3);
    expect(never.calls).toBe(1);
    expect(world.GetContactCount()).toBe(0);

    // No filter at all: even masks that exclude each other do not stop the contact.
    world.SetContactFilter(null);
    const filter = fa.GetFilterData().Clone();
    filter.maskBits = 0;
    fa.SetFilterData(filter);
    world.m_contactManager.AddPair(fa.m_proxies[0], fb.m_proxies[0]);
    expect(world.GetContactCount()).toBe(1);
  });
});

describe('b2ContactManager and joints', () => {
  function jointedPair(collideConnected: boolean): b2World {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2_dynamicBody, 0.0, 0.0);
    const b = createBody(world, b2_dynamicBody, 1.0, 0.0);
    box(a);
    box(b);
    const jd = new b2RevoluteJointDef();
    jd.Initialize(a, b, new b2Vec2(0.5, 0.0));
    jd.collideConnected = collideConnected;
    world.CreateJoint(jd);
    world.Step(dt, 8, 3);
    return world;
  }

  it('suppresses contacts between bodies joined with collideConnected = false', () => {
    expect(jointedPair(false).GetContactCount()).toBe(0);
  });

  it('keeps contacts between bodies joined with collideConnected = true', () => {
    expect(jointedPair(true).GetContactCount()).toBe(1);
  });

  it('destroys an existing contact on the step after such a joint is created', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2_dynamicBody, 0.0, 0.0);
    const b = createBody(world, b2_dynamicBody, 1.0, 0.0);
    box(a);
    box(b);
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(1);
    const jd = new b2RevoluteJointDef();
    jd.Initialize(a, b, new b2Vec2(0.5, 0.0));
    world.CreateJoint(jd);
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(0);
  });
});

describe('b2ContactManager.Destroy and Collide', () => {
  it('Destroy ends a touching contact and unlinks it from the middle of every list', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const recorder = new Recorder();
    world.SetContactListener(recorder);
    const a = createBody(world, b2_dynamicBody, 0.0, 0.0);
    const b = createBody(world, b2_dynamicBody, 1.0, 0.0);
    const c = createBody(world, b2_dynamicBody, -1.0, 0.0);
    const d = createBody(world, b2_dynamicBody, 0.0, 1.0);
    const fa = box(a);
    const cm = world.m_contactManager;
    cm.AddPair(fa.m_proxies[0], box(b).m_proxies[0]);
    cm.AddPair(fa.m_proxies[0], box(c).m_proxies[0]);
    cm.AddPair(fa.m_proxies[0], box(d).m_proxies[0]);
    const [ad, ac, ab] = contactList(world);
    cm.Collide();
    expect(recorder.events).toEqual(['begin', 'begin', 'begin']);
    expect(ac.IsTouching()).toBe(true);

    cm.Destroy(ac);
    expect(recorder.events).toEqual(['begin', 'begin', 'begin', 'end']);
    expect(cm.m_contactCount).toBe(2);
    expect(contactList(world)).toEqual([ad, ab]);
    expect(ab.m_prev).toBe(ad);
    expect(bodyContacts(a)).toEqual([ad, ab]);
    expect(ab.m_nodeA.prev).toBe(ad.m_nodeA);
    expect(c.GetContactList()).toBeNull();

    cm.Destroy(ad);
    cm.Destroy(ab);
    expect(cm.m_contactList).toBeNull();
    expect(a.GetContactList()).toBeNull();
    expect(cm.m_contactCount).toBe(0);
  });

  it('forgets a contact destroyed after its proxies, so a new fixture reusing a proxy id gets a contact', () => {
    // b2Body.SetActive(false) destroys the proxies before the contacts; the pair set must drop the
    // pair under the ids the contact was created with.
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2_dynamicBody, 0.0, 0.0);
    const fa = box(a);
    const fb = box(createBody(world, b2_dynamicBody, 1.0, 0.0));
    world.Step(dt, 8, 3);
    expect(world.GetContactCount()).toBe(1);
    const idA = fa.m_proxies[0].proxyId;
    const idB = fb.m_proxies[0].proxyId;
    expect(world.m_contactManager.m_pairs.Has(idA, idB)).toBe(true);

    a.SetActive(false);
    expect(world.GetContactCount()).toBe(0);
    expect(world.m_contactManager.m_pairs.GetCount()).toBe(0);

    const fc = box(createBody(world, b2_dynamicBody, 0.5, 0.0));
    expect(fc.m_proxies[0].proxyId).toBe(idA);
    world.Step(dt, 8, 3);
    const contacts = contactList(world);
    expect(contacts).toHaveLength(1);
    expect(new Set([contacts[0].GetFixtureA(), contacts[0].GetFixtureB()])).toEqual(new Set([fb, fc]));
  });

  it('Destroy sends no EndContact for a contact that is not touching', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const recorder = new Recorder();
    world.SetContactListener(recorder);
    const fa = box(createBody(world, b2_dynamicBody, 0.0, 0.0));
    const fb = box(createBody(world, b2_dynamicBody, 1.0, 0.0));
    world.m_contactManager.AddPair(fa.m_proxies[0], fb.m_proxies[0]);
    world.m_contactManager.Destroy(world.GetContactList()!);
    expect(recorder.events).toEqual([]);
    expect(world.GetContactCount()).toBe(0);
  });

  it('Collide destroys contacts whose fat AABBs stopped overlapping', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const recorder = new Recorder();
    world.SetContactListener(recorder);
    box(createBody(world, b2_dynamicBody, 0.0, 0.0));
    const b = createBody(world, b2_dynamicBody, 1.0, 0.0);
    box(b);
    world.Step(dt, 8, 3);
    expect(recorder.events).toEqual(['begin']);

    b.SetTransform(new b2Vec2(50.0, 0.0), 0.0);
    expect(world.GetContactCount()).toBe(1);
    world.m_contactManager.Collide();
    expect(world.GetContactCount()).toBe(0);
    expect(recorder.events).toEqual(['begin', 'end']);
  });

  it('Collide leaves contacts alone when neither body is awake and non-static', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const a = createBody(world, b2_dynamicBody, 0.0, 0.0);
    const b = createBody(world, b2_dynamicBody, 1.0, 0.0);
    box(a);
    box(b);
    world.Step(dt, 8, 3);
    const contact = world.GetContactList()!;
    expect(contact.IsTouching()).toBe(true);

    // Separate the shapes without telling the broad-phase: only Update would notice.
    b.m_xf.p.Set(1.5, 3.0);
    a.SetAwake(false);
    b.SetAwake(false);
    world.m_contactManager.Collide();
    expect(contact.IsTouching()).toBe(true);

    b.SetAwake(true);
    world.m_contactManager.Collide();
    expect(contact.IsTouching()).toBe(false);
    expect(world.GetContactCount()).toBe(1);
  });

  it('Collide re-runs the filters on flagged contacts and clears the flag when they pass', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const fa = box(createBody(world, b2_dynamicBody, 0.0, 0.0));
    box(createBody(world, b2_dynamicBody, 1.0, 0.0));
    world.Step(dt, 8, 3);
    const contact = world.GetContactList()!;

    fa.Refilter();
    expect(contact.m_flags & b2Contact.e_filterFlag).toBe(b2Contact.e_filterFlag);
    world.m_contactManager.Collide();
    expect(contact.m_flags & b2Contact.e_filterFlag).toBe(0);
    expect(world.GetContactList()).toBe(contact);

    let asked = 0;
    world.SetContactFilter({
      ShouldCollide: () => {
        ++asked;
        return false;
      },
    });
    fa.Refilter();
    world.m_contactManager.Collide();
    expect(asked).toBe(1);
    expect(world.GetContactCount()).toBe(0);
  });
});
