// Revolute.h: revolute joints with limits and a motor, a bullet plank, mask filtering, and the
// mass of a small polygon far from the origin. Keys: l limits, m motor.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2FixtureDef, b2PolygonShape, b2RevoluteJointDef, b2Vec2, b2_dynamicBody, b2_pi } from '../../src/index';
import type { b2Body, b2RevoluteJoint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Revolute extends Test {
  m_ball: b2Body;
  m_joint: b2RevoluteJoint;

  constructor() {
    super();
    let ground: b2Body;
    {
      const bd = new b2BodyDef();
      ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));

      const fd = new b2FixtureDef();
      fd.shape = shape;
      //fd.filter.categoryBits = 2;

      ground.CreateFixture(fd);
    }

    {
      const shape = new b2CircleShape();
      shape.m_radius = 0.5;

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;

      const rjd = new b2RevoluteJointDef();

      bd.position.Set(-10.0, 20.0);
      const body = this.m_world.CreateBody(bd);
      body.CreateFixture(shape, 5.0);

      const w = 100.0;
      body.SetAngularVelocity(w);
      body.SetLinearVelocity(new b2Vec2(-8.0 * w, 0.0));

      rjd.Initialize(ground, body, new b2Vec2(-10.0, 12.0));
      rjd.motorSpeed = 1.0 * b2_pi;
      rjd.maxMotorTorque = 10000.0;
      rjd.enableMotor = false;
      rjd.lowerAngle = -0.25 * b2_pi;
      rjd.upperAngle = 0.5 * b2_pi;
      rjd.enableLimit = true;
      rjd.collideConnected = true;

      this.m_joint = this.m_world.CreateJoint(rjd) as b2RevoluteJoint;
    }

    {
      const circle_shape = new b2CircleShape();
      circle_shape.m_radius = 3.0;

      const circle_bd = new b2BodyDef();
      circle_bd.type = b2_dynamicBody;
      circle_bd.position.Set(5.0, 30.0);

      const fd = new b2FixtureDef();
      fd.density = 5.0;
      fd.filter.maskBits = 1;
      fd.shape = circle_shape;

      this.m_ball = this.m_world.CreateBody(circle_bd);
      this.m_ball.CreateFixture(fd);

      const polygon_shape = new b2PolygonShape();
      polygon_shape.SetAsBox(10.0, 0.2, new b2Vec2(-10.0, 0.0), 0.0);

      const polygon_bd = new b2BodyDef();
      polygon_bd.position.Set(20.0, 10.0);
      polygon_bd.type = b2_dynamicBody;
      polygon_bd.bullet = true;
      const polygon_body = this.m_world.CreateBody(polygon_bd);
      polygon_body.CreateFixture(polygon_shape, 2.0);

      const rjd = new b2RevoluteJointDef();
      rjd.Initialize(ground, polygon_body, new b2Vec2(20.0, 10.0));
      rjd.lowerAngle = -0.25 * b2_pi;
      rjd.upperAngle = 0.0 * b2_pi;
      rjd.enableLimit = true;
      this.m_world.CreateJoint(rjd);
    }

    // Tests mass computation of a small object far from the origin
    {
      const bodyDef = new b2BodyDef();
      bodyDef.type = b2_dynamicBody;
      const body = this.m_world.CreateBody(bodyDef);

      const polyShape = new b2PolygonShape();
      const verts = [new b2Vec2(17.63, 36.31), new b2Vec2(17.52, 36.69), new b2Vec2(17.19, 36.36)];
      polyShape.Set(verts, 3);

      const polyFixtureDef = new b2FixtureDef();
      polyFixtureDef.shape = polyShape;
      polyFixtureDef.density = 1;

      body.CreateFixture(polyFixtureDef); //assertion hits inside here
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
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Keys: (l) limits, (m) motor');
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new Revolute();
  }
}
