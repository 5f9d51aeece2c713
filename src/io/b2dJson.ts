/*
 * b2dJson scene reading and writing: the JSON format of R.U.B.E. and iforce2d's b2dJson, with the
 * conventions that make a round trip exact (see b2dJsonRead and b2dJsonWrite).
 */

export { b2dJsonRead } from './b2dJsonRead';
export { b2dJsonStringify, b2dJsonWrite, b2dJsonWriteString } from './b2dJsonWrite';
export type { b2dJsonWriteOptions } from './b2dJsonWrite';
export { b2dJson_stateKey, b2dJson_stateVersion } from './b2dJsonState';
export {
  b2dJsonBodiesInCreationOrder,
  b2dJsonError,
  b2dJsonFixturesInCreationOrder,
  b2dJsonImage,
  b2dJsonJointsInCreationOrder,
  b2dJsonScene,
  b2dJson_defaultStepSettings,
} from './b2dJsonScene';
export type {
  b2dJsonColor,
  b2dJsonCustomProperty,
  b2dJsonItem,
  b2dJsonObject,
  b2dJsonReadOptions,
  b2dJsonSkippedItem,
  b2dJsonStepSettings,
  b2dJsonValue,
} from './b2dJsonScene';
