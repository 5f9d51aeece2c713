// Tiles.h: stresses the dynamic tree broad-phase (2,000 static box fixtures), and shows that
// tile based collision is _not_ smooth due to Box2D not knowing about adjacency.
import { b2BodyDef, b2PolygonShape, b2Timer, b2Vec2, b2_dynamicBody } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Tiles extends Test {
  static readonly e_count = 20;

  m_fixtureCount: number;
  m_createTime: number;

  constructor() {
    super();
    this.m_fixtureCount = 0;
    const timer = new b2Timer();

    {
      const a = 0.5;
      const bd = new b2BodyDef();
      bd.position.y = -a;
      const ground = this.m_world.CreateBody(bd);

      // (#if 1 branch of the C++)
      const N = 200;
      const M = 10;
      const position = new b2Vec2();
      position.y = 0.0;
      for (let j = 0; j < M; ++j) {
        position.x = -N * a;
        for (let i = 0; i < N; ++i) {
          const shape = new b2PolygonShape();
          shape.SetAsBox(a, a, position, 0.0);
          ground.CreateFixture(shape, 0.0);
          ++this.m_fixtureCount;
          position.x += 2.0 * a;
        }
        position.y -= 2.0 * a;
      }
    }

    {
      const a = 0.5;
      const shape = new b2PolygonShape();
      shape.SetAsBox(a, a);

      const x = new b2Vec2(-7.0, 0.75);
      const y = new b2Vec2();
      const deltaX = new b2Vec2(0.5625, 1.25);
      const deltaY = new b2Vec2(1.125, 0.0);

      for (let i = 0; i < Tiles.e_count; ++i) {
        y.Assign(x);

        for (let j = i; j < Tiles.e_count; ++j) {
          const bd = new b2BodyDef();
          bd.type = b2_dynamicBody;
          bd.position.Assign(y);

          const body = this.m_world.CreateBody(bd);
          body.CreateFixture(shape, 5.0);
          ++this.m_fixtureCount;
          y.Add(deltaY);
        }

        x.Add(deltaX);
      }
    }

    this.m_createTime = timer.GetMilliseconds();
  }

  override Step(settings: Settings): void {
    const cm = this.m_world.GetContactManager();
    const height = cm.m_broadPhase.GetTreeHeight();
    const leafCount = cm.m_broadPhase.GetProxyCount();
    const minimumNodeCount = 2 * leafCount - 1;
    const minimumHeight = Math.ceil(Math.log(minimumNodeCount) / Math.log(2.0));
    this.m_debugDraw.DrawString(5, this.m_textLine, 'dynamic tree height = %d, min = %d', height, minimumHeight | 0);
    this.m_textLine += 15;

    super.Step(settings);

    this.m_debugDraw.DrawString(5, this.m_textLine, 'create time = %6.2f ms, fixture count = %d', this.m_createTime, this.m_fixtureCount);
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new Tiles();
  }
}
