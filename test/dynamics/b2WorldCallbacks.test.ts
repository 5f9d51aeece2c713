/*
 * When and how the world calls the user callbacks of b2WorldCallbacks.h during b2World.Step and
 * b2World.DestroyBody, as Box2D 2.2.1 does:
 * - b2ContactListener: BeginContact, PreSolve and EndContact come from b2Contact::Update in the
 *   collide phase; PostSolve comes from b2Island::Report after the island's solver stored the
 *   impulses. Sensors get Begin/End only. A contact disabled in PreSolve is not solved that step.
 * - b2ContactFilter: consulted before a contact is created; a rejected pair never gets one.
 * - b2DestructionListener: DestroyBody says goodbye to each joint, then ends the body's contacts,
 *   then says goodbye to each fixture.
 * - Every listener callback runs inside the locked step.
 */

import { describe, expect, it } from 'vitest';
import type { b2Manifold } from '../../src/collision/b2Collision';
import { b2CircleShape } from '../../src/collision/shapes/b2CircleShape';
import { b2PolygonShape } from '../../src/collision/shapes/b2PolygonShape';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2_linearSlop, b2_polygonRadius } from '../../src/common/b2Settings';
import { b2Body, b2BodyDef, b2BodyType } from '../../src/dynamics/b2Body';
import { b2Fixture, b2FixtureDef } from '../../src/dynamics/b2Fixture';
import { b2World } from '../../src/dynamics/b2World';
import { b2ContactFilter, b2ContactImpulse, b2ContactListener, b2DestructionListener } from '../../src/dynamics/b2WorldCallbacks';
import { b2Contact } from '../../src/dynamics/contacts/b2Contact';
import { b2DistanceJointDef } from '../../src/dynamics/joints/b2DistanceJoint';
import type { b2Joint } from '../../src/dynamics/joints/b2Joint';

const h = 1.0 / 60.0;

function createBody(world: b2World, type: b2BodyType, x: number, y: number, userData: any = null): b2Body {
  const bd = new b2BodyDef();
  bd.type = type;
  bd.position.Set(x, y);
  bd.userData = userData;
  return world.CreateBody(bd);
}

function addBox(body: b2Body, hx: number, hy: number, density: number, isSensor = false): b2Fixture {
  const fd = new b2FixtureDef();
  fd.shape = new b2PolygonShape().SetAsBox(hx, hy);
  fd.density = density;
  fd.isSensor = isSensor;
  return body.CreateFixture(fd);
}

function addCircle(body: b2Body, radius: number, density: number, isSensor = false): b2Fixture {
  const shape = new b2CircleShape();
  shape.m_radius = radius;
  const fd = new b2FixtureDef();
  fd.shape = shape;
  fd.density = density;
  fd.isSensor = isSensor;
  return body.CreateFixture(fd);
}

/** Where a 1 x 1 box rests on a surface at y = top: the two skins overlap by the linear slop. */
function restingY(top: number): number {
  return top + 0.5 + 2.0 * b2_polygonRadius - b2_linearSlop;
}

/** A static 10 x 1 ground (top at y = 0.5) and a 1 x 1 box of mass 1 already at rest on it. */
function boxOnGround(): { world: b2World; ground: b2Body; box: b2Body } {
  const world = new b2World(new b2Vec2(0.0, -10.0));
  const ground = createBody(world, b2BodyType.b2_staticBody, 0.0, 0.0, 'ground');
  addBox(ground, 5.0, 0.5, 0.0);
  const box = createBody(world, b2BodyType.b2_dynamicBody, 0.0, restingY(0.5), 'box');
  addBox(box, 0.5, 0.5, 1.0);
  return { world, ground, box };
}

function bodyNames(contact: b2Contact): string {
  return [contact.GetFixtureA().GetBody().GetUserData(), contact.GetFixtureB().GetBody().GetUserData()].sort().join('-');
}

interface Event {
  step: number;
  kind: 'BeginContact' | 'PreSolve' | 'PostSolve' | 'EndContact';
  pair: string;
  touching: boolean;
  /** PreSolve: the old manifold's point count and normal impulses. */
  oldCount?: number;
  oldImpulses?: number[];
  /** PreSolve: the new manifold's point count. */
  newCount?: number;
  /** PostSolve: the reported count and normal impulses, and the manifold's stored impulses. */
  count?: number;
  impulses?: number[];
  stored?: number[];
}

/** Records every contact callback with the step it happened in. */
class Recorder extends b2ContactListener {
  readonly events: Event[] = [];
  step = 0;

  override BeginContact(contact: b2Contact): void {
    this.events.push({ step: this.step, kind: 'BeginContact', pair: bodyNames(contact), touching: contact.IsTouching() });
  }

  override EndContact(contact: b2Contact): void {
    this.events.push({ step: this.step, kind: 'EndContact', pair: bodyNames(contact), touching: contact.IsTouching() });
  }

  override PreSolve(contact: b2Contact, oldManifold: b2Manifold): void {
    this.events.push({
      step: this.step,
      kind: 'PreSolve',
      pair: bodyNames(contact),
      touching: contact.IsTouching(),
      oldCount: oldManifold.pointCount,
      oldImpulses: oldManifold.points.slice(0, oldManifold.pointCount).map((p) => p.normalImpulse),
      newCount: contact.GetManifold().pointCount,
    });
  }

  override PostSolve(contact: b2Contact, impulse: b2ContactImpulse): void {
    const manifold = contact.GetManifold();
    this.events.push({
      step: this.step,
      kind: 'PostSolve',
      pair: bodyNames(contact),
      touching: contact.IsTouching(),
      count: impulse.count,
      impulses: impulse.normalImpulses.slice(0, impulse.count),
      stored: manifold.points.slice(0, manifold.pointCount).map((p) => p.normalImpulse),
    });
  }

  kindsAt(step: number): string[] {
    return this.events.filter((e) => e.step === step).map((e) => e.kind);
  }
}

function run(world: b2World, recorder: Recorder, steps: number, before?: (step: number) => void, after?: (step: number) => void): void {
  for (let k = 1; k <= steps; ++k) {
    recorder.step = k;
    before?.(k);
    world.Step(h, 8, 3);
    after?.(k);
  }
}

describe('b2ContactListener order during Step', () => {
  it('fires BeginContact then PreSolve before solving, PostSolve after it, every touching step, then EndContact', () => {
    const { world, box } = boxOnGround();
    const recorder = new Recorder();
    world.SetContactListener(recorder);
    // The box rests for 7 steps, is thrown up before step 8 and has left the ground by step 9.
    run(world, recorder, 12, (k) => {
      if (k === 8) box.SetLinearVelocity(new b2Vec2(0.0, 3.0));
    });

    expect(recorder.kindsAt(1)).toEqual(['BeginContact', 'PreSolve', 'PostSolve']);
    for (let k = 2; k <= 8; ++k) expect(recorder.kindsAt(k)).toEqual(['PreSolve', 'PostSolve']);
    expect(recorder.kindsAt(9)).toEqual(['EndContact']);
    for (let k = 10; k <= 12; ++k) expect(recorder.kindsAt(k)).toEqual([]);
    for (const e of recorder.events) expect(e.pair).toBe('box-ground');

    // Touching in Begin, PreSolve and PostSolve; no longer touching in EndContact.
    expect(recorder.events.filter((e) => e.kind !== 'EndContact').every((e) => e.touching)).toBe(true);
    expect(recorder.events.find((e) => e.kind === 'EndContact')!.touching).toBe(false);

    const pre = recorder.events.filter((e) => e.kind === 'PreSolve');
    const post = recorder.events.filter((e) => e.kind === 'PostSolve');
    // The first PreSolve sees the empty manifold the contact had before it began touching.
    expect([pre[0].oldCount, pre[0].newCount]).toEqual([0, 2]);
    for (let i = 1; i < pre.length; ++i) {
      // The old manifold is the one the previous step's solver left: its stored impulses.
      expect(pre[i].oldCount).toBe(2);
      expect(pre[i].oldImpulses).toEqual(post[i - 1].impulses);
    }
    for (const e of post) {
      // Reported after StoreImpulses: the impulses are those in the manifold.
      expect(e.count).toBe(2);
      expect(e.impulses).toEqual(e.stored);
    }
    // At rest the two points carry the weight m g h between them; thrown up, the solver clamps
    // both accumulated impulses to zero.
    for (const e of post.slice(0, 7)) {
      expect(e.impulses![0]).toBeGreaterThan(0.0);
      expect(e.impulses![1]).toBeGreaterThan(0.0);
      expect(e.impulses![0] + e.impulses![1]).toBeCloseTo(box.GetMass() * 10.0 * h, 12);
    }
    expect(post[7].impulses).toEqual([0.0, 0.0]);
  });

  it('reports a sensor only by BeginContact as a body enters it and EndContact as it leaves, never solving it', () => {
    const world = new b2World(new b2Vec2(0.0, 0.0));
    const sensorBody = createBody(world, b2BodyType.b2_staticBody, 0.0, 0.0, 'sensor');
    const R = 1.0;
    addCircle(sensorBody, R, 0.0, true);
    const r = 0.25;
    const ball = createBody(world, b2BodyType.b2_dynamicBody, -3.0, 0.0, 'ball');
    addCircle(ball, r, 1.0);
    ball.SetLinearVelocity(new b2Vec2(6.0, 0.0));

    const recorder = new Recorder();
    world.SetContactListener(recorder);
    const xBefore: number[] = [];
    const touching: boolean[] = [];
    run(
      world,
      recorder,
      60,
      () => xBefore.push(ball.GetPosition().x),
      () => {
        const c = world.GetContactList();
        touching.push(c !== null && c.IsTouching());
        if (c !== null) {
          expect(c.GetManifold().pointCount).toBe(0);
          // Never added to an island, so never given to the contact solver.
          expect(c.m_flags & b2Contact.e_islandFlag).toBe(0);
        }
      },
    );

    // The contact updates at the start of a step from the positions the previous step left:
    // it begins in the first step that starts with the ball overlapping the sensor (x = -1.2, in
    // step 19) and ends in the first that starts with it clear again (x = 1.3, in step 44).
    const overlaps = xBefore.map((x) => Math.abs(x) < R + r);
    const enter = overlaps.indexOf(true) + 1;
    const leave = overlaps.indexOf(false, enter) + 1;
    expect([enter, leave]).toEqual([19, 44]);
    expect(recorder.events.map((e) => [e.step, e.kind, e.pair])).toEqual([
      [enter, 'BeginContact', 'ball-sensor'],
      [leave, 'EndContact', 'ball-sensor'],
    ]);
    expect(touching.map((t, i) => t === (i + 1 >= enter && i + 1 < leave))).not.toContain(false);

    // The sensor never pushed the ball.
    expect(ball.GetLinearVelocity()).toEqual(new b2Vec2(6.0, 0.0));
    expect(ball.GetPosition().y).toBe(0.0);
    expect(ball.GetAngularVelocity()).toBe(0.0);
  });

  it('skips the solver for a contact disabled in PreSolve, for that step only', () => {
    const { world, box } = boxOnGround();
    let disableAt = 4;
    const recorder = new (class extends Recorder {
      override PreSolve(contact: b2Contact, oldManifold: b2Manifold): void {
        super.PreSolve(contact, oldManifold);
        if (this.step === disableAt) contact.SetEnabled(false);
      }
    })();
    world.SetContactListener(recorder);
    const vy: number[] = [0.0];
    const enabled: boolean[] = [];
    run(world, recorder, 6, undefined, () => {
      vy.push(box.GetLinearVelocity().y);
      enabled.push(world.GetContactList()!.IsEnabled());
    });

    expect(recorder.kindsAt(3)).toEqual(['PreSolve', 'PostSolve']);
    expect(recorder.kindsAt(4)).toEqual(['PreSolve']);
    expect(recorder.kindsAt(5)).toEqual(['PreSolve', 'PostSolve']);
    // Disabled until the next Update re-enables it.
    expect(enabled).toEqual([true, true, true, false, true, true]);
    // In step 4 the box is in free fall: only gravity changes its velocity.
    expect(Object.is(vy[4], vy[3] + h * (1.0 * -10.0 + box.m_invMass * 0.0))).toBe(true);
    expect(vy[4]).toBeLessThan(-0.16);
    // Step 5 solves the contact again and stops the fall.
    expect(vy[5]).toBeGreaterThan(vy[4]);
    disableAt = -1;
  });

  it('calls PostSolve once per touching solid contact of each awake island, and never for sleeping islands', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    world.SetAllowSleeping(false);
    const ground = createBody(world, b2BodyType.b2_staticBody, 0.0, 0.0, 'ground');
    addBox(ground, 10.0, 0.5, 0.0);
    // Island 1: a stack of two boxes. Island 2: one box, with a static sensor overlapping it.
    const box1 = createBody(world, b2BodyType.b2_dynamicBody, 0.0, restingY(0.5), 'box1');
    addBox(box1, 0.5, 0.5, 1.0);
    const box2 = createBody(world, b2BodyType.b2_dynamicBody, 0.0, restingY(restingY(0.5) + 0.5), 'box2');
    addBox(box2, 0.5, 0.5, 1.0);
    const box3 = createBody(world, b2BodyType.b2_dynamicBody, 5.0, restingY(0.5), 'box3');
    addBox(box3, 0.5, 0.5, 1.0);
    const sensor = createBody(world, b2BodyType.b2_staticBody, 5.0, 1.0, 'sensor');
    addCircle(sensor, 1.0, 0.0, true);

    const recorder = new Recorder();
    world.SetContactListener(recorder);
    run(world, recorder, 120);

    expect(world.GetContactCount()).toBe(4);
    for (let k = 1; k <= 120; ++k) {
      const posts = recorder.events.filter((e) => e.step === k && e.kind === 'PostSolve');
      expect(posts.map((e) => e.pair).sort()).toEqual(['box1-box2', 'box1-ground', 'box3-ground']);
      for (const e of posts) {
        expect(e.count).toBe(2);
        for (const impulse of e.impulses!) expect(impulse).toBeGreaterThanOrEqual(0.0);
      }
    }
    // Settled: each contact carries the weight of everything above it over one step.
    const last = (pair: string) => recorder.events.filter((e) => e.step === 120 && e.pair === pair && e.kind === 'PostSolve')[0].impulses!;
    const sum = (a: number[]) => a[0] + a[1];
    expect(sum(last('box1-box2'))).toBeCloseTo(1.0 * 10.0 * h, 6);
    expect(sum(last('box1-ground'))).toBeCloseTo(2.0 * 10.0 * h, 6);
    expect(sum(last('box3-ground'))).toBeCloseTo(1.0 * 10.0 * h, 6);
    expect(recorder.events.filter((e) => e.pair.includes('sensor')).map((e) => e.kind)).toEqual(['BeginContact']);

    // Let both islands fall asleep: then nothing is reported.
    world.SetAllowSleeping(true);
    let k = 120;
    while (box1.IsAwake() || box2.IsAwake() || box3.IsAwake()) {
      expect(k).toBeLessThan(400);
      recorder.step = ++k;
      world.Step(h, 8, 3);
    }
    recorder.events.length = 0;
    run(world, recorder, 3);
    expect(recorder.events).toEqual([]);

    // Waking one body wakes only its island.
    box3.SetAwake(true);
    recorder.step = 1;
    world.Step(h, 8, 3);
    expect(recorder.events.filter((e) => e.kind === 'PostSolve').map((e) => e.pair)).toEqual(['box3-ground']);
    expect([box1.IsAwake(), box2.IsAwake()]).toEqual([false, false]);
  });
});

describe('b2ContactFilter', () => {
  it('a custom filter rejecting one pair lets those bodies pass through each other while the others collide', () => {
    const world = new b2World(new b2Vec2(0.0, -10.0));
    const ground = createBody(world, b2BodyType.b2_staticBody, 0.0, 0.0, 'ground');
    const groundFixture = addBox(ground, 10.0, 0.5, 0.0);
    const ghost = createBody(world, b2BodyType.b2_dynamicBody, -2.0, 3.0, 'ghost');
    const ghostFixture = addCircle(ghost, 0.5, 1.0);
    const solid = createBody(world, b2BodyType.b2_dynamicBody, 2.0, 3.0, 'solid');
    addCircle(solid, 0.5, 1.0);

    const asked: string[] = [];
    class GhostFilter extends b2ContactFilter {
      override ShouldCollide(fixtureA: b2Fixture, fixtureB: b2Fixture): boolean {
        expect(fixtureA).toBeInstanceOf(b2Fixture);
        expect(fixtureB).toBeInstanceOf(b2Fixture);
        asked.push([fixtureA.GetBody().GetUserData(), fixtureB.GetBody().GetUserData()].sort().join('-'));
        const pair = [fixtureA, fixtureB];
        if (pair.includes(ghostFixture) && pair.includes(groundFixture)) return false;
        return super.ShouldCollide(fixtureA, fixtureB);
      }
    }
    world.SetContactFilter(new GhostFilter());

    for (let k = 0; k < 120; ++k) {
      world.Step(h, 8, 3);
      for (let c = world.GetContactList(); c; c = c.GetNext()) {
        expect(bodyNames(c)).toBe('ground-solid');
      }
    }

    expect(asked).toContain('ghost-ground');
    expect(asked).toContain('ground-solid');
    // The ghost fell through the ground; the solid ball rests on it.
    expect(ghost.GetPosition().y).toBeLessThan(-5.0);
    expect(solid.GetPosition().y).toBeCloseTo(0.5 + 0.5 + b2_polygonRadius - b2_linearSlop, 6);
    expect(world.GetContactCount()).toBe(1);
  });
});

describe('b2DestructionListener', () => {
  it('DestroyBody says goodbye to each joint while it is still in the world, ends the touching contacts, then says goodbye to each fixture', () => {
    const { world, ground, box } = boxOnGround();
    const fixture = box.GetFixtureList()!;
    // Near enough for the fat AABBs to overlap (a contact), too far to touch.
    const neighbour = createBody(world, b2BodyType.b2_dynamicBody, 1.15, restingY(0.5), 'neighbour');
    addBox(neighbour, 0.5, 0.5, 1.0);
    const other = createBody(world, b2BodyType.b2_dynamicBody, 0.0, 5.0, 'other');
    const jd = new b2DistanceJointDef();
    jd.Initialize(box, other, box.GetPosition(), other.GetPosition());
    const joint = world.CreateJoint(jd);
    world.Step(h, 8, 3);
    const touchingPairs = [] as string[];
    for (let c = world.GetContactList(); c; c = c.GetNext()) touchingPairs.push(`${bodyNames(c)}:${c.IsTouching()}`);
    expect(touchingPairs.sort()).toEqual(['box-ground:true', 'box-neighbour:false', 'ground-neighbour:true']);

    const calls: string[] = [];
    class Goodbye extends b2DestructionListener {
      SayGoodbyeJoint(j: b2Joint): void {
        expect(j).toBe(joint);
        calls.push(`SayGoodbyeJoint (joints in world: ${world.GetJointCount()})`);
      }
      SayGoodbyeFixture(f: b2Fixture): void {
        expect(f).toBe(fixture);
        expect(f.GetBody()).toBe(box);
        calls.push(`SayGoodbyeFixture (contacts in world: ${world.GetContactCount()})`);
      }
    }
    class Ends extends b2ContactListener {
      override EndContact(c: b2Contact): void {
        calls.push(`EndContact ${bodyNames(c)}`);
      }
    }
    world.SetDestructionListener(new Goodbye());
    world.SetContactListener(new Ends());
    world.DestroyBody(box);

    // The non-touching box-neighbour contact is destroyed without an EndContact.
    expect(calls).toEqual(['SayGoodbyeJoint (joints in world: 1)', 'EndContact box-ground', 'SayGoodbyeFixture (contacts in world: 1)']);
    expect(world.GetJointCount()).toBe(0);
    expect(world.GetContactCount()).toBe(1);
    expect(ground.GetContactList()!.other).toBe(neighbour);
  });
});

describe('callbacks run in the locked step', () => {
  for (const callback of ['BeginContact', 'PreSolve', 'PostSolve', 'EndContact'] as const) {
    it(`rejects CreateBody, DestroyBody and CreateFixture from ${callback} with a clear error; the world stays usable`, () => {
      const { world, ground, box } = boxOnGround();
      const errors: string[] = [];
      const locked: boolean[] = [];
      const listener = new b2ContactListener();
      listener[callback] = () => {
        locked.push(world.IsLocked());
        const attempts = [
          () => world.CreateBody(new b2BodyDef()),
          () => world.DestroyBody(box),
          () => ground.CreateFixture(new b2PolygonShape().SetAsBox(1.0, 1.0), 0.0),
        ];
        for (const attempt of attempts) {
          try {
            attempt();
            errors.push('no error');
          } catch (e) {
            errors.push((e as Error).message);
          }
        }
      };
      world.SetContactListener(listener);
      for (let k = 1; k <= 10; ++k) {
        if (k === 5) box.SetLinearVelocity(new b2Vec2(0.0, 3.0));
        world.Step(h, 8, 3);
      }

      expect(locked.length).toBeGreaterThan(0);
      expect(locked.every((l) => l)).toBe(true);
      expect(errors.length).toBe(3 * locked.length);
      for (let i = 0; i < errors.length; i += 3) {
        expect(errors[i]).toBe('b2World.CreateBody: the world is locked (called during a time step or a callback)');
        expect(errors[i + 1]).toBe('b2World.DestroyBody: the world is locked (called during a time step or a callback)');
        expect(errors[i + 2]).toMatch(/^b2Body\.CreateFixture: the world is locked/);
      }
      expect(world.IsLocked()).toBe(false);
      expect(world.GetBodyCount()).toBe(2);
      expect(ground.m_fixtureCount).toBe(1);

      // Usable afterwards: the same calls succeed and the simulation goes on.
      world.SetContactListener(null);
      const extra = world.CreateBody(new b2BodyDef());
      ground.CreateFixture(new b2PolygonShape().SetAsBox(1.0, 1.0, new b2Vec2(8.0, 0.0), 0.0), 0.0);
      world.DestroyBody(extra);
      const y = box.GetPosition().y;
      world.Step(h, 8, 3);
      expect(box.GetPosition().y).not.toBe(y);
      world.DestroyBody(box);
      expect(world.GetBodyCount()).toBe(1);
    });
  }
});
