/*
 * Box2DWeb's Box2D.Common.b2Settings: the settings constants of Box2D 2.2.1 under their names,
 * 2.1a's b2MixFriction, b2MixRestitution and b2Assert, and 2.1a's own names where 2.2.1 kept the
 * setting under another (b2_contactBaumgarte is b2_baumgarte). Reading a 2.1a setting that
 * Box2D 2.2 dropped throws.
 */

import * as settings from '../common/b2Settings';
import { b2MixFriction, b2MixRestitution } from '../dynamics/contacts/b2Contact';
import { defineRemovedProperty } from './patch';

export const b2Settings = {
  /** 2.1a's version string; b2_version holds the engine's (2.2.1). */
  VERSION: '2.2.1',
  USHRT_MAX: 0xffff,
  b2_maxFloat: settings.b2_maxFloat,
  b2_epsilon: settings.b2_epsilon,
  b2_pi: settings.b2_pi,
  b2_maxManifoldPoints: settings.b2_maxManifoldPoints,
  b2_maxPolygonVertices: settings.b2_maxPolygonVertices,
  b2_aabbExtension: settings.b2_aabbExtension,
  b2_aabbMultiplier: settings.b2_aabbMultiplier,
  b2_linearSlop: settings.b2_linearSlop,
  b2_angularSlop: settings.b2_angularSlop,
  b2_polygonRadius: settings.b2_polygonRadius,
  b2_maxSubSteps: settings.b2_maxSubSteps,
  b2_maxTOIContacts: settings.b2_maxTOIContacts,
  b2_velocityThreshold: settings.b2_velocityThreshold,
  b2_maxLinearCorrection: settings.b2_maxLinearCorrection,
  b2_maxAngularCorrection: settings.b2_maxAngularCorrection,
  b2_maxTranslation: settings.b2_maxTranslation,
  b2_maxTranslationSquared: settings.b2_maxTranslationSquared,
  b2_maxRotation: settings.b2_maxRotation,
  b2_maxRotationSquared: settings.b2_maxRotationSquared,
  b2_baumgarte: settings.b2_baumgarte,
  /** 2.1a's name for b2_baumgarte. */
  b2_contactBaumgarte: settings.b2_baumgarte,
  b2_toiBaugarte: settings.b2_toiBaugarte,
  b2_timeToSleep: settings.b2_timeToSleep,
  b2_linearSleepTolerance: settings.b2_linearSleepTolerance,
  b2_angularSleepTolerance: settings.b2_angularSleepTolerance,
  b2_version: settings.b2_version,
  /** Friction mixing law: sqrt(friction1 * friction2). */
  b2MixFriction,
  /** Restitution mixing law: the larger of the two. */
  b2MixRestitution,
  /** Throw if the condition is false. */
  b2Assert: settings.b2Assert,
};

for (const [name, instead] of [
  ['b2_toiSlop', 'The time of impact solver targets b2_linearSlop now.'],
  ['b2_maxTOIContactsPerIsland', 'Use b2_maxTOIContacts, the limit of the 2.2 TOI solver.'],
  ['b2_maxTOIJointsPerIsland', 'Joints take no part in the 2.2 TOI solver.'],
] as const) {
  defineRemovedProperty(b2Settings, name, `b2Settings.${name}`, instead);
}
