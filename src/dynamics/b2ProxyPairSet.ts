/*
 * Not in the C++: the set of broad-phase proxy pairs that have a contact, which answers
 * b2ContactManager::AddPair's question "does a contact already exist?".
 *
 * The C++ answers it by walking body B's contact list. That walk is short in a sparse scene, but a
 * pile of small bodies gives every body a score of contacts (fat AABBs overlap well beyond the
 * touching neighbours), and a body whose fat AABB moves reports every pair it overlaps again: in
 * the tumbler benchmark some 2,600 pairs a step walked 50,000 contact edges, one cache miss each.
 * A fixture child's proxy id names it uniquely for as long as its contacts live (every call that
 * destroys proxies, DestroyFixture, DestroyBody and SetActive(false), destroys their contacts in
 * the same call, and SetType keeps the proxies), so the set holds exactly the pairs the walk would
 * find, and the answer is the same.
 *
 * Open addressing with linear probing over one Int32Array of (lower id, higher id) slots, -1 for
 * an empty slot; removal shifts the following entries back (no tombstones), so a lookup stops at
 * the first empty slot. The table doubles when half full.
 */

const EMPTY = -1;

export class b2ProxyPairSet {
  /** Slot i holds its pair's lower id at 2i and higher id at 2i + 1. */
  private m_slots: Int32Array;
  private m_mask: number;
  private m_count = 0;

  constructor(capacity = 256) {
    let slots = 16;
    while (slots < 2 * capacity) slots *= 2;
    this.m_slots = new Int32Array(2 * slots).fill(EMPTY);
    this.m_mask = slots - 1;
  }

  /** The number of pairs held. */
  GetCount(): number {
    return this.m_count;
  }

  /** Whether the pair of proxies idA and idB (either order) is held. */
  Has(idA: number, idB: number): boolean {
    return this.Find(idA, idB) >= 0;
  }

  /** Adds the pair of proxies idA and idB (ids are non-negative; the pair must not be held). */
  Add(idA: number, idB: number): void {
    if (2 * (this.m_count + 1) > this.m_mask + 1) this.Grow();
    this.Insert(idA < idB ? idA : idB, idA < idB ? idB : idA);
    ++this.m_count;
  }

  /** Removes the pair of proxies idA and idB (either order); returns whether it was held. */
  Remove(idA: number, idB: number): boolean {
    const i = this.Find(idA, idB);
    if (i < 0) return false;
    const slots = this.m_slots;
    const mask = this.m_mask;
    // Shift back every following entry of the run that may move into the hole: one whose home
    // slot does not lie cyclically in (hole, j].
    let hole = i;
    for (let j = (i + 1) & mask; slots[2 * j] !== EMPTY; j = (j + 1) & mask) {
      const home = b2ProxyPairSet.Hash(slots[2 * j], slots[2 * j + 1]) & mask;
      if (((j - home) & mask) >= ((j - hole) & mask)) {
        slots[2 * hole] = slots[2 * j];
        slots[2 * hole + 1] = slots[2 * j + 1];
        hole = j;
      }
    }
    slots[2 * hole] = EMPTY;
    slots[2 * hole + 1] = EMPTY;
    --this.m_count;
    return true;
  }

  /** Removes every pair. */
  Clear(): void {
    this.m_slots.fill(EMPTY);
    this.m_count = 0;
  }

  /** The slot holding the pair of proxies idA and idB (either order), or -1. */
  private Find(idA: number, idB: number): number {
    const lo = idA < idB ? idA : idB;
    const hi = idA < idB ? idB : idA;
    const slots = this.m_slots;
    const mask = this.m_mask;
    for (let i = b2ProxyPairSet.Hash(lo, hi) & mask; ; i = (i + 1) & mask) {
      const l = slots[2 * i];
      if (l === EMPTY) return -1;
      if (l === lo && slots[2 * i + 1] === hi) return i;
    }
  }

  private Insert(lo: number, hi: number): void {
    const slots = this.m_slots;
    const mask = this.m_mask;
    let i = b2ProxyPairSet.Hash(lo, hi) & mask;
    while (slots[2 * i] !== EMPTY) i = (i + 1) & mask;
    slots[2 * i] = lo;
    slots[2 * i + 1] = hi;
  }

  private Grow(): void {
    const old = this.m_slots;
    this.m_slots = new Int32Array(2 * old.length).fill(EMPTY);
    this.m_mask = old.length - 1;
    for (let i = 0; i < old.length; i += 2) {
      if (old[i] !== EMPTY) this.Insert(old[i], old[i + 1]);
    }
  }

  /** Mixes both ids into every bit (multiplicative hashing), so that a power-of-two mask spreads them. */
  private static Hash(lo: number, hi: number): number {
    const h = Math.imul(lo, 0x9e3779b1) ^ Math.imul(hi, 0x85ebca77);
    return h ^ (h >>> 15);
  }
}
