// compact.wgsl: GpuStage.Compact, the compact lists: the solver's contacts and the begin/end
// events, from the flags persist.wgsl wrote and their exclusive prefix sums (scan.wgsl).
//
// In:  solverOffsets[i] / eventOffsets[s] (the scanned flags; totals npState[NP_SOLVER],
//      npState[NP_EVENTS]), this step's and the previous step's manifold headers and keys.
// Out: `main` (per contact i): solverList[solverOffsets[i]] = i for each touching non-sensor
//      contact; events[eventOffsets[i]] = (proxy A, proxy B, EVENT_BEGIN or EVENT_END, i) for
//      each contact that began or ended touching.
//      `vanished` (per previous contact j): events[eventOffsets[NP_CONTACTS + j]] = (proxy A,
//      proxy B, EVENT_END, j | 0x80000000) for a touching contact that is gone.
//      `args` (one invocation): the indirect size of a pass over the solver list (NP_ARGS_SOLVER).
// Invariants: both lists are in contact order (this step's contacts by key, then the vanished
// ones by key), so they are the same on every run; proxy A / B follow the contact's fixture order.

@group(0) @binding(0) var<storage, read_write> npState: array<u32>;
@group(0) @binding(1) var<storage, read_write> npIndirect: array<u32>;
@group(0) @binding(2) var<storage, read> manifolds: array<vec4<u32>>;
@group(0) @binding(3) var<storage, read> prevManifolds: array<vec4<u32>>;
@group(0) @binding(4) var<storage, read> solverOffsets: array<u32>;
@group(0) @binding(5) var<storage, read> eventOffsets: array<u32>;
@group(0) @binding(6) var<storage, read> curKey: array<vec4<u32>>;
@group(0) @binding(7) var<storage, read> prevKey: array<vec4<u32>>;
@group(0) @binding(8) var<storage, read_write> solverList: array<u32>;
@group(0) @binding(9) var<storage, read_write> events: array<vec4<u32>>;

fn oriented(key: vec4<u32>, header: u32) -> vec2<u32> {
  if ((header & MF_SWAPPED) != 0u) {
    return vec2<u32>(key.y, key.x);
  }
  return key.xy;
}

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let i = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (i >= npState[NP_CONTACTS]) {
    return;
  }
  let h = manifolds[4u * i].x;
  if ((h & (MF_TOUCHING | MF_SENSOR)) == MF_TOUCHING) {
    solverList[solverOffsets[i]] = i;
  }
  if ((h & (MF_BEGAN | MF_ENDED)) != 0u) {
    let ab = oriented(curKey[i], h);
    events[eventOffsets[i]] = vec4<u32>(ab.x, ab.y, select(EVENT_END, EVENT_BEGIN, (h & MF_BEGAN) != 0u), i);
  }
}

@compute @workgroup_size(256)
fn vanished(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
            @builtin(local_invocation_index) lid: u32) {
  let j = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (j >= npState[NP_PREV]) {
    return;
  }
  let s = npState[NP_CONTACTS] + j;
  var next = npState[NP_EVENTS];
  if (s + 1u < npState[NP_EVENT_SLOTS]) {
    next = eventOffsets[s + 1u];
  }
  if (next != eventOffsets[s]) {
    let ab = oriented(prevKey[j], prevManifolds[4u * j].x);
    events[eventOffsets[s]] = vec4<u32>(ab.x, ab.y, EVENT_END, j | 0x80000000u);
  }
}

@compute @workgroup_size(1)
fn args() {
  let size = dispatch_size(npState[NP_SOLVER], WORKGROUP_SIZE);
  npIndirect[NP_ARGS_SOLVER] = size.x;
  npIndirect[NP_ARGS_SOLVER + 1u] = size.y;
  npIndirect[NP_ARGS_SOLVER + 2u] = size.z;
}
