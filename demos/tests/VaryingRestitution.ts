// VaryingRestitution.h: circles of restitution 0 to 1. Note: even with a restitution of 1.0,
// there is some energy change due to position correction.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2FixtureDef, b2Vec2, b2_dynamicBody } from '../../src/index';
import { Test } from '../framework/test';

export class VaryingRestitution extends Test {
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
      const shape = new b2CircleShape();
      shape.m_radius = 1.0;

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 1.0;

      const restitution = [0.0, 0.1, 0.3, 0.5, 0.75, 0.9, 1.0];

      for (let i = 0; i < 7; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(-10.0 + 3.0 * i, 20.0);

        const body = this.m_world.CreateBody(bd);

        fd.restitution = restitution[i];
        body.CreateFixture(fd);
      }
    }
  }

  static Create(): Test {
    return new VaryingRestitution();
  }
}
