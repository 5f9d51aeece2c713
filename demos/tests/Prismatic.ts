// Prismatic.h: a prismatic joint with a motor and limits. The motor in this test gets smoother with
// higher velocity iterations. Keys: l limits, m motor, s reverses the speed.
import { b2BodyDef, b2EdgeShape, b2PolygonShape, b2PrismaticJointDef, b2Vec2, b2_dynamicBody, b2_pi } from '../../src/index';
import type { b2Body, b2PrismaticJoint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Prismatic extends Test {
  m_joint: b2PrismaticJoint;

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
      shape.SetAsBox(2.0, 0.5);

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(-10.0, 10.0);
      bd.angle = 0.5 * b2_pi;
      bd.allowSleep = false;
      const body = this.m_world.CreateBody(bd);
      body.CreateFixture(shape, 5.0);

      const pjd = new b2PrismaticJointDef();

      // Bouncy limit
      const axis = new b2Vec2(2.0, 1.0);
      axis.Normalize();
      pjd.Initialize(ground, body, new b2Vec2(0.0, 0.0), axis);

      // Non-bouncy limit
      //pjd.Initialize(ground, body, b2Vec2(-10.0f, 10.0f), b2Vec2(1.0f, 0.0f));

      pjd.motorSpeed = 10.0;
      pjd.maxMotorForce = 10000.0;
      pjd.enableMotor = true;
      pjd.lowerTranslation = 0.0;
      pjd.upperTranslation = 20.0;
      pjd.enableLimit = true;

      this.m_joint = this.m_world.CreateJoint(pjd) as b2PrismaticJoint;
    }
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'l':
        this.m_joint.EnableLimit(!this.m_joint.IsLimitEnabled());
        break;

      case 'm':
        this.m_joint.EnableMotor(!this.m_joint.IsMotorEnabled());
        break;

      case 's':
        this.m_joint.SetMotorSpeed(-this.m_joint.GetMotorSpeed());
        break;
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Keys: (l) limits, (m) motors, (s) speed');
    this.m_textLine += 15;
    const force = this.m_joint.GetMotorForce(settings.hz);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Motor Force = %4.0f', force);
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new Prismatic();
  }
}
