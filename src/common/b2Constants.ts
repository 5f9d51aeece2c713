/*
 * The engine's flag bits and type numbers, in one module that imports nothing.
 *
 * In Box2D they are enums nested in their classes (b2Body::e_awakeFlag, b2Shape::e_circle). Here
 * the classes re-export them as statics and enums under the same names, and everything that only
 * needs a number (the other dynamics files, the GPU backend and its WGSL, which must agree bit for
 * bit) imports it from this leaf, so that sharing a constant never makes two classes import each
 * other.
 */

/**
 * The body type.
 * static: zero mass, zero velocity, may be manually moved
 * kinematic: zero mass, non-zero velocity set by user, moved by solver
 * dynamic: positive mass, non-zero velocity determined by forces, moved by solver
 */
export enum b2BodyType {
  b2_staticBody = 0,
  b2_kinematicBody = 1,
  b2_dynamicBody = 2,
}

/** b2Body::m_flags. */
export const b2BodyFlags = {
  e_islandFlag: 0x0001,
  e_awakeFlag: 0x0002,
  e_autoSleepFlag: 0x0004,
  e_bulletFlag: 0x0008,
  e_fixedRotationFlag: 0x0010,
  e_activeFlag: 0x0020,
  e_toiFlag: 0x0040,
} as const;

/** b2World::m_flags. */
export const b2WorldFlags = {
  e_newFixture: 0x0001,
  e_locked: 0x0002,
  e_clearForces: 0x0004,
} as const;

/** b2Contact::m_flags. */
export const b2ContactFlags = {
  /** Used when crawling contact graph when forming islands. */
  e_islandFlag: 0x0001,
  /** Set when the shapes are touching. */
  e_touchingFlag: 0x0002,
  /** This contact can be disabled (by user) */
  e_enabledFlag: 0x0004,
  /** This contact needs filtering because a fixture filter was changed. */
  e_filterFlag: 0x0008,
  /** This bullet contact had a TOI event */
  e_bulletHitFlag: 0x0010,
  /** This contact has a valid TOI in m_toi */
  e_toiFlag: 0x0020,
} as const;

/** b2Shape::Type. */
export const b2ShapeType = {
  e_circle: 0,
  e_edge: 1,
  e_polygon: 2,
  e_chain: 3,
  e_typeCount: 4,
} as const;

/** b2Manifold::Type. */
export const b2ManifoldType = {
  e_circles: 0,
  e_faceA: 1,
  e_faceB: 2,
} as const;

/** b2ContactFeature::Type. */
export const b2ContactFeatureType = {
  e_vertex: 0,
  e_face: 1,
} as const;

export enum b2JointType {
  e_unknownJoint,
  e_revoluteJoint,
  e_prismaticJoint,
  e_distanceJoint,
  e_pulleyJoint,
  e_mouseJoint,
  e_gearJoint,
  e_wheelJoint,
  e_weldJoint,
  e_frictionJoint,
  e_ropeJoint,
}

export enum b2LimitState {
  e_inactiveLimit,
  e_atLowerLimit,
  e_atUpperLimit,
  e_equalLimits,
}
