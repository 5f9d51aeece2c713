// Car.h: a fun demo that shows off the wheel joint.
import {
  b2BodyDef,
  b2CircleShape,
  b2EdgeShape,
  b2FixtureDef,
  b2Max,
  b2PolygonShape,
  b2RevoluteJointDef,
  b2Vec2,
  b2WheelJointDef,
  b2_dynamicBody,
  b2_pi,
} from '../../src/index';
import type { b2Body, b2WheelJoint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Car extends Test {
  m_car: b2Body;
  m_wheel1: b2Body;
  m_wheel2: b2Body;

  m_hz: number;
  m_zeta: number;
  m_speed: number;
  m_spring1: b2WheelJoint;
  m_spring2: b2WheelJoint;

  constructor() {
    super();
    this.m_hz = 4.0;
    this.m_zeta = 0.7;
    this.m_speed = 50.0;

    let ground: b2Body;
    {
      const bd = new b2BodyDef();
      ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 0.0;
      fd.friction = 0.6;

      shape.Set(new b2Vec2(-20.0, 0.0), new b2Vec2(20.0, 0.0));
      ground.CreateFixture(fd);

      const hs = [0.25, 1.0, 4.0, 0.0, 0.0, -1.0, -2.0, -2.0, -1.25, 0.0];

      let x = 20.0;
      let y1 = 0.0;
      const dx = 5.0;

      for (let i = 0; i < 10; ++i) {
        const y2 = hs[i];
        shape.Set(new b2Vec2(x, y1), new b2Vec2(x + dx, y2));
        ground.CreateFixture(fd);
        y1 = y2;
        x += dx;
      }

      for (let i = 0; i < 10; ++i) {
        const y2 = hs[i];
        shape.Set(new b2Vec2(x, y1), new b2Vec2(x + dx, y2));
        ground.CreateFixture(fd);
        y1 = y2;
        x += dx;
      }

      shape.Set(new b2Vec2(x, 0.0), new b2Vec2(x + 40.0, 0.0));
      ground.CreateFixture(fd);

      x += 80.0;
      shape.Set(new b2Vec2(x, 0.0), new b2Vec2(x + 40.0, 0.0));
      ground.CreateFixture(fd);

      x += 40.0;
      shape.Set(new b2Vec2(x, 0.0), new b2Vec2(x + 10.0, 5.0));
      ground.CreateFixture(fd);

      x += 20.0;
      shape.Set(new b2Vec2(x, 0.0), new b2Vec2(x + 40.0, 0.0));
      ground.CreateFixture(fd);

      x += 40.0;
      shape.Set(new b2Vec2(x, 0.0), new b2Vec2(x, 20.0));
      ground.CreateFixture(fd);
    }

    // Teeter
    {
      const bd = new b2BodyDef();
      bd.position.Set(140.0, 1.0);
      bd.type = b2_dynamicBody;
      const body = this.m_world.CreateBody(bd);

      const box = new b2PolygonShape();
      box.SetAsBox(10.0, 0.25);
      body.CreateFixture(box, 1.0);

      const jd = new b2RevoluteJointDef();
      jd.Initialize(ground, body, body.GetPosition());
      jd.lowerAngle = (-8.0 * b2_pi) / 180.0;
      jd.upperAngle = (8.0 * b2_pi) / 180.0;
      jd.enableLimit = true;
      this.m_world.CreateJoint(jd);

      body.ApplyAngularImpulse(100.0);
    }

    // Bridge
    {
      const N = 20;
      const shape = new b2PolygonShape();
      shape.SetAsBox(1.0, 0.125);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 1.0;
      fd.friction = 0.6;

      const jd = new b2RevoluteJointDef();

      let prevBody = ground;
      for (let i = 0; i < N; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(161.0 + 2.0 * i, -0.125);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(fd);

        const anchor = new b2Vec2(160.0 + 2.0 * i, -0.125);
        jd.Initialize(prevBody, body, anchor);
        this.m_world.CreateJoint(jd);

        prevBody = body;
      }

      const anchor = new b2Vec2(160.0 + 2.0 * N, -0.125);
      jd.Initialize(prevBody, ground, anchor);
      this.m_world.CreateJoint(jd);
    }

    // Boxes
    {
      const box = new b2PolygonShape();
      box.SetAsBox(0.5, 0.5);

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;

      for (const y of [0.5, 1.5, 2.5, 3.5, 4.5]) {
        bd.position.Set(230.0, y);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(box, 0.5);
      }
    }

    // Car
    {
      const chassis = new b2PolygonShape();
      const vertices = [
        new b2Vec2(-1.5, -0.5),
        new b2Vec2(1.5, -0.5),
        new b2Vec2(1.5, 0.0),
        new b2Vec2(0.0, 0.9),
        new b2Vec2(-1.15, 0.9),
        new b2Vec2(-1.5, 0.2),
      ];
      chassis.Set(vertices, 6);

      const circle = new b2CircleShape();
      circle.m_radius = 0.4;

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(0.0, 1.0);
      this.m_car = this.m_world.CreateBody(bd);
      this.m_car.CreateFixture(chassis, 1.0);

      const fd = new b2FixtureDef();
      fd.shape = circle;
      fd.density = 1.0;
      fd.friction = 0.9;

      bd.position.Set(-1.0, 0.35);
      this.m_wheel1 = this.m_world.CreateBody(bd);
      this.m_wheel1.CreateFixture(fd);

      bd.position.Set(1.0, 0.4);
      this.m_wheel2 = this.m_world.CreateBody(bd);
      this.m_wheel2.CreateFixture(fd);

      const jd = new b2WheelJointDef();
      const axis = new b2Vec2(0.0, 1.0);

      jd.Initialize(this.m_car, this.m_wheel1, this.m_wheel1.GetPosition(), axis);
      jd.motorSpeed = 0.0;
      jd.maxMotorTorque = 20.0;
      jd.enableMotor = true;
      jd.frequencyHz = this.m_hz;
      jd.dampingRatio = this.m_zeta;
      this.m_spring1 = this.m_world.CreateJoint(jd) as b2WheelJoint;

      jd.Initialize(this.m_car, this.m_wheel2, this.m_wheel2.GetPosition(), axis);
      jd.motorSpeed = 0.0;
      jd.maxMotorTorque = 10.0;
      jd.enableMotor = false;
      jd.frequencyHz = this.m_hz;
      jd.dampingRatio = this.m_zeta;
      this.m_spring2 = this.m_world.CreateJoint(jd) as b2WheelJoint;
    }
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'a':
        this.m_spring1.SetMotorSpeed(this.m_speed);
        break;

      case 's':
        this.m_spring1.SetMotorSpeed(0.0);
        break;

      case 'd':
        this.m_spring1.SetMotorSpeed(-this.m_speed);
        break;

      case 'q':
        this.m_hz = b2Max(0.0, this.m_hz - 1.0);
        this.m_spring1.SetSpringFrequencyHz(this.m_hz);
        this.m_spring2.SetSpringFrequencyHz(this.m_hz);
        break;

      case 'e':
        this.m_hz += 1.0;
        this.m_spring1.SetSpringFrequencyHz(this.m_hz);
        this.m_spring2.SetSpringFrequencyHz(this.m_hz);
        break;
    }
  }

  override Step(settings: Settings): void {
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Keys: left = a, brake = s, right = d, hz down = q, hz up = e');
    this.m_textLine += 15;
    this.m_debugDraw.DrawString(5, this.m_textLine, 'frequency = %g hz, damping ratio = %g', this.m_hz, this.m_zeta);
    this.m_textLine += 15;

    settings.viewCenter.x = this.m_car.GetPosition().x;
    super.Step(settings);
  }

  static Create(): Test {
    return new Car();
  }
}
