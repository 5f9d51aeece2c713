// Cantilever.h: rigid and soft weld-joint chains.
// It is difficult to make a cantilever made of links completely rigid with weld joints. You will
// have to use a high number of iterations to make them stiff. So why not go ahead and use soft
// weld joints? They behave like a revolute joint with a rotational spring.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2FixtureDef, b2PolygonShape, b2Vec2, b2WeldJointDef, b2_dynamicBody } from '../../src/index';
import type { b2Body } from '../../src/index';
import { Test } from '../framework/test';

export class Cantilever extends Test {
  static readonly e_count = 8;

  m_middle: b2Body | null = null;

  constructor() {
    super();
    const e_count = Cantilever.e_count;
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
      shape.SetAsBox(0.5, 0.125);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;

      const jd = new b2WeldJointDef();

      let prevBody = ground;
      for (let i = 0; i < e_count; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(-14.5 + 1.0 * i, 5.0);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(fd);

        const anchor = new b2Vec2(-15.0 + 1.0 * i, 5.0);
        jd.Initialize(prevBody, body, anchor);
        this.m_world.CreateJoint(jd);

        prevBody = body;
      }
    }

    {
      const shape = new b2PolygonShape();
      shape.SetAsBox(1.0, 0.125);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;

      const jd = new b2WeldJointDef();
      jd.frequencyHz = 5.0;
      jd.dampingRatio = 0.7;

      let prevBody = ground;
      for (let i = 0; i < 3; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(-14.0 + 2.0 * i, 15.0);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(fd);

        const anchor = new b2Vec2(-15.0 + 2.0 * i, 15.0);
        jd.Initialize(prevBody, body, anchor);
        this.m_world.CreateJoint(jd);

        prevBody = body;
      }
    }

    {
      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 0.125);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;

      const jd = new b2WeldJointDef();

      let prevBody = ground;
      for (let i = 0; i < e_count; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(-4.5 + 1.0 * i, 5.0);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(fd);

        if (i > 0) {
          const anchor = new b2Vec2(-5.0 + 1.0 * i, 5.0);
          jd.Initialize(prevBody, body, anchor);
          this.m_world.CreateJoint(jd);
        }

        prevBody = body;
      }
    }

    {
      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 0.125);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;

      const jd = new b2WeldJointDef();
      jd.frequencyHz = 8.0;
      jd.dampingRatio = 0.7;

      let prevBody = ground;
      for (let i = 0; i < e_count; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(5.5 + 1.0 * i, 10.0);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(fd);

        if (i > 0) {
          const anchor = new b2Vec2(5.0 + 1.0 * i, 10.0);
          jd.Initialize(prevBody, body, anchor);
          this.m_world.CreateJoint(jd);
        }

        prevBody = body;
      }
    }

    for (let i = 0; i < 2; ++i) {
      const vertices = [new b2Vec2(-0.5, 0.0), new b2Vec2(0.5, 0.0), new b2Vec2(0.0, 1.5)];

      const shape = new b2PolygonShape();
      shape.Set(vertices, 3);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 1.0;

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(-8.0 + 8.0 * i, 12.0);
      const body = this.m_world.CreateBody(bd);
      body.CreateFixture(fd);
    }

    for (let i = 0; i < 2; ++i) {
      const shape = new b2CircleShape();
      shape.m_radius = 0.5;

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 1.0;

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(-6.0 + 6.0 * i, 10.0);
      const body = this.m_world.CreateBody(bd);
      body.CreateFixture(fd);
    }
  }

  static Create(): Test {
    return new Cantilever();
  }
}
