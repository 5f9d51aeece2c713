/*
 * Every golden scene (../shared/golden/scenes, 34) stepped by the GPU backend (GpuStepper: all
 * joint types, sleeping and the time-of-impact pass, with each scene's own world flags) next to the
 * JavaScript engine from the same start, STEPS steps. The scenes diverge in float32 (rain, a
 * tumbler, breaking bodies are chaotic), so the checks are physical rather than positional:
 *   - every body's state stays finite;
 *   - penetration after a collision-only step is at most the engine's deepest + PENETRATION_SLACK
 *     (3 b2_linearSlop at least: where 2.2.1's position iterations stop);
 *   - the kinetic energy (every 10 steps) never exceeds ENERGY_FACTOR x the engine's largest at
 *     any step of the run + 1 J (motors and applied forces put energy in on both sides; a bullet
 *     the GPU stops at its time of impact keeps its speed a step longer than the engine's; a
 *     solver that blows up exceeds it by orders of magnitude);
 *   - revolute and weld joints hold their anchors together within the engine's largest gap of the
 *     run + JOINT_SLACK.
 * The motion itself against the engine's is checked where it can be (solverScenes.test.ts, the
 * joint tests, solverIslands.test.ts, solverTimeOfImpact.test.ts).
 */

import { expect, it } from 'vitest';
import { b2Vec2 } from '../../src/common/b2Math';
import { b2_linearSlop } from '../../src/common/b2Settings';
import type { b2World } from '../../src/dynamics/b2World';
import { GpuStepper } from '../../src-gpu/stepper';
import { goldenSceneNames, loadGoldenScene } from '../support/scene';
import { engineDeepest, gpuDeepestPenetration, kineticEnergy } from './physics';
import { describeGpu } from './support';

const STEPS = 40;
/** Penetration beyond the engine's: float32 positions and solve order (2 cm). */
const PENETRATION_SLACK = 0.02;
const ENERGY_FACTOR = 2;
/** Anchor gap beyond the engine's: the coloured Gauss-Seidel order converges chains more slowly. */
const JOINT_SLACK = 0.05;

const e_revoluteJoint = 1;
const e_weldJoint = 8;

const SCENES = goldenSceneNames();

const a = new b2Vec2();
const b = new b2Vec2();

function largestAnchorGap(world: b2World): number {
  let gap = 0;
  for (let j = world.m_jointList; j; j = j.m_next) {
    if (j.m_type !== e_revoluteJoint && j.m_type !== e_weldJoint) continue;
    j.GetAnchorA(a);
    j.GetAnchorB(b);
    gap = Math.max(gap, Math.hypot(a.x - b.x, a.y - b.y));
  }
  return gap;
}

function allFinite(world: b2World): boolean {
  for (let body = world.m_bodyList; body; body = body.m_next) {
    const p = body.m_xf.p;
    const v = body.m_linearVelocity;
    if (![p.x, p.y, body.m_sweep.a, v.x, v.y, body.m_angularVelocity].every(Number.isFinite)) return false;
  }
  return true;
}

describeGpu('GPU backend: every golden scene', (ctx) => {
  it('finds the 34 golden scenes', () => {
    expect(SCENES.length).toBe(34);
  });

  for (const name of SCENES) {
    it(`${name}: ${STEPS} GPU steps stay finite, no deeper than the engine's, no energy or joint gap beyond it`, async () => {
      const js = loadGoldenScene(name);
      const gpu = loadGoldenScene(name);
      const s = gpu.stepSettings;
      const dt = 1 / s.stepsPerSecond;
      const stepper = new GpuStepper(ctx, gpu.world);
      let engineEnergy = 0;
      let gpuEnergy = 0;
      let engineGap = 0;
      let gpuGap = 0;
      for (let step = 1; step <= STEPS; ++step) {
        js.step();
        await stepper.step(dt, s.velocityIterations, s.positionIterations);
        engineEnergy = Math.max(engineEnergy, kineticEnergy(js.world));
        if (step % 10 === 0) {
          await stepper.readBodies();
          gpuEnergy = Math.max(gpuEnergy, kineticEnergy(gpu.world));
          engineGap = Math.max(engineGap, largestAnchorGap(js.world));
          gpuGap = Math.max(gpuGap, largestAnchorGap(gpu.world));
          expect(allFinite(gpu.world), `${name} step ${step}`).toBe(true);
        }
      }
      js.world.Step(0, s.velocityIterations, s.positionIterations);
      await stepper.step(0, s.velocityIterations, s.positionIterations);
      await stepper.readBodies();
      const gpuDeepest = await gpuDeepestPenetration(stepper);
      const jsDeepest = engineDeepest(js.world);
      stepper.destroy();
      console.log(
        `${name}: deepest GPU ${gpuDeepest.toExponential(2)} m, engine ${jsDeepest.toExponential(2)} m; ` +
          `kinetic energy max GPU ${gpuEnergy.toExponential(2)} J, engine ${engineEnergy.toExponential(2)} J; ` +
          `anchor gap GPU ${gpuGap.toExponential(2)} m, engine ${engineGap.toExponential(2)} m`,
      );
      expect(gpuDeepest).toBeLessThan(Math.max(3 * b2_linearSlop, jsDeepest) + PENETRATION_SLACK);
      expect(gpuEnergy).toBeLessThan(ENERGY_FACTOR * engineEnergy + 1);
      expect(gpuGap).toBeLessThan(engineGap + JOINT_SLACK);
    }, 600_000);
  }
});
