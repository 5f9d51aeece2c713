// Pyramid.h: a 20-row pyramid of boxes.
import { b2BodyDef, b2EdgeShape, b2PolygonShape, b2Vec2, b2_dynamicBody } from '../../src/index';
import { Test } from '../framework/test';

export class Pyramid extends Test {
  static readonly e_count = 20;

  constructor() {
    super();
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));
      ground.CreateFixture(shape, 0.0);
    }

    {
      const a = 0.5;
      const shape = new b2PolygonShape();
      shape.SetAsBox(a, a);

      const x = new b2Vec2(-7.0, 0.75);
      const y = new b2Vec2();
      const deltaX = new b2Vec2(0.5625, 1.25);
      const deltaY = new b2Vec2(1.125, 0.0);

      for (let i = 0; i < Pyramid.e_count; ++i) {
        y.Assign(x);

        for (let j = i; j < Pyramid.e_count; ++j) {
          const bd = new b2BodyDef();
          bd.type = b2_dynamicBody;
          bd.position.Assign(y);
          const body = this.m_world.CreateBody(bd);
          body.CreateFixture(shape, 5.0);

          y.Add(deltaY);
        }

        x.Add(deltaX);
      }
    }
  }

  static Create(): Test {
    return new Pyramid();
  }
}
