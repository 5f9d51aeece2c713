// DistanceTest.h: b2Distance (GJK) between two boxes; w/a/s/d move and q/e turn box B.
import { b2Color, b2Distance, b2DistanceInput, b2DistanceOutput, b2MulXV, b2PolygonShape, b2SimplexCache, b2Transform, b2Vec2, b2_pi } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class DistanceTest extends Test {
  readonly m_positionB = new b2Vec2();
  m_angleB: number;

  readonly m_transformA = new b2Transform();
  readonly m_transformB = new b2Transform();
  readonly m_polygonA = new b2PolygonShape();
  readonly m_polygonB = new b2PolygonShape();

  constructor() {
    super();
    {
      this.m_transformA.SetIdentity();
      this.m_transformA.p.Set(0.0, -0.2);
      this.m_polygonA.SetAsBox(10.0, 0.2);
    }

    {
      this.m_positionB.Set(12.017401, 0.13678508);
      this.m_angleB = -0.0109265;
      this.m_transformB.Set(this.m_positionB, this.m_angleB);

      this.m_polygonB.SetAsBox(2.0, 0.1);
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);

    const input = new b2DistanceInput();
    input.proxyA.Set(this.m_polygonA, 0);
    input.proxyB.Set(this.m_polygonB, 0);
    input.transformA.Assign(this.m_transformA);
    input.transformB.Assign(this.m_transformB);
    input.useRadii = true;
    const cache = new b2SimplexCache();
    cache.count = 0;
    const output = new b2DistanceOutput();
    b2Distance(output, cache, input);

    this.m_debugDraw.DrawString(5, this.m_textLine, 'distance = %g', output.distance);
    this.m_textLine += 15;

    this.m_debugDraw.DrawString(5, this.m_textLine, 'iterations = %d', output.iterations);
    this.m_textLine += 15;

    {
      const color = new b2Color(0.9, 0.9, 0.9);
      const v: b2Vec2[] = [];
      for (let i = 0; i < this.m_polygonA.m_vertexCount; ++i) {
        v.push(b2MulXV(this.m_transformA, this.m_polygonA.m_vertices[i], new b2Vec2()));
      }
      this.m_debugDraw.DrawPolygon(v, this.m_polygonA.m_vertexCount, color);

      v.length = 0;
      for (let i = 0; i < this.m_polygonB.m_vertexCount; ++i) {
        v.push(b2MulXV(this.m_transformB, this.m_polygonB.m_vertices[i], new b2Vec2()));
      }
      this.m_debugDraw.DrawPolygon(v, this.m_polygonB.m_vertexCount, color);
    }

    const x1 = output.pointA;
    const x2 = output.pointB;

    const c1 = new b2Color(1.0, 0.0, 0.0);
    this.m_debugDraw.DrawPoint(x1, 4.0, c1);

    const c2 = new b2Color(1.0, 1.0, 0.0);
    this.m_debugDraw.DrawPoint(x2, 4.0, c2);
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'a':
        this.m_positionB.x -= 0.1;
        break;

      case 'd':
        this.m_positionB.x += 0.1;
        break;

      case 's':
        this.m_positionB.y -= 0.1;
        break;

      case 'w':
        this.m_positionB.y += 0.1;
        break;

      case 'q':
        this.m_angleB += 0.1 * b2_pi;
        break;

      case 'e':
        this.m_angleB -= 0.1 * b2_pi;
        break;
    }

    this.m_transformB.Set(this.m_positionB, this.m_angleB);
  }

  static Create(): Test {
    return new DistanceTest();
  }
}
