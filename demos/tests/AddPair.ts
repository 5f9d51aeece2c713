// AddPair.h: broad-phase pair stress, 400 small circles and a fast bullet box.
import { b2BodyDef, b2CircleShape, b2PolygonShape, b2Vec2, b2_dynamicBody } from '../../src/index';
import { RandomFloat } from '../framework/random';
import { Test } from '../framework/test';

export class AddPair extends Test {
  constructor() {
    super();
    this.m_world.SetGravity(new b2Vec2(0.0, 0.0));
    {
      const shape = new b2CircleShape();
      shape.m_p.SetZero();
      shape.m_radius = 0.1;

      const minX = -6.0;
      const maxX = 0.0;
      const minY = 4.0;
      const maxY = 6.0;

      for (let i = 0; i < 400; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        // b2Vec2(RandomFloat(minX, maxX), RandomFloat(minY, maxY)): C++ leaves the order of the
        // two calls open; GCC on x86-64 evaluates the arguments right to left.
        const y = RandomFloat(minY, maxY);
        const x = RandomFloat(minX, maxX);
        bd.position.Set(x, y);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(shape, 0.01);
      }
    }

    {
      const shape = new b2PolygonShape();
      shape.SetAsBox(1.5, 1.5);
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(-40.0, 5.0);
      bd.bullet = true;
      const body = this.m_world.CreateBody(bd);
      body.CreateFixture(shape, 1.0);
      body.SetLinearVelocity(new b2Vec2(150.0, 0.0));
    }
  }

  static Create(): Test {
    return new AddPair();
  }
}
