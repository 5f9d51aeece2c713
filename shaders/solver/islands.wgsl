// islands.wgsl: islands and sleeping, b2World::Solve's island search and the end of
// b2Island::Solve, as connected components of the body graph (union-find) instead of a DFS.
//
// In:  params (h, body and joint slot counts, allowSleep), solverState (SV_SKIP, SV_COUNT,
//      SV_POSITION_DONE), npState[NP_CONTACTS], contactRef (bodies A and B), manifolds (header
//      flags), solverList (touching non-sensor contacts), joints, bodyFlags, bodyAwake (1 awake,
//      0 asleep), bodySweep (sleepTime in word 7), bodyVel.
// Out: before the solver: `init` (per body slot) resets the union-find; `wake` (per contact) wakes
//      both bodies of a contact new this step (b2ContactManager::AddPair) or whose touching state
//      changed, sensors excepted (b2Contact::Update); `hook_contacts` (per solver contact) and
//      `hook_joints` (per joint slot) unite the two bodies when neither is static (b2World::Solve
//      never continues its search through a static body); `label` (per body) points every body at
//      its component's root and marks the component awake when any body in it is; `spread` (per
//      body) wakes every body of an awake component (SetAwake(true): sleepTime = 0) and keeps a
//      sleeping body at zero velocity and sleep time (SetAwake(false)'s state, also when the
//      application put it to sleep).
//      After the position iterations: `sleep_time` (per awake body) b2Island::Solve's sleep timer
//      and the component's minimum (atomicMin of the f32 bits: the times are >= 0, so the bits
//      order as the floats do); `sleep` (per awake body) puts the whole component to sleep once
//      the minimum is >= b2_timeToSleep and the position iterations converged, and counts the
//      nodes still awake into solverState[SV_AWAKE] (0: the world is at rest, and the host
//      records no more steps until it uploads something: GpuPipeline.skipResting).
// Invariants: nodes are live active non-static bodies; islands[4i] (the parent) only ever points
//      to a smaller slot, a root only to itself, so after `label` every body of a component holds
//      the component's smallest slot whatever order the hooks ran in: the same labels every run.
//      No float atomics. Nothing runs when SV_SKIP is set (the host reruns the step). Static
//      bodies are no nodes: their awake word is never written and wakes nothing.

struct IslandParams {
  h: f32,
  bodySlots: u32,
  jointSlots: u32,
  allowSleep: u32,
}

@group(0) @binding(0) var<uniform> params: IslandParams;
@group(0) @binding(1) var<storage, read_write> solverState: array<atomic<u32>>;
@group(0) @binding(2) var<storage, read> npState: array<u32>;
@group(0) @binding(3) var<storage, read> contactRef: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read> manifolds: array<vec4<u32>>;
@group(0) @binding(5) var<storage, read> solverList: array<u32>;
@group(0) @binding(6) var<storage, read> joints: array<vec4<u32>>;
@group(0) @binding(7) var<storage, read> bodyFlags: array<u32>;
@group(0) @binding(8) var<storage, read_write> bodyAwake: array<atomic<u32>>;
@group(0) @binding(9) var<storage, read_write> islands: array<atomic<u32>>;
@group(0) @binding(10) var<storage, read_write> bodySweep: array<vec4<f32>>;
@group(0) @binding(11) var<storage, read_write> bodyVel: array<vec4<f32>>;

// islands: ISLAND_WORDS per body slot.
const ISLAND_WORDS: u32 = 4u;
const ISLAND_PARENT: u32 = 0u;       // union-find parent; after `label` the component's root (its smallest slot); NO_ISLAND for a non-node
const ISLAND_AWAKE: u32 = 1u;        // (roots) 1 when a body of the component is awake
const ISLAND_MIN_SLEEP: u32 = 2u;    // (roots) f32 bits of the component's smallest sleep time
const NO_ISLAND: u32 = 0xffffffffu;
const FLT_MAX_BITS: u32 = 0x7f7fffffu;

fn is_node(i: u32) -> bool {
  let flags = bodyFlags[i];
  return (flags & BODY_LIVE) != 0u && (flags & BODY_ACTIVE) != 0u && body_type(flags) != STATIC_BODY;
}

fn body_index(wid: vec3<u32>, nwg: vec3<u32>, lid: u32) -> u32 {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (i >= params.bodySlots || atomicLoad(&solverState[SV_SKIP]) != 0u) {
    return NO_ISLAND;
  }
  return i;
}

// The root of x's tree, halving the path on the way (a parent is only ever replaced by one of its
// ancestors, so concurrent finds and hooks keep every pointer valid).
fn find(x: u32) -> u32 {
  var r = x;
  loop {
    let p = atomicLoad(&islands[ISLAND_WORDS * r + ISLAND_PARENT]);
    if (p == r) {
      return r;
    }
    let g = atomicLoad(&islands[ISLAND_WORDS * p + ISLAND_PARENT]);
    if (g != p) {
      atomicStore(&islands[ISLAND_WORDS * r + ISLAND_PARENT], g);
    }
    r = p;
  }
}

// Hooks the larger root under the smaller one; a failed exchange means that root was hooked
// meanwhile (or a spurious failure): find the roots again and retry. Lock-free: every retry follows
// another invocation's successful hook.
fn unite(a: u32, b: u32) {
  var ra = find(a);
  var rb = find(b);
  loop {
    if (ra == rb) {
      return;
    }
    let hi = max(ra, rb);
    let lo = min(ra, rb);
    let result = atomicCompareExchangeWeak(&islands[ISLAND_WORDS * hi + ISLAND_PARENT], hi, lo);
    if (result.exchanged) {
      return;
    }
    ra = find(hi);
    rb = find(lo);
  }
}

@compute @workgroup_size(256)
fn init(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let i = body_index(wid, nwg, lid);
  if (i == NO_ISLAND) {
    return;
  }
  let base = ISLAND_WORDS * i;
  atomicStore(&islands[base + ISLAND_PARENT], select(NO_ISLAND, i, is_node(i)));
  atomicStore(&islands[base + ISLAND_AWAKE], 0u);
  atomicStore(&islands[base + ISLAND_MIN_SLEEP], FLT_MAX_BITS);
}

@compute @workgroup_size(256)
fn wake(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (atomicLoad(&solverState[SV_SKIP]) != 0u || i >= npState[NP_CONTACTS]) {
    return;
  }
  let header = manifolds[4u * i].x;
  let touchChanged = (header & (MF_BEGAN | MF_ENDED)) != 0u && (header & MF_SENSOR) == 0u;
  if ((header & MF_WARM) != 0u && !touchChanged) {
    return;
  }
  let a = contactRef[2u * i].z;
  let b = contactRef[2u * i + 1u].z;
  if (is_node(a)) {
    atomicStore(&bodyAwake[a], 1u);
  }
  if (is_node(b)) {
    atomicStore(&bodyAwake[b], 1u);
  }
}

@compute @workgroup_size(256)
fn hook_contacts(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
                 @builtin(local_invocation_index) lid: u32) {
  let k = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (k >= atomicLoad(&solverState[SV_COUNT])) {
    return;
  }
  let i = solverList[k];
  let a = contactRef[2u * i].z;
  let b = contactRef[2u * i + 1u].z;
  if (is_node(a) && is_node(b)) {
    unite(a, b);
  }
}

@compute @workgroup_size(256)
fn hook_joints(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
               @builtin(local_invocation_index) lid: u32) {
  let j = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (j >= params.jointSlots || atomicLoad(&solverState[SV_SKIP]) != 0u) {
    return;
  }
  let joint = joints[j];
  if ((joint.w & JOINT_LIVE) != 0u && is_node(joint.x) && is_node(joint.y)) {
    unite(joint.x, joint.y);
  }
}

@compute @workgroup_size(256)
fn label(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
         @builtin(local_invocation_index) lid: u32) {
  let i = body_index(wid, nwg, lid);
  if (i == NO_ISLAND || !is_node(i)) {
    return;
  }
  let root = find(i);
  atomicStore(&islands[ISLAND_WORDS * i + ISLAND_PARENT], root);
  if (atomicLoad(&bodyAwake[i]) != 0u) {
    atomicOr(&islands[ISLAND_WORDS * root + ISLAND_AWAKE], 1u);
  }
}

@compute @workgroup_size(256)
fn spread(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
          @builtin(local_invocation_index) lid: u32) {
  let i = body_index(wid, nwg, lid);
  if (i == NO_ISLAND || !is_node(i)) {
    return;
  }
  let root = atomicLoad(&islands[ISLAND_WORDS * i + ISLAND_PARENT]);
  let s1 = bodySweep[2u * i + 1u];
  if (atomicLoad(&islands[ISLAND_WORDS * root + ISLAND_AWAKE]) != 0u) {
    if (atomicLoad(&bodyAwake[i]) == 0u) {
      atomicStore(&bodyAwake[i], 1u);
      bodySweep[2u * i + 1u] = vec4<f32>(s1.xyz, 0.0);
    }
  } else {
    bodyVel[i] = vec4<f32>(0.0);
    bodySweep[2u * i + 1u] = vec4<f32>(s1.xyz, 0.0);
  }
}

// The root of an awake node that may sleep this step, or NO_ISLAND.
fn sleep_candidate(i: u32) -> u32 {
  if (i == NO_ISLAND || params.allowSleep == 0u || !is_node(i) || atomicLoad(&bodyAwake[i]) == 0u) {
    return NO_ISLAND;
  }
  return atomicLoad(&islands[ISLAND_WORDS * i + ISLAND_PARENT]);
}

@compute @workgroup_size(256)
fn sleep_time(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
              @builtin(local_invocation_index) lid: u32) {
  let i = body_index(wid, nwg, lid);
  let root = sleep_candidate(i);
  if (root == NO_ISLAND) {
    return;
  }
  let vel = bodyVel[i];
  let s1 = bodySweep[2u * i + 1u];
  let linTolSqr = LINEAR_SLEEP_TOLERANCE * LINEAR_SLEEP_TOLERANCE;
  let angTolSqr = ANGULAR_SLEEP_TOLERANCE * ANGULAR_SLEEP_TOLERANCE;
  var sleepTime = 0.0;
  if ((bodyFlags[i] & BODY_AUTO_SLEEP) != 0u && vel.z * vel.z <= angTolSqr && vel.x * vel.x + vel.y * vel.y <= linTolSqr) {
    sleepTime = s1.w + params.h;
  }
  bodySweep[2u * i + 1u] = vec4<f32>(s1.xyz, sleepTime);
  atomicMin(&islands[ISLAND_WORDS * root + ISLAND_MIN_SLEEP], bitcast<u32>(sleepTime));
}

@compute @workgroup_size(256)
fn sleep(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
         @builtin(local_invocation_index) lid: u32) {
  let i = body_index(wid, nwg, lid);
  if (i == NO_ISLAND || !is_node(i) || atomicLoad(&bodyAwake[i]) == 0u) {
    return;
  }
  let root = sleep_candidate(i);
  if (root == NO_ISLAND || atomicLoad(&solverState[SV_POSITION_DONE]) == 0u ||
      bitcast<f32>(atomicLoad(&islands[ISLAND_WORDS * root + ISLAND_MIN_SLEEP])) < TIME_TO_SLEEP) {
    atomicAdd(&solverState[SV_AWAKE], 1u);
    return;
  }
  atomicStore(&bodyAwake[i], 0u);
  bodyVel[i] = vec4<f32>(0.0);
  let s1 = bodySweep[2u * i + 1u];
  bodySweep[2u * i + 1u] = vec4<f32>(s1.xyz, 0.0);
}
