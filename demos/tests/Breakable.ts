// Breakable.h: a body of two boxes that splits in two when PostSolve reports a large impulse.
import { b2BodyDef, b2CrossSV, b2EdgeShape, b2Max, b2PolygonShape, b2SubVV, b2Vec2, b2_dynamicBody, b2_pi } from '../../src/index';
import type { b2Body, b2Contact, b2ContactImpulse, b2Fixture } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class Breakable extends Test {
  static readonly e_count = 7;

  m_body1: b2Body;
  readonly m_velocity = new b2Vec2();
  m_angularVelocity = 0.0;
  readonly m_shape1 = new b2PolygonShape();
  readonly m_shape2 = new b2PolygonShape();
  m_piece1: b2Fixture;
  m_piece2: b2Fixture | null;

  m_broke: boolean;
  m_break: boolean;

  constructor() {
    super();
    // Ground body
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));
      ground.CreateFixture(shape, 0.0);
    }

    // Breakable dynamic body
    {
      const bd = new b2BodyDef();
      bd.type = b2_dynamicBody;
      bd.position.Set(0.0, 40.0);
      bd.angle = 0.25 * b2_pi;
      this.m_body1 = this.m_world.CreateBody(bd);

      this.m_shape1.SetAsBox(0.5, 0.5, new b2Vec2(-0.5, 0.0), 0.0);
      this.m_piece1 = this.m_body1.CreateFixture(this.m_shape1, 1.0);

      this.m_shape2.SetAsBox(0.5, 0.5, new b2Vec2(0.5, 0.0), 0.0);
      this.m_piece2 = this.m_body1.CreateFixture(this.m_shape2, 1.0);
    }

    this.m_break = false;
    this.m_broke = false;
  }

  override PostSolve(contact: b2Contact, impulse: b2ContactImpulse): void {
    if (this.m_broke) {
      // The body already broke.
      return;
    }

    // Should the body break?
    const count = contact.GetManifold().pointCount;

    let maxImpulse = 0.0;
    for (let i = 0; i < count; ++i) {
      maxImpulse = b2Max(maxImpulse, impulse.normalImpulses[i]);
    }

    if (maxImpulse > 40.0) {
      // Flag the body for breaking.
      this.m_break = true;
    }
  }

  Break(): void {
    // Create two bodies from one.
    const body1 = this.m_piece1.GetBody();
    const center = body1.GetWorldCenter().Clone();

    body1.DestroyFixture(this.m_piece2!);
    this.m_piece2 = null;

    const bd = new b2BodyDef();
    bd.type = b2_dynamicBody;
    bd.position.Assign(body1.GetPosition());
    bd.angle = body1.GetAngle();

    const body2 = this.m_world.CreateBody(bd);
    this.m_piece2 = body2.CreateFixture(this.m_shape2, 1.0);

    // Compute consistent velocities for new bodies based on cached velocity.
    const center1 = body1.GetWorldCenter();
    const center2 = body2.GetWorldCenter();

    const velocity1 = b2CrossSV(this.m_angularVelocity, b2SubVV(center1, center, new b2Vec2()), new b2Vec2());
    velocity1.Set(this.m_velocity.x + velocity1.x, this.m_velocity.y + velocity1.y);
    const velocity2 = b2CrossSV(this.m_angularVelocity, b2SubVV(center2, center, new b2Vec2()), new b2Vec2());
    velocity2.Set(this.m_velocity.x + velocity2.x, this.m_velocity.y + velocity2.y);

    body1.SetAngularVelocity(this.m_angularVelocity);
    body1.SetLinearVelocity(velocity1);

    body2.SetAngularVelocity(this.m_angularVelocity);
    body2.SetLinearVelocity(velocity2);
  }

  override Step(settings: Settings): void {
    if (this.m_break) {
      this.Break();
      this.m_broke = true;
      this.m_break = false;
    }

    // Cache velocities to improve movement on breakage.
    if (this.m_broke === false) {
      this.m_body1.GetLinearVelocity(this.m_velocity);
      this.m_angularVelocity = this.m_body1.GetAngularVelocity();
    }

    super.Step(settings);
  }

  static Create(): Test {
    return new Breakable();
  }
}
