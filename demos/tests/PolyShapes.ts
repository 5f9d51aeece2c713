// PolyShapes.h: stacking, and b2World::QueryAABB with b2TestOverlap. Up to 4 fixtures overlapping
// the circle are highlighted. Keys: 1-5 drop shapes, a (de)activates every other body, d destroys.
import {
  b2BodyDef,
  b2CircleShape,
  b2Color,
  b2EdgeShape,
  b2FixtureDef,
  b2MulXV,
  b2QueryCallback,
  b2Shape,
  b2TestOverlapShapes,
  b2Transform,
  b2Vec2,
  b2_dynamicBody,
  b2_pi,
  b2AABB,
} from '../../src/index';
import type { b2Body, b2Fixture, b2PolygonShape } from '../../src/index';
import { RandomFloat } from '../framework/random';
import type { TestbedDraw } from '../framework/render';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';
import { makeTestPolygons } from './EdgeShapes';

const k_maxBodies = 256;

/**
 * This callback is called by b2World::QueryAABB. We find all the fixtures that overlap an AABB. Of
 * those, we use b2TestOverlap to determine which fixtures overlap a circle. Up to 4 overlapped
 * fixtures will be highlighted with a yellow border.
 */
class PolyShapesCallback extends b2QueryCallback {
  static readonly e_maxCount = 4;

  readonly m_circle = new b2CircleShape();
  readonly m_transform = new b2Transform();
  m_debugDraw: TestbedDraw | null = null;
  m_count = 0;

  DrawFixture(fixture: b2Fixture): void {
    const color = new b2Color(0.95, 0.95, 0.6);
    const xf = fixture.GetBody().GetTransform();

    switch (fixture.GetType()) {
      case b2Shape.e_circle:
        {
          const circle = fixture.GetShape() as b2CircleShape;

          const center = b2MulXV(xf, circle.m_p, new b2Vec2());
          const radius = circle.m_radius;

          this.m_debugDraw!.DrawCircle(center, radius, color);
        }
        break;

      case b2Shape.e_polygon:
        {
          const poly = fixture.GetShape() as b2PolygonShape;
          const vertexCount = poly.m_vertexCount;
          const vertices: b2Vec2[] = [];

          for (let i = 0; i < vertexCount; ++i) {
            vertices.push(b2MulXV(xf, poly.m_vertices[i], new b2Vec2()));
          }

          this.m_debugDraw!.DrawPolygon(vertices, vertexCount, color);
        }
        break;

      default:
        break;
    }
  }

  /** Called for each fixture found in the query AABB. @return false to terminate the query. */
  ReportFixture(fixture: b2Fixture): boolean {
    if (this.m_count === PolyShapesCallback.e_maxCount) {
      return false;
    }

    const body = fixture.GetBody();
    const shape = fixture.GetShape();

    const overlap = b2TestOverlapShapes(shape, 0, this.m_circle, 0, body.GetTransform(), this.m_transform);

    if (overlap) {
      this.DrawFixture(fixture);
      ++this.m_count;
    }

    return true;
  }
}

export class PolyShapes extends Test {
  m_bodyIndex: number;
  readonly m_bodies: (b2Body | null)[] = new Array(k_maxBodies).fill(null);
  readonly m_polygons: b2PolygonShape[];
  readonly m_circle = new b2CircleShape();

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

    this.m_polygons = makeTestPolygons();
    this.m_circle.m_radius = 0.5;

    this.m_bodyIndex = 0;
  }

  Create(index: number): void {
    if (this.m_bodies[this.m_bodyIndex] !== null) {
      this.m_world.DestroyBody(this.m_bodies[this.m_bodyIndex]!);
      this.m_bodies[this.m_bodyIndex] = null;
    }

    const bd = new b2BodyDef();
    bd.type = b2_dynamicBody;

    const x = RandomFloat(-2.0, 2.0);
    bd.position.Set(x, 10.0);
    bd.angle = RandomFloat(-b2_pi, b2_pi);

    if (index === 4) {
      bd.angularDamping = 0.02;
    }

    const body = this.m_world.CreateBody(bd);
    this.m_bodies[this.m_bodyIndex] = body;

    const fd = new b2FixtureDef();
    fd.shape = index < 4 ? this.m_polygons[index] : this.m_circle;
    fd.density = 1.0;
    fd.friction = 0.3;
    body.CreateFixture(fd);

    this.m_bodyIndex = (this.m_bodyIndex + 1) % k_maxBodies;
  }

  DestroyBody(): void {
    for (let i = 0; i < k_maxBodies; ++i) {
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

      case 'a':
        for (let i = 0; i < k_maxBodies; i += 2) {
          const body = this.m_bodies[i];
          if (body !== null) {
            const active = body.IsActive();
            body.SetActive(!active);
          }
        }
        break;

      case 'd':
        this.DestroyBody();
        break;
    }
  }

  override Step(settings: Settings): void {
    super.Step(settings);

    const callback = new PolyShapesCallback();
    callback.m_circle.m_radius = 2.0;
    callback.m_circle.m_p.Set(0.0, 1.1);
    callback.m_transform.SetIdentity();
    callback.m_debugDraw = this.m_debugDraw;

    const aabb = new b2AABB();
    callback.m_circle.ComputeAABB(aabb, callback.m_transform, 0);

    this.m_world.QueryAABB(callback, aabb);

    const color = new b2Color(0.4, 0.7, 0.8);
    this.m_debugDraw.DrawCircle(callback.m_circle.m_p, callback.m_circle.m_radius, color);

    this.m_debugDraw.DrawString(5, this.m_textLine, 'Press 1-5 to drop stuff');
    this.m_textLine += 15;
    this.m_debugDraw.DrawString(5, this.m_textLine, "Press 'a' to (de)activate some bodies");
    this.m_textLine += 15;
    this.m_debugDraw.DrawString(5, this.m_textLine, "Press 'd' to destroy a body");
    this.m_textLine += 15;
  }

  static Create(): Test {
    return new PolyShapes();
  }
}
