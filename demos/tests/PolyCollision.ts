// PolyCollision.h: b2CollidePolygons between two boxes; w/a/s/d move and q/e turn box B.
import { b2CollidePolygons, b2Color, b2Manifold, b2MulXV, b2PolygonShape, b2Transform, b2Vec2, b2WorldManifold, b2_pi } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class PolyCollision extends Test {
  readonly m_polygonA = new b2PolygonShape();
  readonly m_polygonB = new b2PolygonShape();

  readonly m_transformA = new b2Transform();
  readonly m_transformB = new b2Transform();

  readonly m_positionB = new b2Vec2();
  m_angleB: number;

  constructor() {
    super();
    {
      this.m_polygonA.SetAsBox(0.2, 0.4);
      this.m_transformA.Set(new b2Vec2(0.0, 0.0), 0.0);
    }

    {
      this.m_polygonB.SetAsBox(0.5, 0.5);
      this.m_positionB.Set(19.345284, 1.5632932);
      this.m_angleB = 1.9160721;
      this.m_transformB.Set(this.m_positionB, this.m_angleB);
    }
  }

  override Step(settings: Settings): void {
    // The world is not stepped: this test draws the manifold of its two polygons only.
    const manifold = new b2Manifold();
    b2CollidePolygons(manifold, this.m_polygonA, this.m_transformA, this.m_polygonB, this.m_transformB);

    const worldManifold = new b2WorldManifold();
    worldManifold.Initialize(manifold, this.m_transformA, this.m_polygonA.m_radius, this.m_transformB, this.m_polygonB.m_radius);

    this.m_debugDraw.DrawString(5, this.m_textLine, 'point count = %d', manifold.pointCount);
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

    for (let i = 0; i < manifold.pointCount; ++i) {
      this.m_debugDraw.DrawPoint(worldManifold.points[i], 4.0, new b2Color(0.9, 0.3, 0.3));
    }
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
    return new PolyCollision();
  }
}
