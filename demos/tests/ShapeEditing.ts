// ShapeEditing.h: fixtures created and destroyed on a live body. Keys: c create, d destroy,
// s toggles the sensor flag of the added circle.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2PolygonShape, b2Vec2, b2_dynamicBody } from '../../src/index';
import type { b2Body, b2Fixture } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class ShapeEditing extends Test {
  m_body: b2Body;
  m_fixture1: b2Fixture;
  m_fixture2: b2Fixture | null;
  m_sensor: boolean;

  constructor() {
    super();
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));
      ground.CreateFixture(shape, 0.0);
    }

    const bd = new b2BodyDef();
    bd.type = b2_dynamicBody;
    bd.position.Set(0.0, 10.0);
    this.m_body = this.m_world.CreateBody(bd);

    const shape = new b2PolygonShape();
    shape.SetAsBox(4.0, 4.0, new b2Vec2(0.0, 0.0), 0.0);
    this.m_fixture1 = this.m_body.CreateFixture(shape, 10.0);

    this.m_fixture2 = null;

    this.m_sensor = false;
  }

  override Keyboard(key: string): void {
    switch (key) {
      case 'c':
        if (this.m_fixture2 === null) {
          const shape = new b2CircleShape();
          shape.m_radius = 3.0;
          shape.m_p.Set(0.5, -4.0);
          this.m_fixture2 = this.m_body.CreateFixture(shape, 10.0);
          this.m_body.SetAwake(true);
        }
        break;

      case 'd':
        if (this.m_fixture2 !== null) {
          this.m_body.DestroyFixture(this.m_fixture2);
          this.m_fixture2 = null;
          this.m_body.SetAwake(true);
        }
        break;

      case 's':
        if (this.m_fixture2 !== null) {
          this.m_sensor = !this.m_sensor;
          this.m_fixture2.SetSensor(this.m_sensor);
        }
        break;
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Press: (c) create a shape, (d) destroy a shape.');
    this.m_textLine += 15;
    this.m_debugDraw.DrawString(5, this.m_textLine, 'sensor = %d', this.m_sensor ? 1 : 0);
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new ShapeEditing();
  }
}
