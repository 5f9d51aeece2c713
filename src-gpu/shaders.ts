/*
 * The WGSL of every stage, as text bundled with the code (esbuild's text loader in the builds,
 * a small plugin in vitest.config.ts for the tests). The engine's constants (engineWgsl.ts) and
 * shaders/common.wgsl are prepended to each stage, since WGSL has no include, and shaders/manifold.wgsl (bindings and helpers of the collide
 * kernels) to the four narrow-phase collide stages; shaders/solverCommon.wgsl (the solver's
 * parameters, constants and helpers) to the solver stages, and shaders/solveJointsCommon.wgsl (the
 * joints' share of the colour passes) to the stages that solve joints; shaders/distance.wgsl (GJK)
 * to the sensor test and to continuous collision, which also takes manifold.wgsl's shape helpers.
 */

import { ENGINE_WGSL } from './engineWgsl';
import commonWgsl from '../shaders/common.wgsl';
import bounds from '../shaders/bounds.wgsl';
import axis from '../shaders/axis.wgsl';
import keys from '../shaders/keys.wgsl';
import radixSort from '../shaders/radixSort.wgsl';
import scan from '../shaders/scan.wgsl';
import sweep from '../shaders/sweep.wgsl';
import pairs from '../shaders/pairs.wgsl';
import manifold from '../shaders/manifold.wgsl';
import contacts from '../shaders/contacts.wgsl';
import collideCircle from '../shaders/collideCircle.wgsl';
import collidePolygon from '../shaders/collidePolygon.wgsl';
import collideEdge from '../shaders/collideEdge.wgsl';
import distance from '../shaders/distance.wgsl';
import overlap from '../shaders/overlap.wgsl';
import persist from '../shaders/persist.wgsl';
import compact from '../shaders/compact.wgsl';
import solverCommon from '../shaders/solverCommon.wgsl';
import integrateVelocities from '../shaders/integrateVelocities.wgsl';
import prepareContacts from '../shaders/prepareContacts.wgsl';
import colour from '../shaders/colour.wgsl';
import warmStart from '../shaders/warmStart.wgsl';
import solveVelocity from '../shaders/solveVelocity.wgsl';
import storeImpulses from '../shaders/storeImpulses.wgsl';
import integratePositions from '../shaders/integratePositions.wgsl';
import solvePosition from '../shaders/solvePosition.wgsl';
import solveJoints from '../shaders/solveJoints.wgsl';
import timeOfImpact from '../shaders/timeOfImpact.wgsl';
import solveJointsCommon from '../shaders/solveJointsCommon.wgsl';
import islands from '../shaders/islands.wgsl';

const common = `${ENGINE_WGSL}\n${commonWgsl}`;

export const SHADERS = {
  common,
  bounds: `${common}\n${bounds}`,
  axis: `${common}\n${axis}`,
  keys: `${common}\n${keys}`,
  radixSort: `${common}\n${radixSort}`,
  scan: `${common}\n${scan}`,
  sweep: `${common}\n${sweep}`,
  pairs: `${common}\n${pairs}`,
  contacts: `${common}\n${contacts}`,
  collideCircle: `${common}\n${manifold}\n${collideCircle}`,
  collidePolygon: `${common}\n${manifold}\n${collidePolygon}`,
  collideEdge: `${common}\n${manifold}\n${collideEdge}`,
  overlap: `${common}\n${manifold}\n${distance}\n${overlap}`,
  persist: `${common}\n${persist}`,
  compact: `${common}\n${compact}`,
  integrateVelocities: `${common}\n${solverCommon}\n${integrateVelocities}`,
  prepareContacts: `${common}\n${solverCommon}\n${prepareContacts}`,
  colour: `${common}\n${solverCommon}\n${colour}`,
  warmStart: `${common}\n${solverCommon}\n${solveJointsCommon}\n${warmStart}`,
  solveVelocity: `${common}\n${solverCommon}\n${solveJointsCommon}\n${solveVelocity}`,
  storeImpulses: `${common}\n${solverCommon}\n${storeImpulses}`,
  integratePositions: `${common}\n${solverCommon}\n${integratePositions}`,
  solvePosition: `${common}\n${solverCommon}\n${solveJointsCommon}\n${solvePosition}`,
  solveJoints: `${common}\n${solverCommon}\n${solveJointsCommon}\n${solveJoints}`,
  islands: `${common}\n${solverCommon}\n${islands}`,
  timeOfImpact: `${common}\n${manifold}\n${distance}\n${timeOfImpact}`,
} as const;

export type ShaderName = Exclude<keyof typeof SHADERS, 'common'>;
