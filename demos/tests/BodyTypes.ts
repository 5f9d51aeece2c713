// BodyTypes.h: a platform switched between dynamic, static and kinematic at run time.
import {
  b2BodyDef,
  b2EdgeShape,
  b2FixtureDef,
  b2PolygonShape,
  b2PrismaticJointDef,
  b2RevoluteJointDef,
  b2Vec2,
  b2_dynamicBody,
  b2_kinematicBody,
  b2_pi,
  b2_staticBody,
} from '../../src/index';
import type { b2Body } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class BodyTypes extends Test {
  m_attachment: b2Body;
  m_platform: b2Body;
  m_speed: number;

  constructor() {
    super();
    let ground: b2Body;
    {
      const bd = new b2BodyDef();
      ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-20.0, 0.0), new b2Vec2(20.0, 0.0));

      const fd = new b2FixtureDef();
      fd.shape = shape;

      ground.CreateFixture(fd);
    }

    // Define attachment
    {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(0.0, 3.0);
      this.m_attachment = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 2.0);
      this.m_attachment.CreateFixture(shape, 2.0);
    }

    // Define platform
    {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(-4.0, 5.0);
      this.m_platform = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 4.0, new b2Vec2(4.0, 0.0), 0.5 * b2_pi);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.friction = 0.6;
      fd.density = 2.0;
      this.m_platform.CreateFixture(fd);

      const rjd = new b2RevoluteJointDef();
      rjd.Initialize(this.m_attachment, this.m_platform, new b2Vec2(0.0, 5.0));
      rjd.maxMotorTorque = 50.0;
      rjd.enableMotor = true;
      this.m_world.CreateJoint(rjd);

      const pjd = new b2PrismaticJointDef();
      pjd.Initialize(ground, this.m_platform, new b2Vec2(0.0, 5.0), new b2Vec2(1.0, 0.0));

      pjd.maxMotorForce = 1000.0;
      pjd.enableMotor = true;
      pjd.lowerTranslation = -10.0;
      pjd.upperTranslation = 10.0;
      pjd.enableLimit = true;

      this.m_world.CreateJoint(pjd);

      this.m_speed = 3.0;
    }

    // Create a payload
    {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(0.0, 8.0);
      const body = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(0.75, 0.75);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.friction = 0.6;
      fd.density = 2.0;

      body.CreateFixture(fd);
    }
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'd':
        this.m_platform.SetType(b2_dynamicBody);
        break;

      case 's':
        this.m_platform.SetType(b2_staticBody);
        break;

      case 'k':
        this.m_platform.SetType(b2_kinematicBody);
        this.m_platform.SetLinearVelocity(new b2Vec2(-this.m_speed, 0.0));
        this.m_platform.SetAngularVelocity(0.0);
        break;
    }
  }

  override Step(settings: Settings): void {
    // Drive the kinematic body.
    if (this.m_platform.GetType() === b2_kinematicBody) {
      const p = this.m_platform.GetTransform().p;
      const v = this.m_platform.GetLinearVelocity();

      if ((p.x < -10.0 && v.x < 0.0) || (p.x > 10.0 && v.x > 0.0)) {
        v.x = -v.x;
        this.m_platform.SetLinearVelocity(v);
      }
    }

    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Keys: (d) dynamic, (s) static, (k) kinematic');
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new BodyTypes();
  }
}
