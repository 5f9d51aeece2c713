// TheoJansen.h: Theo Jansen's walker. Inspired by a contribution by roman_m; dimensions scooped
// from APE (http://www.cove.org/ape/index.htm). Keys: a left, s brake, d right, m toggles the motor.
import {
  b2AddVV,
  b2BodyDef,
  b2CircleShape,
  b2DistanceJointDef,
  b2EdgeShape,
  b2FixtureDef,
  b2PolygonShape,
  b2RevoluteJointDef,
  b2SubVV,
  b2Vec2,
  b2Vec2_zero,
  b2_dynamicBody,
  b2_pi,
} from '../../src/index';
import type { b2Body, b2RevoluteJoint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

const add = (a: b2Vec2, b: b2Vec2) => b2AddVV(a, b, new b2Vec2());
const sub = (a: b2Vec2, b: b2Vec2) => b2SubVV(a, b, new b2Vec2());

export class TheoJansen extends Test {
  readonly m_offset = new b2Vec2();
  m_chassis: b2Body;
  m_wheel: b2Body;
  m_motorJoint: b2RevoluteJoint;
  m_motorOn: boolean;
  m_motorSpeed: number;

  CreateLeg(s: number, wheelAnchor: b2Vec2): void {
    const p1 = new b2Vec2(5.4 * s, -6.1);
    const p2 = new b2Vec2(7.2 * s, -1.2);
    const p3 = new b2Vec2(4.3 * s, -1.9);
    const p4 = new b2Vec2(3.1 * s, 0.8);
    const p5 = new b2Vec2(6.0 * s, 1.5);
    const p6 = new b2Vec2(2.5 * s, 3.7);

    const fd1 = new b2FixtureDef();
    const fd2 = new b2FixtureDef();
    fd1.filter.groupIndex = -1;
    fd2.filter.groupIndex = -1;
    fd1.density = 1.0;
    fd2.density = 1.0;

    const poly1 = new b2PolygonShape();
    const poly2 = new b2PolygonShape();

    if (s > 0.0) {
      poly1.Set([p1, p2, p3], 3);
      poly2.Set([b2Vec2_zero, sub(p5, p4), sub(p6, p4)], 3);
    } else {
      poly1.Set([p1, p3, p2], 3);
      poly2.Set([b2Vec2_zero, sub(p6, p4), sub(p5, p4)], 3);
    }

    fd1.shape = poly1;
    fd2.shape = poly2;

    const bd1 = new b2BodyDef();
    const bd2 = new b2BodyDef();
    bd1.type = b2_dynamicBody;
    bd2.type = b2_dynamicBody;
    bd1.position.Assign(this.m_offset);
    bd2.position.Assign(add(p4, this.m_offset));

    bd1.angularDamping = 10.0;
    bd2.angularDamping = 10.0;

    const body1 = this.m_world.CreateBody(bd1);
    const body2 = this.m_world.CreateBody(bd2);

    body1.CreateFixture(fd1);
    body2.CreateFixture(fd2);

    const djd = new b2DistanceJointDef();

    // Using a soft distance constraint can reduce some jitter. It also makes the structure seem a
    // bit more fluid by acting like a suspension system.
    djd.dampingRatio = 0.5;
    djd.frequencyHz = 10.0;

    djd.Initialize(body1, body2, add(p2, this.m_offset), add(p5, this.m_offset));
    this.m_world.CreateJoint(djd);

    djd.Initialize(body1, body2, add(p3, this.m_offset), add(p4, this.m_offset));
    this.m_world.CreateJoint(djd);

    djd.Initialize(body1, this.m_wheel, add(p3, this.m_offset), add(wheelAnchor, this.m_offset));
    this.m_world.CreateJoint(djd);

    djd.Initialize(body2, this.m_wheel, add(p6, this.m_offset), add(wheelAnchor, this.m_offset));
    this.m_world.CreateJoint(djd);

    const rjd = new b2RevoluteJointDef();

    rjd.Initialize(body2, this.m_chassis, add(p4, this.m_offset));
    this.m_world.CreateJoint(rjd);
  }

  constructor() {
    super();
    this.m_offset.Set(0.0, 8.0);
    this.m_motorSpeed = 2.0;
    this.m_motorOn = true;
    const pivot = new b2Vec2(0.0, 0.8);

    // Ground
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-50.0, 0.0), new b2Vec2(50.0, 0.0));
      ground.CreateFixture(shape, 0.0);

      shape.Set(new b2Vec2(-50.0, 0.0), new b2Vec2(-50.0, 10.0));
      ground.CreateFixture(shape, 0.0);

      shape.Set(new b2Vec2(50.0, 0.0), new b2Vec2(50.0, 10.0));
      ground.CreateFixture(shape, 0.0);
    }

    // Balls
    for (let i = 0; i < 40; ++i) {
      const shape = new b2CircleShape();
      shape.m_radius = 0.25;

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(-40.0 + 2.0 * i, 0.5);

      const body = this.m_world.CreateBody(bd);
      body.CreateFixture(shape, 1.0);
    }

    // Chassis
    {
      const shape = new b2PolygonShape();
      shape.SetAsBox(2.5, 1.0);

      const sd = new b2FixtureDef();
      sd.density = 1.0;
      sd.shape = shape;
      sd.filter.groupIndex = -1;
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Assign(add(pivot, this.m_offset));
      this.m_chassis = this.m_world.CreateBody(bd);
      this.m_chassis.CreateFixture(sd);
    }

    {
      const shape = new b2CircleShape();
      shape.m_radius = 1.6;

      const sd = new b2FixtureDef();
      sd.density = 1.0;
      sd.shape = shape;
      sd.filter.groupIndex = -1;
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Assign(add(pivot, this.m_offset));
      this.m_wheel = this.m_world.CreateBody(bd);
      this.m_wheel.CreateFixture(sd);
    }

    {
      const jd = new b2RevoluteJointDef();
      jd.Initialize(this.m_wheel, this.m_chassis, add(pivot, this.m_offset));
      jd.collideConnected = false;
      jd.motorSpeed = this.m_motorSpeed;
      jd.maxMotorTorque = 400.0;
      jd.enableMotor = this.m_motorOn;
      this.m_motorJoint = this.m_world.CreateJoint(jd) as b2RevoluteJoint;
    }

    const wheelAnchor = add(pivot, new b2Vec2(0.0, -0.8));

    this.CreateLeg(-1.0, wheelAnchor);
    this.CreateLeg(1.0, wheelAnchor);

    this.m_wheel.SetTransform(this.m_wheel.GetPosition(), (120.0 * b2_pi) / 180.0);
    this.CreateLeg(-1.0, wheelAnchor);
    this.CreateLeg(1.0, wheelAnchor);

    this.m_wheel.SetTransform(this.m_wheel.GetPosition(), (-120.0 * b2_pi) / 180.0);
    this.CreateLeg(-1.0, wheelAnchor);
    this.CreateLeg(1.0, wheelAnchor);
  }

  override Step(settings: Settings): void {
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Keys: left = a, brake = s, right = d, toggle motor = m');
    this.m_textLine += 15;

    super.Step(settings);
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'a':
        this.m_motorJoint.SetMotorSpeed(-this.m_motorSpeed);
        break;

      case 's':
        this.m_motorJoint.SetMotorSpeed(0.0);
        break;

      case 'd':
        this.m_motorJoint.SetMotorSpeed(this.m_motorSpeed);
        break;

      case 'm':
        this.m_motorJoint.EnableMotor(!this.m_motorJoint.IsMotorEnabled());
        break;
    }
  }

  static Create(): Test {
    return new TheoJansen();
  }
}
