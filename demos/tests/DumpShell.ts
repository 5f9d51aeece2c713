// DumpShell.h: a world pasted from b2World::Dump (the C++ the dump prints, as it prints it).
import { b2BodyDef, b2EdgeShape, b2FixtureDef, b2PolygonShape, b2PrismaticJointDef, b2RevoluteJointDef, b2Vec2 } from '../../src/index';
import type { b2Body, b2BodyType, b2Joint } from '../../src/index';
import { Test } from '../framework/test';

export class DumpShell extends Test {
  constructor() {
    super();
    const g = new b2Vec2(0.0, 0.0);
    this.m_world.SetGravity(g);
    const bodies: b2Body[] = new Array(3);
    const joints: b2Joint[] = new Array(2);
    {
      const bd = new b2BodyDef();
      bd.type = 2 as b2BodyType;
      bd.position.Set(1.304347801208496e1, 2.5);
      bd.angle = 0.0;
      bd.linearVelocity.Set(0.0, 0.0);
      bd.angularVelocity = 0.0;
      bd.linearDamping = 5.0e-1;
      bd.angularDamping = 5.0e-1;
      bd.allowSleep = Boolean(4);
      bd.awake = Boolean(2);
      bd.fixedRotation = Boolean(0);
      bd.bullet = Boolean(0);
      bd.active = Boolean(32);
      bd.gravityScale = 1.0;
      bodies[0] = this.m_world.CreateBody(bd);

      {
        const fd = new b2FixtureDef();
        fd.friction = 1.0;
        fd.restitution = 5.0e-1;
        fd.density = 1.0e1;
        fd.isSensor = Boolean(0);
        fd.filter.categoryBits = 1;
        fd.filter.maskBits = 65535;
        fd.filter.groupIndex = 0;
        const shape = new b2PolygonShape();
        const vs = [
          new b2Vec2(-6.900000095367432, -3.00000011920929e-1),
          new b2Vec2(2.000000029802322e-1, -3.00000011920929e-1),
          new b2Vec2(2.000000029802322e-1, 2.000000029802322e-1),
          new b2Vec2(-6.900000095367432, 2.000000029802322e-1),
        ];
        shape.Set(vs, 4);

        fd.shape = shape;

        bodies[0].CreateFixture(fd);
      }
    }
    {
      const bd = new b2BodyDef();
      bd.type = 2 as b2BodyType;
      bd.position.Set(8.478260636329651e-1, 2.5);
      bd.angle = 0.0;
      bd.linearVelocity.Set(0.0, 0.0);
      bd.angularVelocity = 0.0;
      bd.linearDamping = 5.0e-1;
      bd.angularDamping = 5.0e-1;
      bd.allowSleep = Boolean(4);
      bd.awake = Boolean(2);
      bd.fixedRotation = Boolean(0);
      bd.bullet = Boolean(0);
      bd.active = Boolean(32);
      bd.gravityScale = 1.0;
      bodies[1] = this.m_world.CreateBody(bd);

      {
        const fd = new b2FixtureDef();
        fd.friction = 1.0;
        fd.restitution = 5.0e-1;
        fd.density = 1.0e1;
        fd.isSensor = Boolean(0);
        fd.filter.categoryBits = 1;
        fd.filter.maskBits = 65535;
        fd.filter.groupIndex = 0;
        const shape = new b2PolygonShape();
        const vs = [
          new b2Vec2(-3.228000104427338e-1, -2.957000136375427e-1),
          new b2Vec2(6.885900020599365, -3.641000092029572e-1),
          new b2Vec2(6.907599925994873, 3.271999955177307e-1),
          new b2Vec2(-3.228000104427338e-1, 2.825999855995178e-1),
        ];
        shape.Set(vs, 4);

        fd.shape = shape;

        bodies[1].CreateFixture(fd);
      }
    }
    {
      const bd = new b2BodyDef();
      bd.type = 0 as b2BodyType;
      bd.position.Set(0.0, 0.0);
      bd.angle = 0.0;
      bd.linearVelocity.Set(0.0, 0.0);
      bd.angularVelocity = 0.0;
      bd.linearDamping = 0.0;
      bd.angularDamping = 0.0;
      bd.allowSleep = Boolean(4);
      bd.awake = Boolean(2);
      bd.fixedRotation = Boolean(0);
      bd.bullet = Boolean(0);
      bd.active = Boolean(32);
      bd.gravityScale = 1.0;
      bodies[2] = this.m_world.CreateBody(bd);

      // The four edges of the dump: vertex1 and vertex2 of each (vertex0/3 are zero, unused).
      const edges: [number, number, number, number][] = [
        [4.45217399597168e1, 1.669565200805664e1, 4.45217399597168e1, 0.0],
        [0.0, 1.669565200805664e1, 0.0, 0.0],
        [0.0, 1.669565200805664e1, 4.45217399597168e1, 1.669565200805664e1],
        [0.0, 0.0, 4.45217399597168e1, 0.0],
      ];
      for (const [x1, y1, x2, y2] of edges) {
        const fd = new b2FixtureDef();
        fd.friction = 1.0e1;
        fd.restitution = 0.0;
        fd.density = 0.0;
        fd.isSensor = Boolean(0);
        fd.filter.categoryBits = 1;
        fd.filter.maskBits = 65535;
        fd.filter.groupIndex = 0;
        const shape = new b2EdgeShape();
        shape.m_radius = 9.999999776482582e-3;
        shape.m_vertex0.Set(0.0, 0.0);
        shape.m_vertex1.Set(x1, y1);
        shape.m_vertex2.Set(x2, y2);
        shape.m_vertex3.Set(0.0, 0.0);
        shape.m_hasVertex0 = Boolean(0);
        shape.m_hasVertex3 = Boolean(0);

        fd.shape = shape;

        bodies[2].CreateFixture(fd);
      }
    }
    {
      const jd = new b2PrismaticJointDef();
      jd.bodyA = bodies[1];
      jd.bodyB = bodies[0];
      jd.collideConnected = Boolean(0);
      jd.localAnchorA.Set(0.0, 0.0);
      jd.localAnchorB.Set(-1.219565200805664e1, 0.0);
      jd.localAxisA.Set(-1.219565200805664e1, 0.0);
      jd.referenceAngle = 0.0;
      jd.enableLimit = Boolean(1);
      jd.lowerTranslation = -2.0e1;
      jd.upperTranslation = 0.0;
      jd.enableMotor = Boolean(1);
      jd.motorSpeed = 0.0;
      jd.maxMotorForce = 1.0e1;
      joints[0] = this.m_world.CreateJoint(jd);
    }
    {
      const jd = new b2RevoluteJointDef();
      jd.bodyA = bodies[1];
      jd.bodyB = bodies[2];
      jd.collideConnected = Boolean(0);
      jd.localAnchorA.Set(0.0, 0.0);
      jd.localAnchorB.Set(8.478260636329651e-1, 2.5);
      jd.referenceAngle = 0.0;
      jd.enableLimit = Boolean(0);
      jd.lowerAngle = 0.0;
      jd.upperAngle = 0.0;
      jd.enableMotor = Boolean(0);
      jd.motorSpeed = 0.0;
      jd.maxMotorTorque = 0.0;
      joints[1] = this.m_world.CreateJoint(jd);
    }
  }

  static Create(): Test {
    return new DumpShell();
  }
}
