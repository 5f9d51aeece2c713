// solveJointsCommon.wgsl: the joints' share of the colour passes, 2.2.1's ten joint types
// (b2*Joint::InitVelocityConstraints' warm start, SolveVelocityConstraints,
// SolvePositionConstraints) in float32. The host prepends it (after solverCommon.wgsl) to
// solveJoints.wgsl, warmStart.wgsl, solveVelocity.wgsl and solvePosition.wgsl.
//
// In:  jointBodies and jointConstraints as solveJoints.wgsl's `bodies` and `prepare` leave them
//      for the step, jointParams (the mirror's: limits, motor speeds, targets as set from JS).
// Out: joint_warm_start / joint_velocity / joint_position change the motion of a joint's bodies
//      held by the caller (Motion: (v, w) or (c, a) of bodies A, B, C, D, each in its own cell;
//      the caller writes back the dynamic ones); velocity iterations accumulate the impulses in
//      jointConstraints row 2.
// Invariants: one invocation per joint per pass, and no two items of a colour share a dynamic
//      body (colour.wgsl), so a joint's records and bodies have one writer per pass. Positions
//      are taken in body A's cell (B + row 7.xy); a gear works in A's cell for C and in B's cell
//      for D (rows 7.xy, 7.zw). The mouse joint's 0.98 angular damping of B is applied in its
//      warm start (2.2.1 applies it there, in InitVelocityConstraints, whether or not warm
//      starting is on).
// jointBodies (2 x vec4<u32> per joint slot): bodies A, B, C, D (C, D = NO_BODY but for a gear) |
//   b2JointType, dynamic mask (bit i: body i is dynamic and written), 1 when the joint is solved
//   this step (live, its bodies active), b2LimitState (revolute, prismatic, rope).
// jointConstraints rows (JOINT_VEC4 per joint slot; rows 1, 2, 6, 7 shared by every type):
//   1 invMass A, invI A, invMass B, invI B          2 impulses (jointState row 0's layout)
//   6 localAnchorA - localCenterA, localAnchorB - localCenterB
//   7 B's cell relative to A's ((cellB - cellA) x cellSize), 0, 0; gear: C's relative to A's,
//     D's relative to B's
//   revolute   0 rA, rB  3 K ex.x, ey.x, ez.x, ey.y  4 K ez.y, ez.z, motorMass
//   prismatic  0 axis, perp  3 s1, s2, a1, a2  4 K k11, k12, k13, k22  5 k23, k33, motorMass
//   distance   0 rA, rB  3 u, mass, gamma  4 bias
//   pulley     0 rA, rB  3 uA, uB  4 mass, ratio  5 ground anchors A, B in A's cell
//   mouse      0 0, rB  3 mass (ex, ey)  4 beta x C, gamma
//   gear       0 JvAC, JvBD  3 JwA, JwB, JwC, JwD  4 invMass C, invI C, invMass D, invI D
//              5 localAnchorC - lcC, localAnchorD - lcD  8 mass
//   wheel      0 ax, ay  3 sAx, sBx, sAy, sBy  4 mass, motorMass, springMass, bias  5 gamma
//   weld       0 rA, rB  3 mass ex.x, ex.y, ex.z, ey.y  4 mass ey.z, ez.z, gamma, bias
//   friction   0 rA, rB  3 linearMass (ex, ey)  4 angularMass
//   rope       0 rA, rB  3 u, mass, length
// jointParams (JOINT_PARAMS_VEC4 per joint slot) are listed in src-gpu/device/layout.ts.

@group(0) @binding(9) var<uniform> params: SolverParams;
@group(0) @binding(10) var<storage, read_write> jointBodies: array<vec4<u32>>;
@group(0) @binding(11) var<storage, read> jointParams: array<vec4<f32>>;
@group(0) @binding(12) var<storage, read_write> jointConstraints: array<vec4<f32>>;

alias Motion = array<vec4<f32>, 4>;

const JOINT_VEC4: u32 = 9u;
const JOINT_PARAMS_VEC4: u32 = 5u;
const NO_BODY: u32 = 0xffffffffu;

// b2Mat33::Solve22 on the upper-left block (a11 = ex.x, a12 = ey.x, a21 = ex.y, a22 = ey.y); also
// b2Mat22::Solve.
fn solve22(a11: f32, a12: f32, a21: f32, a22: f32, b: vec2<f32>) -> vec2<f32> {
  var det = a11 * a22 - a12 * a21;
  if (det != 0.0) {
    det = 1.0 / det;
  }
  return vec2<f32>(det * (a22 * b.x - a12 * b.y), det * (a11 * b.y - a21 * b.x));
}

// b2Mat33::Solve33.
fn solve33(ex: vec3<f32>, ey: vec3<f32>, ez: vec3<f32>, b: vec3<f32>) -> vec3<f32> {
  var det = dot(ex, cross(ey, ez));
  if (det != 0.0) {
    det = 1.0 / det;
  }
  return vec3<f32>(det * dot(b, cross(ey, ez)), det * dot(ex, cross(b, ez)), det * dot(ex, cross(ey, b)));
}

// b2Mul(b2Mat22 (ex, ey) = (m.xy, m.zw), v).
fn mul22(m: vec4<f32>, v: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(m.x * v.x + m.z * v.y, m.y * v.x + m.w * v.y);
}

// b2MulT(q, v).
fn rotate_t(q: vec2<f32>, v: vec2<f32>) -> vec2<f32> {
  return vec2<f32>(q.x * v.x + q.y * v.y, -q.y * v.x + q.x * v.y);
}

// The warm start of InitVelocityConstraints (impulses already scaled by dtRatio, or zero).
fn joint_warm_start(j: u32, kind: u32, motion: ptr<function, Motion>) {
  let base = JOINT_VEC4 * j;
  let r0 = jointConstraints[base];
  let m = jointConstraints[base + 1u];
  let impulse = jointConstraints[base + 2u];
  let r3 = jointConstraints[base + 3u];
  let r4 = jointConstraints[base + 4u];
  var vA = (*motion)[0].xy;
  var wA = (*motion)[0].z;
  var vB = (*motion)[1].xy;
  var wB = (*motion)[1].z;
  switch kind {
    case REVOLUTE_JOINT: {
      let P = impulse.xy;
      vA = vA - m.x * P;
      wA = wA - m.y * (cross2(r0.xy, P) + impulse.w + impulse.z);
      vB = vB + m.z * P;
      wB = wB + m.w * (cross2(r0.zw, P) + impulse.w + impulse.z);
    }
    case PRISMATIC_JOINT: {
      let P = impulse.x * r0.zw + (impulse.w + impulse.z) * r0.xy;
      let LA = impulse.x * r3.x + impulse.y + (impulse.w + impulse.z) * r3.z;
      let LB = impulse.x * r3.y + impulse.y + (impulse.w + impulse.z) * r3.w;
      vA = vA - m.x * P;
      wA = wA - m.y * LA;
      vB = vB + m.z * P;
      wB = wB + m.w * LB;
    }
    case DISTANCE_JOINT, ROPE_JOINT: {
      let P = impulse.x * r3.xy;
      vA = vA - m.x * P;
      wA = wA - m.y * cross2(r0.xy, P);
      vB = vB + m.z * P;
      wB = wB + m.w * cross2(r0.zw, P);
    }
    case PULLEY_JOINT: {
      let PA = -impulse.x * r3.xy;
      let PB = (-r4.y * impulse.x) * r3.zw;
      vA = vA + m.x * PA;
      wA = wA + m.y * cross2(r0.xy, PA);
      vB = vB + m.z * PB;
      wB = wB + m.w * cross2(r0.zw, PB);
    }
    case MOUSE_JOINT: {
      wB = wB * 0.98;
      vB = vB + m.z * impulse.xy;
      wB = wB + m.w * cross2(r0.zw, impulse.xy);
    }
    case GEAR_JOINT: {
      let mCD = r4;
      var vC = (*motion)[2].xy;
      var wC = (*motion)[2].z;
      var vD = (*motion)[3].xy;
      var wD = (*motion)[3].z;
      vA = vA + (m.x * impulse.x) * r0.xy;
      wA = wA + m.y * impulse.x * r3.x;
      vB = vB + (m.z * impulse.x) * r0.zw;
      wB = wB + m.w * impulse.x * r3.y;
      vC = vC - (mCD.x * impulse.x) * r0.xy;
      wC = wC - mCD.y * impulse.x * r3.z;
      vD = vD - (mCD.z * impulse.x) * r0.zw;
      wD = wD - mCD.w * impulse.x * r3.w;
      (*motion)[2] = vec4<f32>(vC, wC, (*motion)[2].w);
      (*motion)[3] = vec4<f32>(vD, wD, (*motion)[3].w);
    }
    case WHEEL_JOINT: {
      let P = impulse.x * r0.zw + impulse.y * r0.xy;
      let LA = impulse.x * r3.z + impulse.y * r3.x + impulse.z;
      let LB = impulse.x * r3.w + impulse.y * r3.y + impulse.z;
      vA = vA - m.x * P;
      wA = wA - m.y * LA;
      vB = vB + m.z * P;
      wB = wB + m.w * LB;
    }
    case WELD_JOINT, FRICTION_JOINT: {
      let P = impulse.xy;
      vA = vA - m.x * P;
      wA = wA - m.y * (cross2(r0.xy, P) + impulse.z);
      vB = vB + m.z * P;
      wB = wB + m.w * (cross2(r0.zw, P) + impulse.z);
    }
    default: {}
  }
  (*motion)[0] = vec4<f32>(vA, wA, (*motion)[0].w);
  (*motion)[1] = vec4<f32>(vB, wB, (*motion)[1].w);
}

// SolveVelocityConstraints.
fn joint_velocity(j: u32, kind: u32, limitState: u32, motion: ptr<function, Motion>) {
  let base = JOINT_VEC4 * j;
  let p = JOINT_PARAMS_VEC4 * j;
  let r0 = jointConstraints[base];
  let rA = r0.xy;
  let rB = r0.zw;
  let m = jointConstraints[base + 1u];
  let mA = m.x;
  let iA = m.y;
  let mB = m.z;
  let iB = m.w;
  var impulse = jointConstraints[base + 2u];
  let r3 = jointConstraints[base + 3u];
  let r4 = jointConstraints[base + 4u];
  let r5 = jointConstraints[base + 5u];
  var vA = (*motion)[0].xy;
  var wA = (*motion)[0].z;
  var vB = (*motion)[1].xy;
  var wB = (*motion)[1].z;
  let h = params.h;
  switch kind {
    case REVOLUTE_JOINT: {
      let p1 = jointParams[p + 1u];
      let p2 = jointParams[p + 2u];
      let fixedRotation = (iA + iB == 0.0);
      if (p2.z != 0.0 && limitState != EQUAL_LIMITS && !fixedRotation) {
        let Cdot = wB - wA - p2.x;
        var motor = -r4.z * Cdot;
        let oldImpulse = impulse.w;
        let maxImpulse = h * p1.w;
        impulse.w = clamp(impulse.w + motor, -maxImpulse, maxImpulse);
        motor = impulse.w - oldImpulse;
        wA = wA - iA * motor;
        wB = wB + iB * motor;
      }
      // The mass matrix: ex = (exx, eyx, ezx), ey = (eyx, eyy, ezy), ez = (ezx, ezy, ezz).
      let ex = vec3<f32>(r3.x, r3.y, r3.z);
      let ey = vec3<f32>(r3.y, r3.w, r4.x);
      let ez = vec3<f32>(r3.z, r4.x, r4.y);
      if (p2.y != 0.0 && limitState != INACTIVE_LIMIT && !fixedRotation) {
        let Cdot1 = vB + cross_sv(wB, rB) - vA - cross_sv(wA, rA);
        let Cdot2 = wB - wA;
        var lambda = -solve33(ex, ey, ez, vec3<f32>(Cdot1, Cdot2));
        if (limitState == EQUAL_LIMITS) {
          impulse = vec4<f32>(impulse.xyz + lambda, impulse.w);
        } else {
          let newImpulse = impulse.z + lambda.z;
          if ((limitState == AT_LOWER_LIMIT && newImpulse < 0.0) || (limitState == AT_UPPER_LIMIT && newImpulse > 0.0)) {
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
    }
    case PRISMATIC_JOINT: {
      let p1 = jointParams[p + 1u];
      let p2 = jointParams[p + 2u];
      let axis = r0.xy;
      let perp = r0.zw;
      let s1 = r3.x;
      let s2 = r3.y;
      let a1 = r3.z;
      let a2 = r3.w;
      if (p2.z != 0.0 && limitState != EQUAL_LIMITS) {
        let Cdot = dot(axis, vB - vA) + a2 * wB - a1 * wA;
        var motor = r5.z * (p2.x - Cdot);
        let oldImpulse = impulse.w;
        let maxImpulse = h * p1.w;
        impulse.w = clamp(impulse.w + motor, -maxImpulse, maxImpulse);
        motor = impulse.w - oldImpulse;
        let P = motor * axis;
        vA = vA - mA * P;
        wA = wA - iA * (motor * a1);
        vB = vB + mB * P;
        wB = wB + iB * (motor * a2);
      }
      let Cdot1 = vec2<f32>(dot(perp, vB - vA) + s2 * wB - s1 * wA, wB - wA);
      // K: ex = (k11, k12, k13), ey = (k12, k22, k23), ez = (k13, k23, k33).
      let ex = vec3<f32>(r4.x, r4.y, r4.z);
      let ey = vec3<f32>(r4.y, r4.w, r5.x);
      let ez = vec3<f32>(r4.z, r5.x, r5.y);
      var df: vec3<f32>;
      if (p2.y != 0.0 && limitState != INACTIVE_LIMIT) {
        let Cdot2 = dot(axis, vB - vA) + a2 * wB - a1 * wA;
        let f1 = impulse.xyz;
        var f = f1 + solve33(ex, ey, ez, -vec3<f32>(Cdot1, Cdot2));
        if (limitState == AT_LOWER_LIMIT) {
          f.z = max(f.z, 0.0);
        } else if (limitState == AT_UPPER_LIMIT) {
          f.z = min(f.z, 0.0);
        }
        let b = -Cdot1 - (f.z - f1.z) * vec2<f32>(ez.x, ez.y);
        let f2r = solve22(ex.x, ey.x, ex.y, ey.y, b) + f1.xy;
        f = vec3<f32>(f2r, f.z);
        df = f - f1;
        impulse = vec4<f32>(f, impulse.w);
      } else {
        let d2 = solve22(ex.x, ey.x, ex.y, ey.y, -Cdot1);
        impulse = vec4<f32>(impulse.xy + d2, impulse.zw);
        df = vec3<f32>(d2, 0.0);
      }
      let P = df.x * perp + df.z * axis;
      let LA = df.x * s1 + df.y + df.z * a1;
      let LB = df.x * s2 + df.y + df.z * a2;
      vA = vA - mA * P;
      wA = wA - iA * LA;
      vB = vB + mB * P;
      wB = wB + iB * LB;
    }
    case DISTANCE_JOINT: {
      let u = r3.xy;
      let vpA = vA + cross_sv(wA, rA);
      let vpB = vB + cross_sv(wB, rB);
      let Cdot = dot(u, vpB - vpA);
      let lambda = -r3.z * (Cdot + r4.x + r3.w * impulse.x);
      impulse.x = impulse.x + lambda;
      let P = lambda * u;
      vA = vA - mA * P;
      wA = wA - iA * cross2(rA, P);
      vB = vB + mB * P;
      wB = wB + iB * cross2(rB, P);
    }
    case PULLEY_JOINT: {
      let vpA = vA + cross_sv(wA, rA);
      let vpB = vB + cross_sv(wB, rB);
      let ratio = r4.y;
      let Cdot = -dot(r3.xy, vpA) - ratio * dot(r3.zw, vpB);
      let lambda = -r4.x * Cdot;
      impulse.x = impulse.x + lambda;
      let PA = -lambda * r3.xy;
      let PB = -ratio * lambda * r3.zw;
      vA = vA + mA * PA;
      wA = wA + iA * cross2(rA, PA);
      vB = vB + mB * PB;
      wB = wB + iB * cross2(rB, PB);
    }
    case MOUSE_JOINT: {
      let maxForce = jointParams[p + 1u].z;
      let Cdot = vB + cross_sv(wB, rB);
      let old = impulse.xy;
      var acc = old + mul22(r3, -(Cdot + r4.xy + r4.z * old));
      let maxImpulse = h * maxForce;
      if (dot(acc, acc) > maxImpulse * maxImpulse) {
        acc = acc * (maxImpulse / length(acc));
      }
      let lambda = acc - old;
      impulse = vec4<f32>(acc, impulse.zw);
      vB = vB + mB * lambda;
      wB = wB + iB * cross2(rB, lambda);
    }
    case GEAR_JOINT: {
      let mCD = r4;
      var vC = (*motion)[2].xy;
      var wC = (*motion)[2].z;
      var vD = (*motion)[3].xy;
      var wD = (*motion)[3].z;
      let JvAC = r0.xy;
      let JvBD = r0.zw;
      var Cdot = dot(JvAC, vA - vC) + dot(JvBD, vB - vD);
      Cdot = Cdot + ((r3.x * wA - r3.z * wC) + (r3.y * wB - r3.w * wD));
      let lambda = -jointConstraints[base + 8u].x * Cdot;
      impulse.x = impulse.x + lambda;
      vA = vA + (mA * lambda) * JvAC;
      wA = wA + iA * lambda * r3.x;
      vB = vB + (mB * lambda) * JvBD;
      wB = wB + iB * lambda * r3.y;
      vC = vC - (mCD.x * lambda) * JvAC;
      wC = wC - mCD.y * lambda * r3.z;
      vD = vD - (mCD.z * lambda) * JvBD;
      wD = wD - mCD.w * lambda * r3.w;
      (*motion)[2] = vec4<f32>(vC, wC, (*motion)[2].w);
      (*motion)[3] = vec4<f32>(vD, wD, (*motion)[3].w);
    }
    case WHEEL_JOINT: {
      let p1 = jointParams[p + 1u];
      let p2 = jointParams[p + 2u];
      let ax = r0.xy;
      let ay = r0.zw;
      // The spring.
      {
        let Cdot = dot(ax, vB - vA) + r3.y * wB - r3.x * wA;
        let lambda = -r4.z * (Cdot + r4.w + r5.x * impulse.y);
        impulse.y = impulse.y + lambda;
        let P = lambda * ax;
        vA = vA - mA * P;
        wA = wA - iA * (lambda * r3.x);
        vB = vB + mB * P;
        wB = wB + iB * (lambda * r3.y);
      }
      // The motor (motorMass is 0 when it is off).
      {
        let Cdot = wB - wA - p2.x;
        var lambda = -r4.y * Cdot;
        let oldImpulse = impulse.z;
        let maxImpulse = h * p1.w;
        impulse.z = clamp(impulse.z + lambda, -maxImpulse, maxImpulse);
        lambda = impulse.z - oldImpulse;
        wA = wA - iA * lambda;
        wB = wB + iB * lambda;
      }
      // The point to line constraint.
      {
        let Cdot = dot(ay, vB - vA) + r3.w * wB - r3.z * wA;
        let lambda = -r4.x * Cdot;
        impulse.x = impulse.x + lambda;
        let P = lambda * ay;
        vA = vA - mA * P;
        wA = wA - iA * (lambda * r3.z);
        vB = vB + mB * P;
        wB = wB + iB * (lambda * r3.w);
      }
    }
    case WELD_JOINT: {
      // The inverse mass matrix: ex = (r3.x, r3.y, r3.z), ey = (r3.y, r3.w, r4.x), ez = (r3.z, r4.x, r4.y).
      if (jointParams[p + 1u].y > 0.0) {
        let Cdot2 = wB - wA;
        let impulse2 = -r4.y * (Cdot2 + r4.w + r4.z * impulse.z);
        impulse.z = impulse.z + impulse2;
        wA = wA - iA * impulse2;
        wB = wB + iB * impulse2;
        let Cdot1 = vB + cross_sv(wB, rB) - vA - cross_sv(wA, rA);
        let impulse1 = -vec2<f32>(r3.x * Cdot1.x + r3.y * Cdot1.y, r3.y * Cdot1.x + r3.w * Cdot1.y);
        impulse = vec4<f32>(impulse.xy + impulse1, impulse.zw);
        vA = vA - mA * impulse1;
        wA = wA - iA * cross2(rA, impulse1);
        vB = vB + mB * impulse1;
        wB = wB + iB * cross2(rB, impulse1);
      } else {
        let Cdot1 = vB + cross_sv(wB, rB) - vA - cross_sv(wA, rA);
        let Cdot2 = wB - wA;
        let ex = vec3<f32>(r3.x, r3.y, r3.z);
        let ey = vec3<f32>(r3.y, r3.w, r4.x);
        let ez = vec3<f32>(r3.z, r4.x, r4.y);
        let lambda = -(ex * Cdot1.x + ey * Cdot1.y + ez * Cdot2);
        impulse = vec4<f32>(impulse.xyz + lambda, impulse.w);
        let P = lambda.xy;
        vA = vA - mA * P;
        wA = wA - iA * (cross2(rA, P) + lambda.z);
        vB = vB + mB * P;
        wB = wB + iB * (cross2(rB, P) + lambda.z);
      }
    }
    case FRICTION_JOINT: {
      let p1 = jointParams[p + 1u];
      {
        let Cdot = wB - wA;
        var lambda = -r4.x * Cdot;
        let oldImpulse = impulse.z;
        let maxImpulse = h * p1.y;
        impulse.z = clamp(impulse.z + lambda, -maxImpulse, maxImpulse);
        lambda = impulse.z - oldImpulse;
        wA = wA - iA * lambda;
        wB = wB + iB * lambda;
      }
      {
        let Cdot = vB + cross_sv(wB, rB) - vA - cross_sv(wA, rA);
        let old = impulse.xy;
        var acc = old - mul22(r3, Cdot);
        let maxImpulse = h * p1.x;
        if (dot(acc, acc) > maxImpulse * maxImpulse) {
          acc = normalize2(acc) * maxImpulse;
        }
        let lambda = acc - old;
        impulse = vec4<f32>(acc, impulse.zw);
        vA = vA - mA * lambda;
        wA = wA - iA * cross2(rA, lambda);
        vB = vB + mB * lambda;
        wB = wB + iB * cross2(rB, lambda);
      }
    }
    case ROPE_JOINT: {
      let u = r3.xy;
      let vpA = vA + cross_sv(wA, rA);
      let vpB = vB + cross_sv(wB, rB);
      let C = r3.w - jointParams[p + 1u].x;
      var Cdot = dot(u, vpB - vpA);
      // Predictive: the rope may close the gap to its maximum length within the step.
      if (C < 0.0) {
        Cdot = Cdot + (1.0 / h) * C;
      }
      var lambda = -r3.z * Cdot;
      let oldImpulse = impulse.x;
      impulse.x = min(0.0, impulse.x + lambda);
      lambda = impulse.x - oldImpulse;
      let P = lambda * u;
      vA = vA - mA * P;
      wA = wA - iA * cross2(rA, P);
      vB = vB + mB * P;
      wB = wB + iB * cross2(rB, P);
    }
    default: {}
  }
  jointConstraints[base + 2u] = impulse;
  (*motion)[0] = vec4<f32>(vA, wA, (*motion)[0].w);
  (*motion)[1] = vec4<f32>(vB, wB, (*motion)[1].w);
}

// SolvePositionConstraints; returns its "within slop" result (2.2.1's jointsOkay terms).
fn joint_position(j: u32, kind: u32, limitState: u32, motion: ptr<function, Motion>) -> bool {
  if (kind == MOUSE_JOINT || kind == FRICTION_JOINT) {
    return true;
  }
  let base = JOINT_VEC4 * j;
  let p = JOINT_PARAMS_VEC4 * j;
  let m = jointConstraints[base + 1u];
  let mA = m.x;
  let iA = m.y;
  let mB = m.z;
  let iB = m.w;
  let anchors = jointConstraints[base + 6u];
  let cells = jointConstraints[base + 7u];
  let p1 = jointParams[p + 1u];
  var cA = (*motion)[0].xy;
  var aA = (*motion)[0].z;
  var cB = (*motion)[1].xy + cells.xy;
  var aB = (*motion)[1].z;
  var okay = true;
  switch kind {
    case REVOLUTE_JOINT: {
      let p2 = jointParams[p + 2u];
      var angularError = 0.0;
      if (p2.y != 0.0 && limitState != INACTIVE_LIMIT && iA + iB != 0.0) {
        let angle = aB - aA - p1.x;
        var limitImpulse = 0.0;
        let motorMass = jointConstraints[base + 4u].z;
        if (limitState == EQUAL_LIMITS) {
          let C = clamp(angle - p1.y, -MAX_ANGULAR_CORRECTION, MAX_ANGULAR_CORRECTION);
          limitImpulse = -motorMass * C;
          angularError = abs(C);
        } else if (limitState == AT_LOWER_LIMIT) {
          var C = angle - p1.y;
          angularError = -C;
          C = clamp(C + ANGULAR_SLOP, -MAX_ANGULAR_CORRECTION, 0.0);
          limitImpulse = -motorMass * C;
        } else {
          var C = angle - p1.z;
          angularError = C;
          C = clamp(C - ANGULAR_SLOP, 0.0, MAX_ANGULAR_CORRECTION);
          limitImpulse = -motorMass * C;
        }
        aA = aA - iA * limitImpulse;
        aB = aB + iB * limitImpulse;
      }
      let rA = rotate(rot(aA), anchors.xy);
      let rB = rotate(rot(aB), anchors.zw);
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
      okay = positionError <= LINEAR_SLOP && angularError <= ANGULAR_SLOP;
    }
    case PRISMATIC_JOINT: {
      let p2 = jointParams[p + 2u];
      let axes = jointParams[p + 3u];
      let qA = rot(aA);
      let rA = rotate(qA, anchors.xy);
      let rB = rotate(rot(aB), anchors.zw);
      let d = cB + rB - cA - rA;
      let axis = rotate(qA, axes.xy);
      let a1 = cross2(d + rA, axis);
      let a2 = cross2(rB, axis);
      let perp = rotate(qA, axes.zw);
      let s1 = cross2(d + rA, perp);
      let s2 = cross2(rB, perp);
      let C1 = vec2<f32>(dot(perp, d), aB - aA - p1.x);
      var linearError = abs(C1.x);
      let angularError = abs(C1.y);
      var limitActive = false;
      var C2 = 0.0;
      if (p2.y != 0.0) {
        let translation = dot(axis, d);
        if (abs(p1.z - p1.y) < 2.0 * LINEAR_SLOP) {
          C2 = clamp(translation, -MAX_LINEAR_CORRECTION, MAX_LINEAR_CORRECTION);
          linearError = max(linearError, abs(translation));
          limitActive = true;
        } else if (translation <= p1.y) {
          C2 = clamp(translation - p1.y + LINEAR_SLOP, -MAX_LINEAR_CORRECTION, 0.0);
          linearError = max(linearError, p1.y - translation);
          limitActive = true;
        } else if (translation >= p1.z) {
          C2 = clamp(translation - p1.z - LINEAR_SLOP, 0.0, MAX_LINEAR_CORRECTION);
          linearError = max(linearError, translation - p1.z);
          limitActive = true;
        }
      }
      let k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
      let k12 = iA * s1 + iB * s2;
      var k22 = iA + iB;
      if (k22 == 0.0) {
        k22 = 1.0;
      }
      var lambda: vec3<f32>;
      if (limitActive) {
        let k13 = iA * s1 * a1 + iB * s2 * a2;
        let k23 = iA * a1 + iB * a2;
        let k33 = mA + mB + iA * a1 * a1 + iB * a2 * a2;
        lambda = solve33(vec3<f32>(k11, k12, k13), vec3<f32>(k12, k22, k23), vec3<f32>(k13, k23, k33), -vec3<f32>(C1, C2));
      } else {
        lambda = vec3<f32>(solve22(k11, k12, k12, k22, -C1), 0.0);
      }
      let P = lambda.x * perp + lambda.z * axis;
      let LA = lambda.x * s1 + lambda.y + lambda.z * a1;
      let LB = lambda.x * s2 + lambda.y + lambda.z * a2;
      cA = cA - mA * P;
      aA = aA - iA * LA;
      cB = cB + mB * P;
      aB = aB + iB * LB;
      okay = linearError <= LINEAR_SLOP && angularError <= ANGULAR_SLOP;
    }
    case DISTANCE_JOINT: {
      // A soft distance joint has no position constraint.
      if (p1.y > 0.0) {
        return true;
      }
      let rA = rotate(rot(aA), anchors.xy);
      let rB = rotate(rot(aB), anchors.zw);
      var u = cB + rB - cA - rA;
      // b2Vec2::Normalize: the length (0 when shorter than b2_epsilon, u then unchanged).
      let len = select(0.0, length(u), length(u) >= S_EPSILON);
      u = normalize2(u);
      let C = clamp(len - p1.x, -MAX_LINEAR_CORRECTION, MAX_LINEAR_CORRECTION);
      let P = (-jointConstraints[base + 3u].z * C) * u;
      cA = cA - mA * P;
      aA = aA - iA * cross2(rA, P);
      cB = cB + mB * P;
      aB = aB + iB * cross2(rB, P);
      okay = abs(C) < LINEAR_SLOP;
    }
    case PULLEY_JOINT: {
      let ground = jointConstraints[base + 5u];
      let rA = rotate(rot(aA), anchors.xy);
      let rB = rotate(rot(aB), anchors.zw);
      var uA = cA + rA - ground.xy;
      var uB = cB + rB - ground.zw;
      let lengthA = length(uA);
      let lengthB = length(uB);
      uA = select(vec2<f32>(0.0), uA * (1.0 / lengthA), lengthA > 10.0 * LINEAR_SLOP);
      uB = select(vec2<f32>(0.0), uB * (1.0 / lengthB), lengthB > 10.0 * LINEAR_SLOP);
      let ruA = cross2(rA, uA);
      let ruB = cross2(rB, uB);
      let ratio = p1.z;
      var mass = (mA + iA * ruA * ruA) + ratio * ratio * (mB + iB * ruB * ruB);
      if (mass > 0.0) {
        mass = 1.0 / mass;
      }
      let C = p1.w - lengthA - ratio * lengthB;
      let lambda = -mass * C;
      let PA = -lambda * uA;
      let PB = -ratio * lambda * uB;
      cA = cA + mA * PA;
      aA = aA + iA * cross2(rA, PA);
      cB = cB + mB * PB;
      aB = aB + iB * cross2(rB, PB);
      okay = abs(C) < LINEAR_SLOP;
    }
    case GEAR_JOINT: {
      // A and C in A's cell, B and D in B's cell: the two halves never mix positions.
      cB = (*motion)[1].xy;
      var cC = (*motion)[2].xy + cells.xy;
      var aC = (*motion)[2].z;
      var cD = (*motion)[3].xy + cells.zw;
      var aD = (*motion)[3].z;
      let mCD = jointConstraints[base + 4u];
      let localCD = jointConstraints[base + 5u];
      let axes = jointParams[p + 3u];
      let types = bitcast<vec2<u32>>(jointParams[p + 4u].zw);
      let ratio = p1.z;
      var JvAC = vec2<f32>(0.0);
      var JvBD = vec2<f32>(0.0);
      var JwA: f32;
      var JwB: f32;
      var JwC: f32;
      var JwD: f32;
      var mass = 0.0;
      var coordinateA: f32;
      var coordinateB: f32;
      if (types.x == REVOLUTE_JOINT) {
        JwA = 1.0;
        JwC = 1.0;
        mass = mass + iA + mCD.y;
        coordinateA = aA - aC - p1.x;
      } else {
        let qC = rot(aC);
        let u = rotate(qC, axes.xy);
        let rC = rotate(qC, localCD.xy);
        let rA = rotate(rot(aA), anchors.xy);
        JvAC = u;
        JwC = cross2(rC, u);
        JwA = cross2(rA, u);
        mass = mass + mCD.x + mA + mCD.y * JwC * JwC + iA * JwA * JwA;
        let pA = rotate_t(qC, rA + (cA - cC));
        coordinateA = dot(pA - localCD.xy, axes.xy);
      }
      if (types.y == REVOLUTE_JOINT) {
        JwB = ratio;
        JwD = ratio;
        mass = mass + ratio * ratio * (iB + mCD.w);
        coordinateB = aB - aD - p1.y;
      } else {
        let qD = rot(aD);
        let u = rotate(qD, axes.zw);
        let rD = rotate(qD, localCD.zw);
        let rB = rotate(rot(aB), anchors.zw);
        JvBD = ratio * u;
        JwD = ratio * cross2(rD, u);
        JwB = ratio * cross2(rB, u);
        mass = mass + ratio * ratio * (mCD.z + mB) + mCD.w * JwD * JwD + iB * JwB * JwB;
        let pB = rotate_t(qD, rB + (cB - cD));
        coordinateB = dot(pB - localCD.zw, axes.zw);
      }
      let C = (coordinateA + ratio * coordinateB) - p1.w;
      let lambda = select(0.0, -C / mass, mass > 0.0);
      cA = cA + mA * lambda * JvAC;
      aA = aA + iA * lambda * JwA;
      cB = cB + mB * lambda * JvBD;
      aB = aB + iB * lambda * JwB;
      cC = cC - mCD.x * lambda * JvAC;
      aC = aC - mCD.y * lambda * JwC;
      cD = cD - mCD.z * lambda * JvBD;
      aD = aD - mCD.w * lambda * JwD;
      (*motion)[0] = vec4<f32>(cA, aA, (*motion)[0].w);
      (*motion)[1] = vec4<f32>(cB, aB, (*motion)[1].w);
      (*motion)[2] = vec4<f32>(cC - cells.xy, aC, (*motion)[2].w);
      (*motion)[3] = vec4<f32>(cD - cells.zw, aD, (*motion)[3].w);
      // 2.2.1 reports a gear as always within slop (its linear error is never computed).
      return true;
    }
    case WHEEL_JOINT: {
      let r3 = jointConstraints[base + 3u];
      let qA = rot(aA);
      let rA = rotate(qA, anchors.xy);
      let rB = rotate(rot(aB), anchors.zw);
      let d = (cB - cA) + rB - rA;
      let ay = rotate(qA, jointParams[p + 3u].zw);
      let sAy = cross2(d + rA, ay);
      let sBy = cross2(rB, ay);
      let C = dot(d, ay);
      // 2.2.1 takes the effective mass from the velocity step's sAy, sBy (m_sAy, m_sBy).
      let k = mA + mB + iA * r3.z * r3.z + iB * r3.w * r3.w;
      let lambda = select(0.0, -C / k, k != 0.0);
      let P = lambda * ay;
      cA = cA - mA * P;
      aA = aA - iA * (lambda * sAy);
      cB = cB + mB * P;
      aB = aB + iB * (lambda * sBy);
      okay = abs(C) <= LINEAR_SLOP;
    }
    case WELD_JOINT: {
      let rA = rotate(rot(aA), anchors.xy);
      let rB = rotate(rot(aB), anchors.zw);
      let ex = vec3<f32>(mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB, -rA.y * rA.x * iA - rB.y * rB.x * iB, -rA.y * iA - rB.y * iB);
      let ey = vec3<f32>(ex.y, mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB, rA.x * iA + rB.x * iB);
      let ez = vec3<f32>(ex.z, ey.z, iA + iB);
      let C1 = cB + rB - cA - rA;
      let positionError = length(C1);
      var angularError = 0.0;
      var lambda: vec3<f32>;
      if (p1.y > 0.0) {
        lambda = vec3<f32>(-solve22(ex.x, ey.x, ex.y, ey.y, C1), 0.0);
      } else {
        let C2 = aB - aA - p1.x;
        angularError = abs(C2);
        lambda = -solve33(ex, ey, ez, vec3<f32>(C1, C2));
      }
      let P = lambda.xy;
      cA = cA - mA * P;
      aA = aA - iA * (cross2(rA, P) + lambda.z);
      cB = cB + mB * P;
      aB = aB + iB * (cross2(rB, P) + lambda.z);
      okay = positionError <= LINEAR_SLOP && angularError <= ANGULAR_SLOP;
    }
    case ROPE_JOINT: {
      let rA = rotate(rot(aA), anchors.xy);
      let rB = rotate(rot(aB), anchors.zw);
      var u = cB + rB - cA - rA;
      let len = select(0.0, length(u), length(u) >= S_EPSILON);
      u = normalize2(u);
      let C = clamp(len - p1.x, 0.0, MAX_LINEAR_CORRECTION);
      let P = (-jointConstraints[base + 3u].z * C) * u;
      cA = cA - mA * P;
      aA = aA - iA * cross2(rA, P);
      cB = cB + mB * P;
      aB = aB + iB * cross2(rB, P);
      okay = len - p1.x < LINEAR_SLOP;
    }
    default: {}
  }
  (*motion)[0] = vec4<f32>(cA, aA, (*motion)[0].w);
  (*motion)[1] = vec4<f32>(cB - cells.xy, aB, (*motion)[1].w);
  return okay;
}

