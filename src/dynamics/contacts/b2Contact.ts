/*
 * The contact base class, the contact graph edge and the contact factory registry
 * (b2Contact.h, b2Contact.cpp).
 *
 * The registry table lives here but is filled by b2InitializeContactRegisters()
 * (b2ContactRegistry.ts): the concrete contacts extend b2Contact, so this module cannot import
 * them without breaking ES module load order. b2ContactManager's constructor fills it.
 */

import { b2ContactFlags } from '../../common/b2Constants';
import { b2Manifold, b2TestOverlapShapes } from '../../collision/b2Collision';
import { b2ManifoldField, b2ManifoldPointField } from '../../collision/b2ManifoldRecord';
import type { b2WorldManifold } from '../../collision/b2Collision';
import { b2Shape } from '../../collision/shapes/b2Shape';
import type { b2Transform } from '../../common/b2Math';
import { b2Assert } from '../../common/b2Settings';
import type { b2Body } from '../b2Body';
import type { b2Fixture } from '../b2Fixture';
import { b2ContactListener } from '../b2WorldCallbacks';
import type { b2ContactAllocator } from './b2ContactAllocator';

/**
 * Friction mixing law. The idea is to allow either fixture to drive the restitution to zero.
 * For example, anything slides on ice.
 */
export function b2MixFriction(friction1: number, friction2: number): number {
  return Math.sqrt(friction1 * friction2);
}

/**
 * Restitution mixing law. The idea is allow for anything to bounce off an inelastic surface.
 * For example, a superball bounces on anything.
 */
export function b2MixRestitution(restitution1: number, restitution2: number): number {
  return restitution1 > restitution2 ? restitution1 : restitution2;
}

export type b2ContactCreateFcn = (fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number) => b2Contact;
export type b2ContactDestroyFcn = (contact: b2Contact) => void;
/** Not in the C++: a concrete contact type's Evaluate as a function of the contact (b2Contact.m_evaluate). */
export type b2ContactEvaluateFcn = (contact: b2Contact, manifold: b2Manifold, xfA: b2Transform, xfB: b2Transform) => void;

export class b2ContactRegister {
  createFcn: b2ContactCreateFcn | null = null;
  destroyFcn: b2ContactDestroyFcn | null = null;
  primary = false;
}

/**
 * A contact edge is used to connect bodies and contacts together in a contact graph where each
 * body is a node and each contact is an edge. A contact edge belongs to a doubly linked list
 * maintained in each attached body. Each contact has two contact nodes, one for each attached
 * body.
 *
 * `contact` and `other` are typed non-null: a contact's edges are created with the contact and
 * hold the values b2ContactManager.AddPair assigns before the edge joins any list.
 */
export class b2ContactEdge {
  /** provides quick access to the other body attached. */
  other: b2Body;
  /** the contact */
  contact: b2Contact;
  /** the previous contact edge in the body's contact list */
  prev: b2ContactEdge | null = null;
  /** the next contact edge in the body's contact list */
  next: b2ContactEdge | null = null;

  constructor(contact: b2Contact, other: b2Body) {
    this.contact = contact;
    this.other = other;
  }
}

/**
 * Not in the C++: a contact's TOI, in an object of one class. SolveTOI reads it from contacts of
 * every pair of shape types (seven classes, so seven object layouts), and V8 boxes a double read
 * from or written to a field at a site that sees that many layouts: a heap allocation per contact
 * and step. b2Contact.m_toi is an accessor to this field; m_friction and m_restitution are
 * accessors to the manifold's record (b2ManifoldField.friction), where the solver reads them.
 */
export class b2ContactScalars {
  toi = 1.0;
}

/** A manifold as constructed, which b2Contact.Init copies into a reused contact's. */
const s_newManifold = new b2Manifold();

/** The zero-initialised static table of the C++: no create function for any pair. */
function b2MakeRegisters(): b2ContactRegister[][] {
  const registers: b2ContactRegister[][] = [];
  for (let i = 0; i < b2Shape.e_typeCount; ++i) {
    const row: b2ContactRegister[] = [];
    for (let j = 0; j < b2Shape.e_typeCount; ++j) {
      row.push(new b2ContactRegister());
    }
    registers.push(row);
  }
  return registers;
}

// The C++ copies the manifold onto the stack in Update. Update cannot re-enter: the listener
// callbacks run while the world is locked, so one copy serves every contact.
const s_oldManifold = new b2Manifold();

/**
 * The class manages contact between two shapes. A contact exists for each overlapping AABB in
 * the broad-phase (except if filtered). Therefore a contact object may exist that has no
 * contact points.
 *
 * Unlike the C++, where each shape pair has a subclass overriding Evaluate, every contact the
 * engine makes is a b2Contact holding its pair's evaluate function (m_evaluate); the seven
 * concrete classes make them (Create) and answer `instanceof` for them. V8 gives instances of
 * different classes different hidden classes, and a world with more than four contact types
 * then reads every contact field in the contact list walk, the island search and the solver's
 * set-up through a megamorphic lookup (mixed rain, seven types: a fifth of its step).
 */
export class b2Contact {
  // Flags stored in m_flags

  static readonly e_islandFlag = b2ContactFlags.e_islandFlag;
  static readonly e_touchingFlag = b2ContactFlags.e_touchingFlag;
  static readonly e_enabledFlag = b2ContactFlags.e_enabledFlag;
  static readonly e_filterFlag = b2ContactFlags.e_filterFlag;
  static readonly e_bulletHitFlag = b2ContactFlags.e_bulletHitFlag;
  static readonly e_toiFlag = b2ContactFlags.e_toiFlag;

  static readonly s_registers: b2ContactRegister[][] = b2MakeRegisters();
  static s_initialized = false;

  m_flags = 0;

  // World pool and list pointers.
  m_prev: b2Contact | null = null;
  m_next: b2Contact | null = null;

  /**
   * Not in the C++: the broad-phase proxies of fixture A's and fixture B's children while the
   * contact is linked into a world (b2ContactManager.LinkContact), -1 otherwise. The world's pair
   * set is keyed on them, b2ContactManager.Collide reads them rather than the fixtures' proxies
   * (next to m_flags and m_next, which it also reads), and b2Body.SetActive destroys the proxies
   * before the contacts.
   */
  m_proxyIdA = -1;
  m_proxyIdB = -1;

  // Nodes for connecting bodies.
  readonly m_nodeA: b2ContactEdge;
  readonly m_nodeB: b2ContactEdge;

  m_fixtureA!: b2Fixture;
  m_fixtureB!: b2Fixture;

  m_indexA = 0;
  m_indexB = 0;

  readonly m_manifold = new b2Manifold();

  m_toiCount = 0;

  /**
   * Not in the C++: where b2World.SolveTOI's search stands with this contact: 0 until the search
   * first reaches it (and again once destroyed), 1 once it has, 2 if the search keeps it among
   * its candidates (b2World.IsTOICandidate).
   */
  m_toiSearch = 0;

  /**
   * Not in the C++: the storage of m_toi (see b2ContactScalars), made when the contact first
   * becomes one of SolveTOI's candidates (b2World.UpdateTOICandidates) or m_toi is set: only
   * those contacts ever hold a TOI other than 1, and most contacts of a pile never do.
   */
  m_scalars: b2ContactScalars | null = null;

  // The C++ leaves m_toi uninitialised; b2World.SolveTOI writes it before any read.
  get m_toi(): number {
    return this.m_scalars === null ? 1.0 : this.m_scalars.toi;
  }
  set m_toi(toi: number) {
    (this.m_scalars ??= new b2ContactScalars()).toi = toi;
  }

  get m_friction(): number {
    return this.m_manifold.m_record[this.m_manifold.m_offset + b2ManifoldField.friction];
  }
  set m_friction(friction: number) {
    this.m_manifold.m_record[this.m_manifold.m_offset + b2ManifoldField.friction] = friction;
  }

  get m_restitution(): number {
    return this.m_manifold.m_record[this.m_manifold.m_offset + b2ManifoldField.restitution];
  }
  set m_restitution(restitution: number) {
    this.m_manifold.m_record[this.m_manifold.m_offset + b2ManifoldField.restitution] = restitution;
  }

  /** Not in the C++: the concrete type's Evaluate (see the class comment). */
  readonly m_evaluate: b2ContactEvaluateFcn;

  constructor(fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number, evaluate: b2ContactEvaluateFcn) {
    this.m_evaluate = evaluate;
    this.m_nodeA = new b2ContactEdge(this, fixtureB.GetBody());
    this.m_nodeB = new b2ContactEdge(this, fixtureA.GetBody());
    this.Init(fixtureA, indexA, fixtureB, indexB);
  }

  /**
   * Not in the C++ as a method: the constructor's work, also done to a contact that b2Contact.Create
   * takes back from the world's b2ContactAllocator (the C++ constructs it anew in the block
   * allocator's memory). The concrete contacts pass their fixtures' child indices, which are 0 for
   * every shape but a chain.
   */
  Init(fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number): void {
    this.m_flags = b2Contact.e_enabledFlag;

    this.m_fixtureA = fixtureA;
    this.m_fixtureB = fixtureB;

    this.m_indexA = indexA;
    this.m_indexB = indexB;

    // The C++ sets only pointCount; a reused contact's manifold is reset whole, so that it reads
    // as a new contact's (type, normal and points are read back by the state digest and writers).
    this.m_manifold.Assign(s_newManifold);

    this.m_prev = null;
    this.m_next = null;

    this.m_nodeA.contact = this;
    this.m_nodeA.prev = null;
    this.m_nodeA.next = null;
    this.m_nodeA.other = fixtureB.GetBody();

    this.m_nodeB.contact = this;
    this.m_nodeB.prev = null;
    this.m_nodeB.next = null;
    this.m_nodeB.other = fixtureA.GetBody();

    this.m_toiCount = 0;
    this.m_toiSearch = 0;
    if (this.m_scalars !== null) this.m_scalars.toi = 1.0;

    const record = this.m_manifold.m_record;
    const o = this.m_manifold.m_offset;
    record[o + b2ManifoldField.friction] = b2MixFriction(this.m_fixtureA.m_friction, this.m_fixtureB.m_friction);
    record[o + b2ManifoldField.restitution] = b2MixRestitution(this.m_fixtureA.m_restitution, this.m_fixtureB.m_restitution);
  }

  /**
   * Get the contact manifold. Do not modify the manifold unless you understand the internals
   * of Box2D.
   */
  GetManifold(): b2Manifold {
    return this.m_manifold;
  }

  /** Get the world manifold. */
  GetWorldManifold(worldManifold: b2WorldManifold): void {
    const bodyA = this.m_fixtureA.GetBody();
    const bodyB = this.m_fixtureB.GetBody();
    const shapeA = this.m_fixtureA.GetShape();
    const shapeB = this.m_fixtureB.GetShape();

    worldManifold.Initialize(this.m_manifold, bodyA.GetTransform(), shapeA.m_radius, bodyB.GetTransform(), shapeB.m_radius);
  }

  /** Is this contact touching? */
  IsTouching(): boolean {
    return (this.m_flags & b2Contact.e_touchingFlag) === b2Contact.e_touchingFlag;
  }

  /**
   * Enable/disable this contact. This can be used inside the pre-solve contact listener. The
   * contact is only disabled for the current time step (or sub-step in continuous collisions).
   */
  SetEnabled(flag: boolean): void {
    if (flag) {
      this.m_flags |= b2Contact.e_enabledFlag;
    } else {
      this.m_flags &= ~b2Contact.e_enabledFlag;
    }
  }

  /** Has this contact been disabled? */
  IsEnabled(): boolean {
    return (this.m_flags & b2Contact.e_enabledFlag) === b2Contact.e_enabledFlag;
  }

  /** Get the next contact in the world's contact list. */
  GetNext(): b2Contact | null {
    return this.m_next;
  }

  /** Get fixture A in this contact. */
  GetFixtureA(): b2Fixture {
    return this.m_fixtureA;
  }

  /** Get the child primitive index for fixture A. */
  GetChildIndexA(): number {
    return this.m_indexA;
  }

  /** Get fixture B in this contact. */
  GetFixtureB(): b2Fixture {
    return this.m_fixtureB;
  }

  /** Get the child primitive index for fixture B. */
  GetChildIndexB(): number {
    return this.m_indexB;
  }

  /**
   * Override the default friction mixture. You can call this in b2ContactListener.PreSolve.
   * This value persists until set or reset.
   */
  SetFriction(friction: number): void {
    this.m_friction = friction;
  }

  /** Get the friction. */
  GetFriction(): number {
    return this.m_friction;
  }

  /** Reset the friction mixture to the default value. */
  ResetFriction(): void {
    this.m_friction = b2MixFriction(this.m_fixtureA.m_friction, this.m_fixtureB.m_friction);
  }

  /**
   * Override the default restitution mixture. You can call this in b2ContactListener.PreSolve.
   * The value persists until you set or reset.
   */
  SetRestitution(restitution: number): void {
    this.m_restitution = restitution;
  }

  /** Get the restitution. */
  GetRestitution(): number {
    return this.m_restitution;
  }

  /** Reset the restitution to the default value. */
  ResetRestitution(): void {
    this.m_restitution = b2MixRestitution(this.m_fixtureA.m_restitution, this.m_fixtureB.m_restitution);
  }

  /** Evaluate this contact with your own manifold and transforms. */
  Evaluate(manifold: b2Manifold, xfA: b2Transform, xfB: b2Transform): void {
    this.m_evaluate(this, manifold, xfA, xfB);
  }

  /** Flag this contact for filtering. Filtering will occur the next time step. */
  FlagForFiltering(): void {
    this.m_flags |= b2Contact.e_filterFlag;
  }

  static AddType(createFcn: b2ContactCreateFcn, destroyFcn: b2ContactDestroyFcn, type1: number, type2: number): void {
    b2Assert(0 <= type1 && type1 < b2Shape.e_typeCount);
    b2Assert(0 <= type2 && type2 < b2Shape.e_typeCount);

    const register = b2Contact.s_registers[type1][type2];
    register.createFcn = createFcn;
    register.destroyFcn = destroyFcn;
    register.primary = true;

    if (type1 !== type2) {
      const reverse = b2Contact.s_registers[type2][type1];
      reverse.createFcn = createFcn;
      reverse.destroyFcn = destroyFcn;
      reverse.primary = false;
    }
  }

  /**
   * Create the contact for a pair of fixture children, or null when the shape types do not
   * collide (edge and chain pairs). A reverse-order registration swaps A and B, so fixture A is
   * always the polygon, edge or chain side. With an allocator (the world's), a contact it stores
   * for the same shape types is reinitialised instead of a new one constructed.
   */
  static Create(fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number, allocator: b2ContactAllocator | null = null): b2Contact | null {
    // The C++ fills the registry lazily here; this port fills it from b2ContactManager's
    // constructor (see the file header).
    b2Assert(b2Contact.s_initialized, 'b2InitializeContactRegisters() must run before b2Contact.Create');

    const type1 = fixtureA.GetType();
    const type2 = fixtureB.GetType();

    b2Assert(0 <= type1 && type1 < b2Shape.e_typeCount);
    b2Assert(0 <= type2 && type2 < b2Shape.e_typeCount);

    const register = b2Contact.s_registers[type1][type2];
    const createFcn = register.createFcn;
    if (createFcn) {
      if (register.primary) {
        return b2Contact.Construct(createFcn, fixtureA, indexA, fixtureB, indexB, allocator);
      } else {
        return b2Contact.Construct(createFcn, fixtureB, indexB, fixtureA, indexA, allocator);
      }
    } else {
      return null;
    }
  }

  /** The create function's contact, or the allocator's for the same shape types reinitialised. */
  private static Construct(
    createFcn: b2ContactCreateFcn,
    fixtureA: b2Fixture,
    indexA: number,
    fixtureB: b2Fixture,
    indexB: number,
    allocator: b2ContactAllocator | null,
  ): b2Contact {
    const contact = allocator !== null ? allocator.Allocate(fixtureA.GetType(), fixtureB.GetType()) : null;
    if (contact === null) {
      return createFcn(fixtureA, indexA, fixtureB, indexB);
    }
    contact.Init(fixtureA, indexA, fixtureB, indexB);
    return contact;
  }

  /** Destroy a contact the world has unlinked; with an allocator, store it there for reuse. */
  static Destroy(contact: b2Contact, allocator: b2ContactAllocator | null = null): void {
    b2Assert(b2Contact.s_initialized);

    if (contact.m_manifold.pointCount > 0) {
      contact.GetFixtureA().GetBody().SetAwake(true);
      contact.GetFixtureB().GetBody().SetAwake(true);
    }

    const typeA = contact.GetFixtureA().GetType();
    const typeB = contact.GetFixtureB().GetType();

    b2Assert(0 <= typeA && typeB < b2Shape.e_typeCount);
    b2Assert(0 <= typeA && typeB < b2Shape.e_typeCount);

    const destroyFcn = b2Contact.s_registers[typeA][typeB].destroyFcn;
    destroyFcn!(contact);
    contact.m_toiSearch = 0;
    if (allocator !== null) {
      // A stored contact keeps nothing alive: its fixtures and bodies may be on their way out.
      contact.m_fixtureA = contact.m_fixtureB = null as unknown as b2Fixture;
      contact.m_nodeA.other = contact.m_nodeB.other = null as unknown as b2Body;
      allocator.Free(contact, typeA, typeB);
    }
  }

  /**
   * Update the contact manifold and touching status.
   * Note: do not assume the fixture AABBs are overlapping or are valid.
   */
  Update(listener: b2ContactListener | null): void {
    const manifold = this.m_manifold;

    // The C++ copies the whole manifold (oldManifold) for PreSolve and for matching the new
    // points to the old. Only a listener with a PreSolve of its own can see the copy, so it is
    // made only then; the matching reads the old ids and impulses, kept here in locals.
    if (listener !== null && listener.PreSolve !== b2ContactListener.prototype.PreSolve) {
      s_oldManifold.Assign(manifold);
    }
    const oldPointCount = manifold.pointCount;
    const record = manifold.m_record;
    const p0 = manifold.m_offset + b2ManifoldField.points;
    const p1 = p0 + b2ManifoldPointField.stride;
    let oldKey0 = 0;
    let oldNormalImpulse0 = 0.0;
    let oldTangentImpulse0 = 0.0;
    let oldKey1 = 0;
    let oldNormalImpulse1 = 0.0;
    let oldTangentImpulse1 = 0.0;
    if (oldPointCount > 0) {
      oldKey0 = record[p0 + b2ManifoldPointField.key];
      oldNormalImpulse0 = record[p0 + b2ManifoldPointField.normalImpulse];
      oldTangentImpulse0 = record[p0 + b2ManifoldPointField.tangentImpulse];
      if (oldPointCount > 1) {
        oldKey1 = record[p1 + b2ManifoldPointField.key];
        oldNormalImpulse1 = record[p1 + b2ManifoldPointField.normalImpulse];
        oldTangentImpulse1 = record[p1 + b2ManifoldPointField.tangentImpulse];
      }
    }

    // Re-enable this contact.
    this.m_flags |= b2Contact.e_enabledFlag;

    let touching = false;
    const wasTouching = (this.m_flags & b2Contact.e_touchingFlag) === b2Contact.e_touchingFlag;

    const sensorA = this.m_fixtureA.IsSensor();
    const sensorB = this.m_fixtureB.IsSensor();
    const sensor = sensorA || sensorB;

    const bodyA = this.m_fixtureA.GetBody();
    const bodyB = this.m_fixtureB.GetBody();
    // The fields, not GetTransform(): the engine's own step has no backend state to fetch (b2Body.PullState).
    const xfA = bodyA.m_xf;
    const xfB = bodyB.m_xf;

    // Is this contact a sensor?
    if (sensor) {
      const shapeA = this.m_fixtureA.GetShape();
      const shapeB = this.m_fixtureB.GetShape();
      touching = b2TestOverlapShapes(shapeA, this.m_indexA, shapeB, this.m_indexB, xfA, xfB);

      // Sensors don't generate manifolds.
      manifold.pointCount = 0;
    } else {
      this.Evaluate(manifold, xfA, xfB);
      touching = manifold.pointCount > 0;

      // Match old contact ids to new contact ids and copy the
      // stored impulses to warm start the solver.
      for (let i = 0; i < manifold.pointCount; ++i) {
        const mp2 = p0 + i * b2ManifoldPointField.stride;
        record[mp2 + b2ManifoldPointField.normalImpulse] = 0.0;
        record[mp2 + b2ManifoldPointField.tangentImpulse] = 0.0;
        const key2 = record[mp2 + b2ManifoldPointField.key];

        // for (j = 0; j < oldManifold.pointCount; ++j): the first old point with this key.
        if (oldPointCount > 0 && oldKey0 === key2) {
          record[mp2 + b2ManifoldPointField.normalImpulse] = oldNormalImpulse0;
          record[mp2 + b2ManifoldPointField.tangentImpulse] = oldTangentImpulse0;
        } else if (oldPointCount > 1 && oldKey1 === key2) {
          record[mp2 + b2ManifoldPointField.normalImpulse] = oldNormalImpulse1;
          record[mp2 + b2ManifoldPointField.tangentImpulse] = oldTangentImpulse1;
        }
      }

      if (touching !== wasTouching) {
        bodyA.SetAwake(true);
        bodyB.SetAwake(true);
      }
    }

    if (touching) {
      this.m_flags |= b2Contact.e_touchingFlag;
    } else {
      this.m_flags &= ~b2Contact.e_touchingFlag;
    }

    if (wasTouching === false && touching === true && listener) {
      listener.BeginContact(this);
    }

    if (wasTouching === true && touching === false && listener) {
      listener.EndContact(this);
    }

    if (sensor === false && touching && listener) {
      listener.PreSolve(this, s_oldManifold);
    }
  }
}
