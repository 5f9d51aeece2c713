// ApplyForce.h: top-down friction with friction joints; w/a/d push and turn the ship.
import {
  b2BodyDef,
  b2EdgeShape,
  b2FixtureDef,
  b2FrictionJointDef,
  b2MulXV,
  b2PolygonShape,
  b2Sqrt,
  b2Transform,
  b2Vec2,
  b2_dynamicBody,
  b2_pi,
} from '../../src/index';
import type { b2Body } from '../../src/index';
import { Test } from '../framework/test';

export class ApplyForce extends Test {
  m_body: b2Body;

  constructor() {
    super();
    this.m_world.SetGravity(new b2Vec2(0.0, 0.0));

    const k_restitution = 0.4;

    let ground: b2Body;
    {
      const bd = new b2BodyDef();
      bd.position.Set(0.0, 20.0);
      ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();

      const sd = new b2FixtureDef();
      sd.shape = shape;
      sd.density = 0.0;
      sd.restitution = k_restitution;

      // Left vertical
      shape.Set(new b2Vec2(-20.0, -20.0), new b2Vec2(-20.0, 20.0));
      ground.CreateFixture(sd);

      // Right vertical
      shape.Set(new b2Vec2(20.0, -20.0), new b2Vec2(20.0, 20.0));
      ground.CreateFixture(sd);

      // Top horizontal
      shape.Set(new b2Vec2(-20.0, 20.0), new b2Vec2(20.0, 20.0));
      ground.CreateFixture(sd);

      // Bottom horizontal
      shape.Set(new b2Vec2(-20.0, -20.0), new b2Vec2(20.0, -20.0));
      ground.CreateFixture(sd);
    }

    {
      const xf1 = new b2Transform();
      xf1.q.Set(0.3524 * b2_pi);
      xf1.q.GetXAxis(xf1.p);

      const vertices = [new b2Vec2(), new b2Vec2(), new b2Vec2()];
      b2MulXV(xf1, new b2Vec2(-1.0, 0.0), vertices[0]);
      b2MulXV(xf1, new b2Vec2(1.0, 0.0), vertices[1]);
      b2MulXV(xf1, new b2Vec2(0.0, 0.5), vertices[2]);

      const poly1 = new b2PolygonShape();
      poly1.Set(vertices, 3);

      const sd1 = new b2FixtureDef();
      sd1.shape = poly1;
      sd1.density = 4.0;

      const xf2 = new b2Transform();
      xf2.q.Set(-0.3524 * b2_pi);
      xf2.q.GetXAxis(xf2.p);
      xf2.p.Set(-xf2.p.x, -xf2.p.y);

      b2MulXV(xf2, new b2Vec2(-1.0, 0.0), vertices[0]);
      b2MulXV(xf2, new b2Vec2(1.0, 0.0), vertices[1]);
      b2MulXV(xf2, new b2Vec2(0.0, 0.5), vertices[2]);

      const poly2 = new b2PolygonShape();
      poly2.Set(vertices, 3);

      const sd2 = new b2FixtureDef();
      sd2.shape = poly2;
      sd2.density = 2.0;

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.angularDamping = 5.0;
      bd.linearDamping = 0.1;

      bd.position.Set(0.0, 2.0);
      bd.angle = b2_pi;
      bd.allowSleep = false;
      this.m_body = this.m_world.CreateBody(bd);
      this.m_body.CreateFixture(sd1);
      this.m_body.CreateFixture(sd2);
    }

    {
      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 0.5);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 1.0;
      fd.friction = 0.3;

      for (let i = 0; i < 10; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;

        bd.position.Set(0.0, 5.0 + 1.54 * i);
        const body = this.m_world.CreateBody(bd);

        body.CreateFixture(fd);

        const gravity = 10.0;
        const I = body.GetInertia();
        const mass = body.GetMass();

        // For a circle: I = 0.5 * m * r * r ==> r = sqrt(2 * I / m)
        const radius = b2Sqrt((2.0 * I) / mass);

        const jd = new b2FrictionJointDef();
        jd.localAnchorA.SetZero();
        jd.localAnchorB.SetZero();
        jd.bodyA = ground;
        jd.bodyB = body;
        jd.collideConnected = true;
        jd.maxForce = mass * gravity;
        jd.maxTorque = mass * radius * gravity;

        this.m_world.CreateJoint(jd);
      }
    }
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'w':
        {
          const f = this.m_body.GetWorldVector(new b2Vec2(0.0, -200.0));
          const p = this.m_body.GetWorldPoint(new b2Vec2(0.0, 2.0));
          this.m_body.ApplyForce(f, p);
        }
        break;

      case 'a':
        this.m_body.ApplyTorque(50.0);
        break;

      case 'd':
        this.m_body.ApplyTorque(-50.0);
        break;
    }
  }

  static Create(): Test {
    return new ApplyForce();
  }
}
