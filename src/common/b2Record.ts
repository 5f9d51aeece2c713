/*
 * Not in the C++: records, the layout this port gives the structs the step reads most. V8 boxes
 * every double held in an object field (Node 20: a b2Vec2 is a 40-byte object pointing at two
 * 16-byte numbers), so a struct of vectors becomes a scatter of small heap objects, and a step
 * that visits thousands of them waits on memory. A record keeps such a struct's doubles at fixed
 * offsets in a Float64Array shared with its neighbours; the engine's hot paths read and write it,
 * and the struct's public vectors are b2RecordVec2 views onto it, so users see the same objects.
 * Engine code never passes a view to b2Vec2's methods or b2Math's functions, which would then be
 * compiled for two layouts wherever they are inlined (docs/PORTING.md).
 *
 * Invariant: a record belongs to one object for that object's life and is never handed out again;
 * its chunk is garbage once all of its owners are.
 */

import { b2Vec2 } from './b2Math';

/**
 * Hands out records of `stride` doubles from chunks of `chunkRecords`, so that objects created
 * together lie together.
 */
export class b2RecordPool {
  /** The chunk records are being handed out from. */
  chunk = new Float64Array(0);
  private m_next = 0;

  constructor(
    private readonly m_stride: number,
    private readonly m_chunkRecords: number,
  ) {}

  /** The offset of a fresh (zeroed) record in `this.chunk` as it is after the call. */
  Allocate(): number {
    if (this.m_next === this.chunk.length) {
      this.chunk = new Float64Array(this.m_chunkRecords * this.m_stride);
      this.m_next = 0;
    }
    const offset = this.m_next;
    this.m_next += this.m_stride;
    return offset;
  }
}

/**
 * Show the instances of a class that holds a record (a view, or an object with views) to
 * console.log as their toJSON() shows them to JSON.stringify: their values, as plain objects
 * showed them, not the chunk of thousands of doubles they hold (Node's util.inspect hook).
 */
export function b2InspectAsJSON(target: { prototype: { toJSON(): object } }): void {
  Object.defineProperty(target.prototype, Symbol.for('nodejs.util.inspect.custom'), {
    value: function inspect(this: { toJSON(): object }): object {
      return this.toJSON();
    },
  });
}

/**
 * A b2Vec2 whose coordinates are two doubles of a record: reading and writing x and y reads and
 * writes the record. It has b2Vec2's prototype and methods, but not its constructor, whose field
 * writes would run these setters before the record is known.
 */
export class b2RecordVec2 {
  constructor(
    readonly m_record: Float64Array,
    readonly m_offset: number,
  ) {}

  get x(): number {
    return this.m_record[this.m_offset];
  }

  set x(value: number) {
    this.m_record[this.m_offset] = value;
  }

  get y(): number {
    return this.m_record[this.m_offset + 1];
  }

  set y(value: number) {
    this.m_record[this.m_offset + 1] = value;
  }

  toJSON(): { x: number; y: number } {
    return { x: this.x, y: this.y };
  }
}

export interface b2RecordVec2 extends b2Vec2 {}
Object.setPrototypeOf(b2RecordVec2.prototype, b2Vec2.prototype);
b2InspectAsJSON(b2RecordVec2);
