// RopeJoint.h: a rope joint can stabilize a chain of bodies with a heavy payload. The rope joint
// just prevents excessive stretching and has no other effect. By disabling the rope joint you can
// see that the Box2D solver has trouble supporting heavy bodies with light bodies. This test also
// shows contact filtering: the payload does not collide with the chain. Key: j toggles the rope.
import { b2BodyDef, b2EdgeShape, b2FixtureDef, b2PolygonShape, b2RevoluteJointDef, b2RopeJointDef, b2Vec2, b2_dynamicBody } from '../../src/index';
import type { b2Body, b2Joint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class RopeJoint extends Test {
  readonly m_ropeDef = new b2RopeJointDef();
  m_rope: b2Joint | null;

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
      shape.SetAsBox(0.5, 0.125);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;
      fd.friction = 0.2;
      fd.filter.categoryBits = 0x0001;
      fd.filter.maskBits = 0xffff & ~0x0002;

      const jd = new b2RevoluteJointDef();
      jd.collideConnected = false;

      const N = 10;
      const y = 15.0;
      this.m_ropeDef.localAnchorA.Set(0.0, y);

      let prevBody = ground;
      for (let i = 0; i < N; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(0.5 + 1.0 * i, y);
        if (i === N - 1) {
          shape.SetAsBox(1.5, 1.5);
          fd.density = 100.0;
          fd.filter.categoryBits = 0x0002;
          bd.position.Set(1.0 * i, y);
          bd.angularDamping = 0.4;
        }

        const body = this.m_world.CreateBody(bd);

        body.CreateFixture(fd);

        const anchor = new b2Vec2(i, y);
        jd.Initialize(prevBody, body, anchor);
        this.m_world.CreateJoint(jd);

        prevBody = body;
      }

      this.m_ropeDef.localAnchorB.SetZero();

      const extraLength = 0.01;
      this.m_ropeDef.maxLength = N - 1.0 + extraLength;
      this.m_ropeDef.bodyB = prevBody;
    }

    {
      this.m_ropeDef.bodyA = ground;
      this.m_rope = this.m_world.CreateJoint(this.m_ropeDef);
    }
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'j':
        if (this.m_rope !== null) {
          this.m_world.DestroyJoint(this.m_rope);
          this.m_rope = null;
        } else {
          this.m_rope = this.m_world.CreateJoint(this.m_ropeDef);
        }
        break;
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Press (j) to toggle the rope joint.');
    this.m_textLine += 15;
    if (this.m_rope !== null) {
      this.m_debugDraw.DrawString(5, this.m_textLine, 'Rope ON');
    } else {
      this.m_debugDraw.DrawString(5, this.m_textLine, 'Rope OFF');
    }
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new RopeJoint();
  }
}
