/*
 * The host and the shaders agree on the shared layout: the state words, indirect argument
 * offsets, flag bits and tile sizes of src-gpu/device/layout.ts are the constants the WGSL declares; and
 * every stage has its WGSL file and host module, each opening with a comment on its inputs,
 * outputs and invariants. (No GPU needed.)
 */

import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { expect, it } from 'vitest';
import { b2ContactFeature, b2Manifold } from '../../src/collision/b2Collision';
import {
  b2_angularSleepTolerance,
  b2_angularSlop,
  b2_baumgarte,
  b2_linearSleepTolerance,
  b2_maxAngularCorrection,
  b2_linearSlop,
  b2_maxLinearCorrection,
  b2_maxPolygonVertices,
  b2_maxRotation,
  b2_maxTranslation,
  b2_polygonRadius,
  b2_timeToSleep,
  b2_velocityThreshold,
  b2_pi,
} from '../../src/common/b2Settings';
import { b2Shape } from '../../src/collision/shapes/b2Shape';
import { ENGINE_CONSTANTS, ENGINE_WGSL } from '../../src-gpu/device/engineWgsl';
import { SHADERS } from '../../src-gpu/device/shaders';
import { b2BodyFlags, b2BodyType, b2JointType, b2LimitState } from '../../src/common/b2Constants';
import { JOINT_PARAMS_VEC4, JOINT_VEC4 } from '../../src-gpu/solver/solveJoints';
import * as layout from '../../src-gpu/device/layout';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');

/** The files under `dir` (a path from the root) whose names end with `ext`, as paths from the root. */
function filesUnder(dir: string, ext: string): string[] {
  const out: string[] = [];
  for (const entry of readdirSync(path.join(root, dir), { withFileTypes: true })) {
    const rel = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...filesUnder(rel, ext));
    else if (entry.name.endsWith(ext)) out.push(rel);
  }
  return out;
}

/** The one file under `dir` named `name`. */
function fileNamed(dir: string, name: string): string {
  const found = filesUnder(dir, name).filter((f) => path.basename(f) === name);
  expect(found, name).toHaveLength(1);
  return readFileSync(path.join(root, found[0]), 'utf8');
}

const wgsl = (name: string) => fileNamed('shaders', `${name}.wgsl`);

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
  'penetration',
  'cull',
  'render',
  'pointQuery',
  'transforms',
];

it('declares the state words, indirect offsets and flags the host uses', () => {
  const c = constants(wgsl('common'));
  for (const [name, value] of Object.entries(layout.STATE)) expect(c.get(`STATE_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.ARGS)) expect(c.get(`ARGS_${name}`), name).toBe(value);
  expect(c.get('PROXY_LIVE')).toBe(layout.PROXY_LIVE);
  expect(c.get('PROXY_SENSOR')).toBe(layout.PROXY_SENSOR);
  expect(c.get('PROXY_JOINTED')).toBe(layout.PROXY_JOINTED);
  expect(c.get('BODY_LIVE')).toBe(layout.BODY_LIVE);
  expect(c.get('JOINT_LIVE')).toBe(layout.JOINT_LIVE);
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

it("declares the narrow phase's state words, bins, indirect offsets and contact flags the host uses", () => {
  const c = constants(wgsl('common'));
  for (const [name, value] of Object.entries(layout.NP)) expect(c.get(`NP_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.NP_ARGS)) expect(c.get(`NP_ARGS_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.BIN)) expect(c.get(`BIN_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.MF)) expect(c.get(`MF_${name}`), name).toBe(value);
  expect(c.get('BIN_COUNT')).toBe(layout.BIN_COUNT);
  // The bin sort is one 4-bit radix pass: every digit, BIN_NONE and BIN_KEPT included, fits it.
  expect(Math.max(...Object.values(layout.BIN))).toBeLessThan(16);
  expect(c.get('CONTACT_KEPT')).toBe(layout.CONTACT_KEPT);
  expect(c.get('OVERFLOW_CONTACTS')).toBe(layout.OVERFLOW_CONTACTS);
  expect(c.get('NO_CONTACT')).toBe(layout.NO_CONTACT);
  expect(c.get('EVENT_BEGIN')).toBe(layout.EVENT_BEGIN);
  expect(c.get('EVENT_END')).toBe(layout.EVENT_END);
  expect(layout.BIN_NAMES.length).toBe(layout.BIN_COUNT);
  expect(layout.NP.BINS + layout.BIN_COUNT).toBeLessThan(layout.NP_STATE_WORDS);
  expect(layout.NP_ARGS.BINS + 3 * layout.BIN_COUNT).toBeLessThanOrEqual(layout.NP_INDIRECT_WORDS);
});

it("declares the solver's state words, indirect offsets, colour cap and 2.2.1's constants as the host and the engine use them", () => {
  const c = constants(wgsl('common'));
  for (const [name, value] of Object.entries(layout.SV)) expect(c.get(`SV_${name}`), name).toBe(value);
  for (const [name, value] of Object.entries(layout.SV_ARGS)) expect(c.get(`SV_ARGS_${name}`), name).toBe(value);
  expect(c.get('COLOUR_CAP')).toBe(layout.COLOUR_CAP);
  expect(c.get('UNCOLOURED')).toBe(layout.UNCOLOURED);
  expect(c.get('COLOUR_IDLE')).toBe(layout.COLOUR_IDLE);
  expect(c.get('CONSTRAINT_VEC4')).toBe(layout.CONSTRAINT_VEC4);
  expect(layout.SV.COLOUR_START + layout.COLOUR_CAP + 2).toBeLessThanOrEqual(layout.SV.COLOUR_CHANGED);
  expect(layout.SV.COLOUR_SORT_COUNT).toBeLessThan(layout.SV_STATE_WORDS);
  // A step's read-back carries every colour start (the overflow set's end included), the colours used, the penetration and the awake count, as one range.
  expect(layout.SV_READBACK_WORDS).toBeGreaterThanOrEqual(layout.COLOUR_CAP + 2);
  expect(layout.SV.COLOURS_USED).toBeLessThan(layout.SV.COLOUR_START + layout.SV_READBACK_WORDS);
  expect(layout.SV.PENETRATION).toBeLessThan(layout.SV.COLOUR_START + layout.SV_READBACK_WORDS);
  expect(layout.SV.AWAKE).toBe(layout.SV.COLOUR_START + layout.SV_READBACK_WORDS - 1);
  expect(layout.SV.COLOUR_START + layout.SV_READBACK_WORDS).toBeLessThanOrEqual(layout.SV_STATE_WORDS);
  expect(layout.SV_ARGS.COLOURS + 3 * (layout.COLOUR_CAP + 1)).toBeLessThanOrEqual(layout.SV_ARGS.POSITION);
  expect(layout.SV_ARGS.POSITION + 3 * (layout.COLOUR_CAP + 1)).toBeLessThanOrEqual(layout.SV_ARGS.ITEMS);
  expect(layout.SV_ARGS.ROUNDS + 3).toBeLessThanOrEqual(layout.SV_INDIRECT_WORDS);
  // The colour sort's digits (radix passes of 4 bits) hold every colour and the overflow set.
  expect(layout.COLOUR_CAP).toBeLessThan(256);
});

it("declares the joints' record sizes as the host uses them", () => {
  const j = constants(wgsl('solveJointsCommon'));
  expect(j.get('JOINT_VEC4')).toBe(JOINT_VEC4);
  expect(j.get('JOINT_PARAMS_VEC4')).toBe(JOINT_PARAMS_VEC4);
});

it("gives every stage the engine's flags, types and 2.2.1's tolerances from the engine's own modules, and no WGSL file declares them again", () => {
  const declared = constants(ENGINE_WGSL);
  const f32 = (x: number) => Math.fround(x);
  const expected: [string, number][] = [
    ['BODY_AUTO_SLEEP', b2BodyFlags.e_autoSleepFlag],
    ['BODY_BULLET', b2BodyFlags.e_bulletFlag],
    ['BODY_ACTIVE', b2BodyFlags.e_activeFlag],
    ['STATIC_BODY', b2BodyType.b2_staticBody],
    ['DYNAMIC_BODY', b2BodyType.b2_dynamicBody],
    ['SHAPE_CIRCLE', b2Shape.e_circle],
    ['SHAPE_EDGE', b2Shape.e_edge],
    ['SHAPE_POLYGON', b2Shape.e_polygon],
    ['SHAPE_CHAIN', b2Shape.e_chain],
    ['E_CIRCLES', b2Manifold.e_circles],
    ['E_FACE_A', b2Manifold.e_faceA],
    ['E_FACE_B', b2Manifold.e_faceB],
    ['F_VERTEX', b2ContactFeature.e_vertex],
    ['F_FACE', b2ContactFeature.e_face],
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
    ['MAX_POLYGON_VERTICES', b2_maxPolygonVertices],
  ];
  for (const [name, value] of expected) expect(declared.get(name), name).toBe(value);
  const tolerances: [string, number][] = [
    ['PI', b2_pi],
    ['LINEAR_SLOP', b2_linearSlop],
    ['ANGULAR_SLOP', b2_angularSlop],
    ['POLYGON_RADIUS', b2_polygonRadius],
    ['BAUMGARTE', b2_baumgarte],
    ['MAX_LINEAR_CORRECTION', b2_maxLinearCorrection],
    ['MAX_ANGULAR_CORRECTION', b2_maxAngularCorrection],
    ['VELOCITY_THRESHOLD', b2_velocityThreshold],
    ['MAX_TRANSLATION', b2_maxTranslation],
    ['MAX_ROTATION', b2_maxRotation],
    ['TIME_TO_SLEEP', b2_timeToSleep],
    ['LINEAR_SLEEP_TOLERANCE', b2_linearSleepTolerance],
    ['ANGULAR_SLEEP_TOLERANCE', b2_angularSleepTolerance],
  ];
  for (const [name, value] of tolerances) expect(f32(declared.get(name)!), name).toBe(f32(value));
  expect(declared.size).toBe(ENGINE_CONSTANTS.length);
  // Every stage gets them, and the shader files leave them to the generated block.
  for (const stage of STAGES) expect(SHADERS[stage as keyof typeof SHADERS].startsWith(ENGINE_WGSL), stage).toBe(true);
  const again: string[] = [];
  for (const file of filesUnder('shaders', '.wgsl')) {
    for (const name of constants(readFileSync(path.join(root, file), 'utf8')).keys()) {
      if (declared.has(name)) again.push(`${file}: ${name}`);
    }
  }
  expect(again).toEqual([]);
});

it('gives a constant declared in several WGSL files one value (f32 constants as f32)', () => {
  const seen = new Map<string, { file: string; value: number }>();
  const clashes: string[] = [];
  for (const file of filesUnder('shaders', '.wgsl')) {
    const source = readFileSync(path.join(root, file), 'utf8');
    for (const m of source.matchAll(/^const (\w+): (u32|f32) = (0x[0-9a-fA-F]+|[0-9.]+)u?;/gm)) {
      const [name, value] = [m[1], m[2] === 'f32' ? Math.fround(Number(m[3])) : Number(m[3])];
      const first = seen.get(name);
      if (first === undefined) seen.set(name, { file, value });
      else if (first.value !== value) clashes.push(`${name}: ${first.value} in ${first.file}, ${value} in ${file}`);
    }
  }
  expect(clashes).toEqual([]);
});

it('uses the tile sizes the host dispatches with, and the circle outline the renderer draws', () => {
  expect(constants(wgsl('radixSort')).get('TILE')).toBe(layout.SORT_TILE);
  expect(constants(wgsl('scan')).get('BLOCK')).toBe(layout.SCAN_BLOCK);
  expect(constants(wgsl('axis')).get('ITEMS_PER_GROUP')).toBe(layout.AXIS_ITEMS_PER_GROUP);
  expect(constants(wgsl('sweep')).get('CHUNK')).toBe(layout.SWEEP_CHUNK);
  expect(constants(wgsl('contacts')).get('SORT_TILE')).toBe(layout.SORT_TILE);
  expect(constants(wgsl('contacts')).get('SCAN_BLOCK')).toBe(layout.SCAN_BLOCK);
  expect(constants(wgsl('render')).get('CIRCLE_SEGMENTS')).toBe(layout.RENDER_CIRCLE_SEGMENTS);
});

it("declares the renderer's draw lists, their argument records, its point size, small polygons and colour modes as the host uses them", () => {
  const view = constants(wgsl('renderView'));
  for (const [name, value] of Object.entries(layout.RENDER_LIST)) expect(view.get(`LIST_${name}`), name).toBe(value);
  expect(view.get('LIST_COUNT')).toBe(layout.RENDER_LIST_COUNT);
  expect(Object.keys(layout.RENDER_LIST)).toHaveLength(layout.RENDER_LIST_COUNT);
  expect(view.get('DRAW_ARGS_WORDS')).toBe(layout.RENDER_DRAW_ARGS_WORDS);
  const cull = constants(wgsl('cull'));
  expect(cull.get('POINT_PIXELS')).toBe(layout.RENDER_POINT_PIXELS);
  expect(cull.get('SMALL_POLYGON_VERTICES')).toBe(layout.RENDER_SMALL_POLYGON_VERTICES);
  for (const [name, value] of Object.entries(layout.RENDER_COLOUR_MODE)) expect(cull.get(`COLOUR_${name}`), name).toBe(value);
});

it('has one WGSL file and one host module per stage, each opening with what it reads and writes', () => {
  for (const stage of STAGES) {
    const shader = wgsl(stage);
    expect(shader.startsWith(`// ${stage}.wgsl: `), stage).toBe(true);
    expect(shader).toMatch(/\/\/ (In|Out):/);
    const host = fileNamed('src-gpu', `${stage}.ts`);
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

it('imports from the engine only types and its two constant modules, so the GPU bundle carries no second engine', () => {
  const allowed = new Set(['src/common/b2Constants', 'src/common/b2Settings']);
  const offenders: string[] = [];
  for (const file of filesUnder('src-gpu', '.ts')) {
    const source = readFileSync(path.join(root, file), 'utf8');
    for (const m of source.matchAll(/^import (type )?[^;]*? from '(\.[^']+)';/gms)) {
      const target = path.relative(root, path.resolve(root, path.dirname(file), m[2]));
      if (target.startsWith('src/') && m[1] === undefined && !allowed.has(target)) offenders.push(`${file}: ${m[2]}`);
    }
  }
  expect(offenders).toEqual([]);
});
