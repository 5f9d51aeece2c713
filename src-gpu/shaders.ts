/*
 * The WGSL of every stage, as text bundled with the code (esbuild's text loader in the builds,
 * a small plugin in vitest.config.ts for the tests). shaders/common.wgsl is prepended to each
 * stage, since WGSL has no include.
 */

import common from '../shaders/common.wgsl';
import bounds from '../shaders/bounds.wgsl';
import axis from '../shaders/axis.wgsl';
import keys from '../shaders/keys.wgsl';
import radixSort from '../shaders/radixSort.wgsl';
import scan from '../shaders/scan.wgsl';
import sweep from '../shaders/sweep.wgsl';
import pairs from '../shaders/pairs.wgsl';

export const SHADERS = {
  common,
  bounds: `${common}\n${bounds}`,
  axis: `${common}\n${axis}`,
  keys: `${common}\n${keys}`,
  radixSort: `${common}\n${radixSort}`,
  scan: `${common}\n${scan}`,
  sweep: `${common}\n${sweep}`,
  pairs: `${common}\n${pairs}`,
} as const;

export type ShaderName = Exclude<keyof typeof SHADERS, 'common'>;
