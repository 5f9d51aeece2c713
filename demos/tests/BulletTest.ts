// BulletTest.h: a bullet box dropped on a thin plank, relaunched every 60 steps; GJK/TOI counters.
import * as B from '../../src/index';
import { b2BodyDef, b2EdgeShape, b2PolygonShape, b2Vec2, b2Vec2_zero, b2_dynamicBody } from '../../src/index';
import type { b2Body } from '../../src/index';
import { RandomFloat } from '../framework/random';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class BulletTest extends Test {
  m_body: b2Body;
  m_bullet: b2Body;
  m_x: number;

  constructor() {
    super();
    {
      const bd = new b2BodyDef();
      bd.position.Set(0.0, 0.0);
      const body = this.m_world.CreateBody(bd);

      const edge = new b2EdgeShape();

      edge.Set(new b2Vec2(-10.0, 0.0), new b2Vec2(10.0, 0.0));
      body.CreateFixture(edge, 0.0);

      const shape = new b2PolygonShape();
      shape.SetAsBox(0.2, 1.0, new b2Vec2(0.5, 1.0), 0.0);
      body.CreateFixture(shape, 0.0);
    }

    {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(0.0, 4.0);

      const box = new b2PolygonShape();
      box.SetAsBox(2.0, 0.1);

      this.m_body = this.m_world.CreateBody(bd);
      this.m_body.CreateFixture(box, 1.0);

      box.SetAsBox(0.25, 0.25);

      //m_x = RandomFloat(-1.0f, 1.0f);
      this.m_x = 0.20352793;
      bd.position.Set(this.m_x, 10.0);
      bd.bullet = true;

      this.m_bullet = this.m_world.CreateBody(bd);
      this.m_bullet.CreateFixture(box, 100.0);

      this.m_bullet.SetLinearVelocity(new b2Vec2(0.0, -50.0));
    }
  }

  Launch(): void {
    this.m_body.SetTransform(new b2Vec2(0.0, 4.0), 0.0);
    this.m_body.SetLinearVelocity(b2Vec2_zero);
    this.m_body.SetAngularVelocity(0.0);

    this.m_x = RandomFloat(-1.0, 1.0);
    this.m_bullet.SetTransform(new b2Vec2(this.m_x, 10.0), 0.0);
    this.m_bullet.SetLinearVelocity(new b2Vec2(0.0, -50.0));
    this.m_bullet.SetAngularVelocity(0.0);

    B.b2ResetGjkCounters();
    B.b2ResetToiCounters();
  }

  override Step(settings: Settings): void {
    super.Step(settings);

    if (B.b2_gjkCalls > 0) {
      this.m_debugDraw.DrawString(
        5,
        this.m_textLine,
        'gjk calls = %d, ave gjk iters = %3.1f, max gjk iters = %d',
        B.b2_gjkCalls,
        B.b2_gjkIters / B.b2_gjkCalls,
        B.b2_gjkMaxIters,
      );
      this.m_textLine += 15;
    }

    if (B.b2_toiCalls > 0) {
      this.m_debugDraw.DrawString(
        5,
        this.m_textLine,
        'toi calls = %d, ave toi iters = %3.1f, max toi iters = %d',
        B.b2_toiCalls,
        B.b2_toiIters / B.b2_toiCalls,
        B.b2_toiMaxRootIters,
      );
      this.m_textLine += 15;

      this.m_debugDraw.DrawString(
        5,
        this.m_textLine,
        'ave toi root iters = %3.1f, max toi root iters = %d',
        B.b2_toiRootIters / B.b2_toiCalls,
        B.b2_toiMaxRootIters,
      );
      this.m_textLine += 15;
    }

    if (this.m_stepCount % 60 === 0) {
      this.Launch();
    }
  }

  static Create(): Test {
    return new BulletTest();
  }
}
