/*
 * What the reader fed into the engine, so the writer can write it back.
 *
 * Loading is lossy in a few places: b2Body's constructor and ResetMassData/SetMassData move the
 * linear velocity with the center of mass, SetMassData stores I - m|c|^2, the prismatic joint
 * normalizes its axis, the mouse joint keeps a body-local anchor, and SetAsBox and Set build
 * different polygons from the same corners. Writing the engine's state back therefore would not
 * reload to the same bits. The reader records its inputs here, keyed weakly by the created
 * objects; the writer uses a record only while it still reproduces the object's current state.
 */

import { b2Vec2 } from '../common/b2Math';
import type { b2MassData } from '../collision/shapes/b2Shape';
import type { b2PolygonShape } from '../collision/shapes/b2PolygonShape';
import type { b2Body } from '../dynamics/b2Body';
import type { b2Joint } from '../dynamics/joints/b2Joint';

/** The parameters of a SetAsBox call; `center` null for the two-argument form. */
export class b2dJsonBoxRecipe {
  constructor(
    readonly hx: number,
    readonly hy: number,
    readonly center: b2Vec2 | null,
    readonly angle: number,
  ) {}
}

const kBodyStateSize = 19;

/** The body state that the kinematic def fields and the mass data determine. */
function captureBodyState(body: b2Body, out: Float64Array): Float64Array {
  const xf = body.m_xf;
  const sweep = body.m_sweep;
  out[0] = body.m_type;
  out[1] = xf.p.x;
  out[2] = xf.p.y;
  out[3] = xf.q.s;
  out[4] = xf.q.c;
  out[5] = sweep.localCenter.x;
  out[6] = sweep.localCenter.y;
  out[7] = sweep.c0.x;
  out[8] = sweep.c0.y;
  out[9] = sweep.c.x;
  out[10] = sweep.c.y;
  out[11] = sweep.a0;
  out[12] = sweep.a;
  out[13] = sweep.alpha0;
  out[14] = body.m_linearVelocity.x;
  out[15] = body.m_linearVelocity.y;
  out[16] = body.m_angularVelocity;
  out[17] = body.m_mass;
  out[18] = body.m_I;
  return out;
}

function sameBits(a: Float64Array, b: Float64Array): boolean {
  for (let i = 0; i < a.length; ++i) {
    if (!Object.is(a[i], b[i])) return false;
  }
  return true;
}

/** The def values a body was created from, and its state once the scene was loaded. */
export class b2dJsonBodyRecipe {
  readonly loadedState = new Float64Array(kBodyStateSize);

  constructor(
    readonly position: b2Vec2,
    readonly angle: number,
    readonly linearVelocity: b2Vec2,
    readonly angularVelocity: number,
    /** The SetMassData argument, or null when the mass came from the fixtures. */
    readonly massData: b2MassData | null,
  ) {}
}

/** The def values of a joint that its state does not keep exactly. */
export class b2dJsonJointRecipe {
  constructor(
    /** def.bodyA/bodyB: the gear joint replaces its bodies with those of its joints. */
    readonly bodyA: b2Body,
    readonly bodyB: b2Body,
    /** The prismatic def axis before normalization. */
    readonly localAxisA: b2Vec2 | null,
    /** The mouse def target (the world anchor on body B). */
    readonly mouseAnchorB: b2Vec2 | null,
  ) {}
}

const bodyRecipes = new WeakMap<b2Body, b2dJsonBodyRecipe>();
const jointRecipes = new WeakMap<b2Joint, b2dJsonJointRecipe>();
const boxRecipes = new WeakMap<b2PolygonShape, b2dJsonBoxRecipe>();
const s_state = new Float64Array(kBodyStateSize);

export function b2dJsonRecordBody(body: b2Body, recipe: b2dJsonBodyRecipe): void {
  bodyRecipes.set(body, recipe);
}

/** Capture the loaded state of a recorded body; call once the whole scene is built. */
export function b2dJsonSealBody(body: b2Body): void {
  const recipe = bodyRecipes.get(body);
  if (recipe !== undefined) captureBodyState(body, recipe.loadedState);
}

/** The body's recipe, if it has one and the body has not moved or changed mass since loading. */
export function b2dJsonBodyRecipeFor(body: b2Body): b2dJsonBodyRecipe | null {
  const recipe = bodyRecipes.get(body);
  if (recipe === undefined) return null;
  return sameBits(recipe.loadedState, captureBodyState(body, s_state)) ? recipe : null;
}

export function b2dJsonRecordJoint(joint: b2Joint, recipe: b2dJsonJointRecipe): void {
  jointRecipes.set(joint, recipe);
}

export function b2dJsonJointRecipeFor(joint: b2Joint): b2dJsonJointRecipe | null {
  return jointRecipes.get(joint) ?? null;
}

export function b2dJsonRecordBox(shape: b2PolygonShape, recipe: b2dJsonBoxRecipe): void {
  boxRecipes.set(shape, recipe);
}

/** The SetAsBox call recorded for this polygon; the writer checks it still matches. */
export function b2dJsonBoxRecipeFor(shape: b2PolygonShape): b2dJsonBoxRecipe | null {
  return boxRecipes.get(shape) ?? null;
}
