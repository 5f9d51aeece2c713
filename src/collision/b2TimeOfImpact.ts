/*
 * Time of impact by conservative advancement on separating axes (b2TimeOfImpact.h,
 * b2TimeOfImpact.cpp).
 */

import { b2Abs, b2Max, b2MulRV, b2MulTRV, b2MulXV, b2Normalize, b2NormalizeLength, b2Sweep, b2SweepTime, b2Transform, b2Vec2 } from '../common/b2Math';
import { b2Assert, b2_linearSlop, b2_maxPolygonVertices } from '../common/b2Settings';
import { b2Distance, b2DistanceInput, b2DistanceOutput, b2DistanceProxy, b2SimplexCache } from './b2Distance';

/*
 * TOI statistics (the C++ globals). Importers read them as live bindings; ES modules do not let an
 * importer assign them, so the Testbed's `b2_toiCalls = 0; ...` is b2ResetToiCounters().
 */
export let b2_toiCalls = 0;
export let b2_toiIters = 0;
export let b2_toiMaxIters = 0;
export let b2_toiRootIters = 0;
export let b2_toiMaxRootIters = 0;

/** Zero the TOI statistics. */
export function b2ResetToiCounters(): void {
  b2_toiCalls = 0;
  b2_toiIters = 0;
  b2_toiMaxIters = 0;
  b2_toiRootIters = 0;
  b2_toiMaxRootIters = 0;
}

/** Input parameters for b2TimeOfImpact */
export class b2TOIInput {
  readonly proxyA = new b2DistanceProxy();
  readonly proxyB = new b2DistanceProxy();
  readonly sweepA = new b2Sweep();
  readonly sweepB = new b2Sweep();
  /** defines sweep interval [0, tMax] */
  tMax = 0.0;

  Assign(other: Readonly<b2TOIInput>): this {
    this.proxyA.Assign(other.proxyA);
    this.proxyB.Assign(other.proxyB);
    this.sweepA.Assign(other.sweepA);
    this.sweepB.Assign(other.sweepB);
    this.tMax = other.tMax;
    return this;
  }

  Clone(): b2TOIInput {
    return new b2TOIInput().Assign(this);
  }
}

/** Output parameters for b2TimeOfImpact. */
export class b2TOIOutput {
  static readonly e_unknown = 0;
  static readonly e_failed = 1;
  static readonly e_overlapped = 2;
  static readonly e_touching = 3;
  static readonly e_separated = 4;

  state = b2TOIOutput.e_unknown;
  t = 0.0;

  Assign(other: Readonly<b2TOIOutput>): this {
    this.state = other.state;
    this.t = other.t;
    return this;
  }

  Clone(): b2TOIOutput {
    return new b2TOIOutput().Assign(this);
  }
}

/** The witness vertex indices FindMinSeparation reports (the C++ int32* out-parameters). */
class b2SeparationIndices {
  indexA = 0;
  indexB = 0;
}

// Scratch for the separation function; it never calls out of this module while holding them.
const s_xfA = new b2Transform();
const s_xfB = new b2Transform();
const s_normal = new b2Vec2();
const s_negNormal = new b2Vec2();
const s_axis = new b2Vec2();
const s_pointA = new b2Vec2();
const s_pointB = new b2Vec2();

/**
 * The separation function's time argument (s_separationIo[0]) and result (s_separationIo[1]). Its
 * methods take and give them here, not as a double argument and return value: V8 boxes both for a
 * call it does not inline, which was a heap allocation for each root-finder iteration of a step.
 */
const s_separationIo = new Float64Array(2);

class b2SeparationFunction {
  static readonly e_points = 0;
  static readonly e_faceA = 1;
  static readonly e_faceB = 2;

  m_proxyA = new b2DistanceProxy();
  m_proxyB = new b2DistanceProxy();
  readonly m_sweepA = new b2Sweep();
  readonly m_sweepB = new b2Sweep();
  m_type = b2SeparationFunction.e_points;
  readonly m_localPoint = new b2Vec2();
  readonly m_axis = new b2Vec2();

  Initialize(cache: Readonly<b2SimplexCache>, proxyA: b2DistanceProxy, sweepA: Readonly<b2Sweep>, proxyB: b2DistanceProxy, sweepB: Readonly<b2Sweep>): void {
    // Vectors are set field by field and normalized by b2Normalize: this function is past V8's
    // inlining budget, and a call it leaves out of line boxes the doubles it passes or returns.
    const t1 = s_separationIo[0];
    this.m_proxyA = proxyA;
    this.m_proxyB = proxyB;
    const count = cache.count;
    b2Assert(0 < count && count < 3);

    this.m_sweepA.Assign(sweepA);
    this.m_sweepB.Assign(sweepB);

    b2SweepTime[0] = t1;
    const xfA = this.m_sweepA.GetTransformAt(s_xfA);
    const xfB = this.m_sweepB.GetTransformAt(s_xfB);

    const axis = this.m_axis;
    if (count === 1) {
      this.m_type = b2SeparationFunction.e_points;
      const pointA = b2MulXV(xfA, this.m_proxyA.GetVertex(cache.indexA[0]), s_pointA);
      const pointB = b2MulXV(xfB, this.m_proxyB.GetVertex(cache.indexB[0]), s_pointB);
      axis.x = pointB.x - pointA.x;
      axis.y = pointB.y - pointA.y;
      b2Normalize(axis);
      s_separationIo[1] = b2NormalizeLength[0];
      return;
    } else if (cache.indexA[0] === cache.indexA[1]) {
      // Two points on B and one on A.
      this.m_type = b2SeparationFunction.e_faceB;
      const localPointB1 = proxyB.GetVertex(cache.indexB[0]);
      const localPointB2 = proxyB.GetVertex(cache.indexB[1]);

      // b2Cross(localPointB2 - localPointB1, 1.0)
      axis.x = 1.0 * (localPointB2.y - localPointB1.y);
      axis.y = -1.0 * (localPointB2.x - localPointB1.x);
      b2Normalize(axis);
      const normal = b2MulRV(xfB.q, axis, s_normal);

      this.m_localPoint.x = 0.5 * (localPointB1.x + localPointB2.x);
      this.m_localPoint.y = 0.5 * (localPointB1.y + localPointB2.y);
      const pointB = b2MulXV(xfB, this.m_localPoint, s_pointB);

      const pointA = b2MulXV(xfA, proxyA.GetVertex(cache.indexA[0]), s_pointA);

      let s = (pointA.x - pointB.x) * normal.x + (pointA.y - pointB.y) * normal.y;
      if (s < 0.0) {
        axis.x = -axis.x;
        axis.y = -axis.y;
        s = -s;
      }
      s_separationIo[1] = s;
      return;
    } else {
      // Two points on A and one or two points on B.
      this.m_type = b2SeparationFunction.e_faceA;
      const localPointA1 = this.m_proxyA.GetVertex(cache.indexA[0]);
      const localPointA2 = this.m_proxyA.GetVertex(cache.indexA[1]);

      // b2Cross(localPointA2 - localPointA1, 1.0)
      axis.x = 1.0 * (localPointA2.y - localPointA1.y);
      axis.y = -1.0 * (localPointA2.x - localPointA1.x);
      b2Normalize(axis);
      const normal = b2MulRV(xfA.q, axis, s_normal);

      this.m_localPoint.x = 0.5 * (localPointA1.x + localPointA2.x);
      this.m_localPoint.y = 0.5 * (localPointA1.y + localPointA2.y);
      const pointA = b2MulXV(xfA, this.m_localPoint, s_pointA);

      const pointB = b2MulXV(xfB, this.m_proxyB.GetVertex(cache.indexB[0]), s_pointB);

      let s = (pointB.x - pointA.x) * normal.x + (pointB.y - pointA.y) * normal.y;
      if (s < 0.0) {
        axis.x = -axis.x;
        axis.y = -axis.y;
        s = -s;
      }
      s_separationIo[1] = s;
      return;
    }
  }

  FindMinSeparation(indices: b2SeparationIndices): void {
    const t = s_separationIo[0];
    b2SweepTime[0] = t;
    const xfA = this.m_sweepA.GetTransformAt(s_xfA);
    const xfB = this.m_sweepB.GetTransformAt(s_xfB);
    const axis = this.m_axis;

    switch (this.m_type) {
      case b2SeparationFunction.e_points: {
        indices.indexA = this.m_proxyA.GetSupport(b2MulTRV(xfA.q, axis, s_axis));
        // -axis field by field rather than through Set: see s_negD in b2Distance.
        s_negNormal.x = -axis.x;
        s_negNormal.y = -axis.y;
        indices.indexB = this.m_proxyB.GetSupport(b2MulTRV(xfB.q, s_negNormal, s_axis));

        const pointA = b2MulXV(xfA, this.m_proxyA.GetVertex(indices.indexA), s_pointA);
        const pointB = b2MulXV(xfB, this.m_proxyB.GetVertex(indices.indexB), s_pointB);

        const separation = (pointB.x - pointA.x) * axis.x + (pointB.y - pointA.y) * axis.y;
        s_separationIo[1] = separation;
        return;
      }

      case b2SeparationFunction.e_faceA: {
        const normal = b2MulRV(xfA.q, axis, s_normal);
        const pointA = b2MulXV(xfA, this.m_localPoint, s_pointA);

        s_negNormal.x = -normal.x;
        s_negNormal.y = -normal.y;

        indices.indexA = -1;
        indices.indexB = this.m_proxyB.GetSupport(b2MulTRV(xfB.q, s_negNormal, s_axis));

        const pointB = b2MulXV(xfB, this.m_proxyB.GetVertex(indices.indexB), s_pointB);

        const separation = (pointB.x - pointA.x) * normal.x + (pointB.y - pointA.y) * normal.y;
        s_separationIo[1] = separation;
        return;
      }

      case b2SeparationFunction.e_faceB: {
        const normal = b2MulRV(xfB.q, axis, s_normal);
        const pointB = b2MulXV(xfB, this.m_localPoint, s_pointB);

        s_negNormal.x = -normal.x;
        s_negNormal.y = -normal.y;

        indices.indexB = -1;
        indices.indexA = this.m_proxyA.GetSupport(b2MulTRV(xfA.q, s_negNormal, s_axis));

        const pointA = b2MulXV(xfA, this.m_proxyA.GetVertex(indices.indexA), s_pointA);

        const separation = (pointA.x - pointB.x) * normal.x + (pointA.y - pointB.y) * normal.y;
        s_separationIo[1] = separation;
        return;
      }

      default:
        b2Assert(false);
    }
  }

  // The C++ also computes the support axes here; they decide nothing, so they are not computed.
  Evaluate(indexA: number, indexB: number): void {
    const t = s_separationIo[0];
    b2SweepTime[0] = t;
    const xfA = this.m_sweepA.GetTransformAt(s_xfA);
    const xfB = this.m_sweepB.GetTransformAt(s_xfB);
    const axis = this.m_axis;

    switch (this.m_type) {
      case b2SeparationFunction.e_points: {
        const pointA = b2MulXV(xfA, this.m_proxyA.GetVertex(indexA), s_pointA);
        const pointB = b2MulXV(xfB, this.m_proxyB.GetVertex(indexB), s_pointB);
        const separation = (pointB.x - pointA.x) * axis.x + (pointB.y - pointA.y) * axis.y;
        s_separationIo[1] = separation;
        return;
      }

      case b2SeparationFunction.e_faceA: {
        const normal = b2MulRV(xfA.q, axis, s_normal);
        const pointA = b2MulXV(xfA, this.m_localPoint, s_pointA);

        const pointB = b2MulXV(xfB, this.m_proxyB.GetVertex(indexB), s_pointB);

        const separation = (pointB.x - pointA.x) * normal.x + (pointB.y - pointA.y) * normal.y;
        s_separationIo[1] = separation;
        return;
      }

      case b2SeparationFunction.e_faceB: {
        const normal = b2MulRV(xfB.q, axis, s_normal);
        const pointB = b2MulXV(xfB, this.m_localPoint, s_pointB);

        const pointA = b2MulXV(xfA, this.m_proxyA.GetVertex(indexA), s_pointA);

        const separation = (pointA.x - pointB.x) * normal.x + (pointA.y - pointB.y) * normal.y;
        s_separationIo[1] = separation;
        return;
      }

      default:
        b2Assert(false);
    }
  }
}

// b2TimeOfImpact calls only b2Distance, which does not re-enter it, so its locals can be shared.
const s_sweepA = new b2Sweep();
const s_sweepB = new b2Sweep();
const s_cache = new b2SimplexCache();
const s_distanceInput = new b2DistanceInput();
const s_distanceOutput = new b2DistanceOutput();
const s_fcn = new b2SeparationFunction();
const s_indices = new b2SeparationIndices();

/**
 * Compute the upper bound on time before two shapes penetrate. Time is represented as
 * a fraction between [0,tMax]. This uses a swept separating axis and may miss some intermediate,
 * non-tunneling collision. If you change the time interval, you should call this function
 * again.
 * Note: use b2Distance to compute the contact point and normal at the time of impact.
 */
export function b2TimeOfImpact(output: b2TOIOutput, input: Readonly<b2TOIInput>): void {
  ++b2_toiCalls;

  output.state = b2TOIOutput.e_unknown;
  output.t = input.tMax;

  const proxyA = input.proxyA;
  const proxyB = input.proxyB;

  // Copies: the input sweeps stay as the caller gave them.
  const sweepA = s_sweepA.Assign(input.sweepA);
  const sweepB = s_sweepB.Assign(input.sweepB);

  // Large rotations can make the root finder fail, so we normalize the
  // sweep angles.
  sweepA.Normalize();
  sweepB.Normalize();

  const tMax = input.tMax;

  const totalRadius = proxyA.m_radius + proxyB.m_radius;
  const target = b2Max(+b2_linearSlop, totalRadius - 3.0 * b2_linearSlop); // unary plus: docs/PORTING.md
  const tolerance = 0.25 * b2_linearSlop;
  b2Assert(target > tolerance);

  let t1 = 0.0;
  const k_maxIterations = 20; // TODO_ERIN b2Settings
  let iter = 0;

  // Prepare input for distance query.
  const cache = s_cache;
  cache.count = 0;
  const distanceInput = s_distanceInput;
  distanceInput.proxyA.Assign(input.proxyA);
  distanceInput.proxyB.Assign(input.proxyB);
  distanceInput.useRadii = false;
  const distanceOutput = s_distanceOutput;
  const fcn = s_fcn;
  const indices = s_indices;

  // The outer loop progressively attempts to compute new separating axes.
  // This loop terminates when an axis is repeated (no progress is made).
  for (;;) {
    // Get the distance between shapes. We can also use the results
    // to get a separating axis.
    b2SweepTime[0] = t1;
    sweepA.GetTransformAt(distanceInput.transformA);
    sweepB.GetTransformAt(distanceInput.transformB);
    b2Distance(distanceOutput, cache, distanceInput);

    // If the shapes are overlapped, we give up on continuous collision.
    if (distanceOutput.distance <= 0.0) {
      // Failure!
      output.state = b2TOIOutput.e_overlapped;
      output.t = 0.0;
      break;
    }

    if (distanceOutput.distance < target + tolerance) {
      // Victory!
      output.state = b2TOIOutput.e_touching;
      output.t = t1;
      break;
    }

    // Initialize the separating axis.
    s_separationIo[0] = t1;
    fcn.Initialize(cache, proxyA, sweepA, proxyB, sweepB);

    // Compute the TOI on the separating axis. We do this by successively
    // resolving the deepest point. This loop is bounded by the number of vertices.
    let done = false;
    let t2 = tMax;
    let pushBackIter = 0;
    for (;;) {
      // Find the deepest point at t2. Store the witness point indices.
      s_separationIo[0] = t2;
      fcn.FindMinSeparation(indices);
      let s2 = s_separationIo[1];
      const indexA = indices.indexA;
      const indexB = indices.indexB;

      // Is the final configuration separated?
      if (s2 > target + tolerance) {
        // Victory!
        output.state = b2TOIOutput.e_separated;
        output.t = tMax;
        done = true;
        break;
      }

      // Has the separation reached tolerance?
      if (s2 > target - tolerance) {
        // Advance the sweeps
        t1 = t2;
        break;
      }

      // Compute the initial separation of the witness points.
      s_separationIo[0] = t1;
      fcn.Evaluate(indexA, indexB);
      let s1 = s_separationIo[1];

      // Check for initial overlap. This might happen if the root finder
      // runs out of iterations.
      if (s1 < target - tolerance) {
        output.state = b2TOIOutput.e_failed;
        output.t = t1;
        done = true;
        break;
      }

      // Check for touching
      if (s1 <= target + tolerance) {
        // Victory! t1 should hold the TOI (could be 0.0).
        output.state = b2TOIOutput.e_touching;
        output.t = t1;
        done = true;
        break;
      }

      // Compute 1D root of: f(x) - target = 0
      let rootIterCount = 0;
      let a1 = t1;
      let a2 = t2;
      for (;;) {
        // Use a mix of the secant rule and bisection.
        let t: number;
        if (rootIterCount & 1) {
          // Secant rule to improve convergence.
          t = a1 + ((target - s1) * (a2 - a1)) / (s2 - s1);
        } else {
          // Bisection to guarantee progress.
          t = 0.5 * (a1 + a2);
        }

        s_separationIo[0] = t;
        fcn.Evaluate(indexA, indexB);
        const s = s_separationIo[1];

        if (b2Abs(s - target) < tolerance) {
          // t2 holds a tentative value for t1
          t2 = t;
          break;
        }

        // Ensure we continue to bracket the root.
        if (s > target) {
          a1 = t;
          s1 = s;
        } else {
          a2 = t;
          s2 = s;
        }

        ++rootIterCount;
        ++b2_toiRootIters;

        if (rootIterCount === 50) {
          break;
        }
      }

      b2_toiMaxRootIters = b2Max(b2_toiMaxRootIters, rootIterCount);

      ++pushBackIter;

      if (pushBackIter === b2_maxPolygonVertices) {
        break;
      }
    }

    ++iter;
    ++b2_toiIters;

    if (done) {
      break;
    }

    if (iter === k_maxIterations) {
      // Root finder got stuck. Semi-victory.
      output.state = b2TOIOutput.e_failed;
      output.t = t1;
      break;
    }
  }

  b2_toiMaxIters = b2Max(b2_toiMaxIters, iter);
}
