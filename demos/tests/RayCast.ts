// RayCast.h: b2World::RayCast with closest, any and multiple hit callbacks. Polygon 0 is filtered
// out on purpose, so the ray always misses that kind. Keys: 1-5 create, d destroys, m the mode.
import { b2BodyDef, b2CircleShape, b2Color, b2EdgeShape, b2FixtureDef, b2RayCastCallback, b2Vec2, b2_pi } from '../../src/index';
import type { b2Body, b2Fixture, b2PolygonShape } from '../../src/index';
import { cosf, sinf } from '../framework/cmath';
import { RandomFloat } from '../framework/random';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';
import { makeTestPolygons } from './EdgeShapes';

/** What RayCast.h stores as user data: a pointer to the body's shape index. */
interface KindData {
  index: number;
}

function filtered(fixture: b2Fixture): boolean {
  const userData = fixture.GetBody().GetUserData() as KindData | null;
  return userData !== null && userData !== undefined && userData.index === 0;
}

// This callback finds the closest hit. Polygon 0 is filtered.
class RayCastClosestCallback extends b2RayCastCallback {
  m_hit = false;
  readonly m_point = new b2Vec2();
  readonly m_normal = new b2Vec2();

  ReportFixture(fixture: b2Fixture, point: b2Vec2, normal: b2Vec2, fraction: number): number {
    if (filtered(fixture)) {
      // filter
      return -1.0;
    }

    this.m_hit = true;
    this.m_point.Assign(point);
    this.m_normal.Assign(normal);
    return fraction;
  }
}

// This callback finds any hit. Polygon 0 is filtered.
class RayCastAnyCallback extends b2RayCastCallback {
  m_hit = false;
  readonly m_point = new b2Vec2();
  readonly m_normal = new b2Vec2();

  ReportFixture(fixture: b2Fixture, point: b2Vec2, normal: b2Vec2, fraction: number): number {
    if (filtered(fixture)) {
      // filter
      return -1.0;
    }

    this.m_hit = true;
    this.m_point.Assign(point);
    this.m_normal.Assign(normal);
    return 0.0;
  }
}

// This ray cast collects multiple hits along the ray. Polygon 0 is filtered.
class RayCastMultipleCallback extends b2RayCastCallback {
  static readonly e_maxCount = 3;

  readonly m_points = [new b2Vec2(), new b2Vec2(), new b2Vec2()];
  readonly m_normals = [new b2Vec2(), new b2Vec2(), new b2Vec2()];
  m_count = 0;

  ReportFixture(fixture: b2Fixture, point: b2Vec2, normal: b2Vec2, fraction: number): number {
    if (filtered(fixture)) {
      // filter
      return -1.0;
    }

    if (this.m_count >= RayCastMultipleCallback.e_maxCount) throw new Error('Box2D: m_count < e_maxCount');
    this.m_points[this.m_count].Assign(point);
    this.m_normals[this.m_count].Assign(normal);
    ++this.m_count;

    if (this.m_count === RayCastMultipleCallback.e_maxCount) {
      return 0.0;
    }

    return 1.0;
  }
}

enum Mode {
  e_closest,
  e_any,
  e_multiple,
}

export class RayCast extends Test {
  static readonly e_maxBodies = 256;

  m_bodyIndex: number;
  readonly m_bodies: (b2Body | null)[] = new Array(RayCast.e_maxBodies).fill(null);
  readonly m_userData: KindData[] = [];
  readonly m_polygons: b2PolygonShape[];
  readonly m_circle = new b2CircleShape();

  m_angle: number;

  m_mode: Mode;

  constructor() {
    super();
    for (let i = 0; i < RayCast.e_maxBodies; ++i) this.m_userData.push({ index: 0 });
    // Ground body
    {
      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);

      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-40.0, 0.0), new b2Vec2(40.0, 0.0));
      ground.CreateFixture(shape, 0.0);
    }

    this.m_polygons = makeTestPolygons();
    this.m_circle.m_radius = 0.5;

    this.m_bodyIndex = 0;

    this.m_angle = 0.0;

    this.m_mode = Mode.e_closest;
  }

  Create(index: number): void {
    if (this.m_bodies[this.m_bodyIndex] !== null) {
      this.m_world.DestroyBody(this.m_bodies[this.m_bodyIndex]!);
      this.m_bodies[this.m_bodyIndex] = null;
    }

    const bd = new b2BodyDef();

    const x = RandomFloat(-10.0, 10.0);
    const y = RandomFloat(0.0, 20.0);
    bd.position.Set(x, y);
    bd.angle = RandomFloat(-b2_pi, b2_pi);

    this.m_userData[this.m_bodyIndex].index = index;
    bd.userData = this.m_userData[this.m_bodyIndex];

    if (index === 4) {
      bd.angularDamping = 0.02;
    }

    const body = this.m_world.CreateBody(bd);
    this.m_bodies[this.m_bodyIndex] = body;

    const fd = new b2FixtureDef();
    fd.shape = index < 4 ? this.m_polygons[index] : this.m_circle;
    fd.friction = 0.3;
    body.CreateFixture(fd);

    this.m_bodyIndex = (this.m_bodyIndex + 1) % RayCast.e_maxBodies;
  }

  DestroyBody(): void {
    for (let i = 0; i < RayCast.e_maxBodies; ++i) {
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

      case 'm':
        if (this.m_mode === Mode.e_closest) {
          this.m_mode = Mode.e_any;
        } else if (this.m_mode === Mode.e_any) {
          this.m_mode = Mode.e_multiple;
        } else if (this.m_mode === Mode.e_multiple) {
          this.m_mode = Mode.e_closest;
        }
    }
  }

  override Step(settings: Settings): void {
    const advanceRay = settings.pause === 0 || settings.singleStep !== 0;

    super.Step(settings);
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Press 1-5 to drop stuff, m to change the mode');
    this.m_textLine += 15;
    this.m_debugDraw.DrawString(5, this.m_textLine, 'Mode = %d', this.m_mode);
    this.m_textLine += 15;

    const L = 11.0;
    const point1 = new b2Vec2(0.0, 10.0);
    const point2 = new b2Vec2(point1.x + L * cosf(this.m_angle), point1.y + L * sinf(this.m_angle));

    const light = new b2Color(0.8, 0.8, 0.8);
    const hitColor = new b2Color(0.4, 0.9, 0.4);
    const normalColor = new b2Color(0.9, 0.9, 0.4);
    const head = new b2Vec2();

    if (this.m_mode === Mode.e_closest || this.m_mode === Mode.e_any) {
      const callback = this.m_mode === Mode.e_closest ? new RayCastClosestCallback() : new RayCastAnyCallback();
      this.m_world.RayCast(callback, point1, point2);

      if (callback.m_hit) {
        this.m_debugDraw.DrawPoint(callback.m_point, 5.0, hitColor);
        this.m_debugDraw.DrawSegment(point1, callback.m_point, light);
        head.Set(callback.m_point.x + 0.5 * callback.m_normal.x, callback.m_point.y + 0.5 * callback.m_normal.y);
        this.m_debugDraw.DrawSegment(callback.m_point, head, normalColor);
      } else {
        this.m_debugDraw.DrawSegment(point1, point2, light);
      }
    } else if (this.m_mode === Mode.e_multiple) {
      const callback = new RayCastMultipleCallback();
      this.m_world.RayCast(callback, point1, point2);
      this.m_debugDraw.DrawSegment(point1, point2, light);

      for (let i = 0; i < callback.m_count; ++i) {
        const p = callback.m_points[i];
        const n = callback.m_normals[i];
        this.m_debugDraw.DrawPoint(p, 5.0, hitColor);
        this.m_debugDraw.DrawSegment(point1, p, light);
        head.Set(p.x + 0.5 * n.x, p.y + 0.5 * n.y);
        this.m_debugDraw.DrawSegment(p, head, normalColor);
      }
    }

    if (advanceRay) {
      this.m_angle += (0.25 * b2_pi) / 180.0;
    }
  }

  static Create(): Test {
    return new RayCast();
  }
}
