/*
 * Contact between a chain (fixture A) and a polygon (fixture B) (b2ChainAndPolygonContact.h, .cpp). Each child
 * edge of the chain gets its own contact; the child index selects the edge.
 */

import { b2CollideEdgeAndPolygon } from '../../collision/b2CollideEdge';
import type { b2Manifold } from '../../collision/b2Collision';
import type { b2ChainShape } from '../../collision/shapes/b2ChainShape';
import { b2EdgeShape } from '../../collision/shapes/b2EdgeShape';
import type { b2PolygonShape } from '../../collision/shapes/b2PolygonShape';
import { b2Shape } from '../../collision/shapes/b2Shape';
import type { b2Transform } from '../../common/b2Math';
import { b2Assert } from '../../common/b2Settings';
import type { b2Fixture } from '../b2Fixture';
import { b2Contact } from './b2Contact';

// The child edge is rebuilt for every evaluation; the collide function does not keep it.
const s_edge = new b2EdgeShape();

export class b2ChainAndPolygonContact extends b2Contact {
  static override Create(fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number): b2Contact {
    b2Assert(fixtureA.GetType() === b2Shape.e_chain);
    b2Assert(fixtureB.GetType() === b2Shape.e_polygon);
    return new b2Contact(fixtureA, indexA, fixtureB, indexB, b2ChainAndPolygonContact.Evaluate);
  }

  // The C++ frees the memory to the block allocator here; b2Contact.Destroy hands the contact to
  // the world's b2ContactAllocator instead.
  static override Destroy(contact: b2Contact): void {}

  /** The C++ constructor; the engine makes its contacts with Create. */
  constructor(fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number) {
    super(fixtureA, indexA, fixtureB, indexB, b2ChainAndPolygonContact.Evaluate);
    b2Assert(this.m_fixtureA.GetType() === b2Shape.e_chain);
    b2Assert(this.m_fixtureB.GetType() === b2Shape.e_polygon);
  }

  /** The C++ Evaluate, as the function every contact of this type holds (b2Contact.m_evaluate). */
  static Evaluate(contact: b2Contact, manifold: b2Manifold, xfA: b2Transform, xfB: b2Transform): void {
    const chain = contact.m_fixtureA.GetShape() as b2ChainShape;
    chain.GetChildEdge(s_edge, contact.m_indexA);
    b2CollideEdgeAndPolygon(manifold, s_edge, xfA, contact.m_fixtureB.GetShape() as b2PolygonShape, xfB);
  }

  /** True for the contacts Create makes: b2Contacts holding this type's Evaluate. */
  static override [Symbol.hasInstance](value: unknown): boolean {
    return value instanceof b2Contact && value.m_evaluate === b2ChainAndPolygonContact.Evaluate;
  }
}
