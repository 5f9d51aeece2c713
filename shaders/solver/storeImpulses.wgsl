// storeImpulses.wgsl: store impulses (in GpuStage.Velocity), b2ContactSolver::StoreImpulses: the solved impulses go
// back into word 3 of the contact's manifold, where the next step's persist pass finds them.
//
// In:  solverState[SV_COUNT], contactBodies (contact index, points used), constraints (impulses).
// Out: manifolds[4i + 3] (normalImpulse, tangentImpulse of points 0 and 1) of each solver
//      contact i; a point the velocity solver did not use (one point kept of an ill-conditioned
//      pair) keeps the manifold's value, as in 2.2.1. MF_SOLVED in the header of each contact
//      that was solved (one with a dynamic body left by prepareContacts: an awake island's), so
//      that PostSolve skips sleeping contacts as b2Island::Report does (the narrow phase writes
//      every header afresh each step).
// Invariants: one invocation per solver contact, each writing its own manifold.

@group(0) @binding(0) var<storage, read> solverState: array<u32>;
@group(0) @binding(1) var<storage, read> contactBodies: array<vec4<u32>>;
@group(0) @binding(2) var<storage, read> constraints: array<vec4<f32>>;
@group(0) @binding(3) var<storage, read_write> manifolds: array<vec4<u32>>;

@compute @workgroup_size(256)
fn main(@builtin(workgroup_id) wid: vec3<u32>, @builtin(num_workgroups) nwg: vec3<u32>,
        @builtin(local_invocation_index) lid: u32) {
  let k = group_index(wid, nwg) * WORKGROUP_SIZE + lid;
  if (k >= solverState[SV_COUNT]) {
    return;
  }
  let cb = contactBodies[k];
  let impulses = constraints[CONSTRAINT_VEC4 * k + 4u];
  let slot = 4u * cb.w + 3u;
  if ((cb.z & CB_POINTS) == 2u) {
    manifolds[slot] = bitcast<vec4<u32>>(impulses);
  } else {
    let old = manifolds[slot];
    manifolds[slot] = vec4<u32>(bitcast<vec2<u32>>(impulses.xy), old.zw);
  }
  if ((cb.z & (CB_DYNAMIC_A | CB_DYNAMIC_B)) != 0u) {
    manifolds[4u * cb.w].x = manifolds[4u * cb.w].x | MF_SOLVED;
  }
}
