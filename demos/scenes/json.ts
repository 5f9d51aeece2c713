/*
 * A b2dJson file (R.U.B.E., iforce2d's b2dJson, the golden scenes, `webphysics run --out`) as a
 * testbed scene, loaded with the package's own reader (src/io b2dJsonRead). It runs with the
 * file's step settings and world flags, and the view frames its fixtures.
 */

import { b2dJsonRead } from '../../src/index';
import type { b2dJsonScene } from '../../src/index';
import type { StepSettings } from '../framework/settings';
import { Test } from '../framework/test';

export class JsonScene extends Test {
  readonly m_scene: b2dJsonScene;
  /** Settings from the file, read before the framework's Step sets the world flags. */
  private readonly m_settings: Partial<StepSettings>;

  constructor(scene: b2dJsonScene) {
    super(scene.world);
    this.m_scene = scene;
    const world = scene.world;
    this.m_settings = {
      hz: scene.stepSettings.stepsPerSecond,
      velocityIterations: scene.stepSettings.velocityIterations,
      positionIterations: scene.stepSettings.positionIterations,
      enableWarmStarting: world.GetWarmStarting() ? 1 : 0,
      enableContinuous: world.GetContinuousPhysics() ? 1 : 0,
      enableSubStepping: world.GetSubStepping() ? 1 : 0,
      enableSleep: world.GetAllowSleeping() ? 1 : 0,
    };
  }

  /** Parse and load a document (throws the reader's b2dJsonError on a malformed one). */
  static FromText(text: string): JsonScene {
    return new JsonScene(b2dJsonRead(JSON.parse(text)));
  }

  override StepSettingsOverride(): Partial<StepSettings> {
    return this.m_settings;
  }

  override InitialView(): { x: number; y: number; zoom: number } | null {
    let lx = Infinity;
    let ly = Infinity;
    let ux = -Infinity;
    let uy = -Infinity;
    for (let b = this.m_world.GetBodyList(); b !== null; b = b.GetNext()) {
      for (let f = b.GetFixtureList(); f !== null; f = f.GetNext()) {
        for (let i = 0; i < f.m_proxyCount; ++i) {
          const aabb = f.GetAABB(i);
          lx = Math.min(lx, aabb.lowerBound.x);
          ly = Math.min(ly, aabb.lowerBound.y);
          ux = Math.max(ux, aabb.upperBound.x);
          uy = Math.max(uy, aabb.upperBound.y);
        }
      }
    }
    if (!Number.isFinite(lx) || !Number.isFinite(uy)) return null;
    const width = this.m_debugDraw.width;
    const height = this.m_debugDraw.height;
    const ratio = width > 0 && height > 0 ? width / height : 4 / 3;
    // Half the view's height is 25 m times the zoom (Main.cpp); leave a 10% margin.
    const zoom = Math.max((uy - ly) / 2 / 25.0, (ux - lx) / 2 / (25.0 * ratio)) * 1.1;
    return { x: (lx + ux) / 2, y: (ly + uy) / 2, zoom: Math.min(20.0, Math.max(0.02, zoom)) };
  }
}
