// CollisionProcessing.h: collision processing and deferred body destruction. After each step the
// lighter body of every touching pair (from the PreSolve contact points) is destroyed.
import { b2BodyDef, b2CircleShape, b2EdgeShape, b2FixtureDef, b2PolygonShape, b2Vec2, b2_dynamicBody } from '../../src/index';
import type { b2Body } from '../../src/index';
import { RandomFloat } from '../framework/random';
import type { Settings } from '../framework/settings';
import { Test } from '../framework/test';

export class CollisionProcessing extends Test {
  /**
   * The C++ sorts the bodies to destroy by address (std::sort on pointers) to group duplicates;
   * bodies have no address here, so they are sorted by creation order, which is what increasing
   * heap addresses usually are.
   */
  private readonly m_order = new Map<b2Body, number>();

  constructor() {
    super();
    // Ground body
    {
      const shape = new b2EdgeShape();
      shape.Set(new b2Vec2(-50.0, 0.0), new b2Vec2(50.0, 0.0));

      const sd = new b2FixtureDef();
      sd.shape = shape;

      const bd = new b2BodyDef();
      const ground = this.m_world.CreateBody(bd);
      ground.CreateFixture(sd);
    }

    const xLo = -5.0;
    const xHi = 5.0;
    const yLo = 2.0;
    const yHi = 35.0;

    // position.Set(RandomFloat(xLo, xHi), RandomFloat(yLo, yHi)): GCC on x86-64 evaluates the
    // arguments right to left, so y is drawn first (this reproduces the golden scene).
    const randomPosition = (bd: b2BodyDef) => {
      const y = RandomFloat(yLo, yHi);
      const x = RandomFloat(xLo, xHi);
      bd.position.Set(x, y);
    };
    const created = (body: b2Body) => this.m_order.set(body, this.m_order.size);

    // Small triangle
    const vertices = [new b2Vec2(-1.0, 0.0), new b2Vec2(1.0, 0.0), new b2Vec2(0.0, 2.0)];

    const polygon = new b2PolygonShape();
    polygon.Set(vertices, 3);

    const triangleShapeDef = new b2FixtureDef();
    triangleShapeDef.shape = polygon;
    triangleShapeDef.density = 1.0;

    const triangleBodyDef = new b2BodyDef();
    triangleBodyDef.type = b2_dynamicBody;
    randomPosition(triangleBodyDef);

    const body1 = this.m_world.CreateBody(triangleBodyDef);
    body1.CreateFixture(triangleShapeDef);
    created(body1);

    // Large triangle (recycle definitions)
    vertices[0].Multiply(2.0);
    vertices[1].Multiply(2.0);
    vertices[2].Multiply(2.0);
    polygon.Set(vertices, 3);

    randomPosition(triangleBodyDef);

    const body2 = this.m_world.CreateBody(triangleBodyDef);
    body2.CreateFixture(triangleShapeDef);
    created(body2);

    // Small box
    polygon.SetAsBox(1.0, 0.5);

    const boxShapeDef = new b2FixtureDef();
    boxShapeDef.shape = polygon;
    boxShapeDef.density = 1.0;

    const boxBodyDef = new b2BodyDef();
    boxBodyDef.type = b2_dynamicBody;
    randomPosition(boxBodyDef);

    const body3 = this.m_world.CreateBody(boxBodyDef);
    body3.CreateFixture(boxShapeDef);
    created(body3);

    // Large box (recycle definitions)
    polygon.SetAsBox(2.0, 1.0);
    randomPosition(boxBodyDef);

    const body4 = this.m_world.CreateBody(boxBodyDef);
    body4.CreateFixture(boxShapeDef);
    created(body4);

    // Small circle
    const circle = new b2CircleShape();
    circle.m_radius = 1.0;

    const circleShapeDef = new b2FixtureDef();
    circleShapeDef.shape = circle;
    circleShapeDef.density = 1.0;

    const circleBodyDef = new b2BodyDef();
    circleBodyDef.type = b2_dynamicBody;
    randomPosition(circleBodyDef);

    const body5 = this.m_world.CreateBody(circleBodyDef);
    body5.CreateFixture(circleShapeDef);
    created(body5);

    // Large circle
    circle.m_radius *= 2.0;
    randomPosition(circleBodyDef);

    const body6 = this.m_world.CreateBody(circleBodyDef);
    body6.CreateFixture(circleShapeDef);
    created(body6);
  }

  /** The contact points decide what is destroyed (on the WebGPU backend they come from PostSolve). */
  override UsesContactPoints(): boolean {
    return true;
  }

  override Step(settings: Settings): void {
    super.Step(settings);

    // We are going to destroy some bodies according to contact points. We must buffer the bodies
    // that should be destroyed because they may belong to multiple contact points.
    const k_maxNuke = 6;
    const nuke: b2Body[] = [];

    // Traverse the contact results. Destroy bodies that are touching heavier bodies.
    for (let i = 0; i < this.m_pointCount; ++i) {
      const point = this.m_points[i];

      const body1 = point.fixtureA!.GetBody();
      const body2 = point.fixtureB!.GetBody();
      const mass1 = body1.GetMass();
      const mass2 = body2.GetMass();

      if (mass1 > 0.0 && mass2 > 0.0) {
        if (mass2 > mass1) {
          nuke.push(body1);
        } else {
          nuke.push(body2);
        }

        if (nuke.length === k_maxNuke) {
          break;
        }
      }
    }

    // Sort the nuke array to group duplicates.
    const order = (b: b2Body) => this.m_order.get(b) ?? Number.MAX_SAFE_INTEGER;
    nuke.sort((a, b) => order(a) - order(b));

    // Destroy the bodies, skipping duplicates.
    let i = 0;
    while (i < nuke.length) {
      const b = nuke[i++];
      while (i < nuke.length && nuke[i] === b) {
        ++i;
      }

      if (b !== this.m_bomb) {
        this.m_world.DestroyBody(b);
      }
    }
  }

  static Create(): Test {
    return new CollisionProcessing();
  }
}
