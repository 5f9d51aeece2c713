/*
 * The golden trajectory digest (shared/golden/README.md), computed in the page: load a b2dJson
 * scene with b2dJsonRead, step it with its own settings, and hash every body's position, angle and
 * velocities (creation order, 8 little-endian bytes each) with 32-bit FNV-1a after every step.
 * The Node tests (test/support/scene.ts) use these same functions, so every engine hashes alike.
 */

import { b2dJsonRead } from '../src/index';
import type { b2Body } from '../src/index';

/** GetPosition().x, .y, GetAngle(), GetLinearVelocity().x, .y, GetAngularVelocity(). */
export function bodyState(body: b2Body): number[] {
  return [body.m_xf.p.x, body.m_xf.p.y, body.m_sweep.a, body.m_linearVelocity.x, body.m_linearVelocity.y, body.m_angularVelocity];
}

const s_bytes = new DataView(new ArrayBuffer(8));

/**
 * 32-bit FNV-1a over the six doubles of every body (creation order), each as 8 little-endian
 * IEEE-754 bytes; 8 lowercase hex digits.
 */
export function stateDigest(bodies: readonly b2Body[]): string {
  let h = 2166136261;
  for (const body of bodies) {
    for (const value of bodyState(body)) {
      s_bytes.setFloat64(0, value, true);
      for (let i = 0; i < 8; ++i) {
        h = Math.imul(h ^ s_bytes.getUint8(i), 16777619) >>> 0;
      }
    }
  }
  return h.toString(16).padStart(8, '0');
}

/** Digests after 0, 1, ..., `steps` steps of the scene (no listeners, its own step settings). */
export function sceneDigests(json: unknown, steps: number): string[] {
  const scene = b2dJsonRead(json);
  const digests = [stateDigest(scene.bodies)];
  for (let k = 1; k <= steps; ++k) {
    scene.step();
    digests.push(stateDigest(scene.bodies));
  }
  return digests;
}
