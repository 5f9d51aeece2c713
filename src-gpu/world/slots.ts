/*
 * The mirror's bookkeeping: slots for bodies, fixtures, proxies and joints (lowest free first,
 * kept while the object lives), ranges of the shape pool, and the change log the engine's
 * b2ChangeListener fills between syncs.
 *
 * In:  the objects a sync walks (ObjectSlots.acquire), the API's change notifications (ChangeLog).
 * Out: dense slot indices both ways (items, slotOf: the engine objects carry their slot), released
 *      slots (sweep), pool offsets.
 * Invariants: a live object keeps its slot; a released slot goes to the next new object, lowest
 *      first; highWater is one past the highest slot in use.
 */

import type { b2Body } from '../../src/dynamics/b2Body';
import type { b2Fixture } from '../../src/dynamics/b2Fixture';
import { hostTableStore } from '../device/buffers';

/**
 * `array`, or a copy of it with its length doubled until `index` fits (new elements `fill`), in
 * a hostTableStore.
 */
export function withRoom<T extends Int32Array | Uint32Array | Float64Array>(array: T, index: number, fill = 0): T {
  if (index < array.length) return array;
  let size = array.length;
  while (size <= index) size *= 2;
  const grown = new (array.constructor as new (buffer: ArrayBufferLike) => T)(hostTableStore(size * array.BYTES_PER_ELEMENT));
  if (fill !== 0) grown.fill(fill, array.length);
  grown.set(array);
  return grown;
}

/**
 * What the API changed since the last sync: the world's b2ChangeListener while a GpuWorld mirrors
 * it (structurally one: src-gpu imports no engine class).
 */
export class ChangeLog {
  /** A body, fixture or joint came or went (or this is the first sync): walk everything. */
  structure = true;
  /** Bodies set through the API, true when their motion was set. */
  readonly bodies = new Map<b2Body, boolean>();
  readonly fixtures = new Set<b2Fixture>();
  /** Bodies the API asked to be awake (b2ChangeListener.BodyWoken). */
  readonly woken = new Set<b2Body>();

  BodyChanged(body: b2Body, motion: boolean): void {
    if (motion) this.bodies.set(body, true);
    else if (!this.bodies.has(body)) this.bodies.set(body, false);
  }

  BodyWoken(body: b2Body): void {
    this.woken.add(body);
  }

  FixtureChanged(fixture: b2Fixture): void {
    this.fixtures.add(fixture);
  }

  StructureChanged(): void {
    this.structure = true;
  }

  reset(): void {
    this.structure = false;
    this.bodies.clear();
    this.fixtures.clear();
    this.woken.clear();
  }
}

/** Slots handed out lowest free first; `gen` marks the slots seen by the current sync. */
export class SlotAllocator<T> {
  readonly items: (T | null)[] = [];
  gen = new Uint32Array(64);
  /** Free slots below `highWater`, in descending order (pop() gives the lowest). */
  private free: number[] = [];
  highWater = 0;
  live = 0;

  /** A free slot, lowest first. */
  alloc(): number {
    const slot = this.free.length > 0 ? this.free.pop()! : this.highWater++;
    this.live++;
    return slot;
  }

  /** Marks `slot` as seen in `generation`. */
  mark(slot: number, generation: number): void {
    this.gen = withRoom(this.gen, slot);
    this.gen[slot] = generation;
  }

  /** Releases every slot not seen in `generation`; calls `onRelease(slot, item)` for each. */
  sweep(generation: number, onRelease: (slot: number, item: T) => void): number {
    let released = 0;
    for (let slot = 0; slot < this.highWater; ++slot) {
      const item = this.items[slot];
      if (item !== null && item !== undefined && this.gen[slot] !== generation) {
        this.items[slot] = null;
        this.forget(item);
        this.free.push(slot);
        this.live--;
        released++;
        onRelease(slot, item);
      }
    }
    if (released > 0) {
      this.free.sort((a, b) => b - a);
      while (this.free.length > 0 && this.free[0] === this.highWater - 1) {
        this.free.shift();
        this.highWater--;
      }
    }
    return released;
  }

  /** Drops what maps `item` to its slot (released by sweep). */
  protected forget(_item: T): void {}
}

/**
 * The fields the engine's bodies, fixtures and joints hold for a mirror (b2Body.m_mirrorSlot,
 * m_mirrorId): the slot, and which mirror gave it.
 */
export interface MirrorSlotted {
  m_mirrorSlot: number;
  m_mirrorId: number;
}

/** The ids of the ObjectSlots not yet disposed: an object tagged by one of them is taken. */
const liveMirrors = new Set<number>();
let lastMirrorId = 0;

/**
 * Slots of engine objects, found from the object. Each object holds its slot and the id of the
 * allocator that gave it (a field read, where a Map of 10^6 objects made attaching a large world
 * slow); an object already tagged by another live allocator (a second mirror of the same world)
 * is kept in a Map instead.
 */
export class ObjectSlots<T extends MirrorSlotted> extends SlotAllocator<T> {
  readonly id = ++lastMirrorId;
  private readonly others = new Map<T, number>();
  /** Whether the last acquire() created the slot. */
  created = false;
  /** Whether no item had a slot when the walk began (beginWalk): acquire() then need not look one up. */
  private empty = false;

  constructor() {
    super();
    liveMirrors.add(this.id);
  }

  /** Starts a walk that acquires each item at most once (a sync's walk of the world). */
  beginWalk(): void {
    this.empty = this.live === 0;
  }

  /** The item's slot, or -1. */
  slotOf(item: T): number {
    if (item.m_mirrorId === this.id) return item.m_mirrorSlot;
    return this.others.size > 0 ? (this.others.get(item) ?? -1) : -1;
  }

  /**
   * The item's slot (a new one, lowest free first, when it has none); marks it seen. `hint`, the
   * slot the item had at the same place of the previous walk, skips the lookup when it holds.
   */
  acquire(item: T, generation: number, hint = -1): number {
    if (hint >= 0 && hint < this.highWater && this.items[hint] === item) {
      this.created = false;
      this.mark(hint, generation);
      return hint;
    }
    let slot = this.empty ? -1 : this.slotOf(item);
    this.created = slot < 0;
    if (slot < 0) {
      slot = this.alloc();
      this.items[slot] = item;
      if (item.m_mirrorId === 0 || !liveMirrors.has(item.m_mirrorId)) {
        item.m_mirrorId = this.id;
        item.m_mirrorSlot = slot;
      } else {
        this.others.set(item, slot);
      }
    }
    this.mark(slot, generation);
    return slot;
  }

  /** Gives up the tags this allocator set (another allocator may take the objects); it is not used after. */
  dispose(): void {
    liveMirrors.delete(this.id);
  }

  protected override forget(item: T): void {
    if (item.m_mirrorId === this.id) item.m_mirrorId = 0;
    else this.others.delete(item);
  }
}

/** Ranges of the shape pool, reused by size; compacted by rebuilding. */
export class PoolAllocator {
  top = 0;
  live = 0;
  private readonly freeBySize = new Map<number, number[]>();

  alloc(size: number): number {
    this.live += size;
    const list = this.freeBySize.size > 0 ? this.freeBySize.get(size) : undefined;
    if (list && list.length > 0) return list.pop()!;
    const offset = this.top;
    this.top += size;
    return offset;
  }

  free(offset: number, size: number): void {
    this.live -= size;
    let list = this.freeBySize.get(size);
    if (!list) this.freeBySize.set(size, (list = []));
    list.push(offset);
  }

  reset(): void {
    this.top = 0;
    this.live = 0;
    this.freeBySize.clear();
  }

  get fragmented(): boolean {
    return this.top > 2 * this.live + 4096;
  }
}
