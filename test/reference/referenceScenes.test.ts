import { describe, expect, it } from 'vitest';
import { readReferenceExpectation, referenceCaseNames, runReferenceCase } from '../support/referenceScript';

// Worlds the golden set does not cover (the remaining Testbed tests, seeded random worlds, stress
// worlds) and scripted API calls between steps (SetTransform, SetType, SetActive, DestroyBody,
// CreateFixture, SetFilterData, joint setters, ray casts and queries...). Every step's five digests
// must equal those Box2D 2.2.1 (C++, float64) printed; see test/reference-scenes/README.md.
describe('reference scenes and scripts (Box2D 2.2.1 C++, bit for bit)', () => {
  for (const name of referenceCaseNames()) {
    it(`${name} matches the C++ for ${readReferenceExpectation(name).steps} steps`, () => {
      const failure = runReferenceCase(name);
      if (failure !== null) expect.fail(failure);
    });
  }
});
