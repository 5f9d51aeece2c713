// SliderCrank.h: a motor driven slider crank with joint friction. Keys: f friction, m motor.
import { b2BodyDef, b2EdgeShape, b2PolygonShape, b2PrismaticJointDef, b2RevoluteJointDef, b2Vec2, b2_dynamicBody, b2_pi } from '../../src/index';
import type { b2Body, b2PrismaticJoint, b2RevoluteJoint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class SliderCrank extends Test {
  m_joint1: b2RevoluteJoint;
  m_joint2: b2PrismaticJoint;

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
      let prevBody = ground;

      // Define crank.
      {
        const shape = new b2PolygonShape();
        shape.SetAsBox(0.5, 2.0);

        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(0.0, 7.0);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(shape, 2.0);

        const rjd = new b2RevoluteJointDef();
        rjd.Initialize(prevBody, body, new b2Vec2(0.0, 5.0));
        rjd.motorSpeed = 1.0 * b2_pi;
        rjd.maxMotorTorque = 10000.0;
        rjd.enableMotor = true;
        this.m_joint1 = this.m_world.CreateJoint(rjd) as b2RevoluteJoint;

        prevBody = body;
      }

      // Define follower.
      {
        const shape = new b2PolygonShape();
        shape.SetAsBox(0.5, 4.0);

        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(0.0, 13.0);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(shape, 2.0);

        const rjd = new b2RevoluteJointDef();
        rjd.Initialize(prevBody, body, new b2Vec2(0.0, 9.0));
        rjd.enableMotor = false;
        this.m_world.CreateJoint(rjd);

        prevBody = body;
      }

      // Define piston
      {
        const shape = new b2PolygonShape();
        shape.SetAsBox(1.5, 1.5);

        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.fixedRotation = true;
        bd.position.Set(0.0, 17.0);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(shape, 2.0);

        const rjd = new b2RevoluteJointDef();
        rjd.Initialize(prevBody, body, new b2Vec2(0.0, 17.0));
        this.m_world.CreateJoint(rjd);

        const pjd = new b2PrismaticJointDef();
        pjd.Initialize(ground, body, new b2Vec2(0.0, 17.0), new b2Vec2(0.0, 1.0));

        pjd.maxMotorForce = 1000.0;
        pjd.enableMotor = true;

        this.m_joint2 = this.m_world.CreateJoint(pjd) as b2PrismaticJoint;
      }

      // Create a payload
      {
        const shape = new b2PolygonShape();
        shape.SetAsBox(1.5, 1.5);

        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(0.0, 23.0);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(shape, 2.0);
      }
    }
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'f':
        this.m_joint2.EnableMotor(!this.m_joint2.IsMotorEnabled());
        this.m_joint2.GetBodyB().SetAwake(true);
        break;

      case 'm':
        this.m_joint1.EnableMotor(!this.m_joint1.IsMotorEnabled());
        this.m_joint1.GetBodyB().SetAwake(true);
        break;
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Keys: (f) toggle friction, (m) toggle motor');
    this.m_textLine += 15;
    const torque = this.m_joint1.GetMotorTorque(settings.hz);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Motor Torque = %5.0f', torque);
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new SliderCrank();
  }
}
