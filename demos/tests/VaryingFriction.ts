// VaryingFriction.h: boxes of different friction sliding down ramps.
import { b2BodyDef, b2EdgeShape, b2FixtureDef, b2PolygonShape, b2Vec2, b2_dynamicBody } from '../../src/index';
import { floatOf } from '../framework/cmath';
import { Test } from '../framework/test';

export class VaryingFriction extends Test {
  constructor() {
    super();
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));
      ground.CreateFixture(shape, 0.0);
    }

    const staticBox = (hx: number, hy: number, x: number, y: number, angle: number) => {
      const shape = new b2PolygonShape();
      shape.SetAsBox(hx, hy);

      const bd = new b2BodyDef();
      bd.position.Set(x, y);
      bd.angle = angle;
      const ground = this.m_world.CreateBody(bd);
      ground.CreateFixture(shape, 0.0);
    };

    staticBox(13.0, 0.25, -4.0, 22.0, -0.25);
    staticBox(0.25, 1.0, 10.5, 19.0, 0.0);
    staticBox(13.0, 0.25, 4.0, 14.0, 0.25);
    staticBox(0.25, 1.0, -10.5, 11.0, 0.0);
    staticBox(13.0, 0.25, -4.0, 6.0, -0.25);

    {
      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 0.5);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 25.0;

      // `float friction[5]` (float, not float32): the values are floats.
      const friction = [0.75, 0.5, 0.35, 0.1, 0.0].map(floatOf);

      for (let i = 0; i < 5; ++i) {
        const bd = new b2BodyDef();
        bd.type = b2_dynamicBody;
        bd.position.Set(-15.0 + 4.0 * i, 28.0);
        const body = this.m_world.CreateBody(bd);

        fd.friction = friction[i];
        body.CreateFixture(fd);
      }
    }
  }

  static Create(): Test {
    return new VaryingFriction();
  }
}
