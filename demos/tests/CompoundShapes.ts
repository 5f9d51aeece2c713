// CompoundShapes.h: bodies made of several fixtures.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2MulXV, b2PolygonShape, b2Transform, b2Vec2, b2_dynamicBody, b2_pi } from '../../src/index';
import { RandomFloat } from '../framework/random';
import { Test } from '../framework/test';

export class CompoundShapes extends Test {
  constructor() {
    super();
    {
      const bd = new b2BodyDef();
      bd.position.Set(0.0, 0.0);
      const body = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(50.0, 0.0), new b2Vec2(-50.0, 0.0));

      body.CreateFixture(shape, 0.0);
    }

    {
      const circle1 = new b2CircleShape();
      circle1.m_radius = 0.5;
      circle1.m_p.Set(-0.5, 0.5);

      const circle2 = new b2CircleShape();
      circle2.m_radius = 0.5;
      circle2.m_p.Set(0.5, 0.5);

      for (let i = 0; i < 10; ++i) {
        const x = RandomFloat(-0.1, 0.1);
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(x + 5.0, 1.05 + 2.5 * i);
        bd.angle = RandomFloat(-b2_pi, b2_pi);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(circle1, 2.0);
        body.CreateFixture(circle2, 0.0);
      }
    }

    {
      const polygon1 = new b2PolygonShape();
      polygon1.SetAsBox(0.25, 0.5);

      const polygon2 = new b2PolygonShape();
      polygon2.SetAsBox(0.25, 0.5, new b2Vec2(0.0, -0.5), 0.5 * b2_pi);

      for (let i = 0; i < 10; ++i) {
        const x = RandomFloat(-0.1, 0.1);
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(x - 5.0, 1.05 + 2.5 * i);
        bd.angle = RandomFloat(-b2_pi, b2_pi);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(polygon1, 2.0);
        body.CreateFixture(polygon2, 2.0);
      }
    }

    {
      const xf1 = new b2Transform();
      xf1.q.Set(0.3524 * b2_pi);
      xf1.q.GetXAxis(xf1.p);

      const vertices = [new b2Vec2(), new b2Vec2(), new b2Vec2()];

      const triangle1 = new b2PolygonShape();
      b2MulXV(xf1, new b2Vec2(-1.0, 0.0), vertices[0]);
      b2MulXV(xf1, new b2Vec2(1.0, 0.0), vertices[1]);
      b2MulXV(xf1, new b2Vec2(0.0, 0.5), vertices[2]);
      triangle1.Set(vertices, 3);

      const xf2 = new b2Transform();
      xf2.q.Set(-0.3524 * b2_pi);
      xf2.q.GetXAxis(xf2.p);
      xf2.p.Set(-xf2.p.x, -xf2.p.y);

      const triangle2 = new b2PolygonShape();
      b2MulXV(xf2, new b2Vec2(-1.0, 0.0), vertices[0]);
      b2MulXV(xf2, new b2Vec2(1.0, 0.0), vertices[1]);
      b2MulXV(xf2, new b2Vec2(0.0, 0.5), vertices[2]);
      triangle2.Set(vertices, 3);

      for (let i = 0; i < 10; ++i) {
        const x = RandomFloat(-0.1, 0.1);
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(x, 2.05 + 2.5 * i);
        bd.angle = 0.0;
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(triangle1, 2.0);
        body.CreateFixture(triangle2, 2.0);
      }
    }

    {
      const bottom = new b2PolygonShape();
      bottom.SetAsBox(1.5, 0.15);

      const left = new b2PolygonShape();
      left.SetAsBox(0.15, 2.7, new b2Vec2(-1.45, 2.35), 0.2);

      const right = new b2PolygonShape();
      right.SetAsBox(0.15, 2.7, new b2Vec2(1.45, 2.35), -0.2);

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(0.0, 2.0);
      const body = this.m_world.CreateBody(bd);
      body.CreateFixture(bottom, 4.0);
      body.CreateFixture(left, 4.0);
      body.CreateFixture(right, 4.0);
    }
  }

  static Create(): Test {
    return new CompoundShapes();
  }
}
