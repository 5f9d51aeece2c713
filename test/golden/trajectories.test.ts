import { describe, expect, it } from 'vitest';
import { goldenSceneNames, readTrajectory, runGoldenScene } from '../support/scene';

// Each scene is loaded with the b2dJson reader and stepped 600 times; every step's state digest
// must equal the C++ reference's. A failure names the first differing step, body and quantity.
describe('golden trajectories (Box2D 2.2.1 C++, bit for bit)', () => {
  for (const name of goldenSceneNames()) {
    it(`${name} follows the reference trajectory for ${readTrajectory(name).steps} steps`, () => {
      const failure = runGoldenScene(name);
      if (failure !== null) expect.fail(failure);
    });
  }
});
