/*
 * The engine's constants as WGSL, generated from the modules that define them
 * (src/common/b2Constants.ts, src/common/b2Settings.ts) and prepended to every stage's shader
 * (shaders.ts): no WGSL file retypes a flag, a type number or a tolerance of 2.2.1
 * (test/gpu/layout.test.ts checks that none declares one of these names).
 * f32 values are written as the engine's float64 numbers, which WGSL rounds to f32.
 */

import { b2BodyFlags, b2BodyType, b2ContactFeatureType, b2JointType, b2LimitState, b2ManifoldType, b2ShapeType } from '../../src/common/b2Constants';
import {
  b2_angularSleepTolerance,
  b2_angularSlop,
  b2_baumgarte,
  b2_linearSleepTolerance,
  b2_linearSlop,
  b2_maxAngularCorrection,
  b2_maxLinearCorrection,
  b2_maxPolygonVertices,
  b2_maxRotation,
  b2_maxTranslation,
  b2_pi,
  b2_polygonRadius,
  b2_timeToSleep,
  b2_velocityThreshold,
} from '../../src/common/b2Settings';

/** WGSL name, type and value of each engine constant the shaders use. */
export const ENGINE_CONSTANTS: readonly (readonly [string, 'u32' | 'f32', number])[] = [
  ['BODY_AUTO_SLEEP', 'u32', b2BodyFlags.e_autoSleepFlag],
  ['BODY_BULLET', 'u32', b2BodyFlags.e_bulletFlag],
  ['BODY_ACTIVE', 'u32', b2BodyFlags.e_activeFlag],
  ['STATIC_BODY', 'u32', b2BodyType.b2_staticBody],
  ['DYNAMIC_BODY', 'u32', b2BodyType.b2_dynamicBody],
  ['SHAPE_CIRCLE', 'u32', b2ShapeType.e_circle],
  ['SHAPE_EDGE', 'u32', b2ShapeType.e_edge],
  ['SHAPE_POLYGON', 'u32', b2ShapeType.e_polygon],
  ['SHAPE_CHAIN', 'u32', b2ShapeType.e_chain],
  ['E_CIRCLES', 'u32', b2ManifoldType.e_circles],
  ['E_FACE_A', 'u32', b2ManifoldType.e_faceA],
  ['E_FACE_B', 'u32', b2ManifoldType.e_faceB],
  ['F_VERTEX', 'u32', b2ContactFeatureType.e_vertex],
  ['F_FACE', 'u32', b2ContactFeatureType.e_face],
  ['REVOLUTE_JOINT', 'u32', b2JointType.e_revoluteJoint],
  ['PRISMATIC_JOINT', 'u32', b2JointType.e_prismaticJoint],
  ['DISTANCE_JOINT', 'u32', b2JointType.e_distanceJoint],
  ['PULLEY_JOINT', 'u32', b2JointType.e_pulleyJoint],
  ['MOUSE_JOINT', 'u32', b2JointType.e_mouseJoint],
  ['GEAR_JOINT', 'u32', b2JointType.e_gearJoint],
  ['WHEEL_JOINT', 'u32', b2JointType.e_wheelJoint],
  ['WELD_JOINT', 'u32', b2JointType.e_weldJoint],
  ['FRICTION_JOINT', 'u32', b2JointType.e_frictionJoint],
  ['ROPE_JOINT', 'u32', b2JointType.e_ropeJoint],
  ['INACTIVE_LIMIT', 'u32', b2LimitState.e_inactiveLimit],
  ['AT_LOWER_LIMIT', 'u32', b2LimitState.e_atLowerLimit],
  ['AT_UPPER_LIMIT', 'u32', b2LimitState.e_atUpperLimit],
  ['EQUAL_LIMITS', 'u32', b2LimitState.e_equalLimits],
  ['MAX_POLYGON_VERTICES', 'u32', b2_maxPolygonVertices],
  ['PI', 'f32', b2_pi],
  ['LINEAR_SLOP', 'f32', b2_linearSlop],
  ['ANGULAR_SLOP', 'f32', b2_angularSlop],
  ['POLYGON_RADIUS', 'f32', b2_polygonRadius],
  ['BAUMGARTE', 'f32', b2_baumgarte],
  ['MAX_LINEAR_CORRECTION', 'f32', b2_maxLinearCorrection],
  ['MAX_ANGULAR_CORRECTION', 'f32', b2_maxAngularCorrection],
  ['VELOCITY_THRESHOLD', 'f32', b2_velocityThreshold],
  ['MAX_TRANSLATION', 'f32', b2_maxTranslation],
  ['MAX_ROTATION', 'f32', b2_maxRotation],
  ['TIME_TO_SLEEP', 'f32', b2_timeToSleep],
  ['LINEAR_SLEEP_TOLERANCE', 'f32', b2_linearSleepTolerance],
  ['ANGULAR_SLEEP_TOLERANCE', 'f32', b2_angularSleepTolerance],
];

function literal(type: 'u32' | 'f32', value: number): string {
  if (type === 'u32') return `${value}u`;
  const text = String(value);
  return /[.e]/.test(text) ? text : `${text}.0`;
}

export const ENGINE_WGSL = [
  "// The engine's constants (src-gpu/device/engineWgsl.ts, generated from src/common/b2Constants.ts and b2Settings.ts).",
  ...ENGINE_CONSTANTS.map(([name, type, value]) => `const ${name}: ${type} = ${literal(type, value)};`),
].join('\n');
