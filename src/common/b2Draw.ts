/*
 * Debug drawing interface (b2Draw.h). Implement the Draw* methods and register the object with
 * b2World.SetDebugDraw to see shapes, joints, AABBs, broad-phase pairs and centers of mass.
 */

import type { b2Transform, b2Vec2 } from './b2Math';

/** Color for debug drawing. Each value has the range [0,1]. */
export class b2Color {
  constructor(
    public r = 0.0,
    public g = 0.0,
    public b = 0.0,
  ) {}

  Set(ri: number, gi: number, bi: number): this {
    this.r = ri;
    this.g = gi;
    this.b = bi;
    return this;
  }
}

export abstract class b2Draw {
  /** draw shapes */
  static readonly e_shapeBit = 0x0001;
  /** draw joint connections */
  static readonly e_jointBit = 0x0002;
  /** draw axis aligned bounding boxes */
  static readonly e_aabbBit = 0x0004;
  /** draw broad-phase pairs */
  static readonly e_pairBit = 0x0008;
  /** draw center of mass frame */
  static readonly e_centerOfMassBit = 0x0010;

  protected m_drawFlags = 0;

  /** Set the drawing flags. */
  SetFlags(flags: number): void {
    this.m_drawFlags = flags >>> 0;
  }

  /** Get the drawing flags. */
  GetFlags(): number {
    return this.m_drawFlags;
  }

  /** Append flags to the current flags. */
  AppendFlags(flags: number): void {
    this.m_drawFlags = (this.m_drawFlags | flags) >>> 0;
  }

  /** Clear flags from the current flags. */
  ClearFlags(flags: number): void {
    this.m_drawFlags = (this.m_drawFlags & ~flags) >>> 0;
  }

  /** Draw a closed polygon provided in CCW order. */
  abstract DrawPolygon(vertices: readonly b2Vec2[], vertexCount: number, color: b2Color): void;

  /** Draw a solid closed polygon provided in CCW order. */
  abstract DrawSolidPolygon(vertices: readonly b2Vec2[], vertexCount: number, color: b2Color): void;

  /** Draw a circle. */
  abstract DrawCircle(center: b2Vec2, radius: number, color: b2Color): void;

  /** Draw a solid circle. */
  abstract DrawSolidCircle(center: b2Vec2, radius: number, axis: b2Vec2, color: b2Color): void;

  /** Draw a line segment. */
  abstract DrawSegment(p1: b2Vec2, p2: b2Vec2, color: b2Color): void;

  /** Draw a transform. Choose your own length scale. */
  abstract DrawTransform(xf: b2Transform): void;
}
