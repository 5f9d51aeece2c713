/*
 * Contact between two circles (b2CircleContact.h, .cpp).
 */

import { b2CollideCircles } from '../../collision/b2CollideCircle';
import type { b2Manifold } from '../../collision/b2Collision';
import type { b2CircleShape } from '../../collision/shapes/b2CircleShape';
import { b2Shape } from '../../collision/shapes/b2Shape';
import type { b2Transform } from '../../common/b2Math';
import { b2Assert } from '../../common/b2Settings';
import type { b2Fixture } from '../b2Fixture';
import { b2Contact } from './b2Contact';

export class b2CircleContact extends b2Contact {
  static override Create(fixtureA: b2Fixture, indexA: number, fixtureB: b2Fixture, indexB: number): b2Contact {
    b2Assert(fixtureA.GetType() === b2Shape.e_circle);
    b2Assert(fixtureB.GetType() === b2Shape.e_circle);
    return new b2Contact(fixtureA, 0, fixtureB, 0, b2CircleContact.Evaluate);
  }

  // The C++ frees the memory to the block allocator here; b2Contact.Destroy hands the contact to
  // the world's b2ContactAllocator instead.
  static override Destroy(contact: b2Contact): void {}

  /** The C++ constructor; the engine makes its contacts with Create. */
  constructor(fixtureA: b2Fixture, fixtureB: b2Fixture) {
    super(fixtureA, 0, fixtureB, 0, b2CircleContact.Evaluate);
    b2Assert(this.m_fixtureA.GetType() === b2Shape.e_circle);
    b2Assert(this.m_fixtureB.GetType() === b2Shape.e_circle);
  }

  /** The C++ Evaluate, as the function every contact of this type holds (b2Contact.m_evaluate). */
  static Evaluate(contact: b2Contact, manifold: b2Manifold, xfA: b2Transform, xfB: b2Transform): void {
    b2CollideCircles(manifold, contact.m_fixtureA.GetShape() as b2CircleShape, xfA, contact.m_fixtureB.GetShape() as b2CircleShape, xfB);
  }

  /** True for the contacts Create makes: b2Contacts holding this type's Evaluate. */
  static override [Symbol.hasInstance](value: unknown): boolean {
    return value instanceof b2Contact && value.m_evaluate === b2CircleContact.Evaluate;
  }
}
