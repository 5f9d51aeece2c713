// SphereStack.h: ten circles thrown down at 50 m/s onto an edge.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2Vec2, b2_dynamicBody } from '../../src/index';
import type { b2Body } from '../../src/index';
import { Test } from '../framework/test';

export class SphereStack extends Test {
  static readonly e_count = 10;

  readonly m_bodies: b2Body[] = [];

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

      for (let i = 0; i < SphereStack.e_count; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(0.0, 4.0 + 3.0 * i);

        this.m_bodies[i] = this.m_world.CreateBody(bd);

        this.m_bodies[i].CreateFixture(shape, 1.0);

        this.m_bodies[i].SetLinearVelocity(new b2Vec2(0.0, -50.0));
      }
    }
  }

  static Create(): Test {
    return new SphereStack();
  }
}
