/*
 * Not in the C++: a backend that steps a b2World somewhere else (the WebGPU backend,
 * webphysics/gpu). The engine defines the interface and never imports a backend; a backend
 * imports only types from the engine (its bundle carries no second engine), so what it must call
 * at run time is handed to it in b2WorldBackendEngine.
 *
 * The world keeps owning its bodies, fixtures and joints; the backend owns the motion between
 * synchronisations. b2World.Step delegates to Step (which may return before the step has run),
 * StepAsync and Synchronize resolve once the world shows the backend's state. A synchronisation
 * advances b2World.m_stateEpoch and keeps the state on the backend's side; each body fetches its
 * own (PullBody) when it is first read, and queries, ray casts and the debug draw fetch all (PullAll).
 */

import { b2Contact } from './contacts/b2Contact';
import type { b2Body } from './b2Body';
import type { b2Fixture } from './b2Fixture';
import type { b2World } from './b2World';
import { b2CreatePyramidWorld } from './b2PyramidWorld';
import { b2ContactFilter, b2ContactImpulse, b2ContactListener } from './b2WorldCallbacks';

/** Engine functions a backend calls at run time (it imports the engine's types only). */
export interface b2WorldBackendEngine {
  /**
   * Whether a contact listener (or, for ShouldCollide, a contact filter) has its own `method` rather
   * than b2ContactListener's empty one (b2ContactFilter's default rules): a subclass overriding it,
   * or any other object that has it.
   */
  listenerOverrides(listener: object | null, method: b2OverridableCallback): boolean;
  /** b2Contact.Create: the contact for a pair of fixture children (A/B as the registry orders them). */
  createContact(fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number): b2Contact | null;
  createImpulse(): b2ContactImpulse;
  /**
   * b2World.Step on the JavaScript engine although a backend is attached (the arguments already
   * checked by b2World.Step): for a backend that lets the engine step the world.
   */
  step(world: b2World, dt: number, velocityIterations: number, positionIterations: number): void;
  /** b2CreatePyramidWorld: a standard load for a backend to measure its step against the engine's. */
  createPyramidWorld(rows: number, copies: number): b2World;
}

export type b2OverridableCallback = 'BeginContact' | 'EndContact' | 'PreSolve' | 'PostSolve' | 'ShouldCollide';

export interface b2WorldBackend {
  /** Takes over the world's stepping (b2World.SetBackend). Throws when it cannot step this world. */
  Attach(world: b2World, engine: b2WorldBackendEngine): void;
  /**
   * Gives the world back to the JavaScript engine: waits for the steps in flight and writes the
   * backend's state into the world so that the next b2World.Step continues from it.
   */
  Detach(): Promise<void>;
  /** b2World.Step with this backend attached. */
  Step(dt: number, velocityIterations: number, positionIterations: number): void;
  /** A Step, then Synchronize. */
  StepAsync(dt: number, velocityIterations: number, positionIterations: number): Promise<void>;
  /**
   * Resolves once the world shows the state after every step taken so far: the contact events
   * delivered, and the bodies' state fetched as they are read (PullBody) after the backend advances
   * b2World.m_stateEpoch.
   */
  Synchronize(): Promise<void>;
  /** Writes the last synchronisation's motion, awake flag and sleep time into `body`. */
  PullBody(body: b2Body): void;
  /** Every body's last synchronised state, and the engine's broad-phase proxies moved to it. */
  PullAll(): void;
  /**
   * Optional, for a backend that keeps the contacts (the world's contact list stays empty): the
   * deepest penetration (m, >= 0) of the touching non-sensor contacts' manifold points at the
   * transforms after the step the last synchronisation shows, the accuracy target's measure
   * (b2AccuracyTarget.ts); null when that step measured none. Without it the accuracy target
   * cannot measure penetration on the backend.
   */
  GetPenetration?(): number | null;
  /**
   * Optional: whether the backend keeps the world's contacts now (its contact list then stays
   * empty). The engine then leaves the pairs a moved body makes to the backend: b2Body.SetTransform
   * looks for none.
   */
  KeepsContacts?(): boolean;
}

function listenerOverrides(listener: object | null, method: b2OverridableCallback): boolean {
  if (listener === null) return false;
  const own = (listener as Record<string, unknown>)[method];
  const base = method === 'ShouldCollide' ? b2ContactFilter.prototype.ShouldCollide : b2ContactListener.prototype[method];
  return typeof own === 'function' && own !== base;
}

export const b2WorldBackendEngineFunctions: b2WorldBackendEngine = {
  listenerOverrides,
  createContact: (fixtureA, indexA, fixtureB, indexB) => b2Contact.Create(fixtureA, indexA, fixtureB, indexB),
  createImpulse: () => new b2ContactImpulse(),
  step: (world, dt, velocityIterations, positionIterations) => {
    world.m_engineStepsOnBackend++;
    world.StepOnEngine(dt, velocityIterations, positionIterations);
  },
  createPyramidWorld: (rows, copies) => b2CreatePyramidWorld(rows, copies),
};
