// Chain.h: a chain of 30 links on revolute joints.
import { b2BodyDef, b2EdgeShape, b2FixtureDef, b2PolygonShape, b2RevoluteJointDef, b2Vec2, b2_dynamicBody } from '../../src/index';
import type { b2Body } from '../../src/index';
import { Test } from '../framework/test';

export class Chain extends Test {
  constructor() {
    super();
    let ground: b2Body;
    {
      const bd = new b2BodyDef();
      ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));
      ground.CreateFixture(shape, 0.0);
    }

    {
      const shape = new b2PolygonShape();
      shape.SetAsBox(0.6, 0.125);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;
      fd.friction = 0.2;

      const jd = new b2RevoluteJointDef();
      jd.collideConnected = false;

      const y = 25.0;
      let prevBody = ground;
      for (let i = 0; i < 30; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(0.5 + i, y);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(fd);

        const anchor = new b2Vec2(i, y);
        jd.Initialize(prevBody, body, anchor);
        this.m_world.CreateJoint(jd);

        prevBody = body;
      }
    }
  }

  static Create(): Test {
    return new Chain();
  }
}
