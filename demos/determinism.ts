/*
 * The golden trajectory digest (shared/golden/README.md), computed in the page: load a b2dJson
 * scene with b2dJsonRead, step it with its own settings, and hash every body's position, angle and
 * velocities (creation order, 8 little-endian bytes each) with 32-bit FNV-1a after every step.
 * test/support/scene.ts is the Node implementation the browser test compares with.
 */

import { b2dJsonRead } from '../src/index';
import type { b2Body } from '../src/index';

const s_bytes = new DataView(new ArrayBuffer(8));

export function stateDigest(bodies: readonly b2Body[]): string {
  let h = 2166136261;
  for (const body of bodies) {
    const values = [
      body.m_xf.p.x,
      body.m_xf.p.y,
      body.m_sweep.a,
      body.m_linearVelocity.x,
      body.m_linearVelocity.y,
      body.m_angularVelocity,
    ];
    for (const value of values) {
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
