/*
 * The WGSL of every stage, as text bundled with the code (esbuild's text loader in the builds,
 * a small plugin in vitest.config.ts for the tests). The engine's constants (engineWgsl.ts) and
 * shaders/shared/common.wgsl are prepended to each stage, since WGSL has no include, and shaders/shared/manifold.wgsl (bindings and helpers of the collide
 * kernels) to the four narrow-phase collide stages; shaders/shared/solverCommon.wgsl (the solver's
 * parameters, constants and helpers) to the solver stages, and shaders/shared/solveJointsCommon.wgsl (the
 * joints' share of the colour passes) to the stages that solve joints; shaders/shared/distance.wgsl (GJK)
 * to the sensor test and to continuous collision, which also takes manifold.wgsl's shape helpers.
 * The renderer's two stages (shaders/render/cull.wgsl and render.wgsl) take
 * shaders/shared/renderView.wgsl (their view uniform, draw list numbers and shape decoding); the
 * point query's and the bulk transform read's take common.wgsl only.
 */

import { ENGINE_WGSL } from './engineWgsl';
import commonWgsl from '../../shaders/shared/common.wgsl';
import bounds from '../../shaders/broadphase/bounds.wgsl';
import axis from '../../shaders/broadphase/axis.wgsl';
import keys from '../../shaders/broadphase/keys.wgsl';
import radixSort from '../../shaders/primitives/radixSort.wgsl';
import scan from '../../shaders/primitives/scan.wgsl';
import sweep from '../../shaders/broadphase/sweep.wgsl';
import pairs from '../../shaders/broadphase/pairs.wgsl';
import manifold from '../../shaders/shared/manifold.wgsl';
import contacts from '../../shaders/narrowphase/contacts.wgsl';
import collideCircle from '../../shaders/narrowphase/collideCircle.wgsl';
import collidePolygon from '../../shaders/narrowphase/collidePolygon.wgsl';
import collideEdge from '../../shaders/narrowphase/collideEdge.wgsl';
import distance from '../../shaders/shared/distance.wgsl';
import overlap from '../../shaders/narrowphase/overlap.wgsl';
import persist from '../../shaders/narrowphase/persist.wgsl';
import compact from '../../shaders/narrowphase/compact.wgsl';
import solverCommon from '../../shaders/shared/solverCommon.wgsl';
import integrateVelocities from '../../shaders/solver/integrateVelocities.wgsl';
import prepareContacts from '../../shaders/solver/prepareContacts.wgsl';
import colour from '../../shaders/solver/colour.wgsl';
import warmStart from '../../shaders/solver/warmStart.wgsl';
import solveVelocity from '../../shaders/solver/solveVelocity.wgsl';
import storeImpulses from '../../shaders/solver/storeImpulses.wgsl';
import integratePositions from '../../shaders/solver/integratePositions.wgsl';
import solvePosition from '../../shaders/solver/solvePosition.wgsl';
import solveJoints from '../../shaders/solver/solveJoints.wgsl';
import timeOfImpact from '../../shaders/solver/timeOfImpact.wgsl';
import solveJointsCommon from '../../shaders/shared/solveJointsCommon.wgsl';
import islands from '../../shaders/solver/islands.wgsl';
import penetration from '../../shaders/solver/penetration.wgsl';
import renderView from '../../shaders/shared/renderView.wgsl';
import cull from '../../shaders/render/cull.wgsl';
import render from '../../shaders/render/render.wgsl';
import pointQuery from '../../shaders/query/pointQuery.wgsl';
import transforms from '../../shaders/query/transforms.wgsl';

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
  penetration: `${common}\n${solverCommon}\n${penetration}`,
  timeOfImpact: `${common}\n${manifold}\n${distance}\n${timeOfImpact}`,
  cull: `${common}\n${renderView}\n${cull}`,
  render: `${common}\n${renderView}\n${render}`,
  pointQuery: `${common}\n${pointQuery}`,
  transforms: `${common}\n${transforms}`,
} as const;

export type ShaderName = Exclude<keyof typeof SHADERS, 'common'>;
