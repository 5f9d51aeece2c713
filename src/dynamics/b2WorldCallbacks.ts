/*
 * World callbacks (b2WorldCallbacks.h, b2WorldCallbacks.cpp). Subclass these, or pass any object
 * with the same methods.
 */

import type { b2Manifold } from '../collision/b2Collision';
import type { b2Vec2 } from '../common/b2Math';
import { b2_maxManifoldPoints } from '../common/b2Settings';
import type { b2Contact } from './contacts/b2Contact';
import type { b2Body } from './b2Body';
import type { b2Fixture } from './b2Fixture';
import type { b2Joint } from './joints/b2Joint';

/**
 * Joints and fixtures are destroyed when their associated body is destroyed. Implement this
 * listener so that you may nullify references to these joints and shapes.
 *
 * The C++ overloads SayGoodbye on the argument type; here the two have distinct names.
 */
export abstract class b2DestructionListener {
  /** Called when any joint is about to be destroyed due to the destruction of one of its attached bodies. */
  abstract SayGoodbyeJoint(joint: b2Joint): void;

  /** Called when any fixture is about to be destroyed due to the destruction of its parent body. */
  abstract SayGoodbyeFixture(fixture: b2Fixture): void;
}

/**
 * Implement this class to provide collision filtering. In other words, you can implement this
 * class if you want finer control over contact creation.
 */
export class b2ContactFilter {
  /**
   * Return true if contact calculations should be performed between these two shapes.
   * If you implement your own collision filter you may want to build from this implementation.
   * @warning for performance reasons this is only called when the AABBs begin to overlap.
   */
  ShouldCollide(fixtureA: b2Fixture, fixtureB: b2Fixture): boolean {
    const filterA = fixtureA.GetFilterData();
    const filterB = fixtureB.GetFilterData();

    if (filterA.groupIndex === filterB.groupIndex && filterA.groupIndex !== 0) {
      return filterA.groupIndex > 0;
    }

    const collide = (filterA.maskBits & filterB.categoryBits) !== 0 && (filterA.categoryBits & filterB.maskBits) !== 0;
    return collide;
  }
}

/** A packed (not holey) array of n zeros. */
function zeros(n: number): number[] {
  const a: number[] = [];
  for (let i = 0; i < n; ++i) a.push(0.0);
  return a;
}

/**
 * Contact impulses for reporting. Impulses are used instead of forces because sub-step forces
 * may approach infinity for rigid body collisions. These match up one-to-one with the contact
 * points in b2Manifold.
 */
export class b2ContactImpulse {
  readonly normalImpulses: number[] = zeros(b2_maxManifoldPoints);
  readonly tangentImpulses: number[] = zeros(b2_maxManifoldPoints);
  count = 0;

  Clone(): b2ContactImpulse {
    return new b2ContactImpulse().Assign(this);
  }

  Assign(impulse: Readonly<b2ContactImpulse>): this {
    for (let i = 0; i < b2_maxManifoldPoints; ++i) {
      this.normalImpulses[i] = impulse.normalImpulses[i];
      this.tangentImpulses[i] = impulse.tangentImpulses[i];
    }
    this.count = impulse.count;
    return this;
  }
}

/**
 * Implement this class to get contact information. You can use these results for things like
 * sounds and game logic. You can also get contact results by traversing the contact lists after
 * the time step. However, you might miss some contacts because continuous physics leads to
 * sub-stepping. Additionally you may receive multiple callbacks for the same contact in a single
 * time step. You should strive to make your callbacks efficient because there may be many
 * callbacks per time step.
 * @warning You cannot create/destroy Box2D entities inside these callbacks.
 */
export class b2ContactListener {
  /** Called when two fixtures begin to touch. */
  BeginContact(contact: b2Contact): void {}

  /** Called when two fixtures cease to touch. */
  EndContact(contact: b2Contact): void {}

  /**
   * This is called after a contact is updated. This allows you to inspect a contact before it
   * goes to the solver. If you are careful, you can modify the contact manifold (e.g. disable
   * contact). A copy of the old manifold is provided so that you can detect changes.
   * Note: this is called only for awake bodies.
   * Note: this is called even when the number of contact points is zero.
   * Note: this is not called for sensors.
   * Note: if you set the number of contact points to zero, you will not get an EndContact
   * callback. However, you may get a BeginContact callback the next step.
   */
  PreSolve(contact: b2Contact, oldManifold: b2Manifold): void {}

  /**
   * This lets you inspect a contact after the solver is finished. This is useful for inspecting
   * impulses.
   * Note: the contact manifold does not include time of impact impulses, which can be
   * arbitrarily large if the sub-step is small. Hence the impulse is provided explicitly in a
   * separate data structure.
   * Note: this is only called for contacts that are touching, solid, and awake.
   */
  PostSolve(contact: b2Contact, impulse: b2ContactImpulse): void {}
}

/**
 * Not in Box2D 2.2.1: told when the API changes the world's objects, so that a copy of the world
 * kept elsewhere (the WebGPU backend's mirror) can update only what changed instead of comparing
 * every object each step. Register with b2World.SetChangeListener. Only the API is observed:
 * writing m_ fields directly is not reported, and joints report nothing (a mirror reads them all).
 */
export class b2ChangeListener {
  /**
   * A body's state was set through the API. `motion`: its transform, velocities or centre of mass
   * (SetTransform, SetLinearVelocity, impulses, SetMassData...), not only its forces, damping,
   * flags or awake state.
   */
  BodyChanged(body: b2Body, motion: boolean): void {}

  /**
   * The API asked for a body to be awake: SetAwake(true), or a call that wakes it in 2.2.1 (a
   * force, an impulse, a velocity, a joint's motor or target). Told even when the body's flag
   * already says awake: a copy of the world may have put it to sleep since the flag was read.
   */
  BodyWoken(body: b2Body): void {}

  /** A fixture's sensor flag, filter or material was set. */
  FixtureChanged(fixture: b2Fixture): void {}

  /** A body, fixture or joint was created or destroyed, a body's type or active state was set. */
  StructureChanged(): void {}
}

/** Callback class for AABB queries. See b2World.QueryAABB. */
export abstract class b2QueryCallback {
  /**
   * Called for each fixture found in the query AABB.
   * @return false to terminate the query.
   */
  abstract ReportFixture(fixture: b2Fixture): boolean;
}

/** Callback class for ray casts. See b2World.RayCast. */
export abstract class b2RayCastCallback {
  /**
   * Called for each fixture found in the query. You control how the ray cast proceeds by
   * returning a float:
   * return -1: ignore this fixture and continue
   * return 0: terminate the ray cast
   * return fraction: clip the ray to this point
   * return 1: don't clip the ray and continue
   * @param fixture the fixture hit by the ray
   * @param point the point of initial intersection
   * @param normal the normal vector at the point of intersection
   * @return -1 to filter, 0 to terminate, fraction to clip the ray for closest hit, 1 to continue
   */
  abstract ReportFixture(fixture: b2Fixture, point: b2Vec2, normal: b2Vec2, fraction: number): number;
}
