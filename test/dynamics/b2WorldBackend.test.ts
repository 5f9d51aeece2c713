/*
 * The backend hooks of b2World (SetBackend, GetBackend, StepAsync, Synchronize, the branch in
 * Step, the state fetched as it is read) with the JavaScript engine and with recording stand-in
 * backends, and the engine functions handed to a backend (b2WorldBackendEngine).
 */

import { describe, expect, it } from 'vitest';
import { b2AABB } from '../../src/collision/b2Collision';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2BodyDef, b2BodyType } from '../../src/dynamics/b2Body';
import type { b2Body } from '../../src/dynamics/b2Body';
import { b2World } from '../../src/dynamics/b2World';
import { b2WorldBackendEngineFunctions } from '../../src/dynamics/b2WorldBackend';
import type { b2WorldBackend, b2WorldBackendEngine } from '../../src/dynamics/b2WorldBackend';
import { b2ContactFilter, b2ContactImpulse, b2ContactListener } from '../../src/dynamics/b2WorldCallbacks';
import { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { b2RevoluteJoint, b2RevoluteJointDef } from '../../src/dynamics/joints/b2RevoluteJoint';
import { Box2D } from '../../src/index';

const h = 1 / 60;

function scene(): { world: b2World; ground: b2Body; box: b2Body } {
  const world = new b2World(new b2Vec2(0, -10));
  const ground = world.CreateBody(new b2BodyDef());
  const g = new b2PolygonShape();
  g.SetAsBox(10, 1, new b2Vec2(0, -1), 0);
  ground.CreateFixture(g, 0);
  const def = new b2BodyDef();
  def.type = b2BodyType.b2_dynamicBody;
  def.position.Set(0.3, 2);
  def.angle = 0.4;
  const box = world.CreateBody(def);
  const s = new b2PolygonShape();
  s.SetAsBox(0.5, 0.5);
  box.CreateFixture(s, 1);
  return { world, ground, box };
}

/** Records what the world asks of it; Detach resolves when `release` is called. */
class StandIn implements b2WorldBackend {
  readonly calls: string[] = [];
  world: b2World | null = null;
  engine: b2WorldBackendEngine | null = null;
  release: () => void = () => undefined;
  refuse = false;

  Attach(world: b2World, engine: b2WorldBackendEngine): void {
    if (this.refuse) throw new Error('cannot step this world');
    this.world = world;
    this.engine = engine;
    this.calls.push('Attach');
  }
  Detach(): Promise<void> {
    this.calls.push('Detach');
    return new Promise((resolve) => {
      this.release = resolve;
    });
  }
  Step(dt: number, vi: number, pi: number): void {
    this.calls.push(`Step ${dt} ${vi} ${pi}`);
  }
  async StepAsync(dt: number, vi: number, pi: number): Promise<void> {
    this.calls.push(`StepAsync ${dt} ${vi} ${pi}`);
  }
  async Synchronize(): Promise<void> {
    this.calls.push('Synchronize');
  }
  PullBody(body: b2Body): void {
    this.calls.push('PullBody');
  }
  PullAll(): void {
    this.calls.push('PullAll');
  }
}

/**
 * A backend whose synchronisations move every body up by 1 m: it keeps the state on its side and
 * advances the world's epoch, as the WebGPU backend does; records what the world pulls.
 */
class Lifting extends StandIn {
  readonly pulled: b2Body[] = [];
  pulls = 0;
  private readonly lift = new Map<b2Body, number>();

  override async Synchronize(): Promise<void> {
    await super.Synchronize();
    for (let b = this.world!.GetBodyList(); b !== null; b = b.GetNext()) this.lift.set(b, (this.lift.get(b) ?? 0) + 1);
    this.world!.m_stateEpoch++;
  }
  override PullBody(body: b2Body): void {
    this.pulled.push(body);
    body.m_xf.p.y = body.m_sweep.c.y = 100 + (this.lift.get(body) ?? 0);
  }
  override PullAll(): void {
    this.pulls++;
    for (let b = this.world!.GetBodyList(); b !== null; b = b.GetNext()) b.PullState();
  }
}

describe('b2World backend hooks', () => {
  it('on the JavaScript engine: StepAsync is Step (the same bits), Synchronize resolves, GetBackend is null', async () => {
    const a = scene();
    const b = scene();
    for (let i = 0; i < 90; ++i) {
      a.world.Step(h, 8, 3);
      await b.world.StepAsync(h, 8, 3);
      await b.world.Synchronize();
    }
    expect(b.box.GetPosition().x).toBe(a.box.GetPosition().x);
    expect(b.box.GetPosition().y).toBe(a.box.GetPosition().y);
    expect(b.box.GetAngle()).toBe(a.box.GetAngle());
    expect(b.world.GetBackend()).toBeNull();
    await expect(b.world.StepAsync(-1, 8, 3)).rejects.toThrow(/dt/);
  });

  it('with a backend: Step, StepAsync and Synchronize go to it and the engine does not step; SetBackend(null) awaits Detach', async () => {
    const { world, box } = scene();
    const backend = new StandIn();
    await world.SetBackend(backend);
    expect(world.GetBackend()).toBe(backend);
    expect(backend.world).toBe(world);
    expect(backend.engine).toBe(b2WorldBackendEngineFunctions);
    const y = box.GetPosition().y;
    world.Step(h, 8, 3);
    await world.StepAsync(h, 6, 2);
    await world.Synchronize();
    expect(backend.calls).toEqual(['Attach', `Step ${h} 8 3`, `StepAsync ${h} 6 2`, 'Synchronize']);
    expect(box.GetPosition().y).toBe(y);
    // Arguments are still checked by the world.
    expect(() => world.Step(Number.NaN, 8, 3)).toThrow(/dt/);

    let detached = false;
    const detach = world.SetBackend(null).then(() => {
      detached = true;
    });
    await Promise.resolve();
    expect(backend.calls.at(-1)).toBe('Detach');
    expect(detached).toBe(false);
    // A second switch while one is in progress is refused.
    await expect(world.SetBackend(new StandIn())).rejects.toThrow(/switch is in progress/);
    backend.release();
    await detach;
    expect(world.GetBackend()).toBeNull();
    world.Step(h, 8, 3);
    expect(box.GetPosition().y).toBeLessThan(y);
  });

  it('a backend that refuses the world is not attached; SetBackend is refused inside a callback', async () => {
    const { world } = scene();
    const backend = new StandIn();
    backend.refuse = true;
    await expect(world.SetBackend(backend)).rejects.toThrow(/cannot step this world/);
    expect(world.GetBackend()).toBeNull();
    let inside: Promise<void> | null = null;
    class Listener extends b2ContactListener {
      override BeginContact(): void {
        inside ??= world.SetBackend(new StandIn());
      }
    }
    world.SetContactListener(new Listener());
    for (let i = 0; i < 120 && inside === null; ++i) world.Step(h, 8, 3);
    expect(inside).not.toBeNull();
    await expect(inside!).rejects.toThrow(/SetBackend/);
    expect(world.GetBackend()).toBeNull();
  });
});

describe('state fetched as it is read, on a backend that keeps it (b2World.m_stateEpoch)', () => {
  it('a synchronisation moves no body; each body fetches its state when one of its methods first reads it, once per synchronisation', async () => {
    const { world, ground, box } = scene();
    const backend = new Lifting();
    await world.SetBackend(backend);
    await world.Synchronize();
    expect(backend.pulled).toEqual([]);
    expect(box.GetPosition().y).toBe(101);
    expect(box.GetWorldCenter().y).toBe(101);
    expect(box.IsAwake()).toBe(true);
    expect(backend.pulled).toEqual([box]);
    await world.Synchronize();
    await world.Synchronize();
    // Two synchronisations later, one fetch brings the latest state; the ground was never read.
    expect(box.GetLinearVelocity().x).toBe(0);
    expect(box.GetPosition().y).toBe(103);
    expect(backend.pulled).toEqual([box, box]);
    expect(backend.pulled).not.toContain(ground);
    // A body created after a synchronisation has its own state already.
    const def = new b2BodyDef();
    def.position.Set(5, 5);
    const fresh = world.CreateBody(def);
    expect(fresh.GetPosition().y).toBe(5);
    expect(backend.pulled).toHaveLength(2);
  });

  it('a setter fetches first, so the value it sets is not overwritten by a later fetch of the same state', async () => {
    const { world, box } = scene();
    const backend = new Lifting();
    await world.SetBackend(backend);
    await world.Synchronize();
    box.SetLinearVelocity(new b2Vec2(3, 0));
    expect(backend.pulled).toEqual([box]);
    expect(box.GetPosition().y).toBe(101);
    expect(box.GetLinearVelocity().x).toBe(3);
    expect(backend.pulled).toEqual([box]);
  });

  it("queries, ray casts, the debug draw and fixtures' AABBs fetch every body first (PullAll); joint getters fetch their bodies", async () => {
    const { world, box } = scene();
    const backend = new Lifting();
    await world.SetBackend(backend);
    await world.Synchronize();
    const aabb = new b2AABB();
    aabb.lowerBound.Set(-1, -1);
    aabb.upperBound.Set(1, 1);
    world.QueryAABB({ ReportFixture: () => true }, aabb);
    expect(backend.pulls).toBe(1);
    world.RayCast({ ReportFixture: () => 1 }, new b2Vec2(0, 5), new b2Vec2(0, -5));
    box.GetFixtureList()!.GetAABB(0);
    expect(backend.pulls).toBe(3);
    expect(backend.pulled).toHaveLength(2); // both bodies, once
    await world.Synchronize();
    const jd = new b2RevoluteJointDef();
    jd.bodyA = world.GetBodyList()!.GetNext()!;
    jd.bodyB = box;
    jd.collideConnected = false;
    const joint = world.CreateJoint(jd) as b2RevoluteJoint;
    backend.pulled.length = 0;
    await world.Synchronize();
    joint.GetJointAngle();
    expect(new Set(backend.pulled)).toEqual(new Set([box, jd.bodyA]));
  });

  it('on the JavaScript engine the epoch never moves and nothing is fetched: the golden bits stay (see the golden suites)', () => {
    const { world, box } = scene();
    for (let i = 0; i < 30; ++i) world.Step(h, 8, 3);
    expect(world.m_stateEpoch).toBe(0);
    expect(box.m_stateEpoch).toBe(0);
  });
});

describe('the Box2DWeb 2.1a API', () => {
  it('a 2.1a world (new b2World(gravity, doSleep)) has the same hooks: Step goes to the backend', async () => {
    const world = new Box2D.Dynamics.b2World(new Box2D.Common.Math.b2Vec2(0, 10), true);
    const backend = new StandIn();
    await world.SetBackend(backend);
    world.Step(h, 10, 10);
    await world.StepAsync(h, 10, 10);
    await world.Synchronize();
    const detach = world.SetBackend(null);
    backend.release();
    await detach;
    expect(backend.calls).toEqual(['Attach', `Step ${h} 10 10`, `StepAsync ${h} 10 10`, 'Synchronize', 'Detach']);
    expect(world.GetBackend()).toBeNull();
  });
});

describe('b2WorldBackendEngine', () => {
  const engine = b2WorldBackendEngineFunctions;

  it('listenerOverrides: a subclass method or any object with the method counts, the base classes do not', () => {
    expect(engine.listenerOverrides(null, 'PreSolve')).toBe(false);
    expect(engine.listenerOverrides(new b2ContactListener(), 'PreSolve')).toBe(false);
    class Begin extends b2ContactListener {
      override BeginContact(): void {}
    }
    expect(engine.listenerOverrides(new Begin(), 'BeginContact')).toBe(true);
    expect(engine.listenerOverrides(new Begin(), 'PreSolve')).toBe(false);
    expect(engine.listenerOverrides({ PreSolve() {} }, 'PreSolve')).toBe(true);
    expect(engine.listenerOverrides({ BeginContact() {} }, 'PostSolve')).toBe(false);
    expect(engine.listenerOverrides(new b2ContactFilter(), 'ShouldCollide')).toBe(false);
    class Filter extends b2ContactFilter {
      override ShouldCollide(): boolean {
        return false;
      }
    }
    expect(engine.listenerOverrides(new Filter(), 'ShouldCollide')).toBe(true);
  });

  it('createContact is b2Contact.Create (the registry orders A and B); createImpulse makes a b2ContactImpulse', () => {
    const { ground, box } = scene();
    const c = engine.createContact(box.GetFixtureList()!, 0, ground.GetFixtureList()!, 0);
    expect(c).toBeInstanceOf(b2Contact);
    expect(c!.GetFixtureA()).toBe(box.GetFixtureList());
    expect(c!.GetFixtureB()).toBe(ground.GetFixtureList());
    expect(c!.IsTouching()).toBe(false);
    expect(engine.createImpulse()).toBeInstanceOf(b2ContactImpulse);
  });
});
