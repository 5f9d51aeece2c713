// solvePosition.wgsl: GpuStage.Position, one position iteration over one colour (or a run of them
// in one workgroup): its contacts' b2ContactSolver::SolvePositionConstraints
// (b2PositionSolverManifold, Baumgarte with b2_linearSlop and b2_maxLinearCorrection), then its
// joints' b2*Joint::SolvePositionConstraints (solveJointsCommon.wgsl); and 2.2.1's early exit as
// GPU work (`check`).
//
// In:  colour (`main`: the pass's colour; `tail`: its first colour), solverState
//      (SV_COLOUR_START, SV_JOINTS, SV_COLOURS_USED, SV_MIN_SEPARATION), colourKeys (items: joint
//      slots below SV_JOINTS, then solver contacts), contactBodies, constraints (masses, radii,
//      local geometry and centres, B's cell relative to A's), jointBodies, jointParams,
//      jointConstraints, bodySweep (c, a after integratePositions.wgsl).
// Out: `main`: bodySweep c, a of the dynamic bodies of the colour's items (one colour below
//      COLOUR_CAP); the minimum separation of the iteration (atomicMin of sortable keys:
//      order-independent); SV_JOINT_ERROR when a joint is not within b2_linearSlop /
//      b2_angularSlop. `tail` (one workgroup, after the iteration's passes of `main`): the same
//      for the colours from its first up to SV_COLOURS_USED, with barriers between them, then the
//      overflow set.
//      `check` (one invocation, after each iteration's passes): unless SV_POSITION_DONE, counts
//      the iteration in SV_POSITION_ITERATIONS; when the minimum separation is >= -3
//      b2_linearSlop (2.2.1's contactsOkay) and no joint set SV_JOINT_ERROR (jointsOkay), sets
//      SV_POSITION_DONE and zeroes the indirect sizes of every position pass (the tail's
//      included), so the remaining iterations dispatch no workgroups; resets the minimum to 0
//      (b2ContactSolver starts each iteration at 0) and SV_JOINT_ERROR. colour.wgsl's `offsets`
//      restores the sizes each step.
//      `fused` (one workgroup, for a small world): every iteration of the tail's walk from colour
//      0 and `check` in one dispatch; it stops at the early exit (and leaves the position passes'
//      sizes, which only the per-colour and tail passes read: so it binds no more than the 8
//      storage buffers every browser gives a stage).
// Invariants: one writer per dynamic body per pass (the colouring); no read-back. 2.2.1 solves
//      all of an island's contacts, then all its joints, per iteration; here each colour's
//      contacts, then its joints (the same within a colour, whose items share no dynamic body;
//      the overflow set runs its contacts, then its joints, in one invocation). The exit is
//      global (all contacts and joints of the world), where 2.2.1 exits per island: at least as
//      many iterations as 2.2.1 for every island.

@group(0) @binding(0) var<uniform> colour: ColourParams;
@group(0) @binding(1) var<storage, read_write> solverState: array<atomic<u32>>;
@group(0) @binding(2) var<storage, read> colourKeys: array<vec2<u32>>;
@group(0) @binding(3) var<storage, read> contactBodies: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read> constraints: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read_write> bodySweep: array<vec4<f32>>;
@group(0) @binding(6) var<storage, read_write> solverIndirect: array<u32>;

fn solve(k: u32) -> f32 {
  let cb = contactBodies[k];
  let base = CONSTRAINT_VEC4 * k;
  let masses = constraints[base + 1u];
  let mA = masses.x;
  let iA = masses.y;
  let mB = masses.z;
  let iB = masses.w;
  let radii = constraints[base + 6u].zw;
  let lm = constraints[base + 9u];
  let localPoints = constraints[base + 10u];
  let centres = constraints[base + 11u];
  let cellDelta = constraints[base + 12u].xy;
  let count = (cb.z >> CB_MANIFOLD_POINTS_SHIFT) & 3u;
  let kind = (cb.z >> CB_TYPE_SHIFT) & 3u;
  let sweepA = bodySweep[2u * cb.x + 1u];
  let sweepB = bodySweep[2u * cb.y + 1u];
  var cA = sweepA.xy;
  var aA = sweepA.z;
  var cB = sweepB.xy + cellDelta;
  var aB = sweepB.z;
  var minSeparation = 0.0;
  for (var j = 0u; j < count; j = j + 1u) {
    let qA = rot(aA);
    let qB = rot(aB);
    let pA = cA - rotate(qA, centres.xy);
    let pB = cB - rotate(qB, centres.zw);
    let m = position_manifold(kind, j, pA, qA, pB, qB, lm, localPoints, radii);
    let rA = m.point - cA;
    let rB = m.point - cB;
    minSeparation = min(minSeparation, m.separation);
    let C = clamp(BAUMGARTE * (m.separation + LINEAR_SLOP), -MAX_LINEAR_CORRECTION, 0.0);
    let rnA = cross2(rA, m.normal);
    let rnB = cross2(rB, m.normal);
    let K = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
    let impulse = select(0.0, -C / K, K > 0.0);
    let P = impulse * m.normal;
    cA = cA - mA * P;
    aA = aA - iA * cross2(rA, P);
    cB = cB + mB * P;
    aB = aB + iB * cross2(rB, P);
  }
  if ((cb.z & CB_DYNAMIC_A) != 0u) {
    bodySweep[2u * cb.x + 1u] = vec4<f32>(cA, aA, sweepA.w);
  }
  if ((cb.z & CB_DYNAMIC_B) != 0u) {
    bodySweep[2u * cb.y + 1u] = vec4<f32>(cB - cellDelta, aB, sweepB.w);
  }
  return minSeparation;
}

// One joint's position iteration; false when it is not within its slop.
fn solve_joint(j: u32) -> bool {
  let list = jointBodies[2u * j];
  let info = jointBodies[2u * j + 1u];
  if (info.z == 0u) {
    return true;
  }
  var motion = Motion();
  for (var i = 0u; i < 4u; i = i + 1u) {
    if (list[i] != NO_BODY) {
      motion[i] = bodySweep[2u * list[i] + 1u];
    }
  }
  let okay = joint_position(j, info.x, info.w, &motion);
  for (var i = 0u; i < 4u; i = i + 1u) {
    if ((info.y & (1u << i)) != 0u) {
      bodySweep[2u * list[i] + 1u] = motion[i];
    }
  }
  return okay;
}

// Adds an invocation's results to the iteration's: the minimum separation of its contacts and
// whether its joints are within their slop.
fn report(minSeparation: f32, jointsOkay: bool) {
  if (minSeparation < 0.0) {
    atomicMin(&solverState[SV_MIN_SEPARATION], sortable_key(minSeparation));
  }
  if (!jointsOkay) {
    atomicStore(&solverState[SV_JOINT_ERROR], 1u);
  }
}

// The colour's entries first, first + stride, ... below end, one invocation's share.
fn solve_entries(first: u32, end: u32, stride: u32, joints: u32) {
  var minSeparation = 0.0;
  var jointsOkay = true;
  for (var e = first; e < end; e = e + stride) {
    let item = colourKeys[e].y;
    if (item < joints) {
      jointsOkay = solve_joint(item) && jointsOkay;
    } else {
      minSeparation = min(minSeparation, solve(item - joints));
    }
  }
  report(minSeparation, jointsOkay);
}

// The overflow set in one invocation: its contacts, then its joints, as 2.2.1 orders an island's.
fn solve_serial(start: u32, end: u32, joints: u32) {
  var minSeparation = 0.0;
  var jointsOkay = true;
  // Joints sort first (lower items): the contacts' entries, then the joints'.
  var firstContact = start;
  while (firstContact < end && colourKeys[firstContact].y < joints) {
    firstContact = firstContact + 1u;
  }
  for (var e = firstContact; e < end; e = e + 1u) {
    minSeparation = min(minSeparation, solve(colourKeys[e].y - joints));
  }
  for (var e = start; e < firstContact; e = e + 1u) {
    jointsOkay = solve_joint(colourKeys[e].y) && jointsOkay;
  }
  report(minSeparation, jointsOkay);
}

// One entry per invocation: the grid covers the colour.
@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let start = atomicLoad(&solverState[SV_COLOUR_START + colour.colour]);
  let end = atomicLoad(&solverState[SV_COLOUR_START + colour.colour + 1u]);
  let t = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  solve_entries(start + t, min(end, start + t + 1u), 1u, atomicLoad(&solverState[SV_JOINTS]));
}

var<workgroup> coloursUsed: u32;

// SV_COLOURS_USED, uniform across the workgroup (the walk's loop holds barriers).
fn colours_used(lid: u32) -> u32 {
  if (lid == 0u) {
    coloursUsed = atomicLoad(&solverState[SV_COLOURS_USED]);
  }
  return workgroupUniformLoad(&coloursUsed);
}

// One position iteration of colours first .. colours - 1 by one workgroup, in order, a storage
// barrier after each (the next colour reads the positions it wrote), then the overflow set in one
// invocation: the items and order of the passes of `main`, so the same bits.
fn solve_from(first: u32, colours: u32, lid: u32) {
  let joints = atomicLoad(&solverState[SV_JOINTS]);
  for (var c = first; c < colours; c = c + 1u) {
    let start = atomicLoad(&solverState[SV_COLOUR_START + c]);
    solve_entries(start + lid, atomicLoad(&solverState[SV_COLOUR_START + c + 1u]), WORKGROUP_SIZE, joints);
    storageBarrier();
  }
  if (lid == 0u) {
    solve_serial(atomicLoad(&solverState[SV_COLOUR_START + COLOUR_CAP]), atomicLoad(&solverState[SV_COLOUR_START + COLOUR_CAP + 1u]), joints);
  }
}

// One iteration of the colours from `colour` on (those the host records no pass of `main` for)
// and the overflow set; `check` follows it.
@compute @workgroup_size(256)
fn tail(@builtin(local_invocation_index) lid: u32) {
  solve_from(colour.colour, colours_used(lid), lid);
}

// 2.2.1's early exit after an iteration; true when the iterations are done.
fn check_iteration() -> bool {
  if (atomicLoad(&solverState[SV_POSITION_DONE]) != 0u) {
    return true;
  }
  atomicAdd(&solverState[SV_POSITION_ITERATIONS], 1u);
  let minSeparation = atomicLoad(&solverState[SV_MIN_SEPARATION]);
  let jointsOkay = atomicLoad(&solverState[SV_JOINT_ERROR]) == 0u;
  atomicStore(&solverState[SV_MIN_SEPARATION], sortable_key(0.0));
  atomicStore(&solverState[SV_JOINT_ERROR], 0u);
  if (minSeparation >= sortable_key(-3.0 * LINEAR_SLOP) && jointsOkay) {
    atomicStore(&solverState[SV_POSITION_DONE], 1u);
    return true;
  }
  return false;
}

// The exit after an iteration's passes (per colour, then the tail): once done, every position
// pass's size (the tail's at COLOUR_CAP included) is zeroed, so that the remaining iterations
// dispatch no workgroups.
@compute @workgroup_size(1)
fn check() {
  if (atomicLoad(&solverState[SV_POSITION_DONE]) == 0u && check_iteration()) {
    for (var c = 0u; c <= COLOUR_CAP; c = c + 1u) {
      solverIndirect[SV_ARGS_POSITION + 3u * c] = 0u;
      solverIndirect[SV_ARGS_POSITION + 3u * c + 1u] = 1u;
      solverIndirect[SV_ARGS_POSITION + 3u * c + 2u] = 1u;
    }
  }
}

var<workgroup> done: u32;

// A small world's position iterations in one dispatch of one workgroup: per iteration the walk of
// `tail` from colour 0, then `check`'s early exit, so the same bits and the same iteration count.
@compute @workgroup_size(256)
fn fused(@builtin(local_invocation_index) lid: u32) {
  let colours = colours_used(lid);
  for (var it = 0u; it < params.positionIterations; it = it + 1u) {
    solve_from(0u, colours, lid);
    storageBarrier();
    if (lid == 0u) {
      done = select(0u, 1u, check_iteration());
    }
    storageBarrier();
    if (workgroupUniformLoad(&done) != 0u) {
      break;
    }
  }
}
