// EdgeTest.h: edges whose ghost vertices (m_vertex0/m_vertex3) are set by hand.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2PolygonShape, b2Vec2, b2_dynamicBody } from '../../src/index';
import { Test } from '../framework/test';

export class EdgeTest extends Test {
  constructor() {
    super();
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const v1 = new b2Vec2(-10.0, 0.0);
      const v2 = new b2Vec2(-7.0, -2.0);
      const v3 = new b2Vec2(-4.0, 0.0);
      const v4 = new b2Vec2(0.0, 0.0);
      const v5 = new b2Vec2(4.0, 0.0);
      const v6 = new b2Vec2(7.0, 2.0);
      const v7 = new b2Vec2(10.0, 0.0);

      const shape = new b2EdgeShape();

      shape.Set(v1, v2);
      shape.m_hasVertex3 = true;
      shape.m_vertex3.Assign(v3);
      ground.CreateFixture(shape, 0.0);

      shape.Set(v2, v3);
      shape.m_hasVertex0 = true;
      shape.m_hasVertex3 = true;
      shape.m_vertex0.Assign(v1);
      shape.m_vertex3.Assign(v4);
      ground.CreateFixture(shape, 0.0);

      shape.Set(v3, v4);
      shape.m_hasVertex0 = true;
      shape.m_hasVertex3 = true;
      shape.m_vertex0.Assign(v2);
      shape.m_vertex3.Assign(v5);
      ground.CreateFixture(shape, 0.0);

      shape.Set(v4, v5);
      shape.m_hasVertex0 = true;
      shape.m_hasVertex3 = true;
      shape.m_vertex0.Assign(v3);
      shape.m_vertex3.Assign(v6);
      ground.CreateFixture(shape, 0.0);

      shape.Set(v5, v6);
      shape.m_hasVertex0 = true;
      shape.m_hasVertex3 = true;
      shape.m_vertex0.Assign(v4);
      shape.m_vertex3.Assign(v7);
      ground.CreateFixture(shape, 0.0);

      shape.Set(v6, v7);
      shape.m_hasVertex0 = true;
      shape.m_vertex0.Assign(v5);
      ground.CreateFixture(shape, 0.0);
    }

    {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(-0.5, 0.6);
      bd.allowSleep = false;
      const body = this.m_world.CreateBody(bd);

      const shape = new b2CircleShape();
      shape.m_radius = 0.5;

      body.CreateFixture(shape, 1.0);
    }

    {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(1.0, 0.6);
      bd.allowSleep = false;
      const body = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 0.5);

      body.CreateFixture(shape, 1.0);
    }
  }

  static Create(): Test {
    return new EdgeTest();
  }
}
