// CharacterCollision.h: a test of typical character collision scenarios. This does not show how
// you should implement a character in your application. Instead this is used to test smooth
// collision on edge chains.
import { b2BodyDef, b2ChainShape, b2CircleShape, b2EdgeShape, b2FixtureDef, b2PolygonShape, b2Vec2, b2_dynamicBody, b2_pi } from '../../src/index';
import { cosf, sinf } from '../framework/cmath';
import type { b2Body } from '../../src/index';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

const v = (x: number, y: number) => new b2Vec2(x, y);

export class CharacterCollision extends Test {
  m_character: b2Body;

  constructor() {
    super();
    // Ground body
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(v(-20.0, 0.0), v(20.0, 0.0));
      ground.CreateFixture(shape, 0.0);
    }

    // Collinear edges with no adjacency information.
    // This shows the problematic case where a box shape can hit an internal vertex.
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(v(-8.0, 1.0), v(-6.0, 1.0));
      ground.CreateFixture(shape, 0.0);
      shape.Set(v(-6.0, 1.0), v(-4.0, 1.0));
      ground.CreateFixture(shape, 0.0);
      shape.Set(v(-4.0, 1.0), v(-2.0, 1.0));
      ground.CreateFixture(shape, 0.0);
    }

    // Chain shape
    {
      const bd = new b2BodyDef();
      bd.angle = 0.25 * b2_pi;
      const ground = this.m_world.CreateBody(bd);

      const vs = [v(5.0, 7.0), v(6.0, 8.0), v(7.0, 8.0), v(8.0, 7.0)];
      const shape = new b2ChainShape();
      shape.CreateChain(vs, 4);
      ground.CreateFixture(shape, 0.0);
    }

    // Square tiles. This shows that adjacency shapes may have non-smooth collision. There is no
    // solution to this problem.
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(1.0, 1.0, v(4.0, 3.0), 0.0);
      ground.CreateFixture(shape, 0.0);
      shape.SetAsBox(1.0, 1.0, v(6.0, 3.0), 0.0);
      ground.CreateFixture(shape, 0.0);
      shape.SetAsBox(1.0, 1.0, v(8.0, 3.0), 0.0);
      ground.CreateFixture(shape, 0.0);
    }

    // Square made from an edge loop. Collision should be smooth.
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const vs = [v(-1.0, 3.0), v(1.0, 3.0), v(1.0, 5.0), v(-1.0, 5.0)];
      const shape = new b2ChainShape();
      shape.CreateLoop(vs, 4);
      ground.CreateFixture(shape, 0.0);
    }

    // Edge loop. Collision should be smooth.
    {
      const bd = new b2BodyDef();
      bd.position.Set(-10.0, 4.0);
      const ground = this.m_world.CreateBody(bd);

      const vs = [v(0.0, 0.0), v(6.0, 0.0), v(6.0, 2.0), v(4.0, 1.0), v(2.0, 2.0), v(0.0, 2.0), v(-2.0, 2.0), v(-4.0, 3.0), v(-6.0, 2.0), v(-6.0, 0.0)];
      const shape = new b2ChainShape();
      shape.CreateLoop(vs, 10);
      ground.CreateFixture(shape, 0.0);
    }

    // Square character 1
    {
      const bd = new b2BodyDef();
      bd.position.Set(-3.0, 8.0);
      bd.type = b2_dynamicBody;
      bd.fixedRotation = true;
      bd.allowSleep = false;

      const body = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(0.5, 0.5);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;
      body.CreateFixture(fd);
    }

    // Square character 2
    {
      const bd = new b2BodyDef();
      bd.position.Set(-5.0, 5.0);
      bd.type = b2_dynamicBody;
      bd.fixedRotation = true;
      bd.allowSleep = false;

      const body = this.m_world.CreateBody(bd);

      const shape = new b2PolygonShape();
      shape.SetAsBox(0.25, 0.25);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;
      body.CreateFixture(fd);
    }

    // Hexagon character
    {
      const bd = new b2BodyDef();
      bd.position.Set(-5.0, 8.0);
      bd.type = b2_dynamicBody;
      bd.fixedRotation = true;
      bd.allowSleep = false;

      const body = this.m_world.CreateBody(bd);

      let angle = 0.0;
      const delta = b2_pi / 3.0;
      const vertices: b2Vec2[] = [];
      for (let i = 0; i < 6; ++i) {
        vertices.push(v(0.5 * cosf(angle), 0.5 * sinf(angle)));
        angle += delta;
      }

      const shape = new b2PolygonShape();
      shape.Set(vertices, 6);

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;
      body.CreateFixture(fd);
    }

    // Circle character
    {
      const bd = new b2BodyDef();
      bd.position.Set(3.0, 5.0);
      bd.type = b2_dynamicBody;
      bd.fixedRotation = true;
      bd.allowSleep = false;

      const body = this.m_world.CreateBody(bd);

      const shape = new b2CircleShape();
      shape.m_radius = 0.5;

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;
      body.CreateFixture(fd);
    }

    // Circle character
    {
      const bd = new b2BodyDef();
      bd.position.Set(-7.0, 6.0);
      bd.type = b2_dynamicBody;
      bd.allowSleep = false;

      this.m_character = this.m_world.CreateBody(bd);

      const shape = new b2CircleShape();
      shape.m_radius = 0.25;

      const fd = new b2FixtureDef();
      fd.shape = shape;
      fd.density = 20.0;
      fd.friction = 1.0;
      this.m_character.CreateFixture(fd);
    }
  }

  override Step(settings: Settings): void {
    const vel = this.m_character.GetLinearVelocity();
    vel.x = -5.0;
    this.m_character.SetLinearVelocity(vel);

    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'This tests various character collision shapes.');
    this.m_textLine += 15;
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Limitation: square and hexagon can snag on aligned boxes.');
    this.m_textLine += 15;
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Feature: edge chains have smooth collision inside and out.');
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new CharacterCollision();
  }
}
