/*
 * Contact between a polygon (fixture A) and a circle (fixture B) (b2PolygonAndCircleContact.h, .cpp).
 */

import { b2CollidePolygonAndCircle } from '../../collision/b2CollideCircle';
import type { b2Manifold } from '../../collision/b2Collision';
import type { b2CircleShape } from '../../collision/shapes/b2CircleShape';
import type { b2PolygonShape } from '../../collision/shapes/b2PolygonShape';
import { b2Shape } from '../../collision/shapes/b2Shape';
import type { b2Transform } from '../../common/b2Math';
import { b2Assert } from '../../common/b2Settings';
import type { b2Fixture } from '../b2Fixture';
import { b2Contact } from './b2Contact';

export class b2PolygonAndCircleContact extends b2Contact {
  static override Create(fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number): b2Contact {
    return new b2PolygonAndCircleContact(fixtureA, fixtureB);
  }

  // The C++ frees the memory to the block allocator here; b2Contact.Destroy hands the contact to
  // the world's b2ContactAllocator instead.
  static override Destroy(contact: b2Contact): void {}

  constructor(fixtureA: b2Fixture, fixtureB: b2Fixture) {
    super(fixtureA, 0, fixtureB, 0);
    b2Assert(this.m_fixtureA.GetType() === b2Shape.e_polygon);
    b2Assert(this.m_fixtureB.GetType() === b2Shape.e_circle);
  }

  override Evaluate(manifold: b2Manifold, xfA: b2Transform, xfB: b2Transform): void {
    b2CollidePolygonAndCircle(manifold, this.m_fixtureA.GetShape() as b2PolygonShape, xfA, this.m_fixtureB.GetShape() as b2CircleShape, xfB);
  }
}
