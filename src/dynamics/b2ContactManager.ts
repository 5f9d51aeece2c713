/*
 * The world's delegate for the broad-phase and the contact list (b2ContactManager.h,
 * b2ContactManager.cpp): it creates contacts for new proxy pairs, runs the narrow phase on the
 * existing ones, and destroys contacts whose fat AABBs stop overlapping.
 */

import { b2BroadPhase } from '../collision/b2BroadPhase';
import { b2BodyFlags, b2BodyType } from '../common/b2Constants';
import { b2Contact } from './contacts/b2Contact';
import { b2ContactAllocator } from './contacts/b2ContactAllocator';
import { b2InitializeContactRegisters } from './contacts/b2ContactRegistry';
import type { b2FixtureProxy } from './b2Fixture';
import { b2ProxyPairSet } from './b2ProxyPairSet';
import { b2ContactFilter, b2ContactListener } from './b2WorldCallbacks';

/** The default contact filter, used until b2World.SetContactFilter replaces it. */
export const b2_defaultFilter = new b2ContactFilter();
/** The default contact listener (does nothing), used until b2World.SetContactListener replaces it. */
export const b2_defaultListener = new b2ContactListener();

/** Delegate of b2World. */
export class b2ContactManager {
  readonly m_broadPhase = new b2BroadPhase();
  m_contactList: b2Contact | null = null;
  m_contactCount = 0;
  m_contactFilter: b2ContactFilter | null = b2_defaultFilter;
  m_contactListener: b2ContactListener | null = b2_defaultListener;
  /** The C++ passes the world's block allocator to b2Contact::Create and Destroy; see there. */
  readonly m_allocator = new b2ContactAllocator();
  /** Not in the C++: the proxy pairs of the contacts in m_contactList (see b2ProxyPairSet). */
  readonly m_pairs = new b2ProxyPairSet();

  constructor() {
    // The C++ fills the contact registry lazily in b2Contact::Create; see b2ContactRegistry.ts.
    b2InitializeContactRegisters();
  }

  /** Broad-phase callback: the user data are the fixtures' b2FixtureProxy objects. */
  AddPair(proxyUserDataA: b2FixtureProxy, proxyUserDataB: b2FixtureProxy): void {
    const proxyA = proxyUserDataA;
    const proxyB = proxyUserDataB;

    let fixtureA = proxyA.fixture;
    let fixtureB = proxyB.fixture;

    const indexA = proxyA.childIndex;
    const indexB = proxyB.childIndex;

    let bodyA = fixtureA.GetBody();
    let bodyB = fixtureB.GetBody();

    // Are the fixtures on the same body?
    if (bodyA === bodyB) {
      return;
    }

    // Does a contact already exist? (The C++ walks body B's contact list; see b2ProxyPairSet.)
    if (this.m_pairs.Has(proxyA.proxyId, proxyB.proxyId)) {
      return;
    }

    // Does a joint override collision? Is at least one body dynamic?
    if (bodyB.ShouldCollide(bodyA) === false) {
      return;
    }

    // Check user filtering.
    if (this.m_contactFilter && this.m_contactFilter.ShouldCollide(fixtureA, fixtureB) === false) {
      return;
    }

    // Call the factory.
    const c = b2Contact.Create(fixtureA, indexA, fixtureB, indexB, this.m_allocator);
    if (c === null) {
      return;
    }

    // Contact creation may swap fixtures.
    fixtureA = c.GetFixtureA();
    fixtureB = c.GetFixtureB();
    bodyA = fixtureA.GetBody();
    bodyB = fixtureB.GetBody();

    this.LinkContact(c);

    // Wake up the bodies
    bodyA.SetAwake(true);
    bodyB.SetAwake(true);
  }

  /**
   * AddPair's insertion of a new contact into the world's list and both bodies' lists, and into
   * the pair set (which the state reader's contacts join the same way).
   */
  LinkContact(c: b2Contact): void {
    const bodyA = c.m_fixtureA.m_body;
    const bodyB = c.m_fixtureB.m_body;

    // Insert into the world.
    c.m_prev = null;
    c.m_next = this.m_contactList;
    if (this.m_contactList !== null) {
      this.m_contactList.m_prev = c;
    }
    this.m_contactList = c;

    // Connect to island graph.

    // Connect to body A
    c.m_nodeA.contact = c;
    c.m_nodeA.other = bodyB;

    c.m_nodeA.prev = null;
    c.m_nodeA.next = bodyA.m_contactList;
    if (bodyA.m_contactList !== null) {
      bodyA.m_contactList.prev = c.m_nodeA;
    }
    bodyA.m_contactList = c.m_nodeA;

    // Connect to body B
    c.m_nodeB.contact = c;
    c.m_nodeB.other = bodyA;

    c.m_nodeB.prev = null;
    c.m_nodeB.next = bodyB.m_contactList;
    if (bodyB.m_contactList !== null) {
      bodyB.m_contactList.prev = c.m_nodeB;
    }
    bodyB.m_contactList = c.m_nodeB;

    c.m_proxyIdA = c.m_fixtureA.m_proxies[c.m_indexA].proxyId;
    c.m_proxyIdB = c.m_fixtureB.m_proxies[c.m_indexB].proxyId;
    this.m_pairs.Add(c.m_proxyIdA, c.m_proxyIdB);

    ++this.m_contactCount;
  }

  /**
   * Not in the C++: empties the world's and the bodies' contact lists without destroying the
   * contacts, for a backend that takes them over (b2WorldBackend.Attach).
   */
  UnlinkAllContacts(): void {
    for (let c = this.m_contactList; c; c = c.m_next) {
      c.m_proxyIdA = -1;
      c.m_proxyIdB = -1;
      c.m_fixtureA.m_body.m_contactList = null;
      c.m_fixtureB.m_body.m_contactList = null;
    }
    this.m_contactList = null;
    this.m_contactCount = 0;
    this.m_pairs.Clear();
  }

  /** Create contacts for the proxy pairs that began to overlap since the last call. */
  FindNewContacts(): void {
    this.m_broadPhase.UpdatePairs(this);
  }

  /** Unlink a contact from the world and both bodies (EndContact first if touching) and free it. */
  Destroy(c: b2Contact): void {
    const fixtureA = c.GetFixtureA();
    const fixtureB = c.GetFixtureB();
    const bodyA = fixtureA.GetBody();
    const bodyB = fixtureB.GetBody();

    if (this.m_contactListener && c.IsTouching()) {
      this.m_contactListener.EndContact(c);
    }

    // Remove from the world.
    if (c.m_prev) {
      c.m_prev.m_next = c.m_next;
    }

    if (c.m_next) {
      c.m_next.m_prev = c.m_prev;
    }

    if (c === this.m_contactList) {
      this.m_contactList = c.m_next;
    }

    // Remove from body 1
    if (c.m_nodeA.prev) {
      c.m_nodeA.prev.next = c.m_nodeA.next;
    }

    if (c.m_nodeA.next) {
      c.m_nodeA.next.prev = c.m_nodeA.prev;
    }

    if (c.m_nodeA === bodyA.m_contactList) {
      bodyA.m_contactList = c.m_nodeA.next;
    }

    // Remove from body 2
    if (c.m_nodeB.prev) {
      c.m_nodeB.prev.next = c.m_nodeB.next;
    }

    if (c.m_nodeB.next) {
      c.m_nodeB.next.prev = c.m_nodeB.prev;
    }

    if (c.m_nodeB === bodyB.m_contactList) {
      bodyB.m_contactList = c.m_nodeB.next;
    }

    // Not in the C++, which frees the contact: drop its links, or a stale reference to it (the
    // island's and solver's scratch arrays keep some) would hold every contact and body it was
    // linked to, and through their links a chain of destroyed objects that never ends.
    c.m_prev = null;
    c.m_next = null;
    c.m_nodeA.prev = null;
    c.m_nodeA.next = null;
    c.m_nodeB.prev = null;
    c.m_nodeB.next = null;

    this.m_pairs.Remove(c.m_proxyIdA, c.m_proxyIdB);
    c.m_proxyIdA = -1;
    c.m_proxyIdB = -1;

    // Call the factory.
    b2Contact.Destroy(c, this.m_allocator);
    --this.m_contactCount;
  }

  /**
   * This is the top level collision call for the time step. Here
   * all the narrow phase collision is processed for the world
   * contact list.
   */
  Collide(): void {
    // Update awake contacts.
    let c = this.m_contactList;
    while (c) {
      const fixtureA = c.GetFixtureA();
      const fixtureB = c.GetFixtureB();
      const bodyA = fixtureA.GetBody();
      const bodyB = fixtureB.GetBody();

      // Is this contact flagged for filtering?
      if (c.m_flags & b2Contact.e_filterFlag) {
        // Should these bodies collide?
        if (bodyB.ShouldCollide(bodyA) === false) {
          const cNuke: b2Contact = c;
          c = cNuke.GetNext();
          this.Destroy(cNuke);
          continue;
        }

        // Check user filtering.
        if (this.m_contactFilter && this.m_contactFilter.ShouldCollide(fixtureA, fixtureB) === false) {
          const cNuke: b2Contact = c;
          c = cNuke.GetNext();
          this.Destroy(cNuke);
          continue;
        }

        // Clear the filtering flag.
        c.m_flags &= ~b2Contact.e_filterFlag;
      }

      // The flag, not IsAwake(): the engine's own step has no backend state to fetch (b2Body.PullState).
      const activeA = (bodyA.m_flags & b2BodyFlags.e_awakeFlag) !== 0 && bodyA.m_type !== b2BodyType.b2_staticBody;
      const activeB = (bodyB.m_flags & b2BodyFlags.e_awakeFlag) !== 0 && bodyB.m_type !== b2BodyType.b2_staticBody;

      // At least one body must be awake and it must be dynamic or kinematic.
      if (activeA === false && activeB === false) {
        c = c.GetNext();
        continue;
      }

      // fixtureA.m_proxies[indexA].proxyId and fixtureB's, which LinkContact copied into the
      // contact: a proxy keeps its id until its fixture's contacts are destroyed.
      const overlap = this.m_broadPhase.TestOverlap(c.m_proxyIdA, c.m_proxyIdB);

      // Here we destroy contacts that cease to overlap in the broad-phase.
      if (overlap === false) {
        const cNuke: b2Contact = c;
        c = cNuke.GetNext();
        this.Destroy(cNuke);
        continue;
      }

      // The contact persists.
      c.Update(this.m_contactListener);
      c = c.GetNext();
    }
  }
}
