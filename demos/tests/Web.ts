// Web.h: soft distance joints, body destruction and joint destruction. Keys: b deletes a body,
// j deletes a joint; the destruction listener reports the joints a body takes with it.
import { b2BodyDef, b2DistanceJointDef, b2EdgeShape, b2PolygonShape, b2SubVV, b2Vec2, b2_dynamicBody } from '../../src/index';
import type { b2Body, b2Joint } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Web extends Test {
  readonly m_bodies: (b2Body | null)[] = [null, null, null, null];
  readonly m_joints: (b2Joint | null)[] = [null, null, null, null, null, null, null, null];

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
      shape.SetAsBox(0.5, 0.5);

      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;

      const positions: [number, number][] = [
        [-5.0, 5.0],
        [5.0, 5.0],
        [5.0, 15.0],
        [-5.0, 15.0],
      ];
      for (let i = 0; i < 4; ++i) {
        bd.position.Set(positions[i][0], positions[i][1]);
        const body = this.m_world.CreateBody(bd);
        body.CreateFixture(shape, 5.0);
        this.m_bodies[i] = body;
      }
      const bodies = this.m_bodies as b2Body[];

      const jd = new b2DistanceJointDef();
      const p1 = new b2Vec2();
      const p2 = new b2Vec2();
      const d = new b2Vec2();

      jd.frequencyHz = 2.0;
      jd.dampingRatio = 0.0;

      // bodyA, bodyB, localAnchorA, localAnchorB of the eight joints, in the C++ order.
      const joints: [b2Body, b2Body, number, number, number, number][] = [
        [ground, bodies[0], -10.0, 0.0, -0.5, -0.5],
        [ground, bodies[1], 10.0, 0.0, 0.5, -0.5],
        [ground, bodies[2], 10.0, 20.0, 0.5, 0.5],
        [ground, bodies[3], -10.0, 20.0, -0.5, 0.5],
        [bodies[0], bodies[1], 0.5, 0.0, -0.5, 0.0],
        [bodies[1], bodies[2], 0.0, 0.5, 0.0, -0.5],
        [bodies[2], bodies[3], -0.5, 0.0, 0.5, 0.0],
        [bodies[3], bodies[0], 0.0, -0.5, 0.0, 0.5],
      ];
      for (let i = 0; i < 8; ++i) {
        const [bodyA, bodyB, ax, ay, bx, by] = joints[i];
        jd.bodyA = bodyA;
        jd.bodyB = bodyB;
        jd.localAnchorA.Set(ax, ay);
        jd.localAnchorB.Set(bx, by);
        bodyA.GetWorldPoint(jd.localAnchorA, p1);
        bodyB.GetWorldPoint(jd.localAnchorB, p2);
        b2SubVV(p2, p1, d);
        jd.length = d.Length();
        this.m_joints[i] = this.m_world.CreateJoint(jd);
      }
    }
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'b':
        for (let i = 0; i < 4; ++i) {
          if (this.m_bodies[i] !== null) {
            this.m_world.DestroyBody(this.m_bodies[i]!);
            this.m_bodies[i] = null;
            break;
          }
        }
        break;

      case 'j':
        for (let i = 0; i < 8; ++i) {
          if (this.m_joints[i] !== null) {
            this.m_world.DestroyJoint(this.m_joints[i]!);
            this.m_joints[i] = null;
            break;
          }
        }
        break;
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'This demonstrates a soft distance joint.');
    this.m_textLine += 15;
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Press: (b) to delete a body, (j) to delete a joint');
    this.m_textLine += 15;
  }

  override JointDestroyed(joint: b2Joint): void {
    for (let i = 0; i < 8; ++i) {
      if (this.m_joints[i] === joint) {
        this.m_joints[i] = null;
        break;
      }
    }
  }

  static Create(): Test {
    return new Web();
  }
}
