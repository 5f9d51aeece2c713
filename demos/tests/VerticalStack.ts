// VerticalStack.h: five columns of 16 boxes; ',' fires a bullet at them.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2FixtureDef, b2PolygonShape, b2Vec2, b2_dynamicBody } from '../../src/index';
import type { b2Body } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class VerticalStack extends Test {
  static readonly e_columnCount = 5;
  static readonly e_rowCount = 16;

  m_bullet: b2Body | null;
  readonly m_bodies: b2Body[] = [];
  readonly m_indices: { index: number }[] = [];

  constructor() {
    super();
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));
      ground.CreateFixture(shape, 0.0);

      shape.Set(new b2Vec2(20.0, 0.0), new b2Vec2(20.0, 20.0));
      ground.CreateFixture(shape, 0.0);
    }

    const xs = [0.0, -10.0, -5.0, 5.0, 10.0];

    for (let j = 0; j < VerticalStack.e_columnCount; ++j) {
      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 0.5);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 1.0;
      fd.friction = 0.3;

      for (let i = 0; i < VerticalStack.e_rowCount; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;

        const n = j * VerticalStack.e_rowCount + i;
        this.m_indices[n] = { index: n };
        bd.userData = this.m_indices[n];

        const x = 0.0;
        //float32 x = RandomFloat(-0.02f, 0.02f);
        //float32 x = i % 2 == 0 ? -0.025f : 0.025f;
        bd.position.Set(xs[j] + x, 0.752 + 1.54 * i);
        const body = this.m_world.CreateBody(bd);

        this.m_bodies[n] = body;

        body.CreateFixture(fd);
      }
    }

    this.m_bullet = null;
  }

  override Keyboard(key: string): void {
    switch (key) {
      case ',':
        if (this.m_bullet !== null) {
          this.m_world.DestroyBody(this.m_bullet);
          this.m_bullet = null;
        }

        {
          const shape = new b2CircleShape();
          shape.m_radius = 0.25;

          const fd = new b2FixtureDef();
          fd.shape = shape;
          fd.density = 20.0;
          fd.restitution = 0.05;

          const bd = new b2BodyDef();
          bd.type = b2_dynamicBody;
          bd.bullet = true;
          bd.position.Set(-31.0, 5.0);

          this.m_bullet = this.m_world.CreateBody(bd);
          this.m_bullet.CreateFixture(fd);

          this.m_bullet.SetLinearVelocity(new b2Vec2(400.0, 0.0));
        }
        break;
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Press: (,) to launch a bullet.');
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new VerticalStack();
  }
}
