// solveVelocity.wgsl: GpuStage.Velocity, one velocity iteration over one colour (or a run of them
// in one workgroup): its joints' b2*Joint::SolveVelocityConstraints (solveJointsCommon.wgsl), and
// its contacts' b2ContactSolver::SolveVelocityConstraints: friction first (clamped by friction x
// the normal impulse), then the normal impulses: one point directly, two points with the block
// solver (its four cases: both points active, only the first, only the second, none).
//
// In:  colour (`main`: the pass's colour; `tail`: its first colour), solverState
//      (SV_COLOUR_START, SV_JOINTS, SV_COLOURS_USED), colourKeys (items: joint slots below
//      SV_JOINTS, then solver contacts), contactBodies, constraints (prepareContacts.wgsl),
//      jointBodies, jointParams (motor speeds, limits, forces as set this step), jointConstraints
//      (solveJoints.wgsl), bodyVel.
// Out: bodyVel of the dynamic bodies of the colour's items; constraints rows 4 (accumulated
//      normal and tangent impulses); jointConstraints rows 2 (accumulated joint impulses).
// Invariants: the items of a colour share no dynamic body (one writer per body per pass); the
//      overflow set runs in one invocation, its joints, then its contacts, in item order, as
//      b2Island::Solve orders joints before contacts; float32 in the engine's order.
//      `main` solves one colour below COLOUR_CAP. `tail` (one workgroup, after the iteration's
//      passes of `main`) walks the colours from its first up to SV_COLOURS_USED with barriers
//      between them, then the overflow set; `fused` (for a small world) runs that walk from
//      colour 0 for every iteration in one dispatch.

@group(0) @binding(0) var<uniform> colour: ColourParams;
@group(0) @binding(1) var<storage, read> solverState: array<u32>;
@group(0) @binding(2) var<storage, read> colourKeys: array<vec2<u32>>;
@group(0) @binding(3) var<storage, read> contactBodies: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read_write> constraints: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read_write> bodyVel: array<vec4<f32>>;

fn relative_velocity(vA: vec2<f32>, wA: f32, vB: vec2<f32>, wB: f32, r: vec4<f32>) -> vec2<f32> {
  return vB + cross_sv(wB, r.zw) - vA - cross_sv(wA, r.xy);
}

fn solve(k: u32) {
  let cb = contactBodies[k];
  let base = CONSTRAINT_VEC4 * k;
  let row0 = constraints[base];
  let normal = row0.xy;
  let friction = row0.z;
  let masses = constraints[base + 1u];
  let mA = masses.x;
  let iA = masses.y;
  let mB = masses.z;
  let iB = masses.w;
  let r0 = constraints[base + 2u];
  let r1 = constraints[base + 3u];
  var impulses = constraints[base + 4u];
  let pointMasses = constraints[base + 5u];
  let bias = constraints[base + 6u].xy;
  let velA = bodyVel[cb.x];
  let velB = bodyVel[cb.y];
  var vA = velA.xy;
  var wA = velA.z;
  var vB = velB.xy;
  var wB = velB.z;
  let tangent = cross_vs(normal, 1.0);
  let count = cb.z & CB_POINTS;

  // Tangent constraints first: friction is clamped by the normal impulse of the previous pass.
  for (var j = 0u; j < count; j = j + 1u) {
    let r = select(r1, r0, j == 0u);
    let tangentMass = select(pointMasses.w, pointMasses.y, j == 0u);
    let normalImpulse = select(impulses.z, impulses.x, j == 0u);
    let tangentImpulse = select(impulses.w, impulses.y, j == 0u);
    let dv = relative_velocity(vA, wA, vB, wB, r);
    let vt = dot(dv, tangent);
    var lambda = tangentMass * (-vt);
    let maxFriction = friction * normalImpulse;
    let newImpulse = clamp(tangentImpulse + lambda, -maxFriction, maxFriction);
    lambda = newImpulse - tangentImpulse;
    if (j == 0u) {
      impulses.y = newImpulse;
    } else {
      impulses.w = newImpulse;
    }
    let P = lambda * tangent;
    vA = vA - mA * P;
    wA = wA - iA * cross2(r.xy, P);
    vB = vB + mB * P;
    wB = wB + iB * cross2(r.zw, P);
  }

  if (count == 1u) {
    let dv = relative_velocity(vA, wA, vB, wB, r0);
    let vn = dot(dv, normal);
    var lambda = -pointMasses.x * (vn - bias.x);
    let newImpulse = max(impulses.x + lambda, 0.0);
    lambda = newImpulse - impulses.x;
    impulses.x = newImpulse;
    let P = lambda * normal;
    vA = vA - mA * P;
    wA = wA - iA * cross2(r0.xy, P);
    vB = vB + mB * P;
    wB = wB + iB * cross2(r0.zw, P);
  } else if (count == 2u) {
    // The block solver (b2ContactSolver.cpp): find x >= 0 with vn = A x + b >= 0 and x_i vn_i = 0
    // by trying the four cases in 2.2.1's order.
    let K = constraints[base + 7u];
    let NM = constraints[base + 8u];
    let a = impulses.xz;
    let dv1 = relative_velocity(vA, wA, vB, wB, r0);
    let dv2 = relative_velocity(vA, wA, vB, wB, r1);
    let vn1 = dot(dv1, normal);
    let vn2 = dot(dv2, normal);
    var b = vec2<f32>(vn1 - bias.x, vn2 - bias.y);
    // b -= b2Mul(K, a), with K = (ex, ey) = ((K.x, K.y), (K.z, K.w)).
    b = b - vec2<f32>(K.x * a.x + K.z * a.y, K.y * a.x + K.w * a.y);
    var x = vec2<f32>(0.0);
    var found = false;
    // Case 1: both points active, x = -inverse(K) b.
    x = -vec2<f32>(NM.x * b.x + NM.z * b.y, NM.y * b.x + NM.w * b.y);
    if (x.x >= 0.0 && x.y >= 0.0) {
      found = true;
    }
    // Case 2: only the first point, vn1 = 0.
    if (!found) {
      x = vec2<f32>(-pointMasses.x * b.x, 0.0);
      let v2 = K.y * x.x + b.y;
      if (x.x >= 0.0 && v2 >= 0.0) {
        found = true;
      }
    }
    // Case 3: only the second point, vn2 = 0.
    if (!found) {
      x = vec2<f32>(0.0, -pointMasses.z * b.y);
      let v1 = K.z * x.y + b.x;
      if (x.y >= 0.0 && v1 >= 0.0) {
        found = true;
      }
    }
    // Case 4: neither point, x = 0.
    if (!found) {
      x = vec2<f32>(0.0);
      if (b.x >= 0.0 && b.y >= 0.0) {
        found = true;
      }
    }
    // No case holds (float32 round-off): 2.2.1 applies nothing.
    if (found) {
      let d = x - a;
      let P1 = d.x * normal;
      let P2 = d.y * normal;
      vA = vA - mA * (P1 + P2);
      wA = wA - iA * (cross2(r0.xy, P1) + cross2(r1.xy, P2));
      vB = vB + mB * (P1 + P2);
      wB = wB + iB * (cross2(r0.zw, P1) + cross2(r1.zw, P2));
      impulses.x = x.x;
      impulses.z = x.y;
    }
  }

  constraints[base + 4u] = impulses;
  if ((cb.z & CB_DYNAMIC_A) != 0u) {
    bodyVel[cb.x] = vec4<f32>(vA, wA, 0.0);
  }
  if ((cb.z & CB_DYNAMIC_B) != 0u) {
    bodyVel[cb.y] = vec4<f32>(vB, wB, 0.0);
  }
}

fn solve_joint(j: u32) {
  let list = jointBodies[2u * j];
  let info = jointBodies[2u * j + 1u];
  if (info.z == 0u) {
    return;
  }
  var motion = Motion();
  for (var i = 0u; i < 4u; i = i + 1u) {
    if (list[i] != NO_BODY) {
      motion[i] = bodyVel[list[i]];
    }
  }
  joint_velocity(j, info.x, info.w, &motion);
  for (var i = 0u; i < 4u; i = i + 1u) {
    if ((info.y & (1u << i)) != 0u) {
      bodyVel[list[i]] = vec4<f32>(motion[i].xyz, 0.0);
    }
  }
}

fn solve_item(item: u32, joints: u32) {
  if (item < joints) {
    solve_joint(item);
  } else {
    solve(item - joints);
  }
}

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let start = solverState[SV_COLOUR_START + colour.colour];
  let end = solverState[SV_COLOUR_START + colour.colour + 1u];
  let t = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (start + t < end) {
    solve_item(colourKeys[start + t].y, solverState[SV_JOINTS]);
  }
}

var<workgroup> coloursUsed: u32;

// SV_COLOURS_USED, uniform across the workgroup (the walk's loop holds barriers).
fn colours_used(lid: u32) -> u32 {
  if (lid == 0u) {
    coloursUsed = solverState[SV_COLOURS_USED];
  }
  return workgroupUniformLoad(&coloursUsed);
}

// One velocity iteration of colours first .. colours - 1 by one workgroup, in order, a storage
// barrier after each (the next colour reads the velocities it wrote), then the overflow set in one
// invocation: the items and order of the passes of `main`, so the same bits.
fn solve_from(first: u32, colours: u32, lid: u32) {
  let joints = solverState[SV_JOINTS];
  for (var c = first; c < colours; c = c + 1u) {
    let end = solverState[SV_COLOUR_START + c + 1u];
    for (var e = solverState[SV_COLOUR_START + c] + lid; e < end; e = e + WORKGROUP_SIZE) {
      solve_item(colourKeys[e].y, joints);
    }
    storageBarrier();
  }
  if (lid == 0u) {
    let end = solverState[SV_COLOUR_START + COLOUR_CAP + 1u];
    for (var e = solverState[SV_COLOUR_START + COLOUR_CAP]; e < end; e = e + 1u) {
      solve_item(colourKeys[e].y, joints);
    }
  }
}

// A small world's velocity iterations in one dispatch of one workgroup.
@compute @workgroup_size(256)
fn fused(@builtin(local_invocation_index) lid: u32) {
  let colours = colours_used(lid);
  for (var it = 0u; it < params.velocityIterations; it = it + 1u) {
    solve_from(0u, colours, lid);
    storageBarrier();
  }
}

// One iteration of the colours from `colour` on (those the host records no pass of `main` for)
// and the overflow set.
@compute @workgroup_size(256)
fn tail(@builtin(local_invocation_index) lid: u32) {
  solve_from(colour.colour, colours_used(lid), lid);
}
