/*
 * Global tuning constants based on meters-kilograms-seconds (MKS) units (b2Settings.h).
 *
 * Every value is written exactly as b2Settings.h spells it: the reference engine was built with
 * float32 = double, so `0.005f` is the double 0.005 and `b2_pi` is the literal 3.14159265359,
 * not Math.PI. b2_epsilon and b2_maxFloat keep their float32 values (FLT_EPSILON, FLT_MAX)
 * because the C++ used the macros, not literals.
 */

/**
 * The b2Settings.h integer and float typedefs. JavaScript numbers are float64; the integer widths
 * are enforced where the C++ depends on them (`| 0`, `& 0xff`, `& 0xffff`, see docs/PORTING.md).
 */
export type int8 = number;
export type int16 = number;
export type int32 = number;
export type uint8 = number;
export type uint16 = number;
export type uint32 = number;
/** The reference engine was built with float32 = double, which is what a JavaScript number is. */
export type float32 = number;
export type float64 = number;

/** B2_NOT_USED(x): marks an argument as deliberately unused. Does nothing. */
export function B2_NOT_USED(..._x: unknown[]): void {}

/**
 * Box2D's b2Assert. The C++ asserts vanish in release builds; these stay, so a broken invariant
 * stops with a message instead of corrupting the world.
 */
export function b2Assert(condition: boolean, message = 'assertion failed'): asserts condition {
  if (!condition) {
    throw new Error(`Box2D: ${message}`);
  }
}

export const b2_maxFloat = 3.4028234663852886e38;
export const b2_epsilon = 1.1920928955078125e-7;
export const b2_pi = 3.14159265359;

// Collision

/** The maximum number of contact points between two convex shapes. Do not change this value. */
export const b2_maxManifoldPoints = 2;

/** The maximum number of vertices on a convex polygon. */
export const b2_maxPolygonVertices = 8;

/** Fattens AABBs in the dynamic tree so proxies can move a little without a tree update (m). */
export const b2_aabbExtension = 0.1;

/** Fattens AABBs in the dynamic tree in the direction of motion (dimensionless multiplier). */
export const b2_aabbMultiplier = 2.0;

/** A small length used as a collision and constraint tolerance (m). */
export const b2_linearSlop = 0.005;

/** A small angle used as a collision and constraint tolerance (rad). */
export const b2_angularSlop = (2.0 / 180.0) * b2_pi;

/** The radius of the polygon/edge shape skin. */
export const b2_polygonRadius = 2.0 * b2_linearSlop;

/** Maximum number of sub-steps per contact in continuous physics simulation. */
export const b2_maxSubSteps = 8;

// Dynamics

/** Maximum number of contacts to be handled to solve a TOI impact. */
export const b2_maxTOIContacts = 32;

/** Collisions with a relative normal velocity below this are treated as inelastic (m/s). */
export const b2_velocityThreshold = 1.0;

/** The maximum linear position correction used when solving constraints (m). */
export const b2_maxLinearCorrection = 0.2;

/** The maximum angular position correction used when solving constraints (rad). */
export const b2_maxAngularCorrection = (8.0 / 180.0) * b2_pi;

/** The maximum translation of a body per step (m). */
export const b2_maxTranslation = 2.0;
export const b2_maxTranslationSquared = b2_maxTranslation * b2_maxTranslation;

/** The maximum rotation of a body per step (rad). */
export const b2_maxRotation = 0.5 * b2_pi;
export const b2_maxRotationSquared = b2_maxRotation * b2_maxRotation;

/** How fast overlap is resolved in the contact position solver. */
export const b2_baumgarte = 0.2;
/** The same factor for the TOI position solver (the C++ spelling is kept). */
export const b2_toiBaugarte = 0.75;

// Sleep

/** The time that a body must be still before it will go to sleep (s). */
export const b2_timeToSleep = 0.5;

/** A body cannot sleep if its linear velocity is above this tolerance (m/s). */
export const b2_linearSleepTolerance = 0.01;

/** A body cannot sleep if its angular velocity is above this tolerance (rad/s). */
export const b2_angularSleepTolerance = (2.0 / 180.0) * b2_pi;

/** Version numbering scheme. */
export class b2Version {
  constructor(
    public major = 0,
    public minor = 0,
    public revision = 0,
  ) {}
}

/** Current version. */
export const b2_version = new b2Version(2, 2, 1);

/** The sink for b2Log; replace it to route Dump() output elsewhere. */
export let b2LogSink: (text: string) => void = (text) => {
  if (typeof process !== 'undefined' && process.stdout) process.stdout.write(text);
  else console.log(text);
};

export function b2SetLogSink(sink: (text: string) => void): void {
  b2LogSink = sink;
}

/**
 * C's %.<digits>e: like toExponential, except that an exact tie rounds to even as printf does
 * (toExponential rounds ties up), -0 keeps its sign, and the exponent has at least two digits.
 */
function formatExponential(x: number, digits: number): string {
  const sign = x < 0 || Object.is(x, -0) ? '-' : '';
  const magnitude = Math.abs(x);
  let text = magnitude.toExponential(digits);
  if (Number.isFinite(magnitude) && digits < 99) {
    // A tie at digit digits + 1 means the exact decimal value ends there with a 5; an exact
    // expansion that long fits in 101 significant digits, which toExponential(100) prints exactly.
    const [mantissa, exponent] = magnitude.toExponential(100).split('e');
    const all = mantissa.replace('.', '');
    const kept = all.slice(0, digits + 1);
    const isTie = all[digits + 1] === '5' && /^0*$/.test(all.slice(digits + 2));
    if (isTie && Number(kept[digits]) % 2 === 0) {
      text = `${kept[0]}${digits > 0 ? '.' : ''}${kept.slice(1)}e${exponent}`;
    }
  }
  return sign + text.replace(/e([+-])(\d)$/, 'e$10$2');
}

/**
 * Logging function (b2Log). Box2D's Dump() uses only %d and %.15lef; %s and %% are accepted too.
 */
export function b2Log(format: string, ...args: (number | string | boolean)[]): void {
  let argIndex = 0;
  const text = format.replace(/%(%|d|s|\.(\d+)l?e)/g, (match, _conversion, precision) => {
    if (match === '%%') return '%';
    const arg = args[argIndex++];
    if (match === '%d') return String(Math.trunc(Number(arg)));
    if (match === '%s') return String(arg);
    return formatExponential(Number(arg), Number(precision));
  });
  b2LogSink(text);
}
