/*
 * The world's store of destroyed contacts, in the role the C++ gives the world's b2BlockAllocator
 * (b2Contact::Create and Destroy take it). b2Contact.Destroy hands a contact back; b2Contact.Create
 * reinitialises one of the same pair of shape types before it constructs a new one. Contacts that
 * begin and end every step (a tumbler full of boxes: hundreds a step) then allocate nothing once
 * the store has held as many as end in one step.
 *
 * Invariant: a stored contact has been through b2ContactManager.Destroy (unlinked from the world's
 * list and both bodies' lists) and is referenced by nothing that reads it before Create returns it.
 */

import { b2Shape } from '../../collision/shapes/b2Shape';
import type { b2Contact } from './b2Contact';

export class b2ContactAllocator {
  // One stack per (shape type A, shape type B), kept at its largest size: Array.prototype.pop
  // can shrink an array's storage, and pushing past it again would reallocate.
  private readonly m_free: (b2Contact | null)[][] = [];
  private readonly m_count: number[] = [];

  constructor() {
    for (let i = 0; i < b2Shape.e_typeCount * b2Shape.e_typeCount; ++i) {
      this.m_free.push([]);
      this.m_count.push(0);
    }
  }

  /** A stored contact between fixtures of these shape types, or null when there is none. */
  Allocate(typeA: number, typeB: number): b2Contact | null {
    const k = typeA * b2Shape.e_typeCount + typeB;
    const count = this.m_count[k];
    if (count === 0) {
      return null;
    }
    const free = this.m_free[k];
    const contact = free[count - 1];
    free[count - 1] = null;
    this.m_count[k] = count - 1;
    return contact;
  }

  /** Store a destroyed contact between fixtures of these shape types. */
  Free(contact: b2Contact, typeA: number, typeB: number): void {
    const k = typeA * b2Shape.e_typeCount + typeB;
    const count = this.m_count[k];
    const free = this.m_free[k];
    if (count < free.length) {
      free[count] = contact;
    } else {
      free.push(contact);
    }
    this.m_count[k] = count + 1;
  }

  /** The number of stored contacts (for tests). */
  GetCount(): number {
    let n = 0;
    for (const count of this.m_count) n += count;
    return n;
  }
}
