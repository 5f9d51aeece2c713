// Tumbler.h: a motorised box tumbling small boxes, one added per step up to 800.
import { b2BodyDef, b2PolygonShape, b2RevoluteJointDef, b2Vec2, b2_dynamicBody, b2_pi } from '../../src/index';
import type { b2Body, b2RevoluteJoint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Tumbler extends Test {
  static readonly e_count = 800;

  m_joint: b2RevoluteJoint;
  m_count: number;

  constructor() {
    super();
    let ground: b2Body;
    {
      const bd = new b2BodyDef();
      ground = this.m_world.CreateBody(bd);
    }

    {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.allowSleep = false;
      bd.position.Set(0.0, 10.0);
      const body = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 10.0, new b2Vec2(10.0, 0.0), 0.0);
      body.CreateFixture(shape, 5.0);
      shape.SetAsBox(0.5, 10.0, new b2Vec2(-10.0, 0.0), 0.0);
      body.CreateFixture(shape, 5.0);
      shape.SetAsBox(10.0, 0.5, new b2Vec2(0.0, 10.0), 0.0);
      body.CreateFixture(shape, 5.0);
      shape.SetAsBox(10.0, 0.5, new b2Vec2(0.0, -10.0), 0.0);
      body.CreateFixture(shape, 5.0);

      const jd = new b2RevoluteJointDef();
      jd.bodyA = ground;
      jd.bodyB = body;
      jd.localAnchorA.Set(0.0, 10.0);
      jd.localAnchorB.Set(0.0, 0.0);
      jd.referenceAngle = 0.0;
      jd.motorSpeed = 0.05 * b2_pi;
      jd.maxMotorTorque = 1e8;
      jd.enableMotor = true;
      this.m_joint = this.m_world.CreateJoint(jd) as b2RevoluteJoint;
    }

    this.m_count = 0;
  }

  override Step(settings: Settings): void {
    super.Step(settings);

    if (this.m_count < Tumbler.e_count) {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(0.0, 10.0);
      const body = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(0.125, 0.125);
      body.CreateFixture(shape, 1.0);

      ++this.m_count;
    }
  }

  static Create(): Test {
    return new Tumbler();
  }
}
