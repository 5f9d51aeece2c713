// Pulleys.h: two boxes on a pulley joint with ratio 1.5.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2PolygonShape, b2PulleyJointDef, b2Vec2, b2_dynamicBody } from '../../src/index';
import type { b2Body, b2PulleyJoint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Pulleys extends Test {
  m_joint1: b2PulleyJoint;

  constructor() {
    super();
    const y = 16.0;
    const L = 12.0;
    const a = 1.0;
    const b = 2.0;

    let ground: b2Body;
    {
      const bd = new b2BodyDef();
      ground = this.m_world.CreateBody(bd);

      const edge = new b2EdgeShape();
      edge.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));
      //ground->CreateFixture(&shape, 0.0f);

      const circle = new b2CircleShape();
      circle.m_radius = 2.0;

      circle.m_p.Set(-10.0, y + b + L);
      ground.CreateFixture(circle, 0.0);

      circle.m_p.Set(10.0, y + b + L);
      ground.CreateFixture(circle, 0.0);
    }

    {
      const shape = new b2PolygonShape();
      shape.SetAsBox(a, b);

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;

      //bd.fixedRotation = true;
      bd.position.Set(-10.0, y);
      const body1 = this.m_world.CreateBody(bd);
      body1.CreateFixture(shape, 5.0);

      bd.position.Set(10.0, y);
      const body2 = this.m_world.CreateBody(bd);
      body2.CreateFixture(shape, 5.0);

      const pulleyDef = new b2PulleyJointDef();
      const anchor1 = new b2Vec2(-10.0, y + b);
      const anchor2 = new b2Vec2(10.0, y + b);
      const groundAnchor1 = new b2Vec2(-10.0, y + b + L);
      const groundAnchor2 = new b2Vec2(10.0, y + b + L);
      pulleyDef.Initialize(body1, body2, groundAnchor1, groundAnchor2, anchor1, anchor2, 1.5);

      this.m_joint1 = this.m_world.CreateJoint(pulleyDef) as b2PulleyJoint;
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);

    const ratio = this.m_joint1.GetRatio();
    const L = this.m_joint1.GetLengthA() + ratio * this.m_joint1.GetLengthB();
    this.m_debugDraw.DrawString(5, this.m_textLine, 'L1 + %4.2f * L2 = %4.2f', ratio, L);
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new Pulleys();
  }
}
