// OneSidedPlatform.h: PreSolve disables the contact while the ball is below the platform's top.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2PolygonShape, b2Vec2, b2_dynamicBody, b2_linearSlop } from '../../src/index';
import type { b2Contact, b2Fixture, b2Manifold } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

enum State {
  e_unknown,
  e_above,
  e_below,
}

export class OneSidedPlatform extends Test {
  m_radius: number;
  m_top: number;
  m_bottom: number;
  m_state: State;
  m_platform: b2Fixture;
  m_character: b2Fixture;

  constructor() {
    super();
    // Ground
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-20.0, 0.0), new b2Vec2(20.0, 0.0));
      ground.CreateFixture(shape, 0.0);
    }

    // Platform
    {
      const bd = new b2BodyDef();
      bd.position.Set(0.0, 10.0);
      const body = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(3.0, 0.5);
      this.m_platform = body.CreateFixture(shape, 0.0);

      this.m_bottom = 10.0 - 0.5;
      this.m_top = 10.0 + 0.5;
    }

    // Actor
    {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(0.0, 12.0);
      const body = this.m_world.CreateBody(bd);

      this.m_radius = 0.5;
      const shape = new b2CircleShape();
      shape.m_radius = this.m_radius;
      this.m_character = body.CreateFixture(shape, 20.0);

      body.SetLinearVelocity(new b2Vec2(0.0, -50.0));

      this.m_state = State.e_unknown;
    }
  }

  override PreSolve(contact: b2Contact, oldManifold: b2Manifold): void {
    super.PreSolve(contact, oldManifold);

    const fixtureA = contact.GetFixtureA();
    const fixtureB = contact.GetFixtureB();

    if (fixtureA !== this.m_platform && fixtureA !== this.m_character) {
      return;
    }

    if (fixtureB !== this.m_platform && fixtureB !== this.m_character) {
      return;
    }

    const position = this.m_character.GetBody().GetPosition();

    if (position.y < this.m_top + this.m_radius - 3.0 * b2_linearSlop) {
      contact.SetEnabled(false);
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Press: (c) create a shape, (d) destroy a shape.');
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new OneSidedPlatform();
  }
}
