/*
 * Rigid bodies (b2Body.h, b2Body.cpp).
 *
 * Bodies are created through b2World.CreateBody. Fields keep the C++ names; the ones C++ kept
 * private for its friends (world, island, contact manager, solver, joints) are public here.
 */

import { b2Assert, b2Log } from '../common/b2Settings';
import { b2BodyFlags, b2BodyType, b2JointType, b2WorldFlags } from '../common/b2Constants';
import { b2Transform, b2Sweep, b2SweepTime, b2Vec2 } from '../common/b2Math';
import { b2ArgumentError, b2CheckFinite, b2CheckNonNegative, b2CheckObject, b2CheckVec2, b2DestroyedError, b2LockedError } from '../common/b2ArgumentError';
import { b2MassData, b2Shape } from '../collision/shapes/b2Shape';
import { b2Fixture, b2FixtureDef } from './b2Fixture';
import type { b2World } from './b2World';
import type { b2ContactEdge } from './contacts/b2Contact';
import type { b2JointEdge } from './joints/b2Joint';
import { b2CheckBodyDef, b2CheckBodyType, b2CheckFixtureDef } from './b2BodyDefValidation';

export { b2BodyType };

export const b2_staticBody = b2BodyType.b2_staticBody;
export const b2_kinematicBody = b2BodyType.b2_kinematicBody;
export const b2_dynamicBody = b2BodyType.b2_dynamicBody;

/**
 * A body definition holds all the data needed to construct a rigid body.
 * You can safely re-use body definitions. Shapes are added to a body after construction.
 */
export class b2BodyDef {
  /**
   * The body type: static, kinematic, or dynamic.
   * Note: if a dynamic body would have zero mass, the mass is set to one.
   */
  type: b2BodyType = b2BodyType.b2_staticBody;

  /**
   * The world position of the body. Avoid creating bodies at the origin
   * since this can lead to many overlapping shapes.
   */
  readonly position = new b2Vec2(0.0, 0.0);

  /** The world angle of the body in radians. */
  angle = 0.0;

  /** The linear velocity of the body's origin in world co-ordinates. */
  readonly linearVelocity = new b2Vec2(0.0, 0.0);

  /** The angular velocity of the body. */
  angularVelocity = 0.0;

  /**
   * Linear damping is use to reduce the linear velocity. The damping parameter
   * can be larger than 1.0f but the damping effect becomes sensitive to the
   * time step when the damping parameter is large.
   */
  linearDamping = 0.0;

  /**
   * Angular damping is use to reduce the angular velocity. The damping parameter
   * can be larger than 1.0f but the damping effect becomes sensitive to the
   * time step when the damping parameter is large.
   */
  angularDamping = 0.0;

  /**
   * Set this flag to false if this body should never fall asleep. Note that
   * this increases CPU usage.
   */
  allowSleep = true;

  /** Is this body initially awake or sleeping? */
  awake = true;

  /** Should this body be prevented from rotating? Useful for characters. */
  fixedRotation = false;

  /**
   * Is this a fast moving body that should be prevented from tunneling through
   * other moving bodies? Note that all bodies are prevented from tunneling through
   * kinematic and static bodies. This setting is only considered on dynamic bodies.
   * @warning You should use this flag sparingly since it increases processing time.
   */
  bullet = false;

  /** Does this body start out active? */
  active = true;

  /** Use this to store application specific body data. */
  userData: any = null;

  /** Scale the gravity applied to this body. */
  gravityScale = 1.0;
}

// Scratch for SynchronizeFixtures and ResetMassData/SetMassData: neither calls user code while
// holding them, and neither can re-enter itself.
const s_xf1 = new b2Transform();
const s_massData = new b2MassData();
const s_localCenter = new b2Vec2();
const s_oldCenter = new b2Vec2();

/** Throws unless the body is alive (not destroyed); `locked` also requires an unlocked world. */
function checkBody(body: b2Body, method: string, locked: boolean): void {
  if (body.m_destroyed) {
    throw b2DestroyedError(method, 'this body');
  }
  if (locked && body.m_world.IsLocked()) {
    throw b2LockedError(method);
  }
}

/** A rigid body. These are created via b2World::CreateBody. */
export class b2Body {
  // m_flags
  static readonly e_islandFlag = b2BodyFlags.e_islandFlag;
  static readonly e_awakeFlag = b2BodyFlags.e_awakeFlag;
  static readonly e_autoSleepFlag = b2BodyFlags.e_autoSleepFlag;
  static readonly e_bulletFlag = b2BodyFlags.e_bulletFlag;
  static readonly e_fixedRotationFlag = b2BodyFlags.e_fixedRotationFlag;
  static readonly e_activeFlag = b2BodyFlags.e_activeFlag;
  static readonly e_toiFlag = b2BodyFlags.e_toiFlag;

  m_type: b2BodyType;

  m_flags = 0;

  m_islandIndex = 0;

  /** The body origin transform. */
  readonly m_xf = new b2Transform();
  /** The swept motion for CCD. */
  readonly m_sweep = new b2Sweep();

  readonly m_linearVelocity = new b2Vec2();
  m_angularVelocity = 0.0;

  readonly m_force = new b2Vec2();
  m_torque = 0.0;

  m_world: b2World;
  m_prev: b2Body | null = null;
  m_next: b2Body | null = null;

  m_fixtureList: b2Fixture | null = null;
  m_fixtureCount = 0;

  m_jointList: b2JointEdge | null = null;
  m_contactList: b2ContactEdge | null = null;

  m_mass = 0.0;
  m_invMass = 0.0;

  /** Rotational inertia about the center of mass. */
  m_I = 0.0;
  m_invI = 0.0;

  m_linearDamping = 0.0;
  m_angularDamping = 0.0;
  m_gravityScale = 1.0;

  m_sleepTime = 0.0;

  m_userData: any = null;

  /** Set by b2World.DestroyBody (no C++ counterpart: the C++ frees the memory). */
  m_destroyed = false;

  /**
   * Not in the C++: the world's m_stateEpoch when this object last received its state. On a
   * backend (b2World.SetBackend) a synchronisation only advances the world's epoch; the body
   * fetches its motion, awake flag and sleep time from the backend when one of its methods first
   * reads or changes them (PullState), so a synchronisation costs what the application reads.
   */
  m_stateEpoch = 0;

  /**
   * Not in the C++: where a GPU mirror of the world (src-gpu's GpuWorld) keeps this object, its
   * slot and the mirror's id (0: none), so that the mirror finds it without a map lookup.
   */
  m_mirrorSlot = -1;
  m_mirrorId = 0;

  constructor(bd: b2BodyDef, world: b2World) {
    // The C++ asserts; b2ArgumentError names the field (see b2DefValidation).
    b2CheckBodyDef('b2World.CreateBody', bd);

    if (bd.bullet) {
      this.m_flags |= b2Body.e_bulletFlag;
    }
    if (bd.fixedRotation) {
      this.m_flags |= b2Body.e_fixedRotationFlag;
    }
    if (bd.allowSleep) {
      this.m_flags |= b2Body.e_autoSleepFlag;
    }
    if (bd.awake) {
      this.m_flags |= b2Body.e_awakeFlag;
    }
    if (bd.active) {
      this.m_flags |= b2Body.e_activeFlag;
    }

    this.m_world = world;
    this.m_stateEpoch = world.m_stateEpoch;

    this.m_xf.p.Assign(bd.position);
    this.m_xf.q.Set(bd.angle);

    this.m_sweep.localCenter.SetZero();
    this.m_sweep.c0.Assign(this.m_xf.p);
    this.m_sweep.c.Assign(this.m_xf.p);
    this.m_sweep.a0 = bd.angle;
    this.m_sweep.a = bd.angle;
    this.m_sweep.alpha0 = 0.0;

    this.m_linearVelocity.Assign(bd.linearVelocity);
    this.m_angularVelocity = bd.angularVelocity;

    this.m_linearDamping = bd.linearDamping;
    this.m_angularDamping = bd.angularDamping;
    this.m_gravityScale = bd.gravityScale;

    this.m_type = bd.type;

    if (this.m_type === b2BodyType.b2_dynamicBody) {
      this.m_mass = 1.0;
      this.m_invMass = 1.0;
    } else {
      this.m_mass = 0.0;
      this.m_invMass = 0.0;
    }

    this.m_userData = bd.userData;
  }

  /**
   * Creates a fixture and attach it to this body. Pass a b2FixtureDef if you need to set
   * parameters like friction, restitution, user data, or filtering; or pass a shape and a
   * density (the C++ CreateFixture(shape, density) convenience overload).
   * The shape is cloned. If the density is non-zero, this function automatically updates the
   * mass of the body. Contacts are not created until the next time step.
   * @warning This function is locked during callbacks.
   */
  CreateFixture(defOrShape: b2FixtureDef | b2Shape, density = 0.0): b2Fixture {
    checkBody(this, 'b2Body.CreateFixture', true);
    this.PullState();

    let def: b2FixtureDef;
    if (defOrShape instanceof b2Shape) {
      def = new b2FixtureDef();
      def.shape = defOrShape;
      def.density = density;
      b2CheckNonNegative('b2Body.CreateFixture', 'density', density);
      b2CheckFixtureDef('b2Body.CreateFixture', def, 'shape');
    } else {
      def = defOrShape;
      b2CheckFixtureDef('b2Body.CreateFixture', def);
    }

    const fixture = new b2Fixture(this, def);

    if (this.m_flags & b2Body.e_activeFlag) {
      const broadPhase = this.m_world.m_contactManager.m_broadPhase;
      fixture.CreateProxies(broadPhase, this.m_xf);
    }

    fixture.m_next = this.m_fixtureList;
    this.m_fixtureList = fixture;
    ++this.m_fixtureCount;

    fixture.m_body = this;

    // Adjust mass properties if needed.
    if (fixture.m_density > 0.0) {
      this.ResetMassData();
    }

    // Let the world know we have a new fixture. This will cause new contacts
    // to be created at the beginning of the next time step.
    this.m_world.m_flags |= b2WorldFlags.e_newFixture;

    this.m_world.m_changeListener?.StructureChanged();
    return fixture;
  }

  /**
   * Destroy a fixture. This removes the fixture from the broad-phase and
   * destroys all contacts associated with this fixture. This will
   * automatically adjust the mass of the body if the body is dynamic and the
   * fixture has positive density.
   * All fixtures attached to a body are implicitly destroyed when the body is destroyed.
   * @param fixture the fixture to be removed.
   * @warning This function is locked during callbacks.
   */
  DestroyFixture(fixture: b2Fixture): void {
    checkBody(this, 'b2Body.DestroyFixture', true);
    b2CheckObject('b2Body.DestroyFixture', 'fixture', fixture);
    this.PullState();
    if (fixture.m_destroyed) {
      throw b2DestroyedError('b2Body.DestroyFixture', 'fixture');
    }
    if (fixture.m_body !== this) {
      throw new b2ArgumentError('b2Body.DestroyFixture', 'fixture', 'belongs to another body');
    }

    // Remove the fixture from this body's singly linked list.
    b2Assert(this.m_fixtureCount > 0, 'b2Body.DestroyFixture: the body has no fixtures');
    let prev: b2Fixture | null = null;
    let node = this.m_fixtureList;
    let found = false;
    while (node !== null) {
      if (node === fixture) {
        if (prev === null) {
          this.m_fixtureList = fixture.m_next;
        } else {
          prev.m_next = fixture.m_next;
        }
        found = true;
        break;
      }

      prev = node;
      node = node.m_next;
    }

    // You tried to remove a shape that is not attached to this body.
    b2Assert(found, 'b2Body.DestroyFixture: the fixture is not attached to this body');

    // Destroy any contacts associated with the fixture.
    let edge = this.m_contactList;
    while (edge) {
      const c = edge.contact;
      edge = edge.next;

      const fixtureA = c.GetFixtureA();
      const fixtureB = c.GetFixtureB();

      if (fixture === fixtureA || fixture === fixtureB) {
        // This destroys the contact and removes it from
        // this body's contact list.
        this.m_world.m_contactManager.Destroy(c);
      }
    }

    if (this.m_flags & b2Body.e_activeFlag) {
      const broadPhase = this.m_world.m_contactManager.m_broadPhase;
      fixture.DestroyProxies(broadPhase);
    }

    fixture.Destroy();
    fixture.m_next = null;

    --this.m_fixtureCount;

    // Reset the mass data.
    this.ResetMassData();
    this.m_world.m_changeListener?.StructureChanged();
  }

  /**
   * Set the position of the body's origin and rotation.
   * This breaks any contacts and wakes the other bodies.
   * Manipulating a body's transform may cause non-physical behavior.
   * @param position the world position of the body's local origin.
   * @param angle the world rotation in radians.
   */
  SetTransform(position: Readonly<b2Vec2>, angle: number): void {
    checkBody(this, 'b2Body.SetTransform', true);
    b2CheckVec2('b2Body.SetTransform', 'position', position);
    b2CheckFinite('b2Body.SetTransform', 'angle', angle);
    this.PullState();

    const xf = this.m_xf;
    xf.q.Set(angle);
    xf.p.Assign(position);

    // m_sweep.c = b2Mul(m_xf, m_sweep.localCenter)
    const lc = this.m_sweep.localCenter;
    const lcx = lc.x;
    const lcy = lc.y;
    this.m_sweep.c.x = xf.q.c * lcx - xf.q.s * lcy + xf.p.x;
    this.m_sweep.c.y = xf.q.s * lcx + xf.q.c * lcy + xf.p.y;
    this.m_sweep.a = angle;

    this.m_sweep.c0.Assign(this.m_sweep.c);
    this.m_sweep.a0 = angle;

    const broadPhase = this.m_world.m_contactManager.m_broadPhase;
    for (let f = this.m_fixtureList; f; f = f.m_next) {
      f.Synchronize(broadPhase, xf, xf);
    }

    // Not in the C++: a backend that keeps the contacts finds the moved body's pairs itself.
    if (this.m_world.GetBackend()?.KeepsContacts?.() !== true) this.m_world.m_contactManager.FindNewContacts();
    this.NotifyChanged(true);
  }

  /** Get the body transform for the body's origin (the body's own object: treat it as read-only). */
  GetTransform(): Readonly<b2Transform> {
    this.PullState();
    return this.m_xf;
  }

  /** Get the world body origin position (the body's own object: treat it as read-only). */
  GetPosition(): Readonly<b2Vec2> {
    this.PullState();
    return this.m_xf.p;
  }

  /** Get the angle in radians. */
  GetAngle(): number {
    this.PullState();
    return this.m_sweep.a;
  }

  /** Get the world position of the center of mass (the body's own object: treat it as read-only). */
  GetWorldCenter(): Readonly<b2Vec2> {
    this.PullState();
    return this.m_sweep.c;
  }

  /** Get the local position of the center of mass (the body's own object: treat it as read-only). */
  GetLocalCenter(): Readonly<b2Vec2> {
    return this.m_sweep.localCenter;
  }

  /**
   * Set the linear velocity of the center of mass.
   * @param v the new linear velocity of the center of mass.
   */
  SetLinearVelocity(v: Readonly<b2Vec2>): void {
    checkBody(this, 'b2Body.SetLinearVelocity', false);
    b2CheckVec2('b2Body.SetLinearVelocity', 'v', v);
    this.PullState();
    if (this.m_type === b2BodyType.b2_staticBody) {
      return;
    }

    if (v.x * v.x + v.y * v.y > 0.0) {
      this.SetAwake(true);
    }

    this.m_linearVelocity.Assign(v);
    this.NotifyChanged(true);
  }

  /** Get the linear velocity of the center of mass (a copy, written to `out` when given). */
  GetLinearVelocity(out: b2Vec2 = new b2Vec2()): b2Vec2 {
    this.PullState();
    return out.Assign(this.m_linearVelocity);
  }

  /**
   * Set the angular velocity.
   * @param w the new angular velocity in radians/second.
   */
  SetAngularVelocity(w: number): void {
    checkBody(this, 'b2Body.SetAngularVelocity', false);
    b2CheckFinite('b2Body.SetAngularVelocity', 'w', w);
    this.PullState();
    if (this.m_type === b2BodyType.b2_staticBody) {
      return;
    }

    if (w * w > 0.0) {
      this.SetAwake(true);
    }

    this.m_angularVelocity = w;
    this.NotifyChanged(true);
  }

  /** Get the angular velocity in radians/second. */
  GetAngularVelocity(): number {
    this.PullState();
    return this.m_angularVelocity;
  }

  /**
   * Apply a force at a world point. If the force is not
   * applied at the center of mass, it will generate a torque and
   * affect the angular velocity. This wakes up the body.
   * @param force the world force vector, usually in Newtons (N).
   * @param point the world position of the point of application.
   */
  ApplyForce(force: Readonly<b2Vec2>, point: Readonly<b2Vec2>): void {
    checkBody(this, 'b2Body.ApplyForce', false);
    b2CheckVec2('b2Body.ApplyForce', 'force', force);
    b2CheckVec2('b2Body.ApplyForce', 'point', point);
    this.PullState();
    if (this.m_type !== b2BodyType.b2_dynamicBody) {
      return;
    }

    // Unguarded, unlike the C++ (the same when awake): a change listener hears every wake.
    this.SetAwake(true);

    const fx = force.x;
    const fy = force.y;
    this.m_force.x += fx;
    this.m_force.y += fy;
    // b2Cross(point - m_sweep.c, force)
    const rx = point.x - this.m_sweep.c.x;
    const ry = point.y - this.m_sweep.c.y;
    this.m_torque += rx * fy - ry * fx;
    this.NotifyChanged(false);
  }

  /**
   * Apply a force to the center of mass. This wakes up the body.
   * @param force the world force vector, usually in Newtons (N).
   */
  ApplyForceToCenter(force: Readonly<b2Vec2>): void {
    checkBody(this, 'b2Body.ApplyForceToCenter', false);
    b2CheckVec2('b2Body.ApplyForceToCenter', 'force', force);
    this.PullState();
    if (this.m_type !== b2BodyType.b2_dynamicBody) {
      return;
    }

    // Unguarded, unlike the C++ (the same when awake): a change listener hears every wake.
    this.SetAwake(true);

    this.m_force.x += force.x;
    this.m_force.y += force.y;
    this.NotifyChanged(false);
  }

  /**
   * Apply a torque. This affects the angular velocity
   * without affecting the linear velocity of the center of mass.
   * This wakes up the body.
   * @param torque about the z-axis (out of the screen), usually in N-m.
   */
  ApplyTorque(torque: number): void {
    checkBody(this, 'b2Body.ApplyTorque', false);
    b2CheckFinite('b2Body.ApplyTorque', 'torque', torque);
    this.PullState();
    if (this.m_type !== b2BodyType.b2_dynamicBody) {
      return;
    }

    // Unguarded, unlike the C++ (the same when awake): a change listener hears every wake.
    this.SetAwake(true);

    this.m_torque += torque;
    this.NotifyChanged(false);
  }

  /**
   * Apply an impulse at a point. This immediately modifies the velocity.
   * It also modifies the angular velocity if the point of application
   * is not at the center of mass. This wakes up the body.
   * @param impulse the world impulse vector, usually in N-seconds or kg-m/s.
   * @param point the world position of the point of application.
   */
  ApplyLinearImpulse(impulse: Readonly<b2Vec2>, point: Readonly<b2Vec2>): void {
    checkBody(this, 'b2Body.ApplyLinearImpulse', false);
    b2CheckVec2('b2Body.ApplyLinearImpulse', 'impulse', impulse);
    b2CheckVec2('b2Body.ApplyLinearImpulse', 'point', point);
    this.PullState();
    if (this.m_type !== b2BodyType.b2_dynamicBody) {
      return;
    }

    // Unguarded, unlike the C++ (the same when awake): a change listener hears every wake.
    this.SetAwake(true);
    const ix = impulse.x;
    const iy = impulse.y;
    this.m_linearVelocity.x += this.m_invMass * ix;
    this.m_linearVelocity.y += this.m_invMass * iy;
    // m_invI * b2Cross(point - m_sweep.c, impulse)
    const rx = point.x - this.m_sweep.c.x;
    const ry = point.y - this.m_sweep.c.y;
    this.m_angularVelocity += this.m_invI * (rx * iy - ry * ix);
    this.NotifyChanged(true);
  }

  /**
   * Apply an angular impulse.
   * @param impulse the angular impulse in units of kg*m*m/s
   */
  ApplyAngularImpulse(impulse: number): void {
    checkBody(this, 'b2Body.ApplyAngularImpulse', false);
    b2CheckFinite('b2Body.ApplyAngularImpulse', 'impulse', impulse);
    this.PullState();
    if (this.m_type !== b2BodyType.b2_dynamicBody) {
      return;
    }

    // Unguarded, unlike the C++ (the same when awake): a change listener hears every wake.
    this.SetAwake(true);
    this.m_angularVelocity += this.m_invI * impulse;
    this.NotifyChanged(true);
  }

  /**
   * Get the total mass of the body.
   * @return the mass, usually in kilograms (kg).
   */
  GetMass(): number {
    return this.m_mass;
  }

  /**
   * Get the rotational inertia of the body about the local origin.
   * @return the rotational inertia, usually in kg-m^2.
   */
  GetInertia(): number {
    const lc = this.m_sweep.localCenter;
    return this.m_I + this.m_mass * (lc.x * lc.x + lc.y * lc.y);
  }

  /**
   * Get the mass data of the body.
   * @return a struct containing the mass, inertia and center of the body.
   */
  GetMassData(data: b2MassData): b2MassData {
    const lc = this.m_sweep.localCenter;
    data.mass = this.m_mass;
    data.I = this.m_I + this.m_mass * (lc.x * lc.x + lc.y * lc.y);
    data.center.Assign(lc);
    return data;
  }

  /**
   * Set the mass properties to override the mass properties of the fixtures.
   * Note that this changes the center of mass position.
   * Note that creating or destroying fixtures can also alter the mass.
   * This function has no effect if the body isn't dynamic.
   * @param massData the mass properties.
   */
  SetMassData(massData: Readonly<b2MassData>): void {
    checkBody(this, 'b2Body.SetMassData', true);
    b2CheckObject('b2Body.SetMassData', 'massData', massData);
    b2CheckFinite('b2Body.SetMassData', 'massData.mass', massData.mass);
    b2CheckVec2('b2Body.SetMassData', 'massData.center', massData.center);
    b2CheckFinite('b2Body.SetMassData', 'massData.I', massData.I);
    this.PullState();
    if (massData.I > 0.0 && (this.m_flags & b2Body.e_fixedRotationFlag) === 0) {
      // The C++ asserts that the inertia about the center of mass stays positive.
      const mass = massData.mass > 0.0 ? massData.mass : 1.0;
      const c = massData.center;
      if (!(massData.I - mass * (c.x * c.x + c.y * c.y) > 0.0)) {
        throw new b2ArgumentError(
          'b2Body.SetMassData',
          'massData.I',
          `must exceed mass * |center|^2 (the rotational inertia about the center of mass must be positive), got ${massData.I}`,
        );
      }
    }

    if (this.m_type !== b2BodyType.b2_dynamicBody) {
      return;
    }

    this.m_invMass = 0.0;
    this.m_I = 0.0;
    this.m_invI = 0.0;

    this.m_mass = massData.mass;
    if (this.m_mass <= 0.0) {
      this.m_mass = 1.0;
    }

    this.m_invMass = 1.0 / this.m_mass;

    if (massData.I > 0.0 && (this.m_flags & b2Body.e_fixedRotationFlag) === 0) {
      const center = massData.center;
      this.m_I = massData.I - this.m_mass * (center.x * center.x + center.y * center.y);
      b2Assert(this.m_I > 0.0, 'b2Body.SetMassData: the rotational inertia about the center of mass must be positive');
      this.m_invI = 1.0 / this.m_I;
    }

    // Move center of mass.
    this.m_sweep.localCenter.Assign(massData.center);
    this.MoveCenterOfMass();
  }

  /**
   * This resets the mass properties to the sum of the mass properties of the fixtures.
   * This normally does not need to be called unless you called SetMassData to override
   * the mass and you later want to reset the mass.
   */
  ResetMassData(): void {
    checkBody(this, 'b2Body.ResetMassData', false);
    this.PullState();
    // Compute mass data from shapes. Each shape has its own density.
    this.m_mass = 0.0;
    this.m_invMass = 0.0;
    this.m_I = 0.0;
    this.m_invI = 0.0;
    this.m_sweep.localCenter.SetZero();

    // Static and kinematic bodies have zero mass.
    if (this.m_type === b2BodyType.b2_staticBody || this.m_type === b2BodyType.b2_kinematicBody) {
      this.m_sweep.c0.Assign(this.m_xf.p);
      this.m_sweep.c.Assign(this.m_xf.p);
      this.m_sweep.a0 = this.m_sweep.a;
      this.NotifyChanged(true);
      return;
    }

    b2Assert(this.m_type === b2BodyType.b2_dynamicBody, 'b2Body.ResetMassData: unknown body type');

    // Accumulate mass over all fixtures.
    const localCenter = s_localCenter.SetZero();
    const massData = s_massData;
    for (let f = this.m_fixtureList; f; f = f.m_next) {
      if (f.m_density === 0.0) {
        continue;
      }

      f.GetMassData(massData);
      this.m_mass += massData.mass;
      localCenter.x += massData.mass * massData.center.x;
      localCenter.y += massData.mass * massData.center.y;
      this.m_I += massData.I;
    }

    // Compute center of mass.
    if (this.m_mass > 0.0) {
      this.m_invMass = 1.0 / this.m_mass;
      localCenter.x *= this.m_invMass;
      localCenter.y *= this.m_invMass;
    } else {
      // Force all dynamic bodies to have a positive mass.
      this.m_mass = 1.0;
      this.m_invMass = 1.0;
    }

    if (this.m_I > 0.0 && (this.m_flags & b2Body.e_fixedRotationFlag) === 0) {
      // Center the inertia about the center of mass.
      this.m_I -= this.m_mass * (localCenter.x * localCenter.x + localCenter.y * localCenter.y);
      b2Assert(this.m_I > 0.0, 'b2Body.ResetMassData: the rotational inertia about the center of mass must be positive');
      this.m_invI = 1.0 / this.m_I;
    } else {
      this.m_I = 0.0;
      this.m_invI = 0.0;
    }

    // Move center of mass.
    this.m_sweep.localCenter.Assign(localCenter);
    this.MoveCenterOfMass();
  }

  /**
   * The tail shared by SetMassData and ResetMassData once m_sweep.localCenter holds the new
   * center: move the world center there and keep the velocity of the body origin.
   */
  private MoveCenterOfMass(): void {
    const oldCenter = s_oldCenter.Assign(this.m_sweep.c);
    const xf = this.m_xf;
    const lc = this.m_sweep.localCenter;
    // m_sweep.c0 = m_sweep.c = b2Mul(m_xf, m_sweep.localCenter)
    this.m_sweep.c.x = xf.q.c * lc.x - xf.q.s * lc.y + xf.p.x;
    this.m_sweep.c.y = xf.q.s * lc.x + xf.q.c * lc.y + xf.p.y;
    this.m_sweep.c0.Assign(this.m_sweep.c);

    // Update center of mass velocity: m_linearVelocity += b2Cross(m_angularVelocity, m_sweep.c - oldCenter)
    const w = this.m_angularVelocity;
    const dx = this.m_sweep.c.x - oldCenter.x;
    const dy = this.m_sweep.c.y - oldCenter.y;
    this.m_linearVelocity.x += -w * dy;
    this.m_linearVelocity.y += w * dx;
    this.NotifyChanged(true);
  }

  /**
   * Get the world coordinates of a point given the local coordinates.
   * @param localPoint a point on the body measured relative the the body's origin.
   * @return the same point expressed in world coordinates (in `out` when given).
   */
  GetWorldPoint(localPoint: Readonly<b2Vec2>, out: b2Vec2 = new b2Vec2()): b2Vec2 {
    this.PullState();
    const xf = this.m_xf;
    const x = localPoint.x;
    const y = localPoint.y;
    out.x = xf.q.c * x - xf.q.s * y + xf.p.x;
    out.y = xf.q.s * x + xf.q.c * y + xf.p.y;
    return out;
  }

  /**
   * Get the world coordinates of a vector given the local coordinates.
   * @param localVector a vector fixed in the body.
   * @return the same vector expressed in world coordinates (in `out` when given).
   */
  GetWorldVector(localVector: Readonly<b2Vec2>, out: b2Vec2 = new b2Vec2()): b2Vec2 {
    this.PullState();
    const q = this.m_xf.q;
    const x = localVector.x;
    const y = localVector.y;
    out.x = q.c * x - q.s * y;
    out.y = q.s * x + q.c * y;
    return out;
  }

  /**
   * Gets a local point relative to the body's origin given a world point.
   * @param worldPoint a point in world coordinates.
   * @return the corresponding local point relative to the body's origin (in `out` when given).
   */
  GetLocalPoint(worldPoint: Readonly<b2Vec2>, out: b2Vec2 = new b2Vec2()): b2Vec2 {
    this.PullState();
    const xf = this.m_xf;
    const px = worldPoint.x - xf.p.x;
    const py = worldPoint.y - xf.p.y;
    out.x = xf.q.c * px + xf.q.s * py;
    out.y = -xf.q.s * px + xf.q.c * py;
    return out;
  }

  /**
   * Gets a local vector given a world vector.
   * @param worldVector a vector in world coordinates.
   * @return the corresponding local vector (in `out` when given).
   */
  GetLocalVector(worldVector: Readonly<b2Vec2>, out: b2Vec2 = new b2Vec2()): b2Vec2 {
    this.PullState();
    const q = this.m_xf.q;
    const x = worldVector.x;
    const y = worldVector.y;
    out.x = q.c * x + q.s * y;
    out.y = -q.s * x + q.c * y;
    return out;
  }

  /**
   * Get the world linear velocity of a world point attached to this body.
   * @param worldPoint a point in world coordinates.
   * @return the world velocity of a point (in `out` when given).
   */
  GetLinearVelocityFromWorldPoint(worldPoint: Readonly<b2Vec2>, out: b2Vec2 = new b2Vec2()): b2Vec2 {
    this.PullState();
    // m_linearVelocity + b2Cross(m_angularVelocity, worldPoint - m_sweep.c)
    const w = this.m_angularVelocity;
    const dx = worldPoint.x - this.m_sweep.c.x;
    const dy = worldPoint.y - this.m_sweep.c.y;
    out.x = this.m_linearVelocity.x + -w * dy;
    out.y = this.m_linearVelocity.y + w * dx;
    return out;
  }

  /**
   * Get the world velocity of a local point.
   * @param localPoint a point in local coordinates.
   * @return the world velocity of a point (in `out` when given).
   */
  GetLinearVelocityFromLocalPoint(localPoint: Readonly<b2Vec2>, out: b2Vec2 = new b2Vec2()): b2Vec2 {
    return this.GetLinearVelocityFromWorldPoint(this.GetWorldPoint(localPoint, out), out);
  }

  /** Get the linear damping of the body. */
  GetLinearDamping(): number {
    return this.m_linearDamping;
  }

  /** Set the linear damping of the body. */
  SetLinearDamping(linearDamping: number): void {
    checkBody(this, 'b2Body.SetLinearDamping', false);
    b2CheckNonNegative('b2Body.SetLinearDamping', 'linearDamping', linearDamping);
    this.m_linearDamping = linearDamping;
    this.NotifyChanged(false);
  }

  /** Get the angular damping of the body. */
  GetAngularDamping(): number {
    return this.m_angularDamping;
  }

  /** Set the angular damping of the body. */
  SetAngularDamping(angularDamping: number): void {
    checkBody(this, 'b2Body.SetAngularDamping', false);
    b2CheckNonNegative('b2Body.SetAngularDamping', 'angularDamping', angularDamping);
    this.m_angularDamping = angularDamping;
    this.NotifyChanged(false);
  }

  /** Get the gravity scale of the body. */
  GetGravityScale(): number {
    return this.m_gravityScale;
  }

  /** Set the gravity scale of the body. */
  SetGravityScale(scale: number): void {
    checkBody(this, 'b2Body.SetGravityScale', false);
    b2CheckFinite('b2Body.SetGravityScale', 'scale', scale);
    this.m_gravityScale = scale;
    this.NotifyChanged(false);
  }

  /**
   * Set the type of this body. This may alter the mass and velocity.
   * Contacts are flagged for filtering: those the new type rules out are destroyed by the
   * next time step's collide phase.
   */
  SetType(type: b2BodyType): void {
    checkBody(this, 'b2Body.SetType', true);
    b2CheckBodyType('b2Body.SetType', 'type', type);
    this.PullState();
    if (type !== b2BodyType.b2_dynamicBody) {
      for (let je = this.m_jointList; je; je = je.next) {
        if (je.joint.m_type === b2JointType.e_mouseJoint && je.joint.m_bodyB === this) {
          throw new b2ArgumentError('b2Body.SetType', 'type', 'must stay b2_dynamicBody while a mouse joint drags this body (destroy the mouse joint first)');
        }
      }
    }

    if (this.m_type === type) {
      return;
    }

    this.m_type = type;
    this.m_world.m_toiCandidatesStale = true;

    this.ResetMassData();

    if (this.m_type === b2BodyType.b2_staticBody) {
      this.m_linearVelocity.SetZero();
      this.m_angularVelocity = 0.0;
      this.m_sweep.a0 = this.m_sweep.a;
      this.m_sweep.c0.Assign(this.m_sweep.c);
      this.SynchronizeFixtures();
    }

    this.SetAwake(true);

    this.m_force.SetZero();
    this.m_torque = 0.0;

    // Since the body type changed, we need to flag contacts for filtering.
    for (let f = this.m_fixtureList; f; f = f.m_next) {
      f.Refilter();
    }
    this.m_world.m_changeListener?.StructureChanged();
  }

  /** Get the type of this body. */
  GetType(): b2BodyType {
    return this.m_type;
  }

  /** Should this body be treated like a bullet for continuous collision detection? */
  SetBullet(flag: boolean): void {
    checkBody(this, 'b2Body.SetBullet', false);
    if (flag) {
      this.m_flags |= b2Body.e_bulletFlag;
    } else {
      this.m_flags &= ~b2Body.e_bulletFlag;
    }
    this.m_world.m_toiCandidatesStale = true;
    this.NotifyChanged(false);
  }

  /** Is this body treated like a bullet for continuous collision detection? */
  IsBullet(): boolean {
    return (this.m_flags & b2Body.e_bulletFlag) === b2Body.e_bulletFlag;
  }

  /**
   * You can disable sleeping on this body. If you disable sleeping, the
   * body will be woken.
   */
  SetSleepingAllowed(flag: boolean): void {
    checkBody(this, 'b2Body.SetSleepingAllowed', false);
    this.PullState();
    if (flag) {
      this.m_flags |= b2Body.e_autoSleepFlag;
    } else {
      this.m_flags &= ~b2Body.e_autoSleepFlag;
      this.SetAwake(true);
    }
    this.NotifyChanged(false);
  }

  /** Is this body allowed to sleep */
  IsSleepingAllowed(): boolean {
    return (this.m_flags & b2Body.e_autoSleepFlag) === b2Body.e_autoSleepFlag;
  }

  /**
   * Set the sleep state of the body. A sleeping body has very
   * low CPU cost.
   * @param flag set to true to put body to sleep, false to wake it.
   */
  SetAwake(flag: boolean): void {
    this.PullState();
    if (flag) {
      if ((this.m_flags & b2Body.e_awakeFlag) === 0) {
        this.m_flags |= b2Body.e_awakeFlag;
        this.m_sleepTime = 0.0;
        this.NotifyChanged(false);
      }
      this.m_world.m_changeListener?.BodyWoken(this);
    } else {
      this.m_flags &= ~b2Body.e_awakeFlag;
      this.m_sleepTime = 0.0;
      this.m_linearVelocity.SetZero();
      this.m_angularVelocity = 0.0;
      this.m_force.SetZero();
      this.m_torque = 0.0;
      this.NotifyChanged(false);
    }
  }

  /**
   * Get the sleeping state of this body.
   * @return true if the body is awake.
   */
  IsAwake(): boolean {
    this.PullState();
    return (this.m_flags & b2Body.e_awakeFlag) === b2Body.e_awakeFlag;
  }

  /**
   * Set the active state of the body. An inactive body is not
   * simulated and cannot be collided with or woken up.
   * If you pass a flag of true, all fixtures will be added to the
   * broad-phase.
   * If you pass a flag of false, all fixtures will be removed from
   * the broad-phase and all contacts will be destroyed.
   * Fixtures and joints are otherwise unaffected. You may continue
   * to create/destroy fixtures and joints on inactive bodies.
   * Fixtures on an inactive body are implicitly inactive and will
   * not participate in collisions, ray-casts, or queries.
   * Joints connected to an inactive body are implicitly inactive.
   * An inactive body is still owned by a b2World object and remains
   * in the body list.
   */
  SetActive(flag: boolean): void {
    checkBody(this, 'b2Body.SetActive', true);
    this.PullState();

    if (flag === this.IsActive()) {
      return;
    }

    if (flag) {
      this.m_flags |= b2Body.e_activeFlag;

      // Create all proxies.
      const broadPhase = this.m_world.m_contactManager.m_broadPhase;
      for (let f = this.m_fixtureList; f; f = f.m_next) {
        f.CreateProxies(broadPhase, this.m_xf);
      }

      // Contacts are created the next time step.
    } else {
      this.m_flags &= ~b2Body.e_activeFlag;

      // Destroy all proxies.
      const broadPhase = this.m_world.m_contactManager.m_broadPhase;
      for (let f = this.m_fixtureList; f; f = f.m_next) {
        f.DestroyProxies(broadPhase);
      }

      // Destroy the attached contacts.
      let ce = this.m_contactList;
      while (ce) {
        const ce0 = ce;
        ce = ce.next;
        this.m_world.m_contactManager.Destroy(ce0.contact);
      }
      this.m_contactList = null;
    }
    this.m_world.m_changeListener?.StructureChanged();
  }

  /** Get the active state of the body. */
  IsActive(): boolean {
    return (this.m_flags & b2Body.e_activeFlag) === b2Body.e_activeFlag;
  }

  /**
   * Set this body to have fixed rotation. This causes the mass
   * to be reset.
   */
  SetFixedRotation(flag: boolean): void {
    checkBody(this, 'b2Body.SetFixedRotation', false);
    this.PullState();
    if (flag) {
      this.m_flags |= b2Body.e_fixedRotationFlag;
    } else {
      this.m_flags &= ~b2Body.e_fixedRotationFlag;
    }

    this.ResetMassData();
    this.NotifyChanged(true);
  }

  /** Does this body have fixed rotation? */
  IsFixedRotation(): boolean {
    return (this.m_flags & b2Body.e_fixedRotationFlag) === b2Body.e_fixedRotationFlag;
  }

  /** Get the list of all fixtures attached to this body. */
  GetFixtureList(): b2Fixture | null {
    return this.m_fixtureList;
  }

  /** Get the list of all joints attached to this body. */
  GetJointList(): b2JointEdge | null {
    return this.m_jointList;
  }

  /**
   * Get the list of all contacts attached to this body.
   * @warning this list changes during the time step and you may
   * miss some collisions if you don't use b2ContactListener.
   */
  GetContactList(): b2ContactEdge | null {
    return this.m_contactList;
  }

  /** Get the next body in the world's body list. */
  GetNext(): b2Body | null {
    return this.m_next;
  }

  /** Get the user data pointer that was provided in the body definition. */
  GetUserData(): any {
    return this.m_userData;
  }

  /** Set the user data. Use this to store your application specific data. */
  SetUserData(data: any): void {
    this.m_userData = data;
  }

  /** Get the parent world of this body. */
  GetWorld(): b2World {
    return this.m_world;
  }

  /** Dump this body to a log file */
  Dump(): void {
    this.PullState();
    const bodyIndex = this.m_islandIndex;

    b2Log('{\n');
    b2Log('  b2BodyDef bd;\n');
    b2Log('  bd.type = b2BodyType(%d);\n', this.m_type);
    b2Log('  bd.position.Set(%.15lef, %.15lef);\n', this.m_xf.p.x, this.m_xf.p.y);
    b2Log('  bd.angle = %.15lef;\n', this.m_sweep.a);
    b2Log('  bd.linearVelocity.Set(%.15lef, %.15lef);\n', this.m_linearVelocity.x, this.m_linearVelocity.y);
    b2Log('  bd.angularVelocity = %.15lef;\n', this.m_angularVelocity);
    b2Log('  bd.linearDamping = %.15lef;\n', this.m_linearDamping);
    b2Log('  bd.angularDamping = %.15lef;\n', this.m_angularDamping);
    b2Log('  bd.allowSleep = bool(%d);\n', this.m_flags & b2Body.e_autoSleepFlag);
    b2Log('  bd.awake = bool(%d);\n', this.m_flags & b2Body.e_awakeFlag);
    b2Log('  bd.fixedRotation = bool(%d);\n', this.m_flags & b2Body.e_fixedRotationFlag);
    b2Log('  bd.bullet = bool(%d);\n', this.m_flags & b2Body.e_bulletFlag);
    b2Log('  bd.active = bool(%d);\n', this.m_flags & b2Body.e_activeFlag);
    b2Log('  bd.gravityScale = %.15lef;\n', this.m_gravityScale);
    b2Log('  bodies[%d] = m_world->CreateBody(&bd);\n', this.m_islandIndex);
    b2Log('\n');
    for (let f = this.m_fixtureList; f; f = f.m_next) {
      b2Log('  {\n');
      f.Dump(bodyIndex);
      b2Log('  }\n');
    }
    b2Log('}\n');
  }

  /**
   * Not in the C++: on a backend, brings this object to the last synchronisation's state if it has
   * not received it yet (m_stateEpoch); a no-op on this engine. The methods that read or change the
   * motion, the awake flag or the sleep time call it first; code reading the m_ fields directly
   * on a backend calls it too.
   */
  PullState(): void {
    if (this.m_stateEpoch !== this.m_world.m_stateEpoch) this.m_world.PullBody(this);
  }

  /** Not in the C++: tells the world's change listener (b2ChangeListener) that this body changed. */
  private NotifyChanged(motion: boolean): void {
    const listener = this.m_world.m_changeListener;
    if (listener !== null) listener.BodyChanged(this, motion);
  }

  /** Recompute the broad-phase proxies for the motion from (c0, a0) to the current transform. */
  SynchronizeFixtures(): void {
    const xf1 = s_xf1;
    xf1.q.Set(this.m_sweep.a0);
    // xf1.p = m_sweep.c0 - b2Mul(xf1.q, m_sweep.localCenter)
    const lc = this.m_sweep.localCenter;
    xf1.p.x = this.m_sweep.c0.x - (xf1.q.c * lc.x - xf1.q.s * lc.y);
    xf1.p.y = this.m_sweep.c0.y - (xf1.q.s * lc.x + xf1.q.c * lc.y);

    const broadPhase = this.m_world.m_contactManager.m_broadPhase;
    for (let f = this.m_fixtureList; f; f = f.m_next) {
      f.Synchronize(broadPhase, xf1, this.m_xf);
    }
  }

  /** Rebuild the origin transform from the sweep's current center and angle. */
  SynchronizeTransform(): void {
    const xf = this.m_xf;
    xf.q.Set(this.m_sweep.a);
    // m_xf.p = m_sweep.c - b2Mul(m_xf.q, m_sweep.localCenter)
    const lc = this.m_sweep.localCenter;
    xf.p.x = this.m_sweep.c.x - (xf.q.c * lc.x - xf.q.s * lc.y);
    xf.p.y = this.m_sweep.c.y - (xf.q.s * lc.x + xf.q.c * lc.y);
  }

  /**
   * This is used to prevent connected bodies from colliding.
   * It may lie, depending on the collideConnected flag.
   */
  ShouldCollide(other: b2Body): boolean {
    // At least one body should be dynamic.
    if (this.m_type !== b2BodyType.b2_dynamicBody && other.m_type !== b2BodyType.b2_dynamicBody) {
      return false;
    }

    // Does a joint prevent collision?
    for (let jn = this.m_jointList; jn; jn = jn.next) {
      if (jn.other === other) {
        if (jn.joint.m_collideConnected === false) {
          return false;
        }
      }
    }

    return true;
  }

  /** Advance to the new safe time. This doesn't sync the broad-phase. */
  Advance(alpha: number): void {
    b2SweepTime[0] = alpha;
    this.AdvanceAt();
  }

  /** Not in the C++: Advance to alpha = b2SweepTime[0] (see there). */
  AdvanceAt(): void {
    this.m_sweep.AdvanceAt();
    this.m_sweep.c.Assign(this.m_sweep.c0);
    this.m_sweep.a = this.m_sweep.a0;
    this.SynchronizeTransform();
  }
}
