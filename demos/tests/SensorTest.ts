// SensorTest.h: a sensor circle on the ground; BeginContact/EndContact track which balls touch it,
// and those are pulled toward its centre.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2FixtureDef, b2Vec2, b2_dynamicBody, b2_epsilon } from '../../src/index';
import type { b2Body, b2Contact, b2Fixture } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

/** What SensorTest.h stores as a body's user data: a pointer to its `touching` flag. */
interface Touching {
  touching: boolean;
}

export class SensorTest extends Test {
  static readonly e_count = 7;

  m_sensor: b2Fixture;
  readonly m_bodies: b2Body[] = [];
  readonly m_touching: Touching[] = [];

  constructor() {
    super();
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      {
        const shape = new b2EdgeShape();
        shape.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));
        ground.CreateFixture(shape, 0.0);
      }

      // (#else branch of the C++: a circle sensor)
      {
        const shape = new b2CircleShape();
        shape.m_radius = 5.0;
        shape.m_p.Set(0.0, 10.0);

        const fd = new b2FixtureDef();
        fd.shape = shape;
        fd.isSensor = true;
        this.m_sensor = ground.CreateFixture(fd);
      }
    }

    {
      const shape = new b2CircleShape();
      shape.m_radius = 1.0;

      for (let i = 0; i < SensorTest.e_count; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(-10.0 + 3.0 * i, 20.0);
        this.m_touching[i] = { touching: false };
        bd.userData = this.m_touching[i];

        this.m_bodies[i] = this.m_world.CreateBody(bd);
        this.m_bodies[i].CreateFixture(shape, 1.0);
      }
    }
  }

  // Implement contact listener.
  override BeginContact(contact: b2Contact): void {
    const fixtureA = contact.GetFixtureA();
    const fixtureB = contact.GetFixtureB();

    if (fixtureA === this.m_sensor) {
      const userData = fixtureB.GetBody().GetUserData() as Touching | null;
      if (userData) {
        userData.touching = true;
      }
    }

    if (fixtureB === this.m_sensor) {
      const userData = fixtureA.GetBody().GetUserData() as Touching | null;
      if (userData) {
        userData.touching = true;
      }
    }
  }

  // Implement contact listener.
  override EndContact(contact: b2Contact): void {
    const fixtureA = contact.GetFixtureA();
    const fixtureB = contact.GetFixtureB();

    if (fixtureA === this.m_sensor) {
      const userData = fixtureB.GetBody().GetUserData() as Touching | null;
      if (userData) {
        userData.touching = false;
      }
    }

    if (fixtureB === this.m_sensor) {
      const userData = fixtureA.GetBody().GetUserData() as Touching | null;
      if (userData) {
        userData.touching = false;
      }
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);

    // Traverse the contact results. Apply a force on shapes that overlap the sensor.
    for (let i = 0; i < SensorTest.e_count; ++i) {
      if (this.m_touching[i].touching === false) {
        continue;
      }

      const body = this.m_bodies[i];
      const ground = this.m_sensor.GetBody();

      const circle = this.m_sensor.GetShape() as b2CircleShape;
      const center = ground.GetWorldPoint(circle.m_p);

      const position = body.GetPosition();

      const d = new b2Vec2(center.x - position.x, center.y - position.y);
      if (d.LengthSquared() < b2_epsilon * b2_epsilon) {
        continue;
      }

      d.Normalize();
      const F = new b2Vec2(100.0 * d.x, 100.0 * d.y);
      body.ApplyForce(F, position);
    }
  }

  static Create(): Test {
    return new SensorTest();
  }
}
