// Pinball.h: bullet collision in a gameplay scenario, with a chain loop; 'a' works the flippers.
import { b2BodyDef, b2ChainShape, b2CircleShape, b2FixtureDef, b2PolygonShape, b2RevoluteJointDef, b2Vec2, b2_dynamicBody, b2_pi } from '../../src/index';
import type { b2Body, b2RevoluteJoint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Pinball extends Test {
  m_leftJoint: b2RevoluteJoint;
  m_rightJoint: b2RevoluteJoint;
  m_ball: b2Body;
  m_button: boolean;

  constructor() {
    super();
    // Ground body
    let ground: b2Body;
    {
      const bd = new b2BodyDef();
      ground = this.m_world.CreateBody(bd);

      const vs = [new b2Vec2(0.0, -2.0), new b2Vec2(8.0, 6.0), new b2Vec2(8.0, 20.0), new b2Vec2(-8.0, 20.0), new b2Vec2(-8.0, 6.0)];

      const loop = new b2ChainShape();
      loop.CreateLoop(vs, 5);
      const fd = new b2FixtureDef();
      fd.shape = loop;
      fd.density = 0.0;
      ground.CreateFixture(fd);
    }

    // Flippers
    {
      const p1 = new b2Vec2(-2.0, 0.0);
      const p2 = new b2Vec2(2.0, 0.0);

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;

      bd.position.Assign(p1);
      const leftFlipper = this.m_world.CreateBody(bd);

      bd.position.Assign(p2);
      const rightFlipper = this.m_world.CreateBody(bd);

      const box = new b2PolygonShape();
      box.SetAsBox(1.75, 0.1);

      const fd = new b2FixtureDef();
      fd.shape = box;
      fd.density = 1.0;

      leftFlipper.CreateFixture(fd);
      rightFlipper.CreateFixture(fd);

      const jd = new b2RevoluteJointDef();
      jd.bodyA = ground;
      jd.localAnchorB.SetZero();
      jd.enableMotor = true;
      jd.maxMotorTorque = 1000.0;
      jd.enableLimit = true;

      jd.motorSpeed = 0.0;
      jd.localAnchorA.Assign(p1);
      jd.bodyB = leftFlipper;
      jd.lowerAngle = (-30.0 * b2_pi) / 180.0;
      jd.upperAngle = (5.0 * b2_pi) / 180.0;
      this.m_leftJoint = this.m_world.CreateJoint(jd) as b2RevoluteJoint;

      jd.motorSpeed = 0.0;
      jd.localAnchorA.Assign(p2);
      jd.bodyB = rightFlipper;
      jd.lowerAngle = (-5.0 * b2_pi) / 180.0;
      jd.upperAngle = (30.0 * b2_pi) / 180.0;
      this.m_rightJoint = this.m_world.CreateJoint(jd) as b2RevoluteJoint;
    }

    // Circle character
    {
      const bd = new b2BodyDef();
      bd.position.Set(1.0, 15.0);
      bd.type = b2_dynamicBody;
      bd.bullet = true;

      this.m_ball = this.m_world.CreateBody(bd);

      const shape = new b2CircleShape();
      shape.m_radius = 0.2;

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 1.0;
      this.m_ball.CreateFixture(fd);
    }

    this.m_button = false;
  }

  override Step(settings: Settings): void {
    if (this.m_button) {
      this.m_leftJoint.SetMotorSpeed(20.0);
      this.m_rightJoint.SetMotorSpeed(-20.0);
    } else {
      this.m_leftJoint.SetMotorSpeed(-10.0);
      this.m_rightJoint.SetMotorSpeed(10.0);
    }

    super.Step(settings);

    this.m_debugDraw.DrawString(5, this.m_textLine, "Press 'a' to control the flippers");
    this.m_textLine += 15;
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'a':
      case 'A':
        this.m_button = true;
        break;
    }
  }

  override KeyboardUp(key: string): void {
    switch (key) {
      case 'a':
      case 'A':
        this.m_button = false;
        break;
    }
  }

  static Create(): Test {
    return new Pinball();
  }
}
