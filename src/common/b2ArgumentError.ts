/*
 * Argument and usage errors of the public API (no C++ counterpart).
 *
 * Box2D checks its inputs with asserts that release builds drop. WebPhysics checks them in every
 * build at the public entry points (never inside the time step's loops) and throws a
 * b2ArgumentError before it changes anything, so a rejected call leaves the world as it was.
 *
 * The message is `<method>: <argument> <rule>`:
 *   b2PolygonShape.Set: vertices[2] makes the polygon non-convex (vertices must be counter-clockwise and convex)
 *   b2World.CreateBody: def.angle must be a finite number, got NaN
 *   b2Body.ApplyForce: this body has been destroyed
 *   b2World.CreateJoint: the world is locked (called during a time step or a callback)
 * `argument` names the offending argument or field (a path into it where that helps:
 * `def.shape.m_vertices[3]`), or the object whose state forbids the call (`this body`, `the world`).
 * The b2dJson reader's b2dJsonError is a b2ArgumentError whose argument is a JSON path.
 */

/** A public API call rejected because of its arguments or the state of the objects involved. */
export class b2ArgumentError extends Error {
  /** The rejected call, `Class.Method` (or a function name). */
  readonly method: string;
  /** The argument, field path or object at fault. */
  readonly argument: string;
  /** The rule it broke, with the offending value where one helps. */
  readonly rule: string;

  constructor(method: string, argument: string, rule: string, message = `${method}: ${argument} ${rule}`) {
    super(message);
    this.name = 'b2ArgumentError';
    this.method = method;
    this.argument = argument;
    this.rule = rule;
  }
}

/** A number as a message shows it: -0 keeps its sign. */
export function b2DescribeNumber(x: unknown): string {
  if (typeof x === 'number') return Object.is(x, -0) ? '-0' : String(x);
  if (x === undefined) return 'undefined';
  if (x === null) return 'null';
  if (typeof x === 'string') return `the string ${JSON.stringify(x.length > 40 ? `${x.slice(0, 40)}...` : x)}`;
  return typeof x === 'object' ? 'an object' : typeof x;
}

function isNumber(x: unknown): x is number {
  return typeof x === 'number';
}

/** `value` must be a finite number. */
export function b2CheckFinite(method: string, argument: string, value: number): void {
  if (!isNumber(value) || !Number.isFinite(value)) {
    throw new b2ArgumentError(method, argument, `must be a finite number, got ${b2DescribeNumber(value)}`);
  }
}

/** `value` must be a finite number >= 0. */
export function b2CheckNonNegative(method: string, argument: string, value: number): void {
  if (!isNumber(value) || !Number.isFinite(value) || value < 0) {
    throw new b2ArgumentError(method, argument, `must be a finite number >= 0, got ${b2DescribeNumber(value)}`);
  }
}

/** `value` must be a finite number > 0. */
export function b2CheckPositive(method: string, argument: string, value: number): void {
  if (!isNumber(value) || !Number.isFinite(value) || !(value > 0)) {
    throw new b2ArgumentError(method, argument, `must be a finite number > 0, got ${b2DescribeNumber(value)}`);
  }
}

/** `value` must be an integer in [min, max]. */
export function b2CheckInteger(method: string, argument: string, value: number, min: number, max: number): void {
  if (!isNumber(value) || !Number.isInteger(value) || value < min || value > max) {
    const range = max === Number.MAX_SAFE_INTEGER ? `>= ${min}` : `in [${min}, ${max}]`;
    throw new b2ArgumentError(method, argument, `must be an integer ${range}, got ${b2DescribeNumber(value)}`);
  }
}

/** `value` must be an object (not null or undefined): the message names what was passed. */
export function b2CheckObject(method: string, argument: string, value: unknown): void {
  if (typeof value !== 'object' || value === null) {
    throw new b2ArgumentError(method, argument, `must be set, got ${b2DescribeNumber(value)}`);
  }
}

/** `v` must be a vector {x, y} of finite numbers. */
export function b2CheckVec2(method: string, argument: string, v: { readonly x: number; readonly y: number }): void {
  b2CheckObject(method, argument, v);
  if (!isNumber(v.x) || !Number.isFinite(v.x) || !isNumber(v.y) || !Number.isFinite(v.y)) {
    throw new b2ArgumentError(method, argument, `must be a vector of finite numbers, got (${b2DescribeNumber(v.x)}, ${b2DescribeNumber(v.y)})`);
  }
}

/** The limits must be finite with lower <= upper. */
export function b2CheckLimits(method: string, lowerArgument: string, upperArgument: string, lower: number, upper: number): void {
  b2CheckFinite(method, lowerArgument, lower);
  b2CheckFinite(method, upperArgument, upper);
  if (!(lower <= upper)) {
    throw new b2ArgumentError(method, lowerArgument, `must not exceed ${upperArgument} (${b2DescribeNumber(lower)} > ${b2DescribeNumber(upper)})`);
  }
}

/** The error for a call that the world's lock forbids (CreateBody inside a callback...). */
export function b2LockedError(method: string): b2ArgumentError {
  return new b2ArgumentError(method, 'the world', 'is locked (called during a time step or a callback)');
}

/** The error for a call on, or with, an object already destroyed (`this body`, `joint`...). */
export function b2DestroyedError(method: string, argument: string): b2ArgumentError {
  return new b2ArgumentError(method, argument, 'has been destroyed');
}
