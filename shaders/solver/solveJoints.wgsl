// solveJoints.wgsl: the joints' per-step records, 2.2.1's InitVelocityConstraints of the ten joint
// types up to the warm start (which solveJointsCommon.wgsl's joint_warm_start does in the colour
// passes), in float32, and the impulses stored for the next step.
//
// In:  params (h, dtRatio, warmStarting, cellSize, joint slots), joints (bodies A, B, type,
//      JOINT_LIVE), jointParams (src-gpu/device/layout.ts), jointState (impulses and limit state
//      carried from the previous step), bodyFlags, bodyAwake (after the islands stage), bodyMass,
//      bodySweep, bodyCell, solverState (SV_SKIP).
// Out: `bodies` (per joint slot, before the colouring): jointBodies (bodies A, B, and a gear's C,
//      D; type, which are dynamic, whether the joint is solved: live, every body active, and no
//      dynamic body asleep, as 2.2.1 solves only awake islands' joints),
//      jointConstraints rows 1 and 4 (a gear's C, D) with the inverse masses.
//      `prepare` (per joint slot): the rest of jointConstraints (solveJointsCommon.wgsl lists the
//      rows): anchors, axes, effective masses, springs' gamma and bias, the limit state with its
//      impulse resets, the impulses x dtRatio (or zero), as InitVelocityConstraints leaves them
//      before it touches the velocities.
//      `store` (per joint slot): the impulses and limit state into jointState for the next step.
// Invariants: each invocation writes only its own joint's records. Only dynamic bodies (inverse
//      mass > 0) are marked for writing; a mouse joint never writes body A (2.2.1 ignores it).
//      Positions are taken in body A's cell (B + (cellB - cellA) x cellSize); a gear's C in A's
//      cell and D in B's; world points (pulley ground anchors, the mouse target) arrive as a
//      cell and an offset and are taken into the cell of the body they pull.

@group(0) @binding(1) var<storage, read> solverState: array<u32>;
@group(0) @binding(2) var<storage, read> joints: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read_write> jointState: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read> bodyAwake: array<u32>;
@group(0) @binding(6) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(7) var<storage, read> bodyMass: array<vec4<f32>>;
@group(0) @binding(8) var<storage, read> bodySweep: array<vec4<f32>>;
@group(0) @binding(3) var<storage, read> bodyCell: array<vec2<i32>>;

fn body_active(body: u32) -> bool {
  let flags = bodyFlags[body];
  return (flags & BODY_LIVE) != 0u && (flags & BODY_ACTIVE) != 0u;
}

fn joint_slot(wid: vec3<u32>, nwg: vec3<u32>, lid: u32) -> u32 {
  let j = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  return select(j, NO_BODY, j >= params.jointSlots);
}

@compute @workgroup_size(256)
fn bodies(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
          @builtin(local_invocation_index) lid: u32) {
  let j = joint_slot(wid, nwg, lid);
  if (j == NO_BODY) {
    return;
  }
  let joint = joints[j];
  var list = vec4<u32>(joint.x, joint.y, NO_BODY, NO_BODY);
  var count = 2u;
  if (joint.z == GEAR_JOINT) {
    let gear = bitcast<vec2<u32>>(jointParams[JOINT_PARAMS_VEC4 * j + 4u].xy);
    list = vec4<u32>(joint.x, joint.y, gear.x, gear.y);
    count = 4u;
  }
  var solved = (joint.w & JOINT_LIVE) != 0u;
  var dynamic = 0u;
  var masses = array<vec4<f32>, 4>();
  for (var i = 0u; i < count && solved; i = i + 1u) {
    solved = body_active(list[i]);
    masses[i] = bodyMass[list[i]];
    if (masses[i].x > 0.0) {
      dynamic = dynamic | (1u << i);
      solved = solved && bodyAwake[list[i]] != 0u;
    }
  }
  // A joint not solved this step writes nothing, so it blocks no colour.
  if (!solved) {
    dynamic = 0u;
  }
  if (joint.z == MOUSE_JOINT) {
    dynamic = dynamic & ~1u;
    masses[0] = vec4<f32>(0.0);
  }
  jointBodies[2u * j] = list;
  jointBodies[2u * j + 1u] = vec4<u32>(joint.z, dynamic, select(0u, 1u, solved), INACTIVE_LIMIT);
  let base = JOINT_VEC4 * j;
  jointConstraints[base + 1u] = vec4<f32>(masses[0].xy, masses[1].xy);
  jointConstraints[base + 4u] = vec4<f32>(masses[2].xy, masses[3].xy);
}

// A world point sent as (cell, offset) (src-gpu/world/world.ts), in the given cell.
fn world_point(cell: vec2<f32>, offset: vec2<f32>, inCell: vec2<i32>) -> vec2<f32> {
  return vec2<f32>(bitcast<vec2<i32>>(cell) - inCell) * params.cellSize + offset;
}

@compute @workgroup_size(256)
fn prepare(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
           @builtin(local_invocation_index) lid: u32) {
  let j = joint_slot(wid, nwg, lid);
  if (j == NO_BODY) {
    return;
  }
  let list = jointBodies[2u * j];
  let info = jointBodies[2u * j + 1u];
  if (info.z == 0u) {
    return;
  }
  let kind = info.x;
  let base = JOINT_VEC4 * j;
  let p = JOINT_PARAMS_VEC4 * j;
  let p0 = jointParams[p];
  let p1 = jointParams[p + 1u];
  let p2 = jointParams[p + 2u];
  let p3 = jointParams[p + 3u];
  let m = jointConstraints[base + 1u];
  let mA = m.x;
  let iA = m.y;
  let mB = m.z;
  let iB = m.w;
  let massA = bodyMass[list.x];
  let massB = bodyMass[list.y];
  let cellA = bodyCell[list.x];
  let cellDelta = vec2<f32>(bodyCell[list.y] - cellA) * params.cellSize;
  let sweepA = bodySweep[2u * list.x + 1u];
  let sweepB = bodySweep[2u * list.y + 1u];
  let cA = sweepA.xy;
  let aA = sweepA.z;
  let cB = sweepB.xy + cellDelta;
  let aB = sweepB.z;
  let qA = rot(aA);
  let qB = rot(aB);
  let lA = p0.xy - massA.zw;
  let lB = p0.zw - massB.zw;
  let rA = rotate(qA, lA);
  let rB = rotate(qB, lB);
  let h = params.h;
  var state = jointState[2u * j];
  var limitState = u32(jointState[2u * j + 1u].x);
  var r0 = vec4<f32>(rA, rB);
  var r3 = vec4<f32>(0.0);
  var r4 = jointConstraints[base + 4u];
  var r5 = vec4<f32>(0.0);
  var r7 = vec4<f32>(cellDelta, 0.0, 0.0);
  var r8 = vec4<f32>(0.0);
  // Whether the impulses are applied at all (a slack rope's are not, as 2.2.1 returns early), and
  // their scale.
  var warm = params.warmStarting != 0u;
  var scale = params.dtRatio;

  switch kind {
    case REVOLUTE_JOINT: {
      let fixedRotation = (iA + iB == 0.0);
      r3 = vec4<f32>(mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB, -rA.y * rA.x * iA - rB.y * rB.x * iB,
                     -rA.y * iA - rB.y * iB, mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB);
      var motorMass = iA + iB;
      if (motorMass > 0.0) {
        motorMass = 1.0 / motorMass;
      }
      r4 = vec4<f32>(rA.x * iA + rB.x * iB, iA + iB, motorMass, 0.0);
      if (p2.z == 0.0 || fixedRotation) {
        state.w = 0.0;
      }
      if (p2.y != 0.0 && !fixedRotation) {
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
    }
    case PRISMATIC_JOINT: {
      let d = (cB - cA) + rB - rA;
      let axis = rotate(qA, p3.xy);
      let a1 = cross2(d + rA, axis);
      let a2 = cross2(rB, axis);
      var motorMass = mA + mB + iA * a1 * a1 + iB * a2 * a2;
      if (motorMass > 0.0) {
        motorMass = 1.0 / motorMass;
      }
      let perp = rotate(qA, p3.zw);
      let s1 = cross2(d + rA, perp);
      let s2 = cross2(rB, perp);
      let k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
      let k12 = iA * s1 + iB * s2;
      let k13 = iA * s1 * a1 + iB * s2 * a2;
      var k22 = iA + iB;
      if (k22 == 0.0) {
        k22 = 1.0;
      }
      let k23 = iA * a1 + iB * a2;
      let k33 = mA + mB + iA * a1 * a1 + iB * a2 * a2;
      r0 = vec4<f32>(axis, perp);
      r3 = vec4<f32>(s1, s2, a1, a2);
      r4 = vec4<f32>(k11, k12, k13, k22);
      r5 = vec4<f32>(k23, k33, motorMass, 0.0);
      if (p2.y != 0.0) {
        let jointTranslation = dot(axis, d);
        if (abs(p1.z - p1.y) < 2.0 * LINEAR_SLOP) {
          limitState = EQUAL_LIMITS;
        } else if (jointTranslation <= p1.y) {
          if (limitState != AT_LOWER_LIMIT) {
            limitState = AT_LOWER_LIMIT;
            state.z = 0.0;
          }
        } else if (jointTranslation >= p1.z) {
          if (limitState != AT_UPPER_LIMIT) {
            limitState = AT_UPPER_LIMIT;
            state.z = 0.0;
          }
        } else {
          limitState = INACTIVE_LIMIT;
          state.z = 0.0;
        }
      } else {
        limitState = INACTIVE_LIMIT;
        state.z = 0.0;
      }
      if (p2.z == 0.0) {
        state.w = 0.0;
      }
    }
    case DISTANCE_JOINT: {
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
        gamma = h * (d + h * k);
        gamma = select(0.0, 1.0 / gamma, gamma != 0.0);
        bias = C * h * k * gamma;
        invMass = invMass + gamma;
        mass = select(0.0, 1.0 / invMass, invMass != 0.0);
      }
      state = vec4<f32>(state.x, 0.0, 0.0, 0.0);
      r3 = vec4<f32>(u, mass, gamma);
      r4 = vec4<f32>(bias, 0.0, 0.0, 0.0);
      limitState = INACTIVE_LIMIT;
    }
    case PULLEY_JOINT: {
      let groundA = world_point(p3.xy, p2.xy, cellA);
      let groundB = world_point(p3.zw, p2.zw, cellA);
      var uA = cA + rA - groundA;
      var uB = cB + rB - groundB;
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
      state = vec4<f32>(state.x, 0.0, 0.0, 0.0);
      r3 = vec4<f32>(uA, uB);
      r4 = vec4<f32>(mass, ratio, 0.0, 0.0);
      r5 = vec4<f32>(groundA, groundB);
      limitState = INACTIVE_LIMIT;
    }
    case MOUSE_JOINT: {
      // Body B only: its own cell, so the target is taken into B's cell.
      let cellB = bodyCell[list.y];
      let targetB = world_point(p3.xy, p2.xy, cellB);
      let mass = p1.w;
      let omega = 2.0 * PI * p1.x;
      let d = 2.0 * mass * p1.y * omega;
      let k = mass * (omega * omega);
      var gamma = h * (d + h * k);
      if (gamma != 0.0) {
        gamma = 1.0 / gamma;
      }
      let beta = h * k * gamma;
      let exx = mB + iB * rB.y * rB.y + gamma;
      let exy = -iB * rB.x * rB.y;
      let eyy = mB + iB * rB.x * rB.x + gamma;
      // b2Mat22::GetInverse.
      var det = exx * eyy - exy * exy;
      if (det != 0.0) {
        det = 1.0 / det;
      }
      r0 = vec4<f32>(0.0, 0.0, rB);
      r3 = vec4<f32>(det * eyy, -det * exy, -det * exy, det * exx);
      r4 = vec4<f32>((sweepB.xy + rB - targetB) * beta, gamma, 0.0);
      state = vec4<f32>(state.xy, 0.0, 0.0);
      limitState = INACTIVE_LIMIT;
    }
    case GEAR_JOINT: {
      let cellB = bodyCell[list.y];
      let massC = bodyMass[list.z];
      let massD = bodyMass[list.w];
      let mCD = r4;
      let aC = bodySweep[2u * list.z + 1u].z;
      let aD = bodySweep[2u * list.w + 1u].z;
      let types = bitcast<vec2<u32>>(jointParams[p + 4u].zw);
      let ratio = p1.z;
      let lC = p2.xy - massC.zw;
      let lD = p2.zw - massD.zw;
      var JvAC = vec2<f32>(0.0);
      var JvBD = vec2<f32>(0.0);
      var Jw = vec4<f32>(0.0);
      var mass = 0.0;
      if (types.x == REVOLUTE_JOINT) {
        Jw.x = 1.0;
        Jw.z = 1.0;
        mass = mass + iA + mCD.y;
      } else {
        let qC = rot(aC);
        let u = rotate(qC, p3.xy);
        let rC = rotate(qC, lC);
        JvAC = u;
        Jw.z = cross2(rC, u);
        Jw.x = cross2(rA, u);
        mass = mass + mCD.x + mA + mCD.y * Jw.z * Jw.z + iA * Jw.x * Jw.x;
      }
      if (types.y == REVOLUTE_JOINT) {
        Jw.y = ratio;
        Jw.w = ratio;
        mass = mass + ratio * ratio * (iB + mCD.w);
      } else {
        let qD = rot(aD);
        let u = rotate(qD, p3.zw);
        let rD = rotate(qD, lD);
        JvBD = ratio * u;
        Jw.w = ratio * cross2(rD, u);
        Jw.y = ratio * cross2(rB, u);
        mass = mass + ratio * ratio * (mCD.z + mB) + mCD.w * Jw.w * Jw.w + iB * Jw.y * Jw.y;
      }
      mass = select(0.0, 1.0 / mass, mass > 0.0);
      r0 = vec4<f32>(JvAC, JvBD);
      r3 = Jw;
      r5 = vec4<f32>(lC, lD);
      r7 = vec4<f32>(vec2<f32>(bodyCell[list.z] - cellA) * params.cellSize, vec2<f32>(bodyCell[list.w] - cellB) * params.cellSize);
      r8 = vec4<f32>(mass, 0.0, 0.0, 0.0);
      state = vec4<f32>(state.x, 0.0, 0.0, 0.0);
      // 2.2.1's b2GearJoint warm-starts with its impulse as stored, not scaled by dtRatio.
      scale = 1.0;
      limitState = INACTIVE_LIMIT;
    }
    case WHEEL_JOINT: {
      let d = cB + rB - cA - rA;
      let ay = rotate(qA, p3.zw);
      let sAy = cross2(d + rA, ay);
      let sBy = cross2(rB, ay);
      var mass = mA + mB + iA * sAy * sAy + iB * sBy * sBy;
      if (mass > 0.0) {
        mass = 1.0 / mass;
      }
      var springMass = 0.0;
      var bias = 0.0;
      var gamma = 0.0;
      var ax = vec2<f32>(0.0);
      var sAx = 0.0;
      var sBx = 0.0;
      if (p1.x > 0.0) {
        ax = rotate(qA, p3.xy);
        sAx = cross2(d + rA, ax);
        sBx = cross2(rB, ax);
        let invMass = mA + mB + iA * sAx * sAx + iB * sBx * sBx;
        if (invMass > 0.0) {
          springMass = 1.0 / invMass;
          let C = dot(d, ax);
          let omega = 2.0 * PI * p1.x;
          let dd = 2.0 * springMass * p1.y * omega;
          let k = springMass * omega * omega;
          gamma = h * (dd + h * k);
          if (gamma > 0.0) {
            gamma = 1.0 / gamma;
          }
          bias = C * h * k * gamma;
          springMass = invMass + gamma;
          if (springMass > 0.0) {
            springMass = 1.0 / springMass;
          }
        }
      } else {
        state.y = 0.0;
      }
      var motorMass = 0.0;
      if (p2.z != 0.0) {
        motorMass = iA + iB;
        if (motorMass > 0.0) {
          motorMass = 1.0 / motorMass;
        }
      } else {
        state.z = 0.0;
      }
      r0 = vec4<f32>(ax, ay);
      r3 = vec4<f32>(sAx, sBx, sAy, sBy);
      r4 = vec4<f32>(mass, motorMass, springMass, bias);
      r5 = vec4<f32>(gamma, 0.0, 0.0, 0.0);
      state.w = 0.0;
      limitState = INACTIVE_LIMIT;
    }
    case WELD_JOINT: {
      let exx = mA + mB + rA.y * rA.y * iA + rB.y * rB.y * iB;
      let eyx = -rA.y * rA.x * iA - rB.y * rB.x * iB;
      let ezx = -rA.y * iA - rB.y * iB;
      let eyy = mA + mB + rA.x * rA.x * iA + rB.x * rB.x * iB;
      let ezy = rA.x * iA + rB.x * iB;
      let ezz = iA + iB;
      if (p1.y > 0.0) {
        // b2Mat33::GetInverse22, then the soft angular row.
        var det = exx * eyy - eyx * eyx;
        if (det != 0.0) {
          det = 1.0 / det;
        }
        var invM = iA + iB;
        let mass = select(0.0, 1.0 / invM, invM > 0.0);
        let C = aB - aA - p1.x;
        let omega = 2.0 * PI * p1.y;
        let d = 2.0 * mass * p1.z * omega;
        let k = mass * omega * omega;
        var gamma = h * (d + h * k);
        gamma = select(0.0, 1.0 / gamma, gamma != 0.0);
        let bias = C * h * k * gamma;
        invM = invM + gamma;
        r3 = vec4<f32>(det * eyy, -det * eyx, 0.0, det * exx);
        r4 = vec4<f32>(0.0, select(0.0, 1.0 / invM, invM != 0.0), gamma, bias);
      } else {
        // b2Mat33::GetSymInverse33.
        var det = dot(vec3<f32>(exx, eyx, ezx), cross(vec3<f32>(eyx, eyy, ezy), vec3<f32>(ezx, ezy, ezz)));
        if (det != 0.0) {
          det = 1.0 / det;
        }
        r3 = vec4<f32>(det * (eyy * ezz - ezy * ezy), det * (ezx * ezy - eyx * ezz), det * (eyx * ezy - ezx * eyy),
                       det * (exx * ezz - ezx * ezx));
        r4 = vec4<f32>(det * (ezx * eyx - exx * ezy), det * (exx * eyy - eyx * eyx), 0.0, 0.0);
      }
      state.w = 0.0;
      limitState = INACTIVE_LIMIT;
    }
    case FRICTION_JOINT: {
      let exx = mA + mB + iA * rA.y * rA.y + iB * rB.y * rB.y;
      let exy = -iA * rA.x * rA.y - iB * rB.x * rB.y;
      let eyy = mA + mB + iA * rA.x * rA.x + iB * rB.x * rB.x;
      var det = exx * eyy - exy * exy;
      if (det != 0.0) {
        det = 1.0 / det;
      }
      var angularMass = iA + iB;
      if (angularMass > 0.0) {
        angularMass = 1.0 / angularMass;
      }
      r3 = vec4<f32>(det * eyy, -det * exy, -det * exy, det * exx);
      r4 = vec4<f32>(angularMass, 0.0, 0.0, 0.0);
      state.w = 0.0;
      limitState = INACTIVE_LIMIT;
    }
    case ROPE_JOINT: {
      var u = cB + rB - cA - rA;
      let len = length(u);
      limitState = select(INACTIVE_LIMIT, AT_UPPER_LIMIT, len - p1.x > 0.0);
      var mass = 0.0;
      if (len > LINEAR_SLOP) {
        u = u * (1.0 / len);
        let crA = cross2(rA, u);
        let crB = cross2(rB, u);
        let invMass = mA + iA * crA * crA + mB + iB * crB * crB;
        mass = select(0.0, 1.0 / invMass, invMass != 0.0);
      } else {
        u = vec2<f32>(0.0);
        warm = false;
      }
      r3 = vec4<f32>(u, mass, len);
      state = vec4<f32>(state.x, 0.0, 0.0, 0.0);
    }
    default: {}
  }
  if (warm) {
    state = state * scale;
  } else {
    state = vec4<f32>(0.0);
  }
  jointBodies[2u * j + 1u].w = limitState;
  jointConstraints[base] = r0;
  jointConstraints[base + 2u] = state;
  jointConstraints[base + 3u] = r3;
  jointConstraints[base + 4u] = r4;
  jointConstraints[base + 5u] = r5;
  jointConstraints[base + 6u] = vec4<f32>(lA, lB);
  jointConstraints[base + 7u] = r7;
  jointConstraints[base + 8u] = r8;
}

@compute @workgroup_size(256)
fn store(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
         @builtin(local_invocation_index) lid: u32) {
  let j = joint_slot(wid, nwg, lid);
  if (j == NO_BODY || solverState[SV_SKIP] != 0u) {
    return;
  }
  let info = jointBodies[2u * j + 1u];
  if (info.z == 0u) {
    return;
  }
  jointState[2u * j] = jointConstraints[JOINT_VEC4 * j + 2u];
  jointState[2u * j + 1u] = vec4<f32>(f32(info.w), 0.0, 0.0, 0.0);
}
