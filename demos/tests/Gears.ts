// Gears.h: gear joints between revolute and prismatic joints.
import {
  b2BodyDef,
  b2CircleShape,
  b2EdgeShape,
  b2GearJointDef,
  b2PolygonShape,
  b2PrismaticJointDef,
  b2RevoluteJointDef,
  b2Vec2,
  b2_dynamicBody,
  b2_staticBody,
} from '../../src/index';
import type { b2Body, b2GearJoint, b2PrismaticJoint, b2RevoluteJoint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Gears extends Test {
  m_joint1: b2RevoluteJoint;
  m_joint2: b2RevoluteJoint;
  m_joint3: b2PrismaticJoint;
  m_joint4: b2GearJoint;
  m_joint5: b2GearJoint;

  constructor() {
    super();
    let ground: b2Body;
    {
      const bd = new b2BodyDef();
      ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(50.0, 0.0), new b2Vec2(-50.0, 0.0));
      ground.CreateFixture(shape, 0.0);
    }

    // Gears co
    {
      const circle1 = new b2CircleShape();
      circle1.m_radius = 1.0;

      const box = new b2PolygonShape();
      box.SetAsBox(0.5, 5.0);

      const circle2 = new b2CircleShape();
      circle2.m_radius = 2.0;

      const bd1 = new b2BodyDef();
      bd1.type = b2_staticBody;
      bd1.position.Set(10.0, 9.0);
      const body1 = this.m_world.CreateBody(bd1);
      body1.CreateFixture(circle1, 0.0);

      const bd2 = new b2BodyDef();
      bd2.type = b2_dynamicBody;
      bd2.position.Set(10.0, 8.0);
      const body2 = this.m_world.CreateBody(bd2);
      body2.CreateFixture(box, 5.0);

      const bd3 = new b2BodyDef();
      bd3.type = b2_dynamicBody;
      bd3.position.Set(10.0, 6.0);
      const body3 = this.m_world.CreateBody(bd3);
      body3.CreateFixture(circle2, 5.0);

      const jd1 = new b2RevoluteJointDef();
      jd1.Initialize(body2, body1, bd1.position);
      const joint1 = this.m_world.CreateJoint(jd1);

      const jd2 = new b2RevoluteJointDef();
      jd2.Initialize(body2, body3, bd3.position);
      const joint2 = this.m_world.CreateJoint(jd2);

      const jd4 = new b2GearJointDef();
      jd4.bodyA = body1;
      jd4.bodyB = body3;
      jd4.joint1 = joint1;
      jd4.joint2 = joint2;
      jd4.ratio = circle2.m_radius / circle1.m_radius;
      this.m_world.CreateJoint(jd4);
    }

    {
      const circle1 = new b2CircleShape();
      circle1.m_radius = 1.0;

      const circle2 = new b2CircleShape();
      circle2.m_radius = 2.0;

      const box = new b2PolygonShape();
      box.SetAsBox(0.5, 5.0);

      const bd1 = new b2BodyDef();
      bd1.type = b2_dynamicBody;
      bd1.position.Set(-3.0, 12.0);
      const body1 = this.m_world.CreateBody(bd1);
      body1.CreateFixture(circle1, 5.0);

      const jd1 = new b2RevoluteJointDef();
      jd1.bodyA = ground;
      jd1.bodyB = body1;
      ground.GetLocalPoint(bd1.position, jd1.localAnchorA);
      body1.GetLocalPoint(bd1.position, jd1.localAnchorB);
      jd1.referenceAngle = body1.GetAngle() - ground.GetAngle();
      this.m_joint1 = this.m_world.CreateJoint(jd1) as b2RevoluteJoint;

      const bd2 = new b2BodyDef();
      bd2.type = b2_dynamicBody;
      bd2.position.Set(0.0, 12.0);
      const body2 = this.m_world.CreateBody(bd2);
      body2.CreateFixture(circle2, 5.0);

      const jd2 = new b2RevoluteJointDef();
      jd2.Initialize(ground, body2, bd2.position);
      this.m_joint2 = this.m_world.CreateJoint(jd2) as b2RevoluteJoint;

      const bd3 = new b2BodyDef();
      bd3.type = b2_dynamicBody;
      bd3.position.Set(2.5, 12.0);
      const body3 = this.m_world.CreateBody(bd3);
      body3.CreateFixture(box, 5.0);

      const jd3 = new b2PrismaticJointDef();
      jd3.Initialize(ground, body3, bd3.position, new b2Vec2(0.0, 1.0));
      jd3.lowerTranslation = -5.0;
      jd3.upperTranslation = 5.0;
      jd3.enableLimit = true;

      this.m_joint3 = this.m_world.CreateJoint(jd3) as b2PrismaticJoint;

      const jd4 = new b2GearJointDef();
      jd4.bodyA = body1;
      jd4.bodyB = body2;
      jd4.joint1 = this.m_joint1;
      jd4.joint2 = this.m_joint2;
      jd4.ratio = circle2.m_radius / circle1.m_radius;
      this.m_joint4 = this.m_world.CreateJoint(jd4) as b2GearJoint;

      const jd5 = new b2GearJointDef();
      jd5.bodyA = body2;
      jd5.bodyB = body3;
      jd5.joint1 = this.m_joint2;
      jd5.joint2 = this.m_joint3;
      jd5.ratio = -1.0 / circle2.m_radius;
      this.m_joint5 = this.m_world.CreateJoint(jd5) as b2GearJoint;
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);

    let ratio = this.m_joint4.GetRatio();
    let value = this.m_joint1.GetJointAngle() + ratio * this.m_joint2.GetJointAngle();
    this.m_debugDraw.DrawString(5, this.m_textLine, 'theta1 + %4.2f * theta2 = %4.2f', ratio, value);
    this.m_textLine += 15;

    ratio = this.m_joint5.GetRatio();
    value = this.m_joint2.GetJointAngle() + ratio * this.m_joint3.GetJointTranslation();
    this.m_debugDraw.DrawString(5, this.m_textLine, 'theta2 + %4.2f * delta = %4.2f', ratio, value);
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new Gears();
  }
}
