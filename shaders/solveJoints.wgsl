// solveJoints.wgsl: the joints of the solver, 2.2.1's b2RevoluteJoint and b2DistanceJoint
// (InitVelocityConstraints, SolveVelocityConstraints, SolvePositionConstraints) in float32.
//
// In:  params (h, dtRatio, warmStarting, cellSize, joint slots), joints (bodies, type, JOINT_LIVE),
//      jointParams (anchors, limits, motor, length, spring: src-gpu/layout.ts), jointState (the
//      impulses carried from the previous step, the revolute limit state), bodyFlags, bodyMass,
//      bodySweep, bodyCell, bodyVel, solverState (SV_SKIP, SV_POSITION_DONE).
// Out: `prepare` (per joint slot): jointConstraints (rows below): anchors, masses, effective
//      masses, the limit state and the impulses scaled by dtRatio (or zeroed), as
//      InitVelocityConstraints leaves them before it touches the velocities.
//      `warm_start`, `velocity`, `position` (one invocation, joint slots in order): the warm-start
//      impulses, one velocity iteration, one position iteration (2.2.1's joints then contacts for
//      velocities, contacts then joints for positions; solver.ts orders the passes);
//      `position` sets SV_JOINT_ERROR when a joint is not within b2_linearSlop / b2_angularSlop.
//      `store` (per joint slot): the impulses and limit state back into jointState for the next
//      step.
// Invariants: joints run in one invocation, in slot order, so joints sharing a body need no
//      colouring yet (Gauss-Seidel as in an island); only dynamic bodies (inverse mass > 0) are
//      written; joints of inactive or dead bodies, and dead slots, are skipped. Positions are
//      taken in body A's cell (B + (cellB - cellA) x cellSize, row 5).
// jointConstraints rows (JOINT_VEC4 per joint slot):
//   0 rA, rB                    1 mA, iA, mB, iB
//   2 impulse (revolute x, y, z, motor impulse; distance: impulse, 0, 0, 0)
//   3 revolute: mass ex.x, ey.x (= ex.y), ez.x (= ex.z), ey.y; distance: u, mass, gamma
//   4 revolute: ez.y (= ey.z), ez.z, motorMass, limit state (b2LimitState as a float); distance: bias
//   5 B's cell relative to A's, 1 when the joint is solved this step, 0
//   6 localAnchorA - localCenterA, localAnchorB - localCenterB

@group(0) @binding(0) var<uniform> params: SolverParams;
@group(0) @binding(1) var<storage, read_write> solverState: array<u32>;
@group(0) @binding(2) var<storage, read> joints: array<vec4<u32>>;
@group(0) @binding(3) var<storage, read> jointParams: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read_write> jointState: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read_write> jointConstraints: array<vec4<f32>>;
@group(0) @binding(6) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(7) var<storage, read> bodyMass: array<vec4<f32>>;
@group(0) @binding(8) var<storage, read_write> bodySweep: array<vec4<f32>>;
@group(0) @binding(9) var<storage, read> bodyCell: array<vec2<i32>>;
@group(0) @binding(10) var<storage, read_write> bodyVel: array<vec4<f32>>;

const JOINT_VEC4: u32 = 7u;
const JOINT_PARAMS_VEC4: u32 = 3u;
const JOINT_LIVE: u32 = 0x80000000u;
const REVOLUTE_JOINT: u32 = 1u;                 // b2JointType
const DISTANCE_JOINT: u32 = 3u;
const INACTIVE_LIMIT: u32 = 0u;                 // b2LimitState
const AT_LOWER_LIMIT: u32 = 1u;
const AT_UPPER_LIMIT: u32 = 2u;
const EQUAL_LIMITS: u32 = 3u;
const ANGULAR_SLOP: f32 = 0.034906585039886591;      // b2_angularSlop = 2 / 180 * b2_pi
const MAX_ANGULAR_CORRECTION: f32 = 0.13962634015954636; // b2_maxAngularCorrection = 8 / 180 * b2_pi
const PI: f32 = 3.14159265359;                  // b2_pi

fn body_active(body: u32) -> bool {
  let flags = bodyFlags[body];
  return (flags & BODY_LIVE) != 0u && (flags & BODY_ACTIVE) != 0u;
}

// b2Mat33::Solve22 on the upper-left block (a11 = ex.x, a12 = ey.x, a21 = ex.y, a22 = ey.y).
fn solve22(a11: f32, a12: f32, a21: f32, a22: f32, b: vec2<f32>) -> vec2<f32> {
  var det = a11 * a22 - a12 * a21;
  if (det != 0.0) {
    det = 1.0 / det;
  }
  return vec2<f32>(det * (a22 * b.x - a12 * b.y), det * (a11 * b.y - a21 * b.x));
}

// b2Mat33::Solve33 for the symmetric mass matrix.
fn solve33(ex: vec3<f32>, ey: vec3<f32>, ez: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
  var det = dot(ex, cross(ey, ez));
  if (det != 0.0) {
    det = 1.0 / det;
  }
  return vec3<f32>(det * dot(b, cross(ey, ez)), det * dot(ex, cross(b, ez)), det * dot(ex, cross(ey, b)));
}

@compute @workgroup_size(256)
fn prepare(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
           @builtin(local_invocation_index) lid: u32) {
  let j = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (j >= params.jointSlots) {
    return;
  }
  let joint = joints[j];
  let base = JOINT_VEC4 * j;
  if ((joint.w & JOINT_LIVE) == 0u || !body_active(joint.x) || !body_active(joint.y)) {
    jointConstraints[base + 5u] = vec4<f32>(0.0);
    return;
  }
  let p = JOINT_PARAMS_VEC4 * j;
  let anchors = jointParams[p];
  let p1 = jointParams[p + 1u];
  let p2 = jointParams[p + 2u];
  let massA = bodyMass[joint.x];
  let massB = bodyMass[joint.y];
  let mA = massA.x;
  let iA = massA.y;
  let mB = massB.x;
  let iB = massB.y;
  let cellDelta = vec2<f32>(bodyCell[joint.y] - bodyCell[joint.x]) * params.cellSize;
  let sweepA = bodySweep[2u * joint.x + 1u];
  let sweepB = bodySweep[2u * joint.y + 1u];
  let cA = sweepA.xy;
  let aA = sweepA.z;
  let cB = sweepB.xy + cellDelta;
  let aB = sweepB.z;
  let qA = rot(aA);
  let qB = rot(aB);
  let lA = anchors.xy - massA.zw;
  let lB = anchors.zw - massB.zw;
  let rA = rotate(qA, lA);
  let rB = rotate(qB, lB);
  var state = jointState[2u * j];
  var limitState = u32(jointState[2u * j + 1u].x);
  var row3 = vec4<f32>(0.0);
  var row4 = vec4<f32>(0.0);

  if (joint.z == REVOLUTE_JOINT) {
    let fixedRotation = (iA + iB == 0.0);
    let exx = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
    let eyx = -rA.y * rA.x * iA - rB.y * rB.x * iB;
    let ezx = -rA.y * iA - rB.y * iB;
    let eyy = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
    let ezy = rA.x * iA + rB.x * iB;
    let ezz = iA + iB;
    var motorMass = iA + iB;
    if (motorMass > 0.0) {
      motorMass = 1.0 / motorMass;
    }
    let enableLimit = p2.y != 0.0;
    let enableMotor = p2.z != 0.0;
    if (!enableMotor || fixedRotation) {
      state.w = 0.0;
    }
    if (enableLimit && !fixedRotation) {
      let jointAngle = aB - aA - p1.x;
      if (abs(p1.z - p1.y) < 2.0 * ANGULAR_SLOP) {
        limitState = EQUAL_LIMITS;
      } else if (jointAngle <= p1.y) {
        if (limitState != AT_LOWER_LIMIT) {
          state.z = 0.0;
        }
        limitState = AT_LOWER_LIMIT;
      } else if (jointAngle >= p1.z) {
        if (limitState != AT_UPPER_LIMIT) {
          state.z = 0.0;
        }
        limitState = AT_UPPER_LIMIT;
      } else {
        limitState = INACTIVE_LIMIT;
        state.z = 0.0;
      }
    } else {
      limitState = INACTIVE_LIMIT;
    }
    row3 = vec4<f32>(exx, eyx, ezx, eyy);
    row4 = vec4<f32>(ezy, ezz, motorMass, f32(limitState));
  } else {
    var u = cB + rB - cA - rA;
    let len = length(u);
    if (len > LINEAR_SLOP) {
      u = u * (1.0 / len);
    } else {
      u = vec2<f32>(0.0);
    }
    let crAu = cross2(rA, u);
    let crBu = cross2(rB, u);
    var invMass = mA + iA * crAu * crAu + mB + iB * crBu * crBu;
    var mass = select(0.0, 1.0 / invMass, invMass != 0.0);
    var gamma = 0.0;
    var bias = 0.0;
    if (p1.y > 0.0) {
      let C = len - p1.x;
      let omega = 2.0 * PI * p1.y;
      let d = 2.0 * mass * p1.z * omega;
      let k = mass * omega * omega;
      let h = params.h;
      gamma = h * (d + h * k);
      gamma = select(0.0, 1.0 / gamma, gamma != 0.0);
      bias = C * h * k * gamma;
      invMass = invMass + gamma;
      mass = select(0.0, 1.0 / invMass, invMass != 0.0);
    }
    state = vec4<f32>(state.x, 0.0, 0.0, 0.0);
    row3 = vec4<f32>(u, mass, gamma);
    row4 = vec4<f32>(bias, 0.0, 0.0, f32(INACTIVE_LIMIT));
  }
  if (params.warmStarting != 0u) {
    state = state * params.dtRatio;
  } else {
    state = vec4<f32>(0.0);
  }
  jointConstraints[base] = vec4<f32>(rA, rB);
  jointConstraints[base + 1u] = vec4<f32>(mA, iA, mB, iB);
  jointConstraints[base + 2u] = state;
  jointConstraints[base + 3u] = row3;
  jointConstraints[base + 4u] = row4;
  jointConstraints[base + 5u] = vec4<f32>(cellDelta, 1.0, 0.0);
  jointConstraints[base + 6u] = vec4<f32>(lA, lB);
}

fn write_velocities(joint: vec4<u32>, masses: vec4<f32>, vA: vec2<f32>, wA: f32, vB: vec2<f32>, wB: f32) {
  if (masses.x > 0.0) {
    bodyVel[joint.x] = vec4<f32>(vA, wA, 0.0);
  }
  if (masses.z > 0.0) {
    bodyVel[joint.y] = vec4<f32>(vB, wB, 0.0);
  }
}

@compute @workgroup_size(1)
fn warm_start() {
  if (solverState[SV_SKIP] != 0u) {
    return;
  }
  for (var j = 0u; j < params.jointSlots; j = j + 1u) {
    let base = JOINT_VEC4 * j;
    if (jointConstraints[base + 5u].z == 0.0) {
      continue;
    }
    let joint = joints[j];
    let r = jointConstraints[base];
    let m = jointConstraints[base + 1u];
    let impulse = jointConstraints[base + 2u];
    let velA = bodyVel[joint.x];
    let velB = bodyVel[joint.y];
    var vA = velA.xy;
    var wA = velA.z;
    var vB = velB.xy;
    var wB = velB.z;
    if (joint.z == REVOLUTE_JOINT) {
      let P = impulse.xy;
      vA = vA - m.x * P;
      wA = wA - m.y * (cross2(r.xy, P) + impulse.w + impulse.z);
      vB = vB + m.z * P;
      wB = wB + m.w * (cross2(r.zw, P) + impulse.w + impulse.z);
    } else {
      let P = impulse.x * jointConstraints[base + 3u].xy;
      vA = vA - m.x * P;
      wA = wA - m.y * cross2(r.xy, P);
      vB = vB + m.z * P;
      wB = wB + m.w * cross2(r.zw, P);
    }
    write_velocities(joint, m, vA, wA, vB, wB);
  }
}

@compute @workgroup_size(1)
fn velocity() {
  if (solverState[SV_SKIP] != 0u) {
    return;
  }
  for (var j = 0u; j < params.jointSlots; j = j + 1u) {
    let base = JOINT_VEC4 * j;
    if (jointConstraints[base + 5u].z == 0.0) {
      continue;
    }
    let joint = joints[j];
    let r = jointConstraints[base];
    let rA = r.xy;
    let rB = r.zw;
    let m = jointConstraints[base + 1u];
    let mA = m.x;
    let iA = m.y;
    let mB = m.z;
    let iB = m.w;
    var impulse = jointConstraints[base + 2u];
    let row3 = jointConstraints[base + 3u];
    let row4 = jointConstraints[base + 4u];
    let velA = bodyVel[joint.x];
    let velB = bodyVel[joint.y];
    var vA = velA.xy;
    var wA = velA.z;
    var vB = velB.xy;
    var wB = velB.z;
    if (joint.z == REVOLUTE_JOINT) {
      let p2 = jointParams[JOINT_PARAMS_VEC4 * j + 2u];
      let maxMotorTorque = jointParams[JOINT_PARAMS_VEC4 * j + 1u].w;
      let limitState = u32(row4.w);
      let fixedRotation = (iA + iB == 0.0);
      if (p2.z != 0.0 && limitState != EQUAL_LIMITS && !fixedRotation) {
        let Cdot = wB - wA - p2.x;
        var motor = -row4.z * Cdot;
        let oldImpulse = impulse.w;
        let maxImpulse = params.h * maxMotorTorque;
        impulse.w = clamp(impulse.w + motor, -maxImpulse, maxImpulse);
        motor = impulse.w - oldImpulse;
        wA = wA - iA * motor;
        wB = wB + iB * motor;
      }
      // The mass matrix: ex = (exx, eyx, ezx), ey = (eyx, eyy, ezy), ez = (ezx, ezy, ezz).
      let ex = vec3<f32>(row3.x, row3.y, row3.z);
      let ey = vec3<f32>(row3.y, row3.w, row4.x);
      let ez = vec3<f32>(row3.z, row4.x, row4.y);
      if (p2.y != 0.0 && limitState != INACTIVE_LIMIT && !fixedRotation) {
        let Cdot1 = vB + cross_sv(wB, rB) - vA - cross_sv(wA, rA);
        let Cdot2 = wB - wA;
        var lambda = -solve33(ex, ey, ez, vec3<f32>(Cdot1, Cdot2));
        if (limitState == EQUAL_LIMITS) {
          impulse = vec4<f32>(impulse.xyz + lambda, impulse.w);
        } else if (limitState == AT_LOWER_LIMIT) {
          let newImpulse = impulse.z + lambda.z;
          if (newImpulse < 0.0) {
            let rhs = -Cdot1 + impulse.z * vec2<f32>(ez.x, ez.y);
            let reduced = solve22(ex.x, ey.x, ex.y, ey.y, rhs);
            lambda = vec3<f32>(reduced, -impulse.z);
            impulse = vec4<f32>(impulse.xy + reduced, 0.0, impulse.w);
          } else {
            impulse = vec4<f32>(impulse.xyz + lambda, impulse.w);
          }
        } else {
          let newImpulse = impulse.z + lambda.z;
          if (newImpulse > 0.0) {
            let rhs = -Cdot1 + impulse.z * vec2<f32>(ez.x, ez.y);
            let reduced = solve22(ex.x, ey.x, ex.y, ey.y, rhs);
            lambda = vec3<f32>(reduced, -impulse.z);
            impulse = vec4<f32>(impulse.xy + reduced, 0.0, impulse.w);
          } else {
            impulse = vec4<f32>(impulse.xyz + lambda, impulse.w);
          }
        }
        let P = lambda.xy;
        vA = vA - mA * P;
        wA = wA - iA * (cross2(rA, P) + lambda.z);
        vB = vB + mB * P;
        wB = wB + iB * (cross2(rB, P) + lambda.z);
      } else {
        let Cdot = vB + cross_sv(wB, rB) - vA - cross_sv(wA, rA);
        let lambda = solve22(ex.x, ey.x, ex.y, ey.y, -Cdot);
        impulse = vec4<f32>(impulse.xy + lambda, impulse.zw);
        vA = vA - mA * lambda;
        wA = wA - iA * cross2(rA, lambda);
        vB = vB + mB * lambda;
        wB = wB + iB * cross2(rB, lambda);
      }
    } else {
      let u = row3.xy;
      let vpA = vA + cross_sv(wA, rA);
      let vpB = vB + cross_sv(wB, rB);
      let Cdot = dot(u, vpB - vpA);
      let lambda = -row3.z * (Cdot + row4.x + row3.w * impulse.x);
      impulse.x = impulse.x + lambda;
      let P = lambda * u;
      vA = vA - mA * P;
      wA = wA - iA * cross2(rA, P);
      vB = vB + mB * P;
      wB = wB + iB * cross2(rB, P);
    }
    jointConstraints[base + 2u] = impulse;
    write_velocities(joint, m, vA, wA, vB, wB);
  }
}

@compute @workgroup_size(1)
fn position() {
  if (solverState[SV_SKIP] != 0u || solverState[SV_POSITION_DONE] != 0u) {
    return;
  }
  var okay = true;
  for (var j = 0u; j < params.jointSlots; j = j + 1u) {
    let base = JOINT_VEC4 * j;
    let row5 = jointConstraints[base + 5u];
    if (row5.z == 0.0) {
      continue;
    }
    let joint = joints[j];
    let m = jointConstraints[base + 1u];
    let mA = m.x;
    let iA = m.y;
    let mB = m.z;
    let iB = m.w;
    let anchor = jointConstraints[base + 6u];
    let cellDelta = row5.xy;
    let sweepA = bodySweep[2u * joint.x + 1u];
    let sweepB = bodySweep[2u * joint.y + 1u];
    var cA = sweepA.xy;
    var aA = sweepA.z;
    var cB = sweepB.xy + cellDelta;
    var aB = sweepB.z;
    if (joint.z == REVOLUTE_JOINT) {
      let p1 = jointParams[JOINT_PARAMS_VEC4 * j + 1u];
      let p2 = jointParams[JOINT_PARAMS_VEC4 * j + 2u];
      let row4 = jointConstraints[base + 4u];
      let limitState = u32(row4.w);
      var angularError = 0.0;
      if (p2.y != 0.0 && limitState != INACTIVE_LIMIT && iA + iB != 0.0) {
        let angle = aB - aA - p1.x;
        var limitImpulse = 0.0;
        if (limitState == EQUAL_LIMITS) {
          let C = clamp(angle - p1.y, -MAX_ANGULAR_CORRECTION, MAX_ANGULAR_CORRECTION);
          limitImpulse = -row4.z * C;
          angularError = abs(C);
        } else if (limitState == AT_LOWER_LIMIT) {
          var C = angle - p1.y;
          angularError = -C;
          C = clamp(C + ANGULAR_SLOP, -MAX_ANGULAR_CORRECTION, 0.0);
          limitImpulse = -row4.z * C;
        } else {
          var C = angle - p1.z;
          angularError = C;
          C = clamp(C - ANGULAR_SLOP, 0.0, MAX_ANGULAR_CORRECTION);
          limitImpulse = -row4.z * C;
        }
        aA = aA - iA * limitImpulse;
        aB = aB + iB * limitImpulse;
      }
      let rA = rotate(rot(aA), anchor.xy);
      let rB = rotate(rot(aB), anchor.zw);
      let C = cB + rB - cA - rA;
      let positionError = length(C);
      let kxx = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
      let kxy = -iA * rA.x * rA.y - iB * rB.x * rB.y;
      let kyy = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;
      let lambda = -solve22(kxx, kxy, kxy, kyy, C);
      cA = cA - mA * lambda;
      aA = aA - iA * cross2(rA, lambda);
      cB = cB + mB * lambda;
      aB = aB + iB * cross2(rB, lambda);
      okay = okay && positionError <= LINEAR_SLOP && angularError <= ANGULAR_SLOP;
    } else {
      let p1 = jointParams[JOINT_PARAMS_VEC4 * j + 1u];
      if (p1.y > 0.0) {
        continue;
      }
      let rA = rotate(rot(aA), anchor.xy);
      let rB = rotate(rot(aB), anchor.zw);
      var u = cB + rB - cA - rA;
      // b2Vec2::Normalize: the length (0 when shorter than b2_epsilon, u then unchanged).
      let len = select(0.0, length(u), length(u) >= S_EPSILON);
      u = normalize2(u);
      var C = len - p1.x;
      C = clamp(C, -MAX_LINEAR_CORRECTION, MAX_LINEAR_CORRECTION);
      let lambda = -jointConstraints[base + 3u].z * C;
      let P = lambda * u;
      cA = cA - mA * P;
      aA = aA - iA * cross2(rA, P);
      cB = cB + mB * P;
      aB = aB + iB * cross2(rB, P);
      okay = okay && abs(C) < LINEAR_SLOP;
    }
    if (mA > 0.0) {
      bodySweep[2u * joint.x + 1u] = vec4<f32>(cA, aA, sweepA.w);
    }
    if (mB > 0.0) {
      bodySweep[2u * joint.y + 1u] = vec4<f32>(cB - cellDelta, aB, sweepB.w);
    }
  }
  if (!okay) {
    solverState[SV_JOINT_ERROR] = 1u;
  }
}

@compute @workgroup_size(256)
fn store(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
         @builtin(local_invocation_index) lid: u32) {
  let j = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (j >= params.jointSlots || solverState[SV_SKIP] != 0u) {
    return;
  }
  let base = JOINT_VEC4 * j;
  if (jointConstraints[base + 5u].z == 0.0) {
    return;
  }
  jointState[2u * j] = jointConstraints[base + 2u];
  jointState[2u * j + 1u] = vec4<f32>(jointConstraints[base + 4u].w, 0.0, 0.0, 0.0);
}
