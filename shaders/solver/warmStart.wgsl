// warmStart.wgsl: warm start (in GpuStage.Velocity) over one colour, or a run of them in one
// workgroup: b2ContactSolver::WarmStart for its contacts (impulses already scaled by dtRatio,
// prepareContacts.wgsl) and the warm start of b2*Joint::InitVelocityConstraints for its joints
// (solveJointsCommon.wgsl; a mouse joint's 0.98 angular damping included, so this pass runs with
// warm starting off too when there are joints).
//
// In:  colour (`main`: the pass's colour; `tail`: its first colour), solverState (SV_COLOUR_START,
//      SV_JOINTS, SV_COLOURS_USED), colourKeys (sorted (colour, item): items below SV_JOINTS are
//      joint slots, the rest solver contacts k + SV_JOINTS), contactBodies, constraints (normal,
//      rA, rB, impulses, masses), jointBodies, jointConstraints, bodyVel.
// Out: bodyVel of the dynamic bodies of the colour's items.
// Invariants: the items of a colour share no dynamic body, so each body has one writer per pass;
//      the overflow set runs in one invocation, its joints first, then its contacts, in item
//      order. 2.2.1 warm-starts all contacts, then the joints: the same sums but for the mouse
//      joint's damping, which here sees the contacts' warm start of earlier colours only.
//      `main` solves one colour below COLOUR_CAP. `tail` (one workgroup, after the host's passes
//      of `main`) walks the colours from its first up to SV_COLOURS_USED with barriers between
//      them, then the overflow set; `fused` (for a small world) is the same walk from colour 0:
//      every colour's pass in one dispatch.

@group(0) @binding(0) var<uniform> colour: ColourParams;
@group(0) @binding(1) var<storage, read> solverState: array<u32>;
@group(0) @binding(2) var<storage, read> colourKeys: array<vec2<u32>>;
@group(0) @binding(3) var<storage, read> contactBodies: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read> constraints: array<vec4<f32>>;
@group(0) @binding(5) var<storage, read_write> bodyVel: array<vec4<f32>>;

fn warm_start_joint(j: u32) {
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
  joint_warm_start(j, info.x, &motion);
  for (var i = 0u; i < 4u; i = i + 1u) {
    if ((info.y & (1u << i)) != 0u) {
      bodyVel[list[i]] = vec4<f32>(motion[i].xyz, 0.0);
    }
  }
}

fn warm_start_item(item: u32, joints: u32) {
  if (item < joints) {
    warm_start_joint(item);
  } else {
    warm_start(item - joints);
  }
}

fn warm_start(k: u32) {
  let cb = contactBodies[k];
  let base = CONSTRAINT_VEC4 * k;
  let normal = constraints[base].xy;
  let masses = constraints[base + 1u];
  let impulses = constraints[base + 4u];
  let tangent = cross_vs(normal, 1.0);
  var velA = bodyVel[cb.x];
  var velB = bodyVel[cb.y];
  var vA = velA.xy;
  var wA = velA.z;
  var vB = velB.xy;
  var wB = velB.z;
  let count = cb.z & CB_POINTS;
  for (var j = 0u; j < count; j = j + 1u) {
    let r = constraints[base + 2u + j];
    let P = select(impulses.z, impulses.x, j == 0u) * normal + select(impulses.w, impulses.y, j == 0u) * tangent;
    wA = wA - masses.y * cross2(r.xy, P);
    vA = vA - masses.x * P;
    wB = wB + masses.w * cross2(r.zw, P);
    vB = vB + masses.z * P;
  }
  if ((cb.z & CB_DYNAMIC_A) != 0u) {
    bodyVel[cb.x] = vec4<f32>(vA, wA, 0.0);
  }
  if ((cb.z & CB_DYNAMIC_B) != 0u) {
    bodyVel[cb.y] = vec4<f32>(vB, wB, 0.0);
  }
}

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let start = solverState[SV_COLOUR_START + colour.colour];
  let end = solverState[SV_COLOUR_START + colour.colour + 1u];
  let t = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (start + t < end) {
    warm_start_item(colourKeys[start + t].y, solverState[SV_JOINTS]);
  }
}

var<workgroup> coloursUsed: u32;

// The warm start of colours first .. SV_COLOURS_USED - 1 by one workgroup, in order, a storage
// barrier after each (the next colour reads the velocities it wrote), then the overflow set in one
// invocation: the items and order of the passes of `main`, so the same bits.
fn warm_start_from(first: u32, lid: u32) {
  if (lid == 0u) {
    coloursUsed = solverState[SV_COLOURS_USED];
  }
  let colours = workgroupUniformLoad(&coloursUsed);
  let joints = solverState[SV_JOINTS];
  for (var c = first; c < colours; c = c + 1u) {
    let end = solverState[SV_COLOUR_START + c + 1u];
    for (var e = solverState[SV_COLOUR_START + c] + lid; e < end; e = e + WORKGROUP_SIZE) {
      warm_start_item(colourKeys[e].y, joints);
    }
    storageBarrier();
  }
  if (lid == 0u) {
    let end = solverState[SV_COLOUR_START + COLOUR_CAP + 1u];
    for (var e = solverState[SV_COLOUR_START + COLOUR_CAP]; e < end; e = e + 1u) {
      warm_start_item(colourKeys[e].y, joints);
    }
  }
}

// A small world's warm start in one dispatch of one workgroup.
@compute @workgroup_size(256)
fn fused(@builtin(local_invocation_index) lid: u32) {
  warm_start_from(0u, lid);
}

// The colours from `colour` on (those the host records no pass of `main` for) and the overflow set.
@compute @workgroup_size(256)
fn tail(@builtin(local_invocation_index) lid: u32) {
  warm_start_from(colour.colour, lid);
}
