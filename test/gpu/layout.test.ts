/*
 * The host and the shaders agree on the shared layout: the state words, indirect argument
 * offsets, flag bits and tile sizes of src-gpu/layout.ts are the constants the WGSL declares; and
 * every stage has its WGSL file and host module, each opening with a comment on its inputs,
 * outputs and invariants. (No GPU needed.)
 */

import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, it } from 'vitest';
import { b2ContactFeature, b2Manifold } from '../../src/collision/b2Collision';
import {
  b2_angularSlop,
  b2_baumgarte,
  b2_maxAngularCorrection,
  b2_linearSlop,
  b2_maxLinearCorrection,
  b2_maxRotation,
  b2_maxTranslation,
  b2_polygonRadius,
  b2_velocityThreshold,
  b2_pi,
} from '../../src/common/b2Settings';
import { b2BodyFlags, b2BodyType, b2JointType, b2LimitState } from '../../src/common/b2Constants';
import { JOINT_PARAMS_VEC4, JOINT_VEC4 } from '../../src-gpu/solveJoints';
import * as layout from '../../src-gpu/layout';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const wgsl = (name: string) => readFileSync(path.join(root, 'shaders', `${name}.wgsl`), 'utf8');

function constants(source: string): Map<string, number> {
  const out = new Map<string, number>();
  for (const m of source.matchAll(/^const (\w+): (?:u32|f32) = (0x[0-9a-fA-F]+|[0-9.]+)u?;/gm)) out.set(m[1], Number(m[2]));
  return out;
}

const STAGES = [
  'bounds',
  'axis',
  'keys',
  'radixSort',
  'scan',
  'sweep',
  'pairs',
  'contacts',
  'collideCircle',
  'collidePolygon',
  'collideEdge',
  'overlap',
  'persist',
  'compact',
  'integrateVelocities',
  'prepareContacts',
  'colour',
  'warmStart',
  'solveVelocity',
  'storeImpulses',
  'integratePositions',
  'solvePosition',
  'solveJoints',
];

it('declares the state words, indirect offsets and flags the host uses', () => {
  const c = constants(wgsl('common'));
  for (const [name, value] of Object.entries(layout.STATE)) expect(c.get(`STATE_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.ARGS)) expect(c.get(`ARGS_${name}`), name).toBe(value);
  expect(c.get('PROXY_LIVE')).toBe(layout.PROXY_LIVE);
  expect(c.get('PROXY_SENSOR')).toBe(layout.PROXY_SENSOR);
  expect(c.get('PROXY_JOINTED')).toBe(layout.PROXY_JOINTED);
  expect(c.get('OVERFLOW_PAIRS')).toBe(layout.OVERFLOW_PAIRS);
  expect(c.get('OVERFLOW_ENTRIES')).toBe(layout.OVERFLOW_ENTRIES);
  expect(c.get('QUANT_BITS')).toBe(layout.QUANT_BITS);
  expect(c.get('MAX_STRIPS')).toBe(layout.MAX_STRIPS);
  // A proxy record packs its first strip and its quantised upper bound into one word (keys.wgsl).
  expect(c.get('MAX_STRIPS')! * (c.get('QUANT_MAX')! + 1)).toBeLessThanOrEqual(2 ** 32);
  expect(c.get('QUANT_MAX')).toBe(2 ** c.get('QUANT_BITS')! - 1);
  expect(c.get('WORKGROUP_SIZE')).toBe(layout.WORKGROUP_SIZE);
  expect(Math.max(...Object.values(layout.STATE))).toBeLessThan(layout.STATE_WORDS);
  expect(Math.max(...Object.values(layout.ARGS)) + 3).toBeLessThanOrEqual(layout.INDIRECT_WORDS);
});

it('declares the narrow phase\'s state words, bins, indirect offsets and contact flags the host uses', () => {
  const c = constants(wgsl('common'));
  for (const [name, value] of Object.entries(layout.NP)) expect(c.get(`NP_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.NP_ARGS)) expect(c.get(`NP_ARGS_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.BIN)) expect(c.get(`BIN_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.MF)) expect(c.get(`MF_${name}`), name).toBe(value);
  expect(c.get('BIN_COUNT')).toBe(layout.BIN_COUNT);
  expect(c.get('OVERFLOW_CONTACTS')).toBe(layout.OVERFLOW_CONTACTS);
  expect(c.get('NO_CONTACT')).toBe(layout.NO_CONTACT);
  expect(c.get('EVENT_BEGIN')).toBe(layout.EVENT_BEGIN);
  expect(c.get('EVENT_END')).toBe(layout.EVENT_END);
  expect(layout.BIN_NAMES.length).toBe(layout.BIN_COUNT);
  expect(layout.NP.BINS + layout.BIN_COUNT).toBeLessThan(layout.NP_STATE_WORDS);
  expect(layout.NP_ARGS.BINS + 3 * layout.BIN_COUNT).toBeLessThanOrEqual(layout.NP_INDIRECT_WORDS);
  // The manifold kernels use b2Manifold::Type and b2ContactFeature::Type as the engine numbers them.
  const m = constants(wgsl('manifold'));
  expect(m.get('E_CIRCLES')).toBe(b2Manifold.e_circles);
  expect(m.get('E_FACE_A')).toBe(b2Manifold.e_faceA);
  expect(m.get('E_FACE_B')).toBe(b2Manifold.e_faceB);
  expect(m.get('F_VERTEX')).toBe(b2ContactFeature.e_vertex);
  expect(m.get('F_FACE')).toBe(b2ContactFeature.e_face);
  expect(m.get('POLYGON_RADIUS')).toBe(b2_polygonRadius);
});

it("declares the solver's state words, indirect offsets, colour cap and 2.2.1's constants as the host and the engine use them", () => {
  const c = constants(wgsl('common'));
  for (const [name, value] of Object.entries(layout.SV)) expect(c.get(`SV_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.SV_ARGS)) expect(c.get(`SV_ARGS_${name}`), name).toBe(value);
  expect(c.get('COLOUR_CAP')).toBe(layout.COLOUR_CAP);
  expect(c.get('UNCOLOURED')).toBe(layout.UNCOLOURED);
  expect(c.get('CONSTRAINT_VEC4')).toBe(layout.CONSTRAINT_VEC4);
  expect(layout.SV.COLOUR_START + layout.COLOUR_CAP + 2).toBeLessThanOrEqual(layout.SV.COLOUR_CHANGED);
  expect(layout.SV.COLOUR_SORT_COUNT).toBeLessThan(layout.SV_STATE_WORDS);
  expect(layout.SV_ARGS.COLOURS + 3 * (layout.COLOUR_CAP + 1)).toBeLessThanOrEqual(layout.SV_ARGS.POSITION);
  expect(layout.SV_ARGS.POSITION + 3 * (layout.COLOUR_CAP + 1)).toBeLessThanOrEqual(layout.SV_ARGS.ITEMS);
  expect(layout.SV_ARGS.ROUNDS + 3).toBeLessThanOrEqual(layout.SV_INDIRECT_WORDS);
  // The colour sort's digits (radix passes of 4 bits) hold every colour and the overflow set.
  expect(layout.COLOUR_CAP).toBeLessThan(256);
  const s = constants(wgsl('solverCommon'));
  const f32 = (x: number) => Math.fround(x);
  expect(f32(s.get('LINEAR_SLOP')!)).toBe(f32(b2_linearSlop));
  expect(f32(s.get('BAUMGARTE')!)).toBe(f32(b2_baumgarte));
  expect(f32(s.get('MAX_LINEAR_CORRECTION')!)).toBe(f32(b2_maxLinearCorrection));
  expect(f32(s.get('VELOCITY_THRESHOLD')!)).toBe(f32(b2_velocityThreshold));
  expect(f32(s.get('MAX_TRANSLATION')!)).toBe(f32(b2_maxTranslation));
  expect(f32(s.get('MAX_ROTATION')!)).toBe(f32(b2_maxRotation));
  expect(s.get('BODY_LIVE')).toBe(layout.BODY_LIVE);
  expect(s.get('BODY_ACTIVE')).toBe(b2BodyFlags.e_activeFlag);
  expect(s.get('DYNAMIC_BODY')).toBe(b2BodyType.b2_dynamicBody);
  expect(s.get('STATIC_BODY')).toBe(b2BodyType.b2_staticBody);
  expect(s.get('E_CIRCLES')).toBe(b2Manifold.e_circles);
  expect(s.get('E_FACE_A')).toBe(b2Manifold.e_faceA);
  expect(s.get('E_FACE_B')).toBe(b2Manifold.e_faceB);
});

it("declares the joints' record sizes, b2JointType, b2LimitState and 2.2.1's angular constants as the host and the engine use them", () => {
  const j = constants(wgsl('solveJointsCommon'));
  expect(j.get('JOINT_VEC4')).toBe(JOINT_VEC4);
  expect(j.get('JOINT_PARAMS_VEC4')).toBe(JOINT_PARAMS_VEC4);
  const types: [string, number][] = [
    ['REVOLUTE_JOINT', b2JointType.e_revoluteJoint],
    ['PRISMATIC_JOINT', b2JointType.e_prismaticJoint],
    ['DISTANCE_JOINT', b2JointType.e_distanceJoint],
    ['PULLEY_JOINT', b2JointType.e_pulleyJoint],
    ['MOUSE_JOINT', b2JointType.e_mouseJoint],
    ['GEAR_JOINT', b2JointType.e_gearJoint],
    ['WHEEL_JOINT', b2JointType.e_wheelJoint],
    ['WELD_JOINT', b2JointType.e_weldJoint],
    ['FRICTION_JOINT', b2JointType.e_frictionJoint],
    ['ROPE_JOINT', b2JointType.e_ropeJoint],
    ['INACTIVE_LIMIT', b2LimitState.e_inactiveLimit],
    ['AT_LOWER_LIMIT', b2LimitState.e_atLowerLimit],
    ['AT_UPPER_LIMIT', b2LimitState.e_atUpperLimit],
    ['EQUAL_LIMITS', b2LimitState.e_equalLimits],
  ];
  for (const [name, value] of types) expect(j.get(name), name).toBe(value);
  const f32 = (x: number) => Math.fround(x);
  expect(f32(j.get('ANGULAR_SLOP')!)).toBe(f32(b2_angularSlop));
  expect(f32(j.get('MAX_ANGULAR_CORRECTION')!)).toBe(f32(b2_maxAngularCorrection));
  expect(f32(j.get('PI')!)).toBe(f32(b2_pi));
});

it("declares the engine's body flags and types as src/common/b2Constants.ts has them, in every stage that tests them", () => {
  const islands = constants(wgsl('islands'));
  expect(islands.get('AUTO_SLEEP')).toBe(b2BodyFlags.e_autoSleepFlag);
  const toi = constants(wgsl('timeOfImpact'));
  expect(toi.get('BULLET_FLAG')).toBe(b2BodyFlags.e_bulletFlag);
  expect(toi.get('DYNAMIC_TYPE')).toBe(b2BodyType.b2_dynamicBody);
  expect(toi.get('STATIC_TYPE')).toBe(b2BodyType.b2_staticBody);
});

it('gives a constant declared in several WGSL files one value (f32 constants as f32)', () => {
  const seen = new Map<string, { file: string; value: number }>();
  const clashes: string[] = [];
  for (const file of readdirSync(path.join(root, 'shaders')).filter((f) => f.endsWith('.wgsl'))) {
    const source = readFileSync(path.join(root, 'shaders', file), 'utf8');
    for (const m of source.matchAll(/^const (\w+): (u32|f32) = (0x[0-9a-fA-F]+|[0-9.]+)u?;/gm)) {
      const [name, value] = [m[1], m[2] === 'f32' ? Math.fround(Number(m[3])) : Number(m[3])];
      const first = seen.get(name);
      if (first === undefined) seen.set(name, { file, value });
      else if (first.value !== value) clashes.push(`${name}: ${first.value} in ${first.file}, ${value} in ${file}`);
    }
  }
  expect(clashes).toEqual([]);
});

it('uses the tile sizes the host dispatches with', () => {
  expect(constants(wgsl('radixSort')).get('TILE')).toBe(layout.SORT_TILE);
  expect(constants(wgsl('scan')).get('BLOCK')).toBe(layout.SCAN_BLOCK);
  expect(constants(wgsl('axis')).get('ITEMS_PER_GROUP')).toBe(layout.AXIS_ITEMS_PER_GROUP);
  expect(constants(wgsl('sweep')).get('CHUNK')).toBe(layout.SWEEP_CHUNK);
  expect(constants(wgsl('contacts')).get('SORT_TILE')).toBe(layout.SORT_TILE);
  expect(constants(wgsl('contacts')).get('SCAN_BLOCK')).toBe(layout.SCAN_BLOCK);
});

it('has one WGSL file and one host module per stage, each opening with what it reads and writes', () => {
  for (const stage of STAGES) {
    const shader = wgsl(stage);
    expect(shader.startsWith(`// ${stage}.wgsl: `), stage).toBe(true);
    expect(shader).toMatch(/\/\/ (In|Out):/);
    const host = readFileSync(path.join(root, 'src-gpu', `${stage}.ts`), 'utf8');
    expect(host.startsWith('/*'), stage).toBe(true);
    expect(host.slice(0, 1500)).toMatch(/In:/);
  }
});

it('keeps the engine free of the GPU backend', () => {
  const offenders: string[] = [];
  const walk = (dir: string) => {
    for (const entry of readdirSync(dir, { withFileTypes: true })) {
      const full = path.join(dir, entry.name);
      if (entry.isDirectory()) walk(full);
      else if (/from '[^']*src-gpu/.test(readFileSync(full, 'utf8'))) offenders.push(full);
    }
  };
  walk(path.join(root, 'src'));
  expect(offenders).toEqual([]);
});
