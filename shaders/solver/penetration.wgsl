// penetration.wgsl: GpuStage.Penetration, the step's deepest penetration for the accuracy target
// (src/dynamics/b2AccuracyTarget.ts): the largest -s over the points of the touching non-sensor
// contacts' manifolds, s the separation as b2PositionSolverManifold computes it
// (solverCommon.wgsl position_manifold), at the bodies' transforms after the step.
//
// A pass of its own, after every stage that moves a body, rather than a by-product of the position
// iterations: those evaluate a point's separation before their own correction, later colours and
// iterations move the bodies again, and the synchronisation and the time of impact come after
// them, so none of their separations is the state after the step. One dispatch over the solver
// contacts, a few words read per contact and one global atomic per workgroup, is the cheapest
// way to that value.
//
// In:  params (cellSize), solverState[SV_COUNT], contactBodies (bodies A, B, contact index),
//      constraints (radii, row 6), manifolds (type, point count, local normal and points: a
//      sleeping island's contacts keep theirs there, as the engine's keep their manifolds),
//      bodyXf and bodyCell after the synchronisation and the time of impact.
// Out: solverState[SV_PENETRATION]: the f32 bits of max(0, -s) over every point (colour.wgsl's
//      `begin` zeroes it each step), read back with the step's counts (pipeline.ts).
// Invariants: non-negative f32s order as their bits, so integer atomicMax (per workgroup, then
//      once per workgroup into the state) gives the float maximum whatever the order: the same
//      bits on every run. Nothing else is written.

@group(0) @binding(0) var<uniform> params: SolverParams;
@group(0) @binding(1) var<storage, read_write> solverState: array<atomic<u32>>;
@group(0) @binding(2) var<storage, read> contactBodies: array<vec4<u32>>;
@group(0) @binding(3) var<storage, read> constraints: array<vec4<f32>>;
@group(0) @binding(4) var<storage, read> manifolds: array<vec4<u32>>;
@group(0) @binding(5) var<storage, read> bodyXf: array<vec4<f32>>;
@group(0) @binding(6) var<storage, read> bodyCell: array<vec2<i32>>;

// The workgroup's deepest point (WebGPU zeroes workgroup memory at the start of each workgroup).
var<workgroup> deepest: atomic<u32>;

// The depth (>= 0) of solver contact k's deepest point, in A's cell.
fn depth(k: u32) -> f32 {
  let cb = contactBodies[k];
  let i = cb.w;
  let header = manifolds[4u * i].x;
  let lm = bitcast<vec4<f32>>(manifolds[4u * i + 1u]);
  let localPoints = bitcast<vec4<f32>>(manifolds[4u * i + 2u]);
  let radii = constraints[CONSTRAINT_VEC4 * k + 6u].zw;
  let xfA = bodyXf[cb.x];
  let xfB = bodyXf[cb.y];
  let cellDelta = vec2<f32>(bodyCell[cb.y] - bodyCell[cb.x]) * params.cellSize;
  var d = 0.0;
  for (var j = 0u; j < ((header >> 2u) & 3u); j = j + 1u) {
    let m = position_manifold(header & 3u, j, xfA.xy, xfA.zw, xfB.xy + cellDelta, xfB.zw, lm, localPoints, radii);
    d = max(d, -m.separation);
  }
  return d;
}

// One invocation per solver contact (the indirect size SV_ARGS_CONTACTS).
@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let k = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (k < atomicLoad(&solverState[SV_COUNT])) {
    let d = depth(k);
    if (d > 0.0) {
      atomicMax(&deepest, bitcast<u32>(d));
    }
  }
  workgroupBarrier();
  if (lid == 0u) {
    let d = atomicLoad(&deepest);
    if (d != 0u) {
      atomicMax(&solverState[SV_PENETRATION], d);
    }
  }
}
