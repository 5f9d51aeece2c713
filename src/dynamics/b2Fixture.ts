/*
 * Fixtures: a shape attached to a body, with its material and filtering data and its
 * broad-phase proxies (b2Fixture.h, b2Fixture.cpp).
 */

import { b2Assert, b2Log, b2_maxPolygonVertices } from '../common/b2Settings';
import { b2Vec2 } from '../common/b2Math';
import { b2MakeArray } from '../common/b2MakeArray';
import { b2ArgumentError, b2CheckNonNegative, b2CheckObject, b2DestroyedError } from '../common/b2ArgumentError';
import type { b2Transform } from '../common/b2Math';
import { b2AABB } from '../collision/b2Collision';
import type { b2RayCastInput, b2RayCastOutput } from '../collision/b2Collision';
import { b2BroadPhase } from '../collision/b2BroadPhase';
import { b2Shape } from '../collision/shapes/b2Shape';
import type { b2MassData } from '../collision/shapes/b2Shape';
import type { b2CircleShape } from '../collision/shapes/b2CircleShape';
import type { b2EdgeShape } from '../collision/shapes/b2EdgeShape';
import type { b2PolygonShape } from '../collision/shapes/b2PolygonShape';
import type { b2ChainShape } from '../collision/shapes/b2ChainShape';
import type { b2Body } from './b2Body';

/** This holds contact filtering data. */
export class b2Filter {
  /** The collision category bits. Normally you would just set one bit. */
  categoryBits = 0x0001;

  /**
   * The collision mask bits. This states the categories that this
   * shape would accept for collision.
   */
  maskBits = 0xffff;

  /**
   * Collision groups allow a certain group of objects to never collide (negative)
   * or always collide (positive). Zero means no collision group. Non-zero group
   * filtering always wins against the mask bits.
   */
  groupIndex = 0;

  Clone(): b2Filter {
    return new b2Filter().Assign(this);
  }

  /**
   * this = filter. The C++ fields are uint16, uint16 and int16, so the copy wraps the values
   * the way a C++ assignment to those fields would.
   */
  Assign(filter: Readonly<b2Filter>): this {
    this.categoryBits = filter.categoryBits & 0xffff;
    this.maskBits = filter.maskBits & 0xffff;
    this.groupIndex = (filter.groupIndex << 16) >> 16;
    return this;
  }
}

/**
 * A fixture definition is used to create a fixture. This class defines an
 * abstract fixture definition. You can reuse fixture definitions safely.
 */
export class b2FixtureDef {
  /**
   * The shape, this must be set. The shape will be cloned, so you
   * can create the shape on the stack.
   */
  shape: b2Shape | null = null;

  /** Use this to store application specific fixture data. */
  userData: any = null;

  /** The friction coefficient, usually in the range [0,1]. */
  friction = 0.2;

  /** The restitution (elasticity) usually in the range [0,1]. */
  restitution = 0.0;

  /** The density, usually in kg/m^2. */
  density = 0.0;

  /**
   * A sensor shape collects contact information but never generates a collision
   * response.
   */
  isSensor = false;

  /** Contact filtering data. */
  readonly filter = new b2Filter();
}

/** This proxy is used internally to connect fixtures to the broad-phase. */
export class b2FixtureProxy {
  readonly aabb = new b2AABB();
  fixture: b2Fixture;
  childIndex = 0;
  proxyId: number = b2BroadPhase.e_nullProxy;

  constructor(fixture: b2Fixture) {
    this.fixture = fixture;
  }
}

/** Throws if the fixture has been destroyed (b2Body.DestroyFixture or b2World.DestroyBody). */
function checkFixture(fixture: b2Fixture, method: string): void {
  if (fixture.m_destroyed) {
    throw b2DestroyedError(method, 'this fixture');
  }
}

// Scratch for Synchronize: it never calls user code and cannot re-enter.
const s_aabb1 = new b2AABB();
const s_aabb2 = new b2AABB();
const s_displacement = new b2Vec2();

/**
 * A fixture is used to attach a shape to a body for collision detection. A fixture
 * inherits its transform from its parent. Fixtures hold additional non-geometric data
 * such as friction, collision filters, etc.
 * Fixtures are created via b2Body::CreateFixture.
 * @warning you cannot reuse fixtures.
 */
export class b2Fixture {
  m_density = 0.0;

  m_next: b2Fixture | null = null;
  m_body: b2Body;

  m_shape: b2Shape;

  m_friction = 0.0;
  m_restitution = 0.0;

  /** One proxy slot per shape child; the first m_proxyCount are in the broad-phase. */
  m_proxies: b2FixtureProxy[];
  m_proxyCount = 0;

  readonly m_filter = new b2Filter();

  m_isSensor = false;

  m_userData: any = null;

  /** Set by Destroy (no C++ counterpart: the C++ frees the memory). */
  m_destroyed = false;

  /**
   * Not in the C++: where a GPU mirror of the world (src-gpu's GpuWorld) keeps this object, its
   * slot and the mirror's id (0: none), so that the mirror finds it without a map lookup.
   */
  m_mirrorSlot = -1;
  m_mirrorId = 0;

  /**
   * The C++ default constructor and b2Fixture::Create in one: b2Body.CreateFixture is the only
   * caller, and a constructed fixture is always attached to its body.
   */
  constructor(body: b2Body, def: b2FixtureDef) {
    b2Assert(def.shape !== null, 'b2Body.CreateFixture: def.shape must be set');
    // b2Body.CreateFixture has checked the def (b2CheckFixtureDef).

    this.m_userData = def.userData;
    this.m_friction = def.friction;
    this.m_restitution = def.restitution;

    this.m_body = body;
    this.m_next = null;

    this.m_filter.Assign(def.filter);

    this.m_isSensor = def.isSensor;

    this.m_shape = def.shape.Clone();

    // Reserve proxy space
    this.m_proxies = b2MakeArray(this.m_shape.GetChildCount(), () => new b2FixtureProxy(this));
    this.m_proxyCount = 0;

    this.m_density = def.density;
  }

  /**
   * Get the type of the child shape. You can use this to down cast to the concrete shape.
   * @return the shape type.
   */
  GetType() {
    return this.m_shape.GetType();
  }

  /**
   * Get the child shape. You can modify the child shape, however you should not change the
   * number of vertices because this will crash some collision caching mechanisms.
   * Manipulating the shape may lead to non-physical behavior.
   */
  GetShape(): b2Shape {
    return this.m_shape;
  }

  /** Set if this fixture is a sensor. */
  SetSensor(sensor: boolean): void {
    checkFixture(this, 'b2Fixture.SetSensor');
    if (sensor !== this.m_isSensor) {
      this.m_body.SetAwake(true);
      this.m_isSensor = sensor;
      this.m_body.m_world.m_toiCandidatesStale = true;
      this.NotifyChanged();
    }
  }

  /**
   * Is this fixture a sensor (non-solid)?
   * @return the true if the shape is a sensor.
   */
  IsSensor(): boolean {
    return this.m_isSensor;
  }

  /**
   * Set the contact filtering data. This will not update contacts until the next time
   * step when either parent body is active and awake.
   * This automatically calls Refilter.
   */
  SetFilterData(filter: Readonly<b2Filter>): void {
    checkFixture(this, 'b2Fixture.SetFilterData');
    b2CheckObject('b2Fixture.SetFilterData', 'filter', filter);
    this.m_filter.Assign(filter);

    this.Refilter();
  }

  /** Get the contact filtering data (the fixture's own object: change it through SetFilterData). */
  GetFilterData(): Readonly<b2Filter> {
    return this.m_filter;
  }

  /** Call this if you want to establish collision that was previously disabled by b2ContactFilter::ShouldCollide. */
  Refilter(): void {
    checkFixture(this, 'b2Fixture.Refilter');
    // Flag associated contacts for filtering.
    let edge = this.m_body.GetContactList();
    while (edge) {
      const contact = edge.contact;
      const fixtureA = contact.GetFixtureA();
      const fixtureB = contact.GetFixtureB();
      if (fixtureA === this || fixtureB === this) {
        contact.FlagForFiltering();
      }

      edge = edge.next;
    }

    const world = this.m_body.GetWorld();

    // Touch each proxy so that new pairs may be created
    const broadPhase = world.m_contactManager.m_broadPhase;
    for (let i = 0; i < this.m_proxyCount; ++i) {
      broadPhase.TouchProxy(this.m_proxies[i].proxyId);
    }
    this.NotifyChanged();
  }

  /** Not in the C++: tells the world's change listener (b2ChangeListener) that this fixture changed. */
  private NotifyChanged(): void {
    const listener = this.m_body.m_world.m_changeListener;
    if (listener !== null) listener.FixtureChanged(this);
  }

  /**
   * Get the parent body of this fixture.
   * @return the parent body.
   */
  GetBody(): b2Body {
    return this.m_body;
  }

  /**
   * Get the next fixture in the parent body's fixture list.
   * @return the next shape.
   */
  GetNext(): b2Fixture | null {
    return this.m_next;
  }

  /**
   * Get the user data that was assigned in the fixture definition. Use this to
   * store your application specific data.
   */
  GetUserData(): any {
    return this.m_userData;
  }

  /** Set the user data. Use this to store your application specific data. */
  SetUserData(data: any): void {
    this.m_userData = data;
  }

  /**
   * Test a point for containment in this fixture.
   * @param p a point in world coordinates.
   */
  TestPoint(p: Readonly<b2Vec2>): boolean {
    checkFixture(this, 'b2Fixture.TestPoint');
    return this.m_shape.TestPoint(this.m_body.GetTransform(), p);
  }

  /**
   * Cast a ray against this shape.
   * @param output the ray-cast results.
   * @param input the ray-cast input parameters.
   */
  RayCast(output: b2RayCastOutput, input: Readonly<b2RayCastInput>, childIndex: number): boolean {
    return this.m_shape.RayCast(output, input, this.m_body.GetTransform(), childIndex);
  }

  /**
   * Get the mass data for this fixture. The mass data is based on the density and
   * the shape. The rotational inertia is about the shape's origin. This operation
   * may be expensive.
   */
  GetMassData(massData: b2MassData): void {
    checkFixture(this, 'b2Fixture.GetMassData');
    this.m_shape.ComputeMass(massData, this.m_density);
  }

  /**
   * Set the density of this fixture. This will _not_ automatically adjust the mass
   * of the body. You must call b2Body::ResetMassData to update the body's mass.
   */
  SetDensity(density: number): void {
    checkFixture(this, 'b2Fixture.SetDensity');
    b2CheckNonNegative('b2Fixture.SetDensity', 'density', density);
    this.m_density = density;
    this.NotifyChanged();
  }

  /** Get the density of this fixture. */
  GetDensity(): number {
    return this.m_density;
  }

  /** Get the coefficient of friction. */
  GetFriction(): number {
    return this.m_friction;
  }

  /**
   * Set the coefficient of friction. This will _not_ change the friction of
   * existing contacts.
   */
  SetFriction(friction: number): void {
    checkFixture(this, 'b2Fixture.SetFriction');
    b2CheckNonNegative('b2Fixture.SetFriction', 'friction', friction);
    this.m_friction = friction;
    this.NotifyChanged();
  }

  /** Get the coefficient of restitution. */
  GetRestitution(): number {
    return this.m_restitution;
  }

  /**
   * Set the coefficient of restitution. This will _not_ change the restitution of
   * existing contacts.
   */
  SetRestitution(restitution: number): void {
    checkFixture(this, 'b2Fixture.SetRestitution');
    b2CheckNonNegative('b2Fixture.SetRestitution', 'restitution', restitution);
    this.m_restitution = restitution;
    this.NotifyChanged();
  }

  /**
   * Get the fixture's AABB. This AABB may be enlarge and/or stale.
   * If you need a more accurate AABB, compute it using the shape and
   * the body transform.
   */
  GetAABB(childIndex: number): Readonly<b2AABB> {
    checkFixture(this, 'b2Fixture.GetAABB');
    if (!(Number.isInteger(childIndex) && 0 <= childIndex && childIndex < this.m_proxyCount)) {
      throw new b2ArgumentError(
        'b2Fixture.GetAABB',
        'childIndex',
        `must be an integer in [0, ${this.m_proxyCount}) (the fixture's proxy count; 0 while its body is inactive), got ${childIndex}`,
      );
    }
    this.m_body.m_world.PullState();
    return this.m_proxies[childIndex].aabb;
  }

  /** Dump this fixture to the log file. */
  Dump(bodyIndex: number): void {
    b2Log('    b2FixtureDef fd;\n');
    b2Log('    fd.friction = %.15lef;\n', this.m_friction);
    b2Log('    fd.restitution = %.15lef;\n', this.m_restitution);
    b2Log('    fd.density = %.15lef;\n', this.m_density);
    b2Log('    fd.isSensor = bool(%d);\n', this.m_isSensor);
    b2Log('    fd.filter.categoryBits = uint16(%d);\n', this.m_filter.categoryBits);
    b2Log('    fd.filter.maskBits = uint16(%d);\n', this.m_filter.maskBits);
    b2Log('    fd.filter.groupIndex = int16(%d);\n', this.m_filter.groupIndex);

    switch (this.m_shape.m_type) {
      case b2Shape.e_circle: {
        const s = this.m_shape as b2CircleShape;
        b2Log('    b2CircleShape shape;\n');
        b2Log('    shape.m_radius = %.15lef;\n', s.m_radius);
        b2Log('    shape.m_p.Set(%.15lef, %.15lef);\n', s.m_p.x, s.m_p.y);
        break;
      }

      case b2Shape.e_edge: {
        const s = this.m_shape as b2EdgeShape;
        b2Log('    b2EdgeShape shape;\n');
        b2Log('    shape.m_radius = %.15lef;\n', s.m_radius);
        b2Log('    shape.m_vertex0.Set(%.15lef, %.15lef);\n', s.m_vertex0.x, s.m_vertex0.y);
        b2Log('    shape.m_vertex1.Set(%.15lef, %.15lef);\n', s.m_vertex1.x, s.m_vertex1.y);
        b2Log('    shape.m_vertex2.Set(%.15lef, %.15lef);\n', s.m_vertex2.x, s.m_vertex2.y);
        b2Log('    shape.m_vertex3.Set(%.15lef, %.15lef);\n', s.m_vertex3.x, s.m_vertex3.y);
        b2Log('    shape.m_hasVertex0 = bool(%d);\n', s.m_hasVertex0);
        b2Log('    shape.m_hasVertex3 = bool(%d);\n', s.m_hasVertex3);
        break;
      }

      case b2Shape.e_polygon: {
        const s = this.m_shape as b2PolygonShape;
        b2Log('    b2PolygonShape shape;\n');
        b2Log('    b2Vec2 vs[%d];\n', b2_maxPolygonVertices);
        for (let i = 0; i < s.m_vertexCount; ++i) {
          b2Log('    vs[%d].Set(%.15lef, %.15lef);\n', i, s.m_vertices[i].x, s.m_vertices[i].y);
        }
        b2Log('    shape.Set(vs, %d);\n', s.m_vertexCount);
        break;
      }

      case b2Shape.e_chain: {
        const s = this.m_shape as b2ChainShape;
        b2Log('    b2ChainShape shape;\n');
        b2Log('    b2Vec2 vs[%d];\n', s.m_count);
        for (let i = 0; i < s.m_count; ++i) {
          b2Log('    vs[%d].Set(%.15lef, %.15lef);\n', i, s.m_vertices[i].x, s.m_vertices[i].y);
        }
        b2Log('    shape.CreateChain(vs, %d);\n', s.m_count);
        b2Log('    shape.m_prevVertex.Set(%.15lef, %.15lef);\n', s.m_prevVertex.x, s.m_prevVertex.y);
        b2Log('    shape.m_nextVertex.Set(%.15lef, %.15lef);\n', s.m_nextVertex.x, s.m_nextVertex.y);
        b2Log('    shape.m_hasPrevVertex = bool(%d);\n', s.m_hasPrevVertex);
        b2Log('    shape.m_hasNextVertex = bool(%d);\n', s.m_hasNextVertex);
        break;
      }

      default:
        return;
    }

    b2Log('\n');
    b2Log('    fd.shape = &shape;\n');
    b2Log('\n');
    b2Log('    bodies[%d]->CreateFixture(&fd);\n', bodyIndex);
  }

  /** Release the proxy slots; the proxies must have been destroyed (DestroyProxies) first. */
  Destroy(): void {
    // The proxies must be destroyed before calling this.
    b2Assert(this.m_proxyCount === 0, 'b2Fixture.Destroy: the proxies must be destroyed first');

    // Free the proxy array.
    this.m_proxies = [];
    this.m_destroyed = true;
  }

  /** Create one broad-phase proxy per shape child (body activation and fixture creation). */
  CreateProxies(broadPhase: b2BroadPhase, xf: Readonly<b2Transform>): void {
    b2Assert(this.m_proxyCount === 0, 'b2Fixture.CreateProxies: the proxies already exist');

    // Create proxies in the broad-phase.
    this.m_proxyCount = this.m_shape.GetChildCount();

    for (let i = 0; i < this.m_proxyCount; ++i) {
      const proxy = this.m_proxies[i];
      this.m_shape.ComputeAABB(proxy.aabb, xf, i);
      proxy.proxyId = broadPhase.CreateProxy(proxy.aabb, proxy);
      proxy.childIndex = i;
    }
  }

  /** Remove every proxy from the broad-phase (body deactivation and fixture destruction). */
  DestroyProxies(broadPhase: b2BroadPhase): void {
    // Destroy proxies in the broad-phase.
    for (let i = 0; i < this.m_proxyCount; ++i) {
      const proxy = this.m_proxies[i];
      broadPhase.DestroyProxy(proxy.proxyId);
      proxy.proxyId = b2BroadPhase.e_nullProxy;
    }

    this.m_proxyCount = 0;
  }

  /** Move the proxies to cover the shape swept from transform1 to transform2. */
  Synchronize(broadPhase: b2BroadPhase, transform1: Readonly<b2Transform>, transform2: Readonly<b2Transform>): void {
    if (this.m_proxyCount === 0) {
      return;
    }

    for (let i = 0; i < this.m_proxyCount; ++i) {
      const proxy = this.m_proxies[i];

      // Compute an AABB that covers the swept shape (may miss some rotation effect).
      const aabb1 = s_aabb1;
      const aabb2 = s_aabb2;
      this.m_shape.ComputeAABB(aabb1, transform1, proxy.childIndex);
      this.m_shape.ComputeAABB(aabb2, transform2, proxy.childIndex);

      proxy.aabb.Combine2(aabb1, aabb2);

      const displacement = s_displacement;
      displacement.x = transform2.p.x - transform1.p.x;
      displacement.y = transform2.p.y - transform1.p.y;

      broadPhase.MoveProxy(proxy.proxyId, proxy.aabb, displacement);
    }
  }
}
