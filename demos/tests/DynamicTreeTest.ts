// DynamicTreeTest.h: a b2DynamicTree on its own, checked against brute force on every step.
// Keys: a automates random actions, c creates, d destroys, m moves a proxy.
import {
  b2AABB,
  b2Assert,
  b2ClampV,
  b2Color,
  b2DynamicTree,
  b2Max,
  b2RayCastInput,
  b2RayCastOutput,
  b2TestOverlap,
  b2Vec2,
  b2_nullNode,
} from '../../src/index';
import { RandomFloat, rand, srand } from '../framework/random';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

class Actor {
  readonly aabb = new b2AABB();
  fraction = 0.0;
  overlap = false;
  proxyId = b2_nullNode;
}

export class DynamicTreeTest extends Test {
  static readonly e_actorCount = 128;

  m_worldExtent: number;
  m_proxyExtent: number;

  readonly m_tree = new b2DynamicTree();
  readonly m_queryAABB = new b2AABB();
  readonly m_rayCastInput = new b2RayCastInput();
  readonly m_rayCastOutput = new b2RayCastOutput();
  m_rayActor: Actor | null = null;
  readonly m_actors: Actor[] = [];
  m_automated: boolean;

  constructor() {
    super();
    for (let i = 0; i < DynamicTreeTest.e_actorCount; ++i) this.m_actors.push(new Actor());
    this.m_worldExtent = 15.0;
    this.m_proxyExtent = 0.5;

    srand(888);

    for (let i = 0; i < DynamicTreeTest.e_actorCount; ++i) {
      const actor = this.m_actors[i];
      this.GetRandomAABB(actor.aabb);
      actor.proxyId = this.m_tree.CreateProxy(actor.aabb, actor);
    }

    this.m_stepCount = 0;

    const h = this.m_worldExtent;
    this.m_queryAABB.lowerBound.Set(-3.0, -4.0 + h);
    this.m_queryAABB.upperBound.Set(5.0, 6.0 + h);

    this.m_rayCastInput.p1.Set(-5.0, 5.0 + h);
    this.m_rayCastInput.p2.Set(7.0, -4.0 + h);
    //m_rayCastInput.p1.Set(0.0f, 2.0f + h);
    //m_rayCastInput.p2.Set(0.0f, -2.0f + h);
    this.m_rayCastInput.maxFraction = 1.0;

    this.m_automated = false;
  }

  override Step(settings: Settings): void {
    // The world is not stepped: this test draws its tree only.
    this.m_rayActor = null;
    for (let i = 0; i < DynamicTreeTest.e_actorCount; ++i) {
      this.m_actors[i].fraction = 1.0;
      this.m_actors[i].overlap = false;
    }

    if (this.m_automated === true) {
      const actionCount = b2Max(1, DynamicTreeTest.e_actorCount >> 2);

      for (let i = 0; i < actionCount; ++i) {
        this.Action();
      }
    }

    this.Query();
    this.RayCast();
    // (Set by RayCastCallback during RayCast.)
    const rayActor = this.m_rayActor as Actor | null;

    for (let i = 0; i < DynamicTreeTest.e_actorCount; ++i) {
      const actor = this.m_actors[i];
      if (actor.proxyId === b2_nullNode) continue;

      const c = new b2Color(0.9, 0.9, 0.9);
      if (actor === rayActor && actor.overlap) {
        c.Set(0.9, 0.6, 0.6);
      } else if (actor === rayActor) {
        c.Set(0.6, 0.9, 0.6);
      } else if (actor.overlap) {
        c.Set(0.6, 0.6, 0.9);
      }

      this.m_debugDraw.DrawAABB(actor.aabb, c);
    }

    const c = new b2Color(0.7, 0.7, 0.7);
    this.m_debugDraw.DrawAABB(this.m_queryAABB, c);

    this.m_debugDraw.DrawSegment(this.m_rayCastInput.p1, this.m_rayCastInput.p2, c);

    const c1 = new b2Color(0.2, 0.9, 0.2);
    const c2 = new b2Color(0.9, 0.2, 0.2);
    this.m_debugDraw.DrawPoint(this.m_rayCastInput.p1, 6.0, c1);
    this.m_debugDraw.DrawPoint(this.m_rayCastInput.p2, 6.0, c2);

    if (rayActor !== null) {
      const cr = new b2Color(0.2, 0.2, 0.9);
      const p1 = this.m_rayCastInput.p1;
      const p2 = this.m_rayCastInput.p2;
      const f = rayActor.fraction;
      const p = new b2Vec2(p1.x + f * (p2.x - p1.x), p1.y + f * (p2.y - p1.y));
      this.m_debugDraw.DrawPoint(p, 6.0, cr);
    }

    {
      const height = this.m_tree.GetHeight();
      this.m_debugDraw.DrawString(5, this.m_textLine, 'dynamic tree height = %d', height);
      this.m_textLine += 15;
    }

    ++this.m_stepCount;
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'a':
        this.m_automated = !this.m_automated;
        break;

      case 'c':
        this.CreateProxy();
        break;

      case 'd':
        this.DestroyProxy();
        break;

      case 'm':
        this.MoveProxy();
        break;
    }
  }

  QueryCallback(proxyId: number): boolean {
    const actor = this.m_tree.GetUserData(proxyId) as Actor;
    actor.overlap = b2TestOverlap(this.m_queryAABB, actor.aabb);
    return true;
  }

  RayCastCallback(input: Readonly<b2RayCastInput>, proxyId: number): number {
    const actor = this.m_tree.GetUserData(proxyId) as Actor;

    const output = new b2RayCastOutput();
    const hit = actor.aabb.RayCast(output, input);

    if (hit) {
      this.m_rayCastOutput.normal.Assign(output.normal);
      this.m_rayCastOutput.fraction = output.fraction;
      this.m_rayActor = actor;
      this.m_rayActor.fraction = output.fraction;
      return output.fraction;
    }

    return input.maxFraction;
  }

  private GetRandomAABB(aabb: b2AABB): void {
    const w = new b2Vec2(2.0 * this.m_proxyExtent, 2.0 * this.m_proxyExtent);
    //aabb->lowerBound.x = -m_proxyExtent;
    //aabb->lowerBound.y = -m_proxyExtent + m_worldExtent;
    aabb.lowerBound.x = RandomFloat(-this.m_worldExtent, this.m_worldExtent);
    aabb.lowerBound.y = RandomFloat(0.0, 2.0 * this.m_worldExtent);
    aabb.upperBound.Set(aabb.lowerBound.x + w.x, aabb.lowerBound.y + w.y);
  }

  private MoveAABB(aabb: b2AABB): void {
    const d = new b2Vec2();
    d.x = RandomFloat(-0.5, 0.5);
    d.y = RandomFloat(-0.5, 0.5);
    //d.x = 2.0f;
    //d.y = 0.0f;
    aabb.lowerBound.Add(d);
    aabb.upperBound.Add(d);

    const c0 = new b2Vec2(0.5 * (aabb.lowerBound.x + aabb.upperBound.x), 0.5 * (aabb.lowerBound.y + aabb.upperBound.y));
    const min = new b2Vec2(-this.m_worldExtent, 0.0);
    const max = new b2Vec2(this.m_worldExtent, 2.0 * this.m_worldExtent);
    const c = b2ClampV(c0, min, max, new b2Vec2());

    const dx = c.x - c0.x;
    const dy = c.y - c0.y;
    aabb.lowerBound.x += dx;
    aabb.lowerBound.y += dy;
    aabb.upperBound.x += dx;
    aabb.upperBound.y += dy;
  }

  private CreateProxy(): void {
    for (let i = 0; i < DynamicTreeTest.e_actorCount; ++i) {
      const j = rand() % DynamicTreeTest.e_actorCount;
      const actor = this.m_actors[j];
      if (actor.proxyId === b2_nullNode) {
        this.GetRandomAABB(actor.aabb);
        actor.proxyId = this.m_tree.CreateProxy(actor.aabb, actor);
        return;
      }
    }
  }

  private DestroyProxy(): void {
    for (let i = 0; i < DynamicTreeTest.e_actorCount; ++i) {
      const j = rand() % DynamicTreeTest.e_actorCount;
      const actor = this.m_actors[j];
      if (actor.proxyId !== b2_nullNode) {
        this.m_tree.DestroyProxy(actor.proxyId);
        actor.proxyId = b2_nullNode;
        return;
      }
    }
  }

  private MoveProxy(): void {
    for (let i = 0; i < DynamicTreeTest.e_actorCount; ++i) {
      const j = rand() % DynamicTreeTest.e_actorCount;
      const actor = this.m_actors[j];
      if (actor.proxyId === b2_nullNode) {
        continue;
      }

      const aabb0 = actor.aabb.Clone();
      this.MoveAABB(actor.aabb);
      const c = actor.aabb.GetCenter(new b2Vec2());
      const c0 = aabb0.GetCenter(new b2Vec2());
      const displacement = new b2Vec2(c.x - c0.x, c.y - c0.y);
      this.m_tree.MoveProxy(actor.proxyId, actor.aabb, displacement);
      return;
    }
  }

  private Action(): void {
    const choice = rand() % 20;

    switch (choice) {
      case 0:
        this.CreateProxy();
        break;

      case 1:
        this.DestroyProxy();
        break;

      default:
        this.MoveProxy();
    }
  }

  private Query(): void {
    this.m_tree.Query(this, this.m_queryAABB);

    for (let i = 0; i < DynamicTreeTest.e_actorCount; ++i) {
      if (this.m_actors[i].proxyId === b2_nullNode) {
        continue;
      }

      const overlap = b2TestOverlap(this.m_queryAABB, this.m_actors[i].aabb);
      b2Assert(overlap === this.m_actors[i].overlap, 'DynamicTreeTest: tree query differs from brute force');
    }
  }

  private RayCast(): void {
    this.m_rayActor = null;

    const input = this.m_rayCastInput.Clone();

    // Ray cast against the dynamic tree.
    this.m_tree.RayCast(this, input);

    // Brute force ray cast.
    let bruteActor: Actor | null = null;
    const bruteOutput = new b2RayCastOutput();
    for (let i = 0; i < DynamicTreeTest.e_actorCount; ++i) {
      if (this.m_actors[i].proxyId === b2_nullNode) {
        continue;
      }

      const output = new b2RayCastOutput();
      const hit = this.m_actors[i].aabb.RayCast(output, input);
      if (hit) {
        bruteActor = this.m_actors[i];
        bruteOutput.normal.Assign(output.normal);
        bruteOutput.fraction = output.fraction;
        input.maxFraction = output.fraction;
      }
    }

    if (bruteActor !== null) {
      b2Assert(bruteOutput.fraction === this.m_rayCastOutput.fraction, 'DynamicTreeTest: tree ray cast differs from brute force');
    }
  }

  static Create(): Test {
    return new DynamicTreeTest();
  }
}
