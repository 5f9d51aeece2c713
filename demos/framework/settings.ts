/** Test settings (Test.h's Settings). Some can be controlled in the panel. */
export class Settings {
  readonly viewCenter = { x: 0.0, y: 20.0 };
  hz = 60.0;
  velocityIterations = 8;
  positionIterations = 3;
  drawShapes = 1;
  drawJoints = 1;
  drawAABBs = 0;
  drawPairs = 0;
  drawContactPoints = 0;
  drawContactNormals = 0;
  drawContactForces = 0;
  drawFrictionForces = 0;
  drawCOMs = 0;
  drawStats = 0;
  drawProfile = 0;
  enableWarmStarting = 1;
  enableContinuous = 1;
  enableSubStepping = 0;
  /** Not in 2.2.1's panel (Box2D 2.3 added it): b2World::SetAllowSleeping. On by default, as b2World. */
  enableSleep = 1;
  pause = 0;
  singleStep = 0;
}

/** The settings a scene may set when it is selected (the b2dJson and benchmark scenes). */
export type StepSettings = Pick<
  Settings,
  'hz' | 'velocityIterations' | 'positionIterations' | 'enableWarmStarting' | 'enableContinuous' | 'enableSubStepping' | 'enableSleep'
>;

export const kStepSettingKeys: readonly (keyof StepSettings)[] = [
  'hz',
  'velocityIterations',
  'positionIterations',
  'enableWarmStarting',
  'enableContinuous',
  'enableSubStepping',
  'enableSleep',
];
