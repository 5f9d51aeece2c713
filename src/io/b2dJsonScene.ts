/*
 * A world loaded from (or to be written as) b2dJson, the JSON scene format of R.U.B.E. and
 * iforce2d's b2dJson: the world plus what the format carries beside it (names, custom
 * properties, images, step settings).
 */

import { b2ArgumentError } from '../common/b2ArgumentError';
import type { b2Vec2 } from '../common/b2Math';
import type { b2Body } from '../dynamics/b2Body';
import type { b2Fixture } from '../dynamics/b2Fixture';
import type { b2World } from '../dynamics/b2World';
import type { b2Joint } from '../dynamics/joints/b2Joint';

/** A JSON value as b2dJson reads and writes it. Numbers may be -0. */
export type b2dJsonValue = number | string | boolean | null | b2dJsonValue[] | { [key: string]: b2dJsonValue };

/** A JSON object. */
export type b2dJsonObject = { [key: string]: b2dJsonValue };

/**
 * A malformed document (a b2ArgumentError whose argument is a JSON path). `path` is the JSON path of the offending value (`body[3].fixture[0].friction`,
 * `(root)` for the document itself) and `rule` the requirement it broke.
 */
export class b2dJsonError extends b2ArgumentError {
  readonly path: string;

  /**
   * `method` is the function that rejected the document (b2dJsonRead or b2dJsonWrite). The
   * message is `<path>: <rule>`: the JSON path is the argument at fault.
   */
  constructor(path: string, rule: string, method = 'b2dJsonRead') {
    super(method, path, rule, `${path}: ${rule}`);
    this.name = 'b2dJsonError';
    this.path = path;
  }
}

/**
 * The step settings a scene is meant to run with:
 * `world.Step(1 / stepsPerSecond, velocityIterations, positionIterations)`.
 */
export interface b2dJsonStepSettings {
  stepsPerSecond: number;
  velocityIterations: number;
  positionIterations: number;
}

/** R.U.B.E.'s defaults, which are also the Box2D testbed's. */
export const b2dJson_defaultStepSettings: Readonly<b2dJsonStepSettings> = Object.freeze({
  stepsPerSecond: 60,
  velocityIterations: 8,
  positionIterations: 3,
});

/** Options of b2dJsonRead. */
export interface b2dJsonReadOptions {
  /**
   * Leave out what the reader cannot build (joints of an unknown type such as Box2D 2.3's motor
   * joint, fixtures with no known shape, gear joints coupling a joint left out) instead of
   * rejecting the whole document, as iforce2d's loaders do. Each lands in the scene's `skipped`.
   */
  skipUnknown?: boolean;
}

/** An item b2dJsonRead left out (options.skipUnknown): its JSON path and why. */
export interface b2dJsonSkippedItem {
  readonly path: string;
  readonly reason: string;
}

/** RGBA, each 0..255. */
export type b2dJsonColor = [r: number, g: number, b: number, a: number];

/** One entry of a `customProperties` array: a name and one typed value. */
export type b2dJsonCustomProperty =
  | { name: string; type: 'int'; value: number }
  | { name: string; type: 'float'; value: number }
  | { name: string; type: 'string'; value: string }
  | { name: string; type: 'vec2'; value: b2Vec2 }
  | { name: string; type: 'bool'; value: boolean }
  | { name: string; type: 'color'; value: b2dJsonColor };

/**
 * An image placed in the scene by R.U.B.E. The engine does not use images; they are kept so a
 * scene can be written back. `fields` holds the record's other members (file, center, angle,
 * scale, corners...) as read.
 */
export class b2dJsonImage {
  body: b2Body | null;
  readonly fields: b2dJsonObject;

  constructor(body: b2Body | null = null, fields: b2dJsonObject = {}) {
    this.body = body;
    this.fields = fields;
  }
}

/** Anything that can carry a name and custom properties. */
export type b2dJsonItem = b2World | b2Body | b2Fixture | b2Joint | b2dJsonImage;

/** The bodies of a world in creation order (the world's list is prepended, so newest first). */
export function b2dJsonBodiesInCreationOrder(world: b2World): b2Body[] {
  const bodies: b2Body[] = [];
  for (let b = world.m_bodyList; b !== null; b = b.m_next) bodies.push(b);
  return bodies.reverse();
}

/** The fixtures of a body in creation order (the body's list is prepended). */
export function b2dJsonFixturesInCreationOrder(body: b2Body): b2Fixture[] {
  const fixtures: b2Fixture[] = [];
  for (let f = body.m_fixtureList; f !== null; f = f.m_next) fixtures.push(f);
  return fixtures.reverse();
}

/** The joints of a world in creation order (the world's list is prepended). */
export function b2dJsonJointsInCreationOrder(world: b2World): b2Joint[] {
  const joints: b2Joint[] = [];
  for (let j = world.m_jointList; j !== null; j = j.m_next) joints.push(j);
  return joints.reverse();
}

/**
 * A world with its b2dJson metadata. `bodies` and `joints` are in file order, which is creation
 * order; they are not updated if the world is edited afterwards (the lookups by name and the
 * writer walk the world itself).
 */
export class b2dJsonScene {
  readonly world: b2World;
  readonly bodies: b2Body[] = [];
  readonly joints: b2Joint[] = [];
  readonly images: b2dJsonImage[] = [];
  /** What b2dJsonRead left out with options.skipUnknown, in file order (empty otherwise). */
  readonly skipped: b2dJsonSkippedItem[] = [];
  readonly stepSettings: b2dJsonStepSettings;

  private readonly m_names = new Map<b2dJsonItem, string>();
  private readonly m_customProperties = new Map<b2dJsonItem, b2dJsonCustomProperty[]>();

  constructor(world: b2World, stepSettings: Readonly<b2dJsonStepSettings> = b2dJson_defaultStepSettings) {
    this.world = world;
    this.stepSettings = { ...stepSettings };
  }

  /** Advance the world one step with the scene's step settings. */
  step(): void {
    const s = this.stepSettings;
    this.world.Step(1 / s.stepsPerSecond, s.velocityIterations, s.positionIterations);
  }

  /** The item's name, or '' when it has none (as b2dJson). */
  getName(item: b2dJsonItem): string {
    return this.m_names.get(item) ?? '';
  }

  /** Name an item; '' removes the name. */
  setName(item: b2dJsonItem, name: string): void {
    if (name === '') this.m_names.delete(item);
    else this.m_names.set(item, name);
  }

  /** The item's custom properties in file order (empty when it has none). */
  getCustomProperties(item: b2dJsonItem): readonly b2dJsonCustomProperty[] {
    return this.m_customProperties.get(item) ?? [];
  }

  /** The item's first custom property with this name. */
  getCustomProperty(item: b2dJsonItem, name: string): b2dJsonCustomProperty | undefined {
    return this.getCustomProperties(item).find((p) => p.name === name);
  }

  /** Replace the item's custom properties; an empty list removes them. */
  setCustomProperties(item: b2dJsonItem, properties: readonly b2dJsonCustomProperty[]): void {
    if (properties.length === 0) this.m_customProperties.delete(item);
    else this.m_customProperties.set(item, properties.slice());
  }

  /** The first body of the world, in creation order, with this name. */
  getBodyByName(name: string): b2Body | null {
    return b2dJsonBodiesInCreationOrder(this.world).find((b) => this.m_names.get(b) === name) ?? null;
  }

  /** The first fixture of the world (bodies and fixtures in creation order) with this name. */
  getFixtureByName(name: string): b2Fixture | null {
    for (const body of b2dJsonBodiesInCreationOrder(this.world)) {
      const fixture = b2dJsonFixturesInCreationOrder(body).find((f) => this.m_names.get(f) === name);
      if (fixture !== undefined) return fixture;
    }
    return null;
  }

  /** The first joint of the world, in creation order, with this name. */
  getJointByName(name: string): b2Joint | null {
    return b2dJsonJointsInCreationOrder(this.world).find((j) => this.m_names.get(j) === name) ?? null;
  }

  /** The first image with this name. */
  getImageByName(name: string): b2dJsonImage | null {
    return this.images.find((image) => this.m_names.get(image) === name) ?? null;
  }
}
