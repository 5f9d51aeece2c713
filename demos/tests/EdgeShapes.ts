// EdgeShapes.h: shapes dropped on a ground of 80 edges, and a rotating closest-hit ray cast.
import {
  b2Abs,
  b2BodyDef,
  b2CircleShape,
  b2Color,
  b2EdgeShape,
  b2FixtureDef,
  b2PolygonShape,
  b2RayCastCallback,
  b2Sqrt,
  b2Vec2,
  b2_dynamicBody,
  b2_pi,
} from '../../src/index';
import type { b2Body, b2Fixture } from '../../src/index';
import { cosf, sinf } from '../framework/cmath';
import { RandomFloat } from '../framework/random';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

class EdgeShapesCallback extends b2RayCastCallback {
  m_fixture: b2Fixture | null = null;
  readonly m_point = new b2Vec2();
  readonly m_normal = new b2Vec2();

  ReportFixture(fixture: b2Fixture, point: b2Vec2, normal: b2Vec2, fraction: number): number {
    this.m_fixture = fixture;
    this.m_point.Assign(point);
    this.m_normal.Assign(normal);

    return fraction;
  }
}

/** The four polygons of PolyShapes.h, EdgeShapes.h and RayCast.h. */
export function makeTestPolygons(): b2PolygonShape[] {
  const polygons = [new b2PolygonShape(), new b2PolygonShape(), new b2PolygonShape(), new b2PolygonShape()];
  polygons[0].Set([new b2Vec2(-0.5, 0.0), new b2Vec2(0.5, 0.0), new b2Vec2(0.0, 1.5)], 3);
  polygons[1].Set([new b2Vec2(-0.1, 0.0), new b2Vec2(0.1, 0.0), new b2Vec2(0.0, 1.5)], 3);
  {
    const w = 1.0;
    const b = w / (2.0 + b2Sqrt(2.0));
    const s = b2Sqrt(2.0) * b;

    const vertices = [
      new b2Vec2(0.5 * s, 0.0),
      new b2Vec2(0.5 * w, b),
      new b2Vec2(0.5 * w, b + s),
      new b2Vec2(0.5 * s, w),
      new b2Vec2(-0.5 * s, w),
      new b2Vec2(-0.5 * w, b + s),
      new b2Vec2(-0.5 * w, b),
      new b2Vec2(-0.5 * s, 0.0),
    ];
    polygons[2].Set(vertices, 8);
  }
  polygons[3].SetAsBox(0.5, 0.5);
  return polygons;
}

export class EdgeShapes extends Test {
  static readonly e_maxBodies = 256;

  m_bodyIndex: number;
  readonly m_bodies: (b2Body | null)[] = new Array(EdgeShapes.e_maxBodies).fill(null);
  readonly m_polygons: b2PolygonShape[];
  readonly m_circle = new b2CircleShape();

  m_angle: number;

  constructor() {
    super();
    // Ground body
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      let x1 = -20.0;
      let y1 = 2.0 * cosf((x1 / 10.0) * b2_pi);
      for (let i = 0; i < 80; ++i) {
        const x2 = x1 + 0.5;
        const y2 = 2.0 * cosf((x2 / 10.0) * b2_pi);

        const shape = new b2EdgeShape();
        shape.Set(new b2Vec2(x1, y1), new b2Vec2(x2, y2));
        ground.CreateFixture(shape, 0.0);

        x1 = x2;
        y1 = y2;
      }
    }

    this.m_polygons = makeTestPolygons();
    this.m_circle.m_radius = 0.5;

    this.m_bodyIndex = 0;
    this.m_angle = 0.0;
  }

  Create(index: number): void {
    if (this.m_bodies[this.m_bodyIndex] !== null) {
      this.m_world.DestroyBody(this.m_bodies[this.m_bodyIndex]!);
      this.m_bodies[this.m_bodyIndex] = null;
    }

    const bd = new b2BodyDef();

    const x = RandomFloat(-10.0, 10.0);
    const y = RandomFloat(10.0, 20.0);
    bd.position.Set(x, y);
    bd.angle = RandomFloat(-b2_pi, b2_pi);
    bd.type = b2_dynamicBody;

    if (index === 4) {
      bd.angularDamping = 0.02;
    }

    const body = this.m_world.CreateBody(bd);
    this.m_bodies[this.m_bodyIndex] = body;

    const fd = new b2FixtureDef();
    fd.shape = index < 4 ? this.m_polygons[index] : this.m_circle;
    fd.friction = 0.3;
    fd.density = 20.0;
    body.CreateFixture(fd);

    this.m_bodyIndex = (this.m_bodyIndex + 1) % EdgeShapes.e_maxBodies;
  }

  DestroyBody(): void {
    for (let i = 0; i < EdgeShapes.e_maxBodies; ++i) {
      if (this.m_bodies[i] !== null) {
        this.m_world.DestroyBody(this.m_bodies[i]!);
        this.m_bodies[i] = null;
        return;
      }
    }
  }

  override Keyboard(key: string): void {
    switch (key) {
      case '1':
      case '2':
      case '3':
      case '4':
      case '5':
        this.Create(key.charCodeAt(0) - '1'.charCodeAt(0));
        break;

      case 'd':
        this.DestroyBody();
        break;
    }
  }

  override Step(settings: Settings): void {
    const advanceRay = settings.pause === 0 || settings.singleStep !== 0;

    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Press 1-5 to drop stuff');
    this.m_textLine += 15;

    const L = 25.0;
    const point1 = new b2Vec2(0.0, 10.0);
    const d = new b2Vec2(L * cosf(this.m_angle), -L * b2Abs(sinf(this.m_angle)));
    const point2 = new b2Vec2(point1.x + d.x, point1.y + d.y);

    const callback = new EdgeShapesCallback();

    this.m_world.RayCast(callback, point1, point2);

    if (callback.m_fixture !== null) {
      this.m_debugDraw.DrawPoint(callback.m_point, 5.0, new b2Color(0.4, 0.9, 0.4));

      this.m_debugDraw.DrawSegment(point1, callback.m_point, new b2Color(0.8, 0.8, 0.8));

      const head = new b2Vec2(callback.m_point.x + 0.5 * callback.m_normal.x, callback.m_point.y + 0.5 * callback.m_normal.y);
      this.m_debugDraw.DrawSegment(callback.m_point, head, new b2Color(0.9, 0.9, 0.4));
    } else {
      this.m_debugDraw.DrawSegment(point1, point2, new b2Color(0.8, 0.8, 0.8));
    }

    if (advanceRay) {
      this.m_angle += (0.25 * b2_pi) / 180.0;
    }
  }

  static Create(): Test {
    return new EdgeShapes();
  }
}
