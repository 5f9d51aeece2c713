/*
 * The shape base class and mass data (b2Shape.h).
 */

import { b2ShapeType } from '../../common/b2Constants';
import { b2Vec2 } from '../../common/b2Math';
import type { b2Transform } from '../../common/b2Math';
import type { b2AABB, b2RayCastInput, b2RayCastOutput } from '../b2Collision';

/** This holds the mass data computed for a shape. */
export class b2MassData {
  /** The mass of the shape, usually in kilograms. */
  mass = 0.0;

  /** The position of the shape's centroid relative to the shape's origin. */
  readonly center = new b2Vec2();

  /** The rotational inertia of the shape about the local origin. */
  I = 0.0;

  Clone(): b2MassData {
    return new b2MassData().Assign(this);
  }

  Assign(massData: Readonly<b2MassData>): this {
    this.mass = massData.mass;
    this.center.Assign(massData.center);
    this.I = massData.I;
    return this;
  }
}

/**
 * A shape is used for collision detection. You can create a shape however you like.
 * Shapes used for simulation in b2World are created automatically when a b2Fixture
 * is created. Shapes may encapsulate a one or more child shapes.
 */
export abstract class b2Shape {
  static readonly e_circle = b2ShapeType.e_circle;
  static readonly e_edge = b2ShapeType.e_edge;
  static readonly e_polygon = b2ShapeType.e_polygon;
  static readonly e_chain = b2ShapeType.e_chain;
  static readonly e_typeCount = b2ShapeType.e_typeCount;

  m_type: number;
  m_radius: number;

  protected constructor(type: number, radius: number) {
    this.m_type = type;
    this.m_radius = radius;
  }

  /** Clone the concrete shape. */
  abstract Clone(): b2Shape;

  /**
   * Get the type of this shape. You can use this to down cast to the concrete shape.
   * @return the shape type.
   */
  GetType(): number {
    return this.m_type;
  }

  /** Get the number of child primitives. */
  abstract GetChildCount(): number;

  /**
   * Test a point for containment in this shape. This only works for convex shapes.
   * @param xf the shape world transform.
   * @param p a point in world coordinates.
   */
  abstract TestPoint(xf: Readonly<b2Transform>, p: Readonly<b2Vec2>): boolean;

  /**
   * Cast a ray against a child shape.
   * @param output the ray-cast results.
   * @param input the ray-cast input parameters.
   * @param transform the transform to be applied to the shape.
   * @param childIndex the child shape index
   */
  abstract RayCast(output: b2RayCastOutput, input: Readonly<b2RayCastInput>, transform: Readonly<b2Transform>, childIndex: number): boolean;

  /**
   * Given a transform, compute the associated axis aligned bounding box for a child shape.
   * @param aabb returns the axis aligned box.
   * @param xf the world transform of the shape.
   * @param childIndex the child shape
   */
  abstract ComputeAABB(aabb: b2AABB, xf: Readonly<b2Transform>, childIndex: number): void;

  /**
   * Compute the mass properties of this shape using its dimensions and density.
   * The inertia tensor is computed about the local origin.
   * @param massData returns the mass data for this shape.
   * @param density the density in kilograms per meter squared.
   */
  abstract ComputeMass(massData: b2MassData, density: number): void;
}
