// Confined.h: circles in a box without gravity; 'c' adds a circle.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2FixtureDef, b2Vec2, b2_dynamicBody } from '../../src/index';
import { RandomFloat } from '../framework/random';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Confined extends Test {
  static readonly e_columnCount = 0;
  static readonly e_rowCount = 0;

  constructor() {
    super();
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();

      // Floor
      shape.Set(new b2Vec2(-10.0, 0.0), new b2Vec2(10.0, 0.0));
      ground.CreateFixture(shape, 0.0);

      // Left wall
      shape.Set(new b2Vec2(-10.0, 0.0), new b2Vec2(-10.0, 20.0));
      ground.CreateFixture(shape, 0.0);

      // Right wall
      shape.Set(new b2Vec2(10.0, 0.0), new b2Vec2(10.0, 20.0));
      ground.CreateFixture(shape, 0.0);

      // Roof
      shape.Set(new b2Vec2(-10.0, 20.0), new b2Vec2(10.0, 20.0));
      ground.CreateFixture(shape, 0.0);
    }

    const radius = 0.5;
    const shape = new b2CircleShape();
    shape.m_p.SetZero();
    shape.m_radius = radius;

    const fd = new b2FixtureDef();
    fd.shape = shape;
    fd.density = 1.0;
    fd.friction = 0.1;

    for (let j = 0; j < Confined.e_columnCount; ++j) {
      for (let i = 0; i < Confined.e_rowCount; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(-10.0 + (2.1 * j + 1.0 + 0.01 * i) * radius, (2.0 * i + 1.0) * radius);
        const body = this.m_world.CreateBody(bd);

        body.CreateFixture(fd);
      }
    }

    this.m_world.SetGravity(new b2Vec2(0.0, 0.0));
  }

  CreateCircle(): void {
    const radius = 2.0;
    const shape = new b2CircleShape();
    shape.m_p.SetZero();
    shape.m_radius = radius;

    const fd = new b2FixtureDef();
    fd.shape = shape;
    fd.density = 1.0;
    fd.friction = 0.0;

    // b2Vec2 p(RandomFloat(), 3.0f + RandomFloat()): GCC evaluates the arguments right to left.
    const y = 3.0 + RandomFloat();
    const x = RandomFloat();
    const p = new b2Vec2(x, y);
    const bd = new b2BodyDef();
    bd.type = b2_dynamicBody;
    bd.position.Assign(p);
    //bd.allowSleep = false;
    const body = this.m_world.CreateBody(bd);

    body.CreateFixture(fd);
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'c':
        this.CreateCircle();
        break;
    }
  }

  override Step(settings: Settings): void {
    // The C++ checks here whether every dynamic body sleeps (for a commented-out CreateCircle) and,
    // after the step, whether one left the box (a line for a breakpoint); neither changes anything.
    super.Step(settings);

    this.m_debugDraw.DrawString(5, this.m_textLine, "Press 'c' to create a circle.");
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new Confined();
  }
}
